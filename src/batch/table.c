/* The table of every batch kernel × tier × instruction set (shadecalc/batch.h): stated bound,
 * input domain, reference. tests/unit/test_batch.c checks every bound on >= 10^6 inputs;
 * `shadecalc bench` and its --list read the same rows. */
#include <float.h>
#include <math.h>

#include "shadecalc/batch.h"
#include "simd/kernels.h"

/* double references, element i */
#define REF1(name, expr)                                                                          \
    static void ref_##name(const sc_batch_args *a, size_t i, double *out)                         \
    {                                                                                             \
        double x = (double)a->in[0][i];                                                           \
        out[0] = (expr);                                                                          \
    }
#define REF2(name, expr)                                                                          \
    static void ref_##name(const sc_batch_args *a, size_t i, double *out)                         \
    {                                                                                             \
        double x = (double)a->in[0][i], y = (double)a->in[1][i];                                  \
        out[0] = (expr);                                                                          \
    }
REF1(exp2, exp2(x))
REF1(exp, exp(x))
REF1(log2, log2(x))
REF1(log, log(x))
REF2(pow, pow(x, y))
REF1(inversesqrt, 1.0 / sqrt(x))
REF1(sqrt, sqrt(x))

/* One row per instruction set: the same kernel, tier, bound and domain. */
#define ENTRY(k, t, isa_enum, isa, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)        \
    {#k, #t, isa_enum, sc_batch_##k##_##t##_##isa, ref_##ref, nin, 1, ulp, rel, abs_, dom,        \
     {lo0, lo1}, {hi0, hi1}, ops},
#ifdef SC_HAVE_X86
#define ROWS(k, t, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)                        \
    ENTRY(k, t, SC_ISA_SCALAR, scalar, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)    \
    ENTRY(k, t, SC_ISA_SSE41, sse41, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)      \
    ENTRY(k, t, SC_ISA_AVX2, avx2, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)
#else
#define ROWS(k, t, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)                        \
    ENTRY(k, t, SC_ISA_SCALAR, scalar, ref, nin, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, ops)
#endif

static const double b12 = 0x1p-12, b8 = 0x1p-8, b11 = 0x1p-11;

/* clang-format off */
const sc_batch_entry sc_batch_table[] = {
    ROWS(exp2, u1, exp2, 1, 1, 0, 0, "all x", -150, 128, 0, 0, 60)
    ROWS(exp2, u4, exp2, 1, 4, 0, 0, "-125 <= x < 128 (results below 2^-125 flush to 0)", -125, 127.99, 0, 0, 12)
    ROWS(exp2, bits12, exp2, 1, 0, b12, 0, "-125 <= x < 128", -125, 127.99, 0, 0, 10)
    ROWS(exp2, bits8, exp2, 1, 0, b8, 0, "-125 <= x < 128", -125, 127.99, 0, 0, 9)
    ROWS(exp, u1, exp, 1, 1, 0, 0, "all x", -104, 89, 0, 0, 62)
    ROWS(exp, bits12, exp, 1, 0, b12, 0, "-86 <= x <= 88", -86, 88, 0, 0, 11)
    ROWS(exp, bits8, exp, 1, 0, b8, 0, "-86 <= x <= 88", -86, 88, 0, 0, 10)
    ROWS(log2, u1, log2, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, 70)
    ROWS(log2, u4, log2, 1, 4, 0, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 22)
    ROWS(log2, bits12, log2, 1, 0, b12, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 18)
    ROWS(log2, bits8, log2, 1, 0, b8, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 16)
    ROWS(log, u1, log, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, 70)
    ROWS(log, u4, log, 1, 4, 0, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 23)
    ROWS(log, bits12, log, 1, 0, b12, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 19)
    ROWS(log, bits8, log, 1, 0, b8, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, 17)
    ROWS(pow, u1, pow, 2, 1, 0, 0, "x > 0, result a normal float", 0, FLT_MAX, -160, 160, 130)
    ROWS(pow, bits12, pow, 2, 0, b12, 0, "1/16 <= x <= 16, |y| <= 5", 0.0625, 16, -5, 5, 35)
    ROWS(pow, bits8, pow, 2, 0, b8, 0, "1/16 <= x <= 16, |y| <= 5", 0.0625, 16, -5, 5, 27)
    ROWS(inversesqrt, u1, inversesqrt, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, 6)
    ROWS(inversesqrt, u4, inversesqrt, 1, 4, 0, 0, "2^-126 <= x <= 2^126", FLT_MIN, 0x1p126, 0, 0, 5)
    ROWS(inversesqrt, bits11, inversesqrt, 1, 0, b11, 0, "2^-126 <= x <= 2^126", FLT_MIN, 0x1p126, 0, 0, 1)
    ROWS(sqrt, u1, sqrt, 1, 0.5, 0, 0, "x >= 0", 0, FLT_MAX, 0, 0, 1)
};
/* clang-format on */
const int sc_batch_count = (int)(sizeof sc_batch_table / sizeof sc_batch_table[0]);
