/* pow in binary32 (GLSL ES pow).
 *
 * Method: |x|^y = 2^(y·log2|x|) with the double cores of log.c and exp.c: for a binary32
 * result that does not overflow, |y log2 x| < 150, so the core errors (2^-52 relative) leave
 * the exponent within 2^-44 and the result within 2^-44 relative before the one rounding.
 * Special values are C99 Annex F's (GLSL ES leaves x < 0 and x = 0, y <= 0 undefined; this is
 * the documented result): pow(x, ±0) = 1 and pow(1, y) = 1 even for NaN; pow(−1, ±Inf) = 1;
 * x < 0 gives NaN for a non-integer y and ±|x|^y by the parity of an integer y; ±0 and ±Inf
 * bases follow from log2|x| = ∓Inf/±Inf and the parity rule.
 *
 * Binary64 error bound of the value rounded, the bound make exhaustive relies on (u = 2^-53):
 * |core − x^y| <= (2^-47 + 2^-48 |t|)|core|, t = y log2|x|. log2 carries 29.2u relative
 * (log.c), the product y·lg u more: the exponent within 30.3u|t|, which moves 2^t by
 * ln2·30.3u|t| = 21u|t| relative; then the exp2 bound 2^-47 (exp.c); the sign is exact. For
 * |t| > 1000 the clamp of exp.c rounds the same (0 or ±Inf). Special values are exact.
 * Exact results: where x^y is a binary32 midpoint (pow(4097, 2) = 2^24 + 8193) the core,
 * however accurate, lands on either side; so when the core lies within its bound of a midpoint,
 * x^y is computed exactly if it is a dyadic of at most 53 bits (y = n/2^j with x a 2^j-th
 * power, exact_power) and rounded once. make exhaustive found 48 such misses in 10^5 biased
 * pairs before this. The pairs no exact computation settles, because x^y is not a dyadic but lies
 * closer to a midpoint than the bound, are kept in a table of hard cases (pow_hard_cases).
 *
 * Stated bound: <= 1 ULP against the double reference where the result is a normal binary32;
 * make exhaustive: correctly rounded in 10^9 biased pairs with the table of eight hard pairs.
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

/* 1 if y is an odd integer (every binary32 of magnitude >= 2^24 is an even integer). */
static int is_odd_integer(float y)
{
    if (!(fabsf(y) < 16777216.0f) || y != (float)sc_k_rint((double)y))
        return 0;
    return ((long)y & 1) != 0;
}

static int is_integer(float y)
{
    return fabsf(y) >= 16777216.0f || y == (float)sc_k_rint((double)y);
}

/* ax^y exactly, when it is a double with |log2| <= 1000 (the exact and midpoint results that
 * the core cannot round): y = n/2^j needs ax to be a 2^j-th power (exact square roots, checked
 * with fma), then ax = m·2^k with m odd needs m^n < 2^53 (n >= 1), or m = 1. 0 otherwise. */
static int exact_power(double ax, double y, double *out)
{
    while (y != sc_k_rint(y)) {
        double s = sqrt(ax);
        if (fma(s, s, -ax) != 0.0)
            return 0;
        ax = s;
        y *= 2.0;
    }
    int k;
    double m = frexp(ax, &k); /* ax = m·2^k, m in [1/2, 1) */
    while (m != sc_k_rint(m)) {
        m *= 2.0;
        k--;
    }
    if (fabs(y * k) > 1000.0 || (m != 1.0 && y < 1.0))
        return 0;
    double power = 1.0;
    for (long n = m == 1.0 ? 0 : (long)y; n > 0; n--) {
        if (power > 0x1p53 / m)
            return 0;
        power *= m;
    }
    *out = ldexp(power, (int)(y * k));
    return 1;
}

/* The hard cases of pow: make exhaustive found these eight in 10^9 biased pairs (the core lies
 * within 2^-41 of a midpoint, on the wrong side); each value is |x|^y's midpoint plus one binary64
 * ULP toward the exact value, which MPFR gave at 400 bits. */
static const sc_k_hard_pair pow_hard_cases[] = {
    /* pow(2.8559794e-23, 1.66170335) = 3.4526512988486523e-38 */
    {0x1a0a1b50, 0x3fd4b2b2, 0x1.77f5defffffffp-125},
    /* pow(0.999999821, 128.501465) = 0.99997702240943911 */
    {0x3f7ffffd, 0x43008060, 0x1.fffcfd0000001p-1},
    /* pow(1.00000024, 288042400) = 6.6837810009063689e+29 */
    {0x3f800002, 0x4d89596d, 0x1.0df4ad0000001p+99},
    /* pow(1.00000489, -15082345) = 9.6726981617731900e-33 */
    {0x3f800029, 0xcb662369, 0x1.91c9c4fffffffp-107},
    /* pow(1.00029135, 235813.859) = 6.8128134315270143e+29 */
    {0x3f80098c, 0x48664977, 0x1.132ad70000001p+99},
    /* pow(-0.324662507, -39) = -1.1327827946569249e+19 */
    {0xbea63a2a, 0xc21c0000, 0x1.3a690f0000001p+63},
    /* pow(-1.83595371, 110) = 1.0587417678462033e+29 */
    {0xbfeb0088, 0x42dc0000, 0x1.561910fffffffp+96},
    /* pow(-2834.20996, -7) = -6.8073151907523614e-25 */
    {0xc531235c, 0xc0e00000, 0x1.a55a36fffffffp-81},
};

double sc_k_pow_core(float x, float y)
{
    if (y == 0.0f || x == 1.0f)
        return 1.0;
    if (x != x || y != y)
        return NAN;
    double sign = 1.0, ax = fabs((double)x);
    if (signbit(x)) { /* ±Inf count as even integers */
        if (x < 0.0f && x > -INFINITY && !is_integer(y))
            return NAN;
        sign = is_odd_integer(y) ? -1.0 : 1.0;
    }
    if (ax == 1.0)
        return sign; /* (−1)^±Inf = 1 and (−1)^n */
    double lg = ax == 0.0 ? -INFINITY : ax == INFINITY ? INFINITY : sc_k_log2(ax);
    double t = (double)y * lg; /* ±Inf·finite or finite: never 0·Inf (y ≠ 0, lg ≠ 0) */
    double r = sc_k_exp2(t), exact;
    /* the core's bound, below 2^-40.7 for every result in binary32's range */
    if (sc_k_near_midpoint(r, 0x1p-40))
        r = exact_power(ax, (double)y, &exact)
                ? exact
                : sc_k_lookup_hard_pair(pow_hard_cases, SC_K_TABLE_LEN(pow_hard_cases), x, y, r);
    return sign * r;
}

float sc_powf(float x, float y) { return (float)sc_k_pow_core(x, y); }
