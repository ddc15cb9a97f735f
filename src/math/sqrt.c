/* sqrt and inversesqrt in binary32 (GLSL ES sqrt, inversesqrt).
 *
 * sqrt: the binary64 square root of the float (libm sqrt: correctly rounded IEEE, one
 * instruction), rounded to binary32, is the correctly rounded binary32 square root
 * (53 >= 2·24 + 2, so the double rounding is innocuous). Stated bound: correctly rounded.
 * inversesqrt: 1/√x in binary64 (two roundings, relative error < 2^-52), then rounded to
 * binary32: the error is at most 0.5 ULP + 2^-52 relative < 0.5 + 2^-28 ULP. Stated bound:
 * <= 1 ULP. make exhaustive, every binary32 input: both correctly rounded (sound check, MPFR
 * for the 127 inputs of inversesqrt its bound leaves open).
 * Binary64 error bound of the value rounded, the bound make exhaustive relies on (u = 2^-53):
 * sqrt |core − √x| <= u|core| (IEEE 754 square root, correctly rounded); inversesqrt
 * |core − 1/√x| <= 2^-51 |core| (two roundings: (1 + u)/(1 − u) − 1 < 2.01u).
 * Special values: sqrt(−0) = −0, sqrt(+Inf) = +Inf, sqrt(x < 0) = NaN; inversesqrt(+0) = +Inf,
 * inversesqrt(−0) = −Inf (IEEE 1/−0), inversesqrt(+Inf) = +0, inversesqrt(x < 0) = NaN
 * (GLSL ES: x <= 0 undefined). Subnormal x: exact in double, 1/√x <= 2^74.5 stays finite.
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

double sc_k_sqrt_core(float x) { return sqrt((double)x); }
double sc_k_inversesqrt_core(float x) { return 1.0 / sqrt((double)x); }

float sc_sqrtf(float x) { return (float)sc_k_sqrt_core(x); }
float sc_inversesqrtf(float x) { return (float)sc_k_inversesqrt_core(x); }
