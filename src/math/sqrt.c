/* sqrt and inversesqrt in binary32 (GLSL ES sqrt, inversesqrt).
 *
 * sqrt: the binary64 square root of the float, rounded to binary32, is the correctly rounded
 * binary32 square root (53 >= 2·24 + 2, so the double rounding is innocuous). Stated bound:
 * correctly rounded (0.5 ULP).
 * inversesqrt: 1/√x in binary64 (two roundings, relative error < 2^-52), then rounded to
 * binary32: within 0.5 + 2^-28 ULP. Stated bound: <= 1 ULP.
 * Special values: sqrt(−0) = −0, sqrt(x < 0) = NaN; inversesqrt(+0) = +Inf,
 * inversesqrt(−0) = −Inf (IEEE 1/−0), inversesqrt(x < 0) = NaN, inversesqrt(+Inf) = +0.
 */
#include <math.h>

#include "shadecalc/glsl.h"

float sc_sqrtf(float x) { return (float)sqrt((double)x); }

float sc_inversesqrtf(float x) { return (float)(1.0 / sqrt((double)x)); }
