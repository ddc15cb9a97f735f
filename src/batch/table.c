/* The table of every batch kernel × tier × instruction set (shadecalc/batch.h): stated bound,
 * input domain, reference. tests/unit/test_batch.c checks every bound on >= 10^6 inputs;
 * `shadecalc bench`, its --list and the man page's table read the same rows. Bounds are the
 * measured maxima (`shadecalc bench --list` prints both) rounded up to the tier's name. */
#include <float.h>

#include "batch/reference.h"
#include "batch/reference_light.h"
#include "batch/reference_trig.h"
#include "simd/kernels.h"

/* One row per instruction set: the same kernel, tier, bound and domain. */
#define ENTRY_P(k, t, isa_enum, isa, nin, nout, ulp, rel, abs_, dom, lo0, hi0, lo1, hi1, gen, ops, \
                params)                                                                            \
    {#k,                                                                                           \
     #t,                                                                                           \
     isa_enum,                                                                                     \
     sc_batch_##k##_##t##_##isa,                                                                   \
     sc_batch_ref_##k,                                                                             \
     nin,                                                                                          \
     nout,                                                                                         \
     ulp,                                                                                          \
     rel,                                                                                          \
     abs_,                                                                                         \
     dom,                                                                                          \
     {lo0, lo1},                                                                                   \
     {hi0, hi1},                                                                                   \
     gen,                                                                                          \
     ops,                                                                                          \
     params},
#define ENTRY(...) ENTRY_P(__VA_ARGS__, NULL)
/* ROWS: a kernel without parameters; ROWS_P: with the parameters of its tests (last). */
#ifdef SC_HAVE_X86
#define ROWS_WITH(entry, k, t, ...)                                                                \
    entry(k, t, SC_ISA_SCALAR, scalar, __VA_ARGS__) entry(k, t, SC_ISA_SSE41, sse41, __VA_ARGS__)  \
        entry(k, t, SC_ISA_AVX2, avx2, __VA_ARGS__)                                                \
            entry(k, t, SC_ISA_AVX512, avx512, __VA_ARGS__)
#else
#define ROWS_WITH(entry, k, t, ...) entry(k, t, SC_ISA_SCALAR, scalar, __VA_ARGS__)
#endif
#define ROWS(...) ROWS_WITH(ENTRY, __VA_ARGS__)
#define ROWS_P(...) ROWS_WITH(ENTRY_P, __VA_ARGS__)

#define B22 0x1p-22
#define B12 0x1p-12
#define B11 0x1p-11
#define B8 0x1p-8
#define NOGEN 0, 0, 0, 0, NULL
#define VEC(gen) 0, 0, 0, 0, gen

/* ops: arithmetic vector instructions per vector of 8 elements in the AVX2 kernel (counted in
 * its disassembly: one FMA, estimate or conversion is one), the roofline's compute side. */
/* clang-format off */
const sc_batch_entry sc_batch_table[] = {
    /* kernel, tier, inputs, outputs, ulp, relative, absolute, domain, x range, y range, ops */
    ROWS(exp2, u1, 1, 1, 1, 0, 0, "all x", -150, 128, 0, 0, NULL, 27)
    ROWS(exp2, u4, 1, 1, 4, 0, 0, "all x", -150, 128, 0, 0, NULL, 14)
    ROWS(exp2, bits12, 1, 1, 0, B12, 0, "-125 <= x < 128", -125, 127.99, 0, 0, NULL, 19)
    ROWS(exp2, bits8, 1, 1, 0, B8, 0, "-125 <= x < 128", -125, 127.99, 0, 0, NULL, 18)
    ROWS(exp, u1, 1, 1, 1, 0, 0, "all x", -104, 89, 0, 0, NULL, 29)
    ROWS(exp, u4, 1, 1, 4, 0, 0, "all x", -104, 89, 0, 0, NULL, 16)
    ROWS(exp, bits12, 1, 1, 0, B12, 0, "-86 <= x <= 88", -86, 88, 0, 0, NULL, 20)
    ROWS(exp, bits8, 1, 1, 0, B8, 0, "-86 <= x <= 88", -86, 88, 0, 0, NULL, 19)
    ROWS(log2, u1, 1, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, NULL, 35)
    ROWS(log2, u4, 1, 1, 4, 0, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 23)
    ROWS(log2, bits12, 1, 1, 0, B12, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 26)
    ROWS(log2, bits8, 1, 1, 0, B8, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 25)
    ROWS(log, u1, 1, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, NULL, 35)
    ROWS(log, u4, 1, 1, 4, 0, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 24)
    ROWS(log, bits12, 1, 1, 0, B12, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 27)
    ROWS(log, bits8, 1, 1, 0, B8, 0, "x >= 2^-126", FLT_MIN, FLT_MAX, 0, 0, NULL, 26)
    ROWS(pow, u1, 2, 1, 1, 0, 0, "x > 0, result a normal float", 0, FLT_MAX, -160, 160, NULL, 70)
    ROWS(pow, bits12, 2, 1, 0, B12, 0, "1/16 <= x <= 16, |y| <= 5", 0.0625, 16, -5, 5, NULL, 42)
    ROWS(pow, bits8, 2, 1, 0, B8, 0, "1/16 <= x <= 16, |y| <= 5", 0.0625, 16, -5, 5, NULL, 44)
    ROWS(inversesqrt, u1, 1, 1, 1, 0, 0, "x > 0", 0, FLT_MAX, 0, 0, NULL, 8)
    ROWS(inversesqrt, u4, 1, 1, 4, 0, 0, "2^-126 <= x <= 2^126", FLT_MIN, 0x1p126, 0, 0, NULL, 6)
    ROWS(inversesqrt, bits11, 1, 1, 0, B11, 0, "2^-126 <= x <= 2^126", FLT_MIN, 0x1p126, 0, 0, NULL, 1)
    ROWS(sqrt, u1, 1, 1, 0.5, 0, 0, "x >= 0", 0, FLT_MAX, 0, 0, NULL, 1)
    ROWS(dot, bits22, 6, 1, 0, 0, B22, "|a|, |b| in [2^-8, 2^8]; error <= 2^-22 sum|a_k b_k|", VEC(sc_batch_gen_pair), 4)
    ROWS(reflect, bits22, 6, 3, 0, 0, B22, "|I| in [2^-8, 2^8], N unit; error <= 2^-22 (|I| + 2|N||N.I|)", VEC(sc_batch_gen_reflect), 8)
    ROWS(normalize, u3, 3, 3, 3, 0, 0, "|a| in [2^-60, 2^60]", VEC(sc_batch_gen_vector), 14)
    ROWS(length, u2, 3, 1, 2, 0, 0, "|a| in [2^-60, 2^60]", VEC(sc_batch_gen_vector), 5)
    ROWS(shade, accurate, 9, 3, 0, 0x1p-15, 0x1p-20, "n, v nonzero, |n.v| >= 2^-6 |n||v|, blinn-phong m <= 128, ggx alpha >= 0.2, cos of the spot angle not within 2^-16 of a hard cone edge; error relative, plus 2^-20 x scale", VEC(sc_batch_gen_shade), 40)
    ROWS(shade, bits12, 9, 3, 0, B12, B12, "as accurate", VEC(sc_batch_gen_shade), 40)
#include "batch/rows_trig.h"
#include "batch/rows_light.h"
};
/* clang-format on */
const int sc_batch_count = (int)(sizeof sc_batch_table / sizeof sc_batch_table[0]);
