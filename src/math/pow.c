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
 * Stated bound: <= 1 ULP against the double reference where the result is a normal binary32;
 * measured <= 0.5 + 2^-20 ULP.
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

float sc_powf(float x, float y)
{
    if (y == 0.0f || x == 1.0f)
        return 1.0f;
    if (x != x || y != y)
        return NAN;
    double sign = 1.0, ax = fabs((double)x);
    if (signbit(x)) { /* ±Inf count as even integers */
        if (x < 0.0f && x > -INFINITY && !is_integer(y))
            return NAN;
        sign = is_odd_integer(y) ? -1.0 : 1.0;
    }
    if (ax == 1.0)
        return (float)sign; /* (−1)^±Inf = 1 and (−1)^n */
    double lg = ax == 0.0 ? -INFINITY : ax == INFINITY ? INFINITY : sc_k_log2(ax);
    double t = (double)y * lg; /* ±Inf·finite or finite: never 0·Inf (y ≠ 0, lg ≠ 0) */
    return (float)(sign * sc_k_exp2(t));
}
