/* exp2 and exp in binary32 (GLSL ES exp2, exp).
 *
 * Method: x = k + f with k = rint(x) and |f| <= 1/2; 2^f = e^(f ln 2) by its Taylor series to
 * degree 13 (truncation below 2^-57 relative on |f ln 2| <= 0.347), evaluated in double by Horner's rule,
 * then scaled by 2^k through the exponent bits; one rounding to binary32 at the end, so
 * overflow, underflow and subnormal results are those of that rounding. exp(x) = 2^(x log2 e)
 * with the product in double (relative error 2^-53, below 2^-45 in the result for
 * |x| <= 104).
 *
 * Binary64 error bound (u = 2^-53; Higham, Accuracy and Stability of Numerical Algorithms,
 * 2nd ed., §5.1 for Horner's rule), the bound make exhaustive relies on:
 *   exp2: |core − 2^x| <= 2^-47 |core|. k and f = x − k are exact; y = f·ln2 carries 2u + u²
 *     (constant and product), moving e^y by <= 0.35·2.01u = 0.7u; Horner on 14 coefficients
 *     (each 1/n! rounded, u) gives <= γ_26·e^|y| + u·e^|y| <= 28.1u·1.415 absolute on a value
 *     >= e^-0.347 = 0.707, so 56.3u relative, plus the truncation 2^-57.2 relative; 2^k exact.
 *     Total 57u + 2^-57.2 < 2^-47.
 *   exp: |core − e^x| <= (2^-47 + 2^-51 |x|)|core|. t = x·log2e carries 2u + u² relative
 *     (constant and product), an absolute error <= 2.01u·|x| log2e in the exponent, which
 *     moves 2^t by ln2·2.01u·|x| log2e = 2.01u|x| relative; then the exp2 bound.
 *   Both, |x| or |t| > 1000: the core computes 2^±1000 (within the bound of 2^±1000); the
 *     exact value lies further out, beyond the binary32 range on the same side, so it rounds to
 *     the same 0 or +Inf (monotone rounding).
 *
 * Stated bound: <= 1 ULP against the double reference for every binary32. make exhaustive,
 * every binary32 input: exp and exp2 correctly rounded with their tables of one and two hard
 * cases (exp_hard_cases, exp2_hard_cases, consulted only when the core lands within its bound of
 * a midpoint).
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

/* 1/n! for n = 0..13 */
static const double inv_factorial[14] = {
    1.0,
    1.0,
    1.0 / 2,
    1.0 / 6,
    1.0 / 24,
    1.0 / 120,
    1.0 / 720,
    1.0 / 5040,
    1.0 / 40320,
    1.0 / 362880,
    1.0 / 3628800,
    1.0 / 39916800,
    1.0 / 479001600,
    1.0 / 6227020800.0,
};

static const double ln2 = 0.6931471805599453094;
static const double log2e = 1.4426950408889634074;

double sc_k_exp2(double x)
{
    if (x != x)
        return x;
    x = x > 1000.0 ? 1000.0 : x < -1000.0 ? -1000.0 : x;
    double k = sc_k_rint(x);
    double y = (x - k) * ln2;
    return sc_k_horner(y, inv_factorial, 14) * sc_k_pow2i((int)k);
}

/* The hard cases of exp2: make exhaustive found these two over all 2^32 inputs (the core rounds
 * them the wrong way); values from MPFR at 300 bits: the midpoint's double plus one ULP. */
static const sc_k_hard_case exp2_hard_cases[] = {
    {0x3b429d37, 0x1.0087090000001p+0}, /* exp2(0.00296957581) = 1.00206047296524057537 */
    {0xbcf3a937, 0x1.f58d610000001p-1}, /* exp2(-0.0297437739) = 0.97959426045417786379 */
};

double sc_k_exp2_core(float x)
{
    double r = sc_k_exp2((double)x);
    return SC_K_SETTLE(exp2_hard_cases, x, r, 0x1p-47);
}
/* The hard case of exp: make exhaustive found this one over all 2^32 inputs (the core rounds it
 * the wrong way); its value from MPFR at 300 bits: the midpoint's double plus one ULP. */
static const sc_k_hard_case exp_hard_cases[] = {
    {0xc2b2e798, 0x1.edb9b00000001p-130}, /* exp(-89.4523315) = 1.41692224155281305922e-39,
                                             4.6e-9 subnormal ULPs above the midpoint */
};

double sc_k_exp_core(float x)
{
    double r = sc_k_exp2((double)x * log2e);
    double bound = 0x1p-47 + 0x1p-51 * fabs((double)x);
    return SC_K_SETTLE(exp_hard_cases, x, r, bound);
}

float sc_exp2f(float x) { return (float)sc_k_exp2_core(x); }
float sc_expf(float x) { return (float)sc_k_exp_core(x); }
