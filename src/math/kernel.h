/* Internal helpers of the binary32 built-ins (src/math/): each kernel computes in binary64 from
 * the float argument and rounds once at the end, with range reduction and polynomials written
 * so that a SIMD version can follow them lane for lane (selects instead of branches in the main
 * path, no tables). The double cores are shared: log2 by log, log2 and pow; exp2 by exp, exp2
 * and pow (and exp by sinh, cosh, tanh); log and its atanh series by asinh, acosh, atanh; atan
 * by atan, atan2, asin and acos. */
#ifndef SHADECALC_MATH_KERNEL_H
#define SHADECALC_MATH_KERNEL_H

#include <stdint.h>
#include <string.h>

static inline uint64_t sc_bits_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline double sc_double_of(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* Nearest integer (ties to even in the default rounding mode), |x| < 2^51: adding and
 * subtracting 1.5·2^52 rounds away the fraction. */
static inline double sc_k_rint(double x)
{
    const double shifter = 0x1.8p52;
    return (x + shifter) - shifter;
}

/* 2^k as a double, -1022 <= k <= 1023, built from its exponent bits. */
static inline double sc_k_pow2i(int k) { return sc_double_of((uint64_t)(k + 1023) << 52); }

/* Polynomial c[0] + c[1]x + ... + c[n-1]x^(n-1) by Horner's rule. */
static inline double sc_k_horner(double x, const double *c, int n)
{
    double r = c[n - 1];
    for (int i = n - 2; i >= 0; i--)
        r = r * x + c[i];
    return r;
}

/* 1 if r, known to within eps·|r|, might round to the binary32 on either side of a midpoint:
 * r − eps·r and r + eps·r round apart. Where a kernel's result is that close, it resolves the
 * input exactly (pow.c) or from a table of hard cases (log.c). */
static inline int sc_k_near_midpoint(double r, double eps)
{
    return (float)(r - r * eps) != (float)(r + r * eps);
}

/* Hard cases (as CORE-MATH keeps them): inputs whose exact result lies closer to a binary32
 * midpoint than a kernel's bound, each with its value within one binary64 ULP on the exact
 * value's side of the midpoint. sc_k_lookup_hard gives x's value, or r when x has no entry. */
typedef struct {
    uint32_t bits;
    double value;
} sc_k_hard_case;

static inline double sc_k_lookup_hard(const sc_k_hard_case *table, int n, float x, double r)
{
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < n; i++)
        if (table[i].bits == bits)
            return table[i].value;
    return r;
}

/* The hard cases of a function of two arguments (pow, atan2): the pair's bits in argument order
 * and the value as in sc_k_hard_case. sc_k_lookup_hard_pair gives (a, b)'s value, or r. */
typedef struct {
    uint32_t a, b;
    double value;
} sc_k_hard_pair;

static inline double sc_k_lookup_hard_pair(const sc_k_hard_pair *table, int n, float a, float b,
                                           double r)
{
    uint32_t abits, bbits;
    memcpy(&abits, &a, sizeof abits);
    memcpy(&bbits, &b, sizeof bbits);
    for (int i = 0; i < n; i++)
        if (table[i].a == abits && table[i].b == bbits)
            return table[i].value;
    return r;
}

/* The hard cases of sin and acos that lie inside the range where their u1 batch kernels run the
 * cores' algorithms in double lanes; src/simd/trig_impl.h sends exactly these inputs to sc_sinf
 * and sc_acosf. (cos's hard cases lie beyond the Cody–Waite range, which goes to sc_cosf.) */
extern const sc_k_hard_case sc_k_sin_hard_cases[2];
extern const sc_k_hard_case sc_k_acos_hard_cases[2];

/* the number of entries of a hard-case table */
#define SC_K_TABLE_LEN(table) ((int)(sizeof(table) / sizeof((table)[0])))

/* r, or x's value from its table when r, known to within eps·|r|, is too close to a midpoint
 * to tell (the hard-case check every correctly rounded core ends with). */
#define SC_K_SETTLE(table, x, r, eps)                                                              \
    (sc_k_near_midpoint((r), (eps)) ? sc_k_lookup_hard((table), SC_K_TABLE_LEN(table), (x), (r))   \
                                    : (r))

/* 2^x for any double x (clamped to ±1000, beyond which every binary32 result is 0 or +Inf);
 * relative error below 2^-52 (exp2.c). */
double sc_k_exp2(double x);
/* log2(x) for positive, finite, normal double x; absolute error below 2^-52·max(1, |log2 x|)
 * (log.c). */
double sc_k_log2(double x);
/* ln(x) for positive, finite, normal double x; relative error below 2^-48 (log.c: 31.2u for
 * x outside [√½, √2), 26.2u inside). */
double sc_k_log(double x);
/* atanh(s) = s + s³/3 + ... + s^23/23 for |s| <= 0.1716; with s exact, relative error below
 * 25u < 2^-48.3 (Horner's 22u, the coefficients' u, z = s² rounded u·0.01, all on a sum >= 1;
 * the product u; truncation
 * 2^-65) (log.c). */
double sc_k_atanh_series(double s);
/* atan(x) for any finite double x; relative error below 2^-52 (atan.c). */
double sc_k_atan(double x);
/* atan2(y, x) for doubles with every C99 Annex F special case (atan.c). */
double sc_k_atan2(double y, double x);

/* The binary64 value each binary32 built-in rounds once: sc_<name>f(x) == (float) of it for
 * every input, special values included. Each one's error bound against the exact value is
 * stated, with its derivation, in the first comment of its source file; tests/exhaustive/
 * checks every binary32 input with those bounds (make exhaustive). */
/* clang-format off */
#define SC_K_CORE1(name) double sc_k_##name##_core(float x);
SC_K_CORE1(exp) SC_K_CORE1(exp2) SC_K_CORE1(log) SC_K_CORE1(log2) SC_K_CORE1(sin) SC_K_CORE1(cos)
SC_K_CORE1(tan) SC_K_CORE1(asin) SC_K_CORE1(acos) SC_K_CORE1(atan) SC_K_CORE1(sqrt)
SC_K_CORE1(inversesqrt) SC_K_CORE1(sinh) SC_K_CORE1(cosh) SC_K_CORE1(tanh) SC_K_CORE1(asinh)
SC_K_CORE1(acosh) SC_K_CORE1(atanh)
#undef SC_K_CORE1
double sc_k_pow_core(float x, float y);
double sc_k_atan2_core(float y, float x);
/* clang-format on */

#endif
