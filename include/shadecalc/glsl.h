/*
 * shadecalc/glsl.h — the GLSL ES 3.00 scalar built-ins in highp (binary32), accurate tier.
 *
 * angle and trigonometry   sc_radiansf sc_degreesf sc_sinf sc_cosf sc_tanf sc_asinf sc_acosf
 *                          sc_atanf (y_over_x) sc_atan2f (y, x)
 * hyperbolic               sc_sinhf sc_coshf sc_tanhf sc_asinhf sc_acoshf sc_atanhf
 * exponential              sc_powf sc_expf sc_logf sc_exp2f sc_log2f sc_sqrtf sc_inversesqrtf
 * common                   sc_absf sc_signf sc_floorf sc_ceilf sc_fractf sc_modf sc_minf sc_maxf
 *                          sc_clampf sc_mixf sc_stepf sc_smoothstepf sc_truncf sc_roundf
 *                          sc_roundevenf sc_modff (GLSL modf; sc_modf is GLSL mod)
 *
 * Semantics are GLSL ES 3.00 §8 (docs/formulas.md §9): mod(x,y) = x - y*floor(x/y) takes the sign of y;
 * sign(±0) = 0; step(e,e) = 1; clamp = min(max(x,lo),hi); round(x) rounds halves to even, as
 * roundEven does (GLSL ES lets the implementation choose; it is the IEEE default rounding
 * that the CPU's rounding instructions perform). Where GLSL ES leaves an input undefined, each
 * function returns the IEEE result of its formula: shadecalc(3), section SPECIAL VALUES, lists
 * them.
 *
 * Each transcendental has a stated worst-case error against the double-precision reference
 * over a stated domain: the manual page shadecalc(3), section ACCURACY, lists them, and
 * sc_accuracy_table (shadecalc/accuracy.h) holds them at run time; the tests check every
 * stated bound on >= 10^6 inputs.
 */
#ifndef SHADECALC_GLSL_H
#define SHADECALC_GLSL_H

#include "shadecalc/api.h"

SC_BEGIN_DECLS

float sc_radiansf(float degrees);
float sc_degreesf(float radians);
float sc_sinf(float x);
float sc_cosf(float x);
float sc_tanf(float x);
float sc_asinf(float x);
float sc_acosf(float x);
float sc_atanf(float y_over_x);
float sc_atan2f(float y, float x);

/* acosh(x < 1) = NaN, atanh(±1) = ±Inf, atanh(|x| > 1) = NaN (GLSL ES: undefined) */
float sc_sinhf(float x);
float sc_coshf(float x);
float sc_tanhf(float x);
float sc_asinhf(float x);
float sc_acoshf(float x);
float sc_atanhf(float x);

float sc_powf(float x, float y);
float sc_expf(float x);
float sc_logf(float x);
float sc_exp2f(float x);
float sc_log2f(float x);
float sc_sqrtf(float x);
float sc_inversesqrtf(float x);

float sc_absf(float x);
float sc_signf(float x);
float sc_floorf(float x);
float sc_ceilf(float x);
float sc_fractf(float x);
float sc_modf(float x, float y);
float sc_minf(float x, float y);
float sc_maxf(float x, float y);
float sc_clampf(float x, float lo, float hi);
float sc_mixf(float x, float y, float a);
float sc_stepf(float edge, float x);
float sc_smoothstepf(float edge0, float edge1, float x);
float sc_truncf(float x);
float sc_roundf(float x);
float sc_roundevenf(float x);
/* modf(x, out i): writes the whole part trunc(x) to *whole and returns the fraction x − trunc(x)
 * with x's sign (±0 for integers and ±Inf, whose whole part is ±Inf; NaN gives NaN for both). */
float sc_modff(float x, float *whole);

SC_END_DECLS

#endif
