/* sinh, cosh and tanh in binary32 (GLSL ES sinh, cosh, tanh).
 *
 * Method, in double from the float argument, one rounding to binary32 at the end:
 *   |x| < 1: sinh x = x·S(x²) with S(z) = Σ z^k/(2k+1)!, k = 0..9 (truncation: the first term
 *     left out, z^10/21!, is below 2^-65 of S >= 1), by Horner's rule; x² is exact (24-bit
 *     significand squared) and a normal double even for subnormal x, so nothing underflows and
 *     tiny x gives S = 1, sinh x = x. tanh x = s/√(1 + s²) with s that sinh.
 *   otherwise, with E = e^|x| (the exp core of exp.c) and R = 1/E:
 *     sinh x = ±(E − R)/2, cosh x = (E + R)/2 (every x), tanh x = ±(E − R)/(E + R).
 *   The exp core clamps |x| log2 e to 1000: for |x| >= 694, E = 2^1000, so sinh and cosh give
 *   2^999 and round to ±Inf like the exact value (sinh and cosh overflow binary32 from
 *   |x| = 89.416, where e^|x|/2 passes FLT_MAX + ½ULP), and tanh gives ±1 exactly (the exact
 *   value differs by 2e^-2|x| < 2^-2000).
 * Special values: sinh(±0) = ±0, tanh(±0) = ±0, cosh(±0) = 1; sinh(±Inf) = ±Inf,
 * cosh(±Inf) = +Inf, tanh(±Inf) = ±1; NaN gives NaN. tanh saturates: it is ±1 in binary32
 * for |x| >= 9.011 (1 − tanh x = 2/(e^2x + 1) < 2^-25, half an ULP below 1).
 *
 * Binary64 error bound of the value rounded (u = 2^-53; Higham, Accuracy and Stability of
 * Numerical Algorithms, 2nd ed., §5.1 for Horner's rule), the bound make exhaustive relies on:
 *   sinh, cosh: |core − exact| <= (2^-46 + 2^-50 |x|)|core| for |x| < 694 (beyond, both round
 *     to the same ±Inf as above).
 *   tanh: |core − exact| <= 2^-47 |core|.
 * Derivation.
 *   Series (|x| < 1): S has positive terms, so Horner's error is <= γ_18·S plus the
 *     coefficients' roundings u·S: 19.1u relative; times x: 20.1u, plus truncation 2^-65:
 *     below 2^-48 for sinh. tanh: s/√(1 + s²) has relative sensitivity 1/cosh²x <= 1 to s's
 *     error (20.1u), and s², 1 + s², √, / add <= 0.3u + 0.5u + u + u: 23u < 2^-47.
 *   Exponentials (|x| >= 1 for sinh and tanh): E carries ε = 2^-47 + 2^-51 |x| (exp.c), R
 *     carries ε + u. To first order E − R is off by E·e1 + R(e1 − e2) (|e1| <= ε, |e2| <= u),
 *     relative to E − R at most ε·coth|x| + u/(E² − 1) <= 1.32ε + 0.16u (|x| >= 1); the
 *     subtraction adds u: sinh within 1.32ε + 1.2u < 2^-46 + 2^-50 |x|. E + R: ε + 0.16u,
 *     plus u: cosh within ε + 1.2u < 2^-46 + 2^-51 |x|. The halving is exact. tanh: the errors
 *     of E reach the quotient (E − R)/(E + R) through d ln tanh / d ln E = 4/(E² − E^-2):
 *     <= 0.552·(2ε + u) at |x| = 1, decreasing (e^2|x| outgrows |x|); so 0.586·2^-47 plus the
 *     three roundings 3u: below 0.7·2^-47.
 *
 * Stated bound: <= 1 ULP against the double reference; make exhaustive checks every binary32
 * input (README, "Correct rounding, every input").
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

/* 1/(2k+1)! for k = 0..9: sinh(x)/x = Σ x^(2k)/(2k+1)! (each factorial is exact in double) */
static const double inv_odd_factorial[10] = {
    1.0,
    1.0 / 6,
    1.0 / 120,
    1.0 / 5040,
    1.0 / 362880,
    1.0 / 39916800,
    1.0 / 6227020800.0,
    1.0 / 1307674368000.0,
    1.0 / 355687428096000.0,
    1.0 / 121645100408832000.0,
};

/* sinh x for |x| < 1 (x a binary32 value, so x² is exact). */
static double sinh_series(double x) { return x * sc_k_horner(x * x, inv_odd_factorial, 10); }

/* e^|x| with its reciprocal. */
static double exp_abs(float x, double *reciprocal)
{
    double e = sc_k_exp_core(fabsf(x));
    *reciprocal = 1.0 / e;
    return e;
}

double sc_k_sinh_core(float x)
{
    if (fabsf(x) < 1.0f)
        return sinh_series((double)x);
    double r, e = exp_abs(x, &r);
    return copysign(0.5 * (e - r), (double)x);
}

double sc_k_cosh_core(float x)
{
    double r, e = exp_abs(x, &r);
    return 0.5 * (e + r);
}

double sc_k_tanh_core(float x)
{
    if (fabsf(x) < 1.0f) {
        double s = sinh_series((double)x);
        return s / sqrt(1.0 + s * s);
    }
    double r, e = exp_abs(x, &r);
    return copysign((e - r) / (e + r), (double)x);
}

float sc_sinhf(float x) { return (float)sc_k_sinh_core(x); }
float sc_coshf(float x) { return (float)sc_k_cosh_core(x); }
float sc_tanhf(float x) { return (float)sc_k_tanh_core(x); }
