/* The GLSL ES 3.00 common functions (§8.3) and angle conversions (§8.1) in binary32, each the
 * specification's defining formula evaluated in float, every operation rounded once
 * (shadecalc/glsl.h). abs, sign, floor, ceil, trunc, round, roundEven, modf, min, max, clamp,
 * step are exact; radians and degrees multiply by the float constants π/180 and 180/π (within
 * 1.5 ULP of x·π/180); fract, mod, mix, smoothstep inherit the roundings of their formulas, as GLSL ES specifies.
 * Results where GLSL ES leaves the input undefined or unspecified (the formula's IEEE value):
 *   sign(±0) = ±0 (0·x keeps the zero's sign; equal to 0.0), sign(NaN) = NaN
 *   min(x, y) = y < x ? y : x, max(x, y) = x < y ? y : x: equal operands (±0) and a NaN y give
 *     x; a NaN x gives NaN
 *   clamp(x, lo, hi) = min(max(x, lo), hi): hi when lo > hi; NaN x gives NaN
 *   fract(x) = x − floor(x): 1.0 (not below) for −2^-25 <= x < 0, e.g. fract(−2^-30) = 1;
 *     0 for |x| >= 2^23; NaN for ±Inf
 *   mod(x, y) = x − y·floor(x/y), sign of y: NaN for y = 0 and for y = ±Inf
 *   mix(x, y, a) = x·(1 − a) + y·a: exactly x at a = 0 and y at a = 1 for finite x, y
 *   step(edge, x) = x < edge ? 0 : 1: step(e, e) = 1, and 1 when either is NaN
 *   smoothstep with edge0 > edge1: the mirrored curve; edge0 = edge1: 0 below, 1 above, NaN at
 *     x = edge0 (0/0)
 *   round(x) = roundEven(x): halves go to the even integer (GLSL ES: either direction), so
 *     round(2.5) = 2, round(−0.5) = −0; the sign of x is kept (round(−0.3) = −0)
 *   modf(x, i): i = trunc(x), the fraction x − i carries x's sign (modf(−3) = −0); ±Inf gives
 *     ±0 and i = ±Inf (C99 modff)
 */
#include <math.h>

#include "shadecalc/glsl.h"

float sc_radiansf(float degrees) { return degrees * (float)(3.14159265358979323846 / 180.0); }
float sc_degreesf(float radians) { return radians * (float)(180.0 / 3.14159265358979323846); }
float sc_absf(float x) { return fabsf(x); }
float sc_signf(float x) { return x > 0.0f ? 1.0f : x < 0.0f ? -1.0f : 0.0f * x; }
float sc_floorf(float x) { return floorf(x); }
float sc_ceilf(float x) { return ceilf(x); }
float sc_fractf(float x) { return x - floorf(x); }
float sc_modf(float x, float y) { return x - y * floorf(x / y); }
float sc_minf(float x, float y) { return y < x ? y : x; }
float sc_maxf(float x, float y) { return x < y ? y : x; }
float sc_clampf(float x, float lo, float hi) { return sc_minf(sc_maxf(x, lo), hi); }
float sc_mixf(float x, float y, float a) { return x * (1.0f - a) + y * a; }
float sc_stepf(float edge, float x) { return x < edge ? 0.0f : 1.0f; }

float sc_smoothstepf(float edge0, float edge1, float x)
{
    float t = sc_clampf((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float sc_truncf(float x) { return truncf(x); }

/* Nearest integer, halves to the even one, whatever the current rounding mode: x − trunc(x)
 * is exact, and |x| >= 2^23 (and ±Inf, NaN) is already its own trunc. */
float sc_roundevenf(float x)
{
    float whole = truncf(x), away = copysignf(1.0f, x), part = fabsf(x - whole);
    int odd = fmodf(whole, 2.0f) != 0.0f;
    return part > 0.5f || (part == 0.5f && odd) ? whole + away : whole;
}

float sc_roundf(float x) { return sc_roundevenf(x); }

float sc_modff(float x, float *whole)
{
    *whole = truncf(x);
    return isinf(x) ? copysignf(0.0f, x) : copysignf(x - *whole, x);
}
