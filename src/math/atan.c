/* atan, atan2, asin, acos in binary32 (GLSL ES atan(y_over_x), atan(y, x), asin, acos).
 *
 * Method: atan(t) for t in [0, 1] reduces once more, t > tan(π/12) giving
 * π/6 + atan((√3 t − 1)/(√3 + t)), to |u| <= tan(π/12) = 0.268, where the series
 * u − u³/3 + u⁵/5 − … to u^31 truncates below 2^-60; |t| > 1 uses π/2 − atan(1/t). All in
 * double. atan2 takes the ratio of the smaller to the larger magnitude (exact enough in double:
 * 2^-53) and places the angle in its quadrant; asin x = atan2(x, √((1−x)(1+x))) and
 * acos x = atan2(√((1−x)(1+x)), x), where 1 ± x is exact in double. One rounding to binary32.
 * Special values: C99 Annex F, including atan2(±0, +0) = ±0 and atan2(±0, −0) = ±π (GLSL ES
 * leaves atan(0, 0) undefined: this is the documented result); asin, acos of |x| > 1: NaN.
 *
 * Stated bound: <= 1 ULP against the double reference for every binary32 input (pairs for
 * atan2); measured <= 0.5 + 2^-20 ULP.
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

static const double pi = 3.14159265358979323846;
static const double sqrt3 = 1.73205080756887729353;
static const double tan_pi_12 = 0.26794919243112270647;

/* (−1)^j/(2j+1), j = 0..15: atan(u)/u = Σ (−1)^j u^(2j)/(2j+1) */
static const double atan_coef[16] = {1.0,       -1.0 / 3,  1.0 / 5,   -1.0 / 7,
                                     1.0 / 9,   -1.0 / 11, 1.0 / 13,  -1.0 / 15,
                                     1.0 / 17,  -1.0 / 19, 1.0 / 21,  -1.0 / 23,
                                     1.0 / 25,  -1.0 / 27, 1.0 / 29,  -1.0 / 31};

/* atan(t), 0 <= t <= 1 */
static double atan_unit(double t)
{
    double base = 0.0;
    if (t > tan_pi_12) {
        t = (sqrt3 * t - 1.0) / (sqrt3 + t);
        base = pi / 6.0;
    }
    return base + t * sc_k_horner(t * t, atan_coef, 16);
}

double sc_k_atan(double x)
{
    double t = fabs(x);
    double a = t <= 1.0 ? atan_unit(t) : pi / 2.0 - atan_unit(1.0 / t);
    return x < 0.0 ? -a : a;
}

double sc_k_atan2(double y, double x)
{
    if (x != x || y != y)
        return x + y;
    double ay = fabs(y), ax = fabs(x), a;
    if (ay == INFINITY && ax == INFINITY)
        a = pi / 4.0;
    else if (ay == 0.0 && ax == 0.0)
        a = 0.0;
    else if (ay <= ax) /* ratio in [0, 1]; 0 when x = ±Inf */
        a = atan_unit(ay / ax);
    else
        a = pi / 2.0 - atan_unit(ax / ay);
    if (signbit(x))
        a = pi - a; /* left half-plane, including x = −0 */
    return signbit(y) ? -a : a;
}

float sc_atanf(float y_over_x)
{
    if (y_over_x != y_over_x)
        return y_over_x;
    return (float)sc_k_atan((double)y_over_x);
}

float sc_atan2f(float y, float x) { return (float)sc_k_atan2((double)y, (double)x); }

/* √((1 − x)(1 + x)) for |x| <= 1: both factors exact in double. */
static double cosine_of_asin(double x) { return sqrt((1.0 - x) * (1.0 + x)); }

float sc_asinf(float x)
{
    if (!(fabsf(x) <= 1.0f))
        return NAN;
    return (float)sc_k_atan2((double)x, cosine_of_asin((double)x));
}

float sc_acosf(float x)
{
    if (!(fabsf(x) <= 1.0f))
        return NAN;
    return (float)sc_k_atan2(cosine_of_asin((double)x), (double)x);
}
