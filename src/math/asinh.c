/* asinh, acosh and atanh in binary32 (GLSL ES asinh, acosh, atanh).
 *
 * Method, in double from the float argument, one rounding to binary32 at the end. The
 * logarithms are the log kernel of log.c (sc_k_log) and its series sc_k_atanh_series (atanh(s)
 * for |s| <= 0.1716); near the points where the argument of the log nears 1, log(1 + w) is
 * computed as 2 atanh(w/(2 + w)) from a w that carries a small relative error, instead of
 * log of the rounded 1 + w (whose absolute error u would be a large relative one):
 *   asinh |x| = log(|x| + √(x² + 1)); for |x| < 0.35, log(1 + w) with w = |x| + x²/(1 + √(x² + 1))
 *     (then 1 + w <= √2, so |w/(2 + w)| <= 0.1716). Odd: the sign of x.
 *   acosh x = log(x + √((x − 1)(x + 1))); for x < 1.06, log(1 + w) with w = (x − 1) +
 *     √((x − 1)(x + 1)), whose x − 1 and product are exact (x < 2).
 *   atanh |x| = atanh series of |x| itself for |x| < 0.17, else ½ log((1 + |x|)/(1 − |x|)),
 *     1 ± |x| exact. Odd.
 * x² is exact (24-bit significand squared) and a normal double for any binary32, so no step
 * underflows or overflows: tiny x gives asinh x = atanh x = x (the correctly rounded value),
 * huge x gives asinh x = log(2|x|) to the bound below.
 * Special and out-of-domain values (GLSL ES leaves acosh x < 1 and atanh |x| >= 1 undefined;
 * these are the C99 Annex F results, as log gives −Inf at 0 and NaN below):
 *   asinh(±0) = ±0, asinh(±Inf) = ±Inf; acosh(1) = +0, acosh(+Inf) = +Inf, acosh(x < 1) = NaN
 *   (−Inf included); atanh(±0) = ±0, atanh(±1) = ±Inf, atanh(|x| > 1) = NaN; NaN gives NaN.
 *
 * Binary64 error bound of the value rounded (u = 2^-53), the bound make exhaustive relies on:
 * |core − exact| <= 2^-47 |core| for all three. Derivation, with the log kernel's 31.2u relative
 * (26.2u inside [√½, √2)) and the series' 25u for an exact argument (kernel.h):
 *   log(1 + w) from w with relative error δ: s = w/(2 + w) within δ + 1.2u (2/(2 + w) <= 1 times
 *     δ, the sum u·w/(2 + w), the quotient u); atanh's relative sensitivity to s is
 *     s/((1 − s²) atanh s) <= 1.03: 25u + 1.03(δ + 1.2u); the doubling is exact.
 *   asinh, |x| < 0.35: √(x² + 1) within 1.5u, 1 + it 1.8u, the quotient x²/(…) 2.8u, a term
 *     <= 0.18|x|, so w within 0.5u + u = 1.5u: 25u + 2.8u < 2^-48. |x| >= 0.35: the log's
 *     argument m = |x| + √(x² + 1) within 2.5u, an absolute 2.5u in log m >= 0.343: 7.3u, plus
 *     31.2u: 38.5u < 2^-47.7.
 *   acosh, x < 1.06: w within 2u (√ of an exact product, then the sum): 25u + 3.3u < 2^-48.
 *     x >= 1.06: (x − 1)(x + 1) within 3u, its root 2.5u, m within 3.5u, an absolute 3.5u in
 *     log m >= 0.346: 10.1u, plus 31.2u: 41.3u < 2^-47.6.
 *   atanh, |x| < 0.17: the series of an exact argument, 25u. Otherwise the quotient rounds once
 *     (u), an absolute u in log q >= 0.343: 2.9u, plus 31.2u: 34.1u < 2^-47.9.
 *
 * Stated bound: <= 1 ULP against the double reference; make exhaustive checks every binary32
 * input (README, "Correct rounding, every input"); asinh and acosh keep tables of the hard cases
 * it found (below).
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

/* The hard cases (as log.c keeps its own): inputs whose exact value lies closer to a binary32
 * midpoint than the bound, found by make exhaustive, each with the midpoint's double plus one
 * ULP on the exact value's side (MPFR). For huge x, asinh x and acosh x are log 2x ± 1/(4x²): these
 * are log's hard cases at half the argument. asinh's are for |x| (it is odd). */
static const sc_k_hard_case asinh_hard_cases[] = {
    {0x4bdd65a5, 0x1.1e06950000001p+4}, /* asinh(29018954) = 17.876606941223144...+ */
    {0x655890d3, 0x1.a9a3f10000001p+5}, /* asinh(6.3918918e22) */
    {0x6eb1a8ec, 0x1.08b5110000001p+6}, /* asinh(2.749153e28) */
};
static const sc_k_hard_case acosh_hard_cases[] = {
    {0x655890d3, 0x1.a9a3f10000001p+5}, /* acosh(6.3918918e22) */
    {0x6eb1a8ec, 0x1.08b5110000001p+6}, /* acosh(2.749153e28) */
};
enum { N_ASINH_HARD = 3, N_ACOSH_HARD = 2 };

/* r, or x's entry of the table when r is within the bound 2^-47 of a midpoint. */
static double settled(double r, const sc_k_hard_case *table, int n, float x)
{
    return sc_k_near_midpoint(r, 0x1p-47) ? sc_k_lookup_hard(table, n, x, r) : r;
}

/* log(1 + w) for 0 <= w <= √2 − 1, w known to a small relative error. */
static double log1p_small(double w) { return 2.0 * sc_k_atanh_series(w / (2.0 + w)); }

double sc_k_asinh_core(float x)
{
    double a = fabs((double)x);
    if (!(a < INFINITY))
        return (double)x; /* ±Inf, NaN */
    double root = sqrt(a * a + 1.0);
    double r = a < 0.35 ? log1p_small(a + a * a / (1.0 + root)) : sc_k_log(a + root);
    /* the hard cases are all above 2^24; below, the check's r·2^-47 would signal a spurious
     * underflow for the tiny x whose result is x exactly */
    double s = a > 0x1p24 ? settled(r, asinh_hard_cases, N_ASINH_HARD, fabsf(x)) : r;
    return copysign(s, (double)x);
}

double sc_k_acosh_core(float x)
{
    double xd = (double)x;
    if (!(xd >= 1.0) || xd == INFINITY)
        return xd == INFINITY ? xd : NAN;
    double below = xd - 1.0, root = sqrt(below * (xd + 1.0));
    double r = xd < 1.06 ? log1p_small(below + root) : sc_k_log(xd + root);
    return settled(r, acosh_hard_cases, N_ACOSH_HARD, x);
}

double sc_k_atanh_core(float x)
{
    double a = fabs((double)x);
    if (!(a < 1.0))
        return a == 1.0 ? copysign(INFINITY, (double)x) : NAN;
    double r = a < 0.17 ? sc_k_atanh_series(a) : 0.5 * sc_k_log((1.0 + a) / (1.0 - a));
    return copysign(r, (double)x);
}

float sc_asinhf(float x) { return (float)sc_k_asinh_core(x); }
float sc_acoshf(float x) { return (float)sc_k_acosh_core(x); }
float sc_atanhf(float x) { return (float)sc_k_atanh_core(x); }
