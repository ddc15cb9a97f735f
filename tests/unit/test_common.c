/* Semantics of the binary32 GLSL ES common functions and angle conversions (shadecalc/glsl.h):
 * each against its GLSL ES 3.00 §8 definition evaluated independently in double, plus the
 * documented results where GLSL ES leaves an input undefined (sign of zero, NaN in min/max,
 * clamp with lo > hi, smoothstep with edge0 >= edge1, fract rounding up to 1, mod by 0). */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/glsl.h"
#include "shadecalc/precision.h"

static const double pi = 3.14159265358979323846;

static void assert_negative_zero(float x) { assert_true(x == 0.0f && signbit(x)); }
static void assert_positive_zero(float x) { assert_true(x == 0.0f && !signbit(x)); }

/* Test inputs: small integers, halves and quarters, a few awkward floats, both signs. */
static const float samples[] = {
    0.0f,  0.25f,  0.5f,     0.75f,  1.0f,  1.5f,   2.0f,    2.75f,      3.0f,
    7.0f,  10.5f,  100.25f,  1e-3f,  0.1f,  1e10f,  1e-30f,  0x1p-149f,  0x1.fffffep-1f,
    -0.0f, -0.25f, -0.5f,    -0.75f, -1.0f, -1.5f,  -2.0f,   -2.75f,     -3.0f,
    -7.0f, -10.5f, -100.25f, -1e-3f, -0.1f, -1e10f, -1e-30f, -0x1p-149f, -0x1.fffffep-1f};
#define N_SAMPLES ((int)(sizeof samples / sizeof samples[0]))

/* ---- radians, degrees ------------------------------------------------------------------- */

/* x·(float)(π/180): the constant is off by at most 2^-24 relative and the product is rounded,
 * so the result is within 1.5 ULP of the exact x·π/180. */
static void radians_and_degrees_use_float_constants(void **state)
{
    (void)state;
    for (float d = -720.0f; d <= 720.0f; d += 0.375f) {
        assert_true(sc_ulp_error(SC_HIGHP, sc_radiansf(d), (double)d * pi / 180.0) <= 1.5);
        assert_true(sc_ulp_error(SC_HIGHP, sc_degreesf(d), (double)d * 180.0 / pi) <= 1.5);
    }
    assert_true(sc_ulp_error(SC_HIGHP, sc_radiansf(180.0f), pi) <= 1.0);
    assert_true(sc_ulp_error(SC_HIGHP, sc_degreesf((float)pi), 180.0) <= 1.0);
    assert_negative_zero(sc_radiansf(-0.0f));
    assert_true(sc_degreesf(INFINITY) == INFINITY && isnan(sc_radiansf(NAN)));
}

/* ---- abs, sign, floor, ceil ------------------------------------------------------------- */

static void abs_sign_floor_ceil_are_exact(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++) {
        float x = samples[i];
        double xd = (double)x;
        assert_true(sc_absf(x) == (float)fabs(xd) && !signbit(sc_absf(x)));
        assert_true(sc_floorf(x) == (float)floor(xd));
        assert_true(sc_ceilf(x) == (float)ceil(xd));
        assert_true(sc_signf(x) == (float)((xd > 0) - (xd < 0)));
    }
    assert_true(sc_absf(-INFINITY) == INFINITY);
    assert_true(sc_floorf(-0.5f) == -1.0f);
    assert_negative_zero(sc_ceilf(-0.5f));
}

/* GLSL ES: sign(0) = 0.0. We return 0·x, which keeps the zero's sign: sign(−0) = −0 (equal to
 * 0.0 under ==). sign(NaN) = NaN. */
static void sign_of_zero_keeps_the_sign_and_nan_stays_nan(void **state)
{
    (void)state;
    assert_positive_zero(sc_signf(0.0f));
    assert_negative_zero(sc_signf(-0.0f));
    assert_true(sc_signf(-0.0f) == 0.0f);
    assert_true(isnan(sc_signf(NAN)));
    assert_true(sc_signf(INFINITY) == 1.0f && sc_signf(-INFINITY) == -1.0f);
    assert_true(sc_signf(0x1p-149f) == 1.0f && sc_signf(-0x1p-149f) == -1.0f);
}

/* ---- fract, mod ------------------------------------------------------------------------- */

/* fract(x) = x − floor(x), one float rounding of the exact difference. In double the difference
 * is exact, or (tiny negative x) within 2^-53 of 1 and far from any float midpoint, so rounding
 * it to float is the reference. */
static void fract_is_x_minus_floor_x(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++) {
        float x = samples[i];
        assert_true(sc_fractf(x) == (float)((double)x - floor((double)x)));
        assert_true(sc_fractf(x) >= 0.0f && sc_fractf(x) <= 1.0f);
    }
    assert_true(sc_fractf(-0.25f) == 0.75f);
    assert_true(sc_fractf(2.75f) == 0.75f);
    assert_positive_zero(sc_fractf(1e20f)); /* every float above 2^23 is an integer */
    assert_positive_zero(sc_fractf(-0.0f));
    assert_true(isnan(sc_fractf(INFINITY)) && isnan(sc_fractf(NAN)));
}

/* The formula's documented edge: for −2^-25 < x < 0, 1 + x rounds to 1.0 (not below 1). */
static void fract_of_tiny_negative_x_rounds_to_one(void **state)
{
    (void)state;
    assert_true(sc_fractf(-0x1p-30f) == 1.0f);
    assert_true(sc_fractf(-0x1p-149f) == 1.0f);
    assert_true(sc_fractf(-0x1p-24f) == 0x1.fffffep-1f); /* 1 − 2^-24 is a float */
}

/* mod(x, y) = x − y·floor(x/y): the result takes the sign of y, unlike C fmod. The reference is
 * fmod (exact) moved into y's half-open interval. For these small operands the formula is exact
 * too: the rounded x/y cannot cross an integer, and the product and difference are exact. */
static void mod_takes_the_sign_of_y(void **state)
{
    (void)state;
    assert_true(sc_modf(-1.0f, 3.0f) == 2.0f);
    assert_true(sc_modf(1.0f, -3.0f) == -2.0f);
    assert_true(sc_modf(-1.0f, -3.0f) == -1.0f);
    assert_true(sc_modf(5.5f, 2.0f) == 1.5f);
    assert_true(sc_modf(-5.5f, 2.0f) == 0.5f);
    assert_true(sc_modf(7.0f, 0.5f) == 0.0f);
    for (int i = -40; i <= 40; i++)
        for (int j = -8; j <= 8; j++) {
            if (j == 0)
                continue;
            double x = i * 0.25, y = j * 0.5, want = fmod(x, y);
            if (want != 0.0 && (want < 0) != (y < 0))
                want += y;
            assert_true(sc_modf((float)x, (float)y) == (float)want);
        }
}

/* GLSL ES leaves y = 0 undefined: x/0 is ±Inf (or NaN), and the formula gives NaN. */
static void mod_by_zero_is_nan(void **state)
{
    (void)state;
    assert_true(isnan(sc_modf(1.0f, 0.0f)));
    assert_true(isnan(sc_modf(-1.0f, -0.0f)));
    assert_true(isnan(sc_modf(0.0f, 0.0f)));
}

/* ---- min, max, clamp -------------------------------------------------------------------- */

static void min_max_of_ordered_values(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++)
        for (int j = 0; j < N_SAMPLES; j++) {
            float x = samples[i], y = samples[j];
            if (x == y)
                continue;
            assert_true(sc_minf(x, y) == (float)fmin(x, y));
            assert_true(sc_maxf(x, y) == (float)fmax(x, y));
        }
}

/* GLSL ES: min = y < x ? y : x, max = x < y ? y : x. So equal operands (±0) give x, a NaN y gives
 * x, and a NaN x gives NaN (the comparison is false). */
static void min_max_return_x_on_ties_and_unordered(void **state)
{
    (void)state;
    assert_negative_zero(sc_minf(-0.0f, 0.0f));
    assert_positive_zero(sc_minf(0.0f, -0.0f));
    assert_negative_zero(sc_maxf(-0.0f, 0.0f));
    assert_true(sc_minf(1.0f, NAN) == 1.0f && sc_maxf(1.0f, NAN) == 1.0f);
    assert_true(isnan(sc_minf(NAN, 1.0f)) && isnan(sc_maxf(NAN, 1.0f)));
    assert_true(sc_minf(-INFINITY, 3.0f) == -INFINITY && sc_maxf(-INFINITY, 3.0f) == 3.0f);
}

static void clamp_is_min_of_max(void **state)
{
    (void)state;
    for (float x = -3.0f; x <= 3.0f; x += 0.125f)
        assert_true(sc_clampf(x, -1.0f, 2.0f) == (float)fmin(fmax(x, -1.0), 2.0));
    assert_true(sc_clampf(NAN, 0.0f, 1.0f) != sc_clampf(NAN, 0.0f, 1.0f)); /* NaN x: NaN */
}

/* GLSL ES leaves lo > hi undefined; min(max(x, lo), hi) gives hi for every x. */
static void clamp_with_lo_above_hi_returns_hi(void **state)
{
    (void)state;
    for (float x = -3.0f; x <= 3.0f; x += 0.5f)
        assert_true(sc_clampf(x, 1.0f, -1.0f) == -1.0f);
}

/* ---- mix, step, smoothstep -------------------------------------------------------------- */

/* x·(1 − a) + y·a is exact at the ends for finite x, y: a = 0 gives x·1 + y·0 = x, a = 1 gives
 * x·0 + y·1 = y (up to the sign of a zero: mix(−0, 1, 0) = −0 + +0 = +0). */
static void mix_is_exact_at_both_ends(void **state)
{
    (void)state;
    for (int i = 0; i < N_SAMPLES; i++)
        for (int j = 0; j < N_SAMPLES; j++) {
            float x = samples[i], y = samples[j];
            assert_true(sc_mixf(x, y, 0.0f) == x);
            assert_true(sc_mixf(x, y, 1.0f) == y);
        }
}

/* 1 − a is exact here; each product is rounded by half a ULP of itself (|terms| <= 2y for
 * |a| <= 2, 0 < x < y) and the sum by half a ULP of the result, so the error is at most
 * 4·y/|result| + 0.5 ULP of the result, extrapolation (a outside [0, 1]) included. */
static void mix_is_the_glsl_formula(void **state)
{
    (void)state;
    assert_true(sc_mixf(1.0f, 3.0f, 0.5f) == 2.0f);
    assert_true(sc_mixf(1.0f, 3.0f, 2.0f) == 5.0f);
    assert_true(sc_mixf(1.0f, 3.0f, -1.0f) == -1.0f);
    for (float a = -1.0f; a <= 2.0f; a += 1.0f / 64)
        for (float x = 0.5f; x < 100.0f; x *= 1.9f) {
            float y = x * 3.7f + 1.0f;
            double exact = (double)x * (1.0 - a) + (double)y * a;
            if (exact > 0.25)
                assert_true(sc_ulp_error(SC_HIGHP, sc_mixf(x, y, a), exact) <= 4 * y / exact + 0.5);
        }
}

static void step_is_zero_below_the_edge_and_one_from_it(void **state)
{
    (void)state;
    assert_true(sc_stepf(1.0f, 1.0f) == 1.0f);
    assert_true(sc_stepf(1.0f, 0x1.fffffep-1f) == 0.0f);
    assert_true(sc_stepf(1.0f, 2.0f) == 1.0f);
    assert_true(sc_stepf(0.0f, -0.0f) == 1.0f); /* −0 < 0 is false */
    assert_true(sc_stepf(-INFINITY, -INFINITY) == 1.0f);
    assert_true(sc_stepf(NAN, 0.0f) == 1.0f && sc_stepf(0.0f, NAN) == 1.0f); /* not x < edge */
}

/* t = clamp((x − e0)/(e1 − e0), 0, 1), t²(3 − 2t): against the same formula in double, where
 * each of the float operations adds at most half a ULP of its own result. */
static void smoothstep_is_the_hermite_formula(void **state)
{
    (void)state;
    for (float x = -1.0f; x <= 3.0f; x += 1.0f / 128) {
        double t = fmin(fmax(((double)x - 0.5) / (2.25 - 0.5), 0.0), 1.0);
        double exact = t * t * (3.0 - 2.0 * t);
        float got = sc_smoothstepf(0.5f, 2.25f, x);
        assert_true(fabs(got - exact) <= 4 * FLT_EPSILON * exact);
    }
    assert_true(sc_smoothstepf(0.0f, 1.0f, 0.5f) == 0.5f);
    assert_true(sc_smoothstepf(0.0f, 1.0f, -5.0f) == 0.0f);
    assert_true(sc_smoothstepf(0.0f, 1.0f, 5.0f) == 1.0f);
    assert_true(sc_smoothstepf(0.0f, 1.0f, 0.25f) == 0.15625f);
}

/* GLSL ES leaves e0 >= e1 undefined; we return the formula's IEEE value: reversed edges give the
 * mirrored curve, e0 = e1 gives a step (0 below, 1 above, NaN at x = e0 from 0/0). */
static void smoothstep_with_reversed_or_equal_edges_is_the_formula(void **state)
{
    (void)state;
    assert_true(sc_smoothstepf(1.0f, 0.0f, 0.25f) == 0.84375f); /* t = 0.75 */
    assert_true(sc_smoothstepf(1.0f, 0.0f, 2.0f) == 0.0f);
    assert_true(sc_smoothstepf(1.0f, 0.0f, -1.0f) == 1.0f);
    assert_true(sc_smoothstepf(1.0f, 1.0f, 0.5f) == 0.0f);
    assert_true(sc_smoothstepf(1.0f, 1.0f, 1.5f) == 1.0f);
    assert_true(isnan(sc_smoothstepf(1.0f, 1.0f, 1.0f)));
}

/* ---- trunc, round, roundEven, modf ------------------------------------------------------ */

static int same_float(float a, float b)
{
    return (isnan(a) && isnan(b)) || (a == b && signbit(a) == signbit(b));
}

/* Against C99's truncf, nearbyintf (halves to even in the default rounding mode) and modff on
 * every 257th bit pattern (every binade, both signs, NaN and Inf patterns). */
static void trunc_round_modf_match_c99_on_every_257th_float(void **state)
{
    (void)state;
    for (uint64_t u = 0; u < (1ULL << 32); u += 257) {
        uint32_t bits = (uint32_t)u;
        float x, whole, want_whole;
        memcpy(&x, &bits, sizeof x);
        float fraction = sc_modff(x, &whole), want_fraction = modff(x, &want_whole);
        if (!same_float(sc_truncf(x), truncf(x)) || !same_float(sc_roundevenf(x), nearbyintf(x)) ||
            !same_float(sc_roundf(x), nearbyintf(x)) || !same_float(fraction, want_fraction) ||
            !same_float(whole, want_whole))
            fail_msg("x = %a: trunc %a round %a roundEven %a modf %a, %a", (double)x,
                     (double)sc_truncf(x), (double)sc_roundf(x), (double)sc_roundevenf(x),
                     (double)fraction, (double)whole);
    }
}

/* Halves go to the even neighbour, the sign of x stays (GLSL ES: round may go either way; ours
 * is roundEven). */
static void halves_round_to_even(void **state)
{
    (void)state;
    static const float x[] = {0.5f,  1.5f,       2.5f,           -0.5f,      -1.5f,   -2.5f,
                              -0.3f, 8388607.5f, 0x1.fffffep-2f, 4194304.5f, 0x1p23f, 1e30f};
    static const float want[] = {0.0f,  2.0f,       2.0f, -0.0f,      -2.0f,   -2.0f,
                                 -0.0f, 8388608.0f, 0.0f, 4194304.0f, 0x1p23f, 1e30f};
    for (size_t i = 0; i < sizeof x / sizeof x[0]; i++) {
        assert_true(same_float(sc_roundevenf(x[i]), want[i]));
        assert_true(same_float(sc_roundf(x[i]), want[i]));
    }
    assert_true(isnan(sc_roundf(NAN)) && sc_roundf(-INFINITY) == -INFINITY);
}

/* modf: both parts carry the sign of x; an infinity is all whole part. */
static void modf_parts_carry_the_sign_of_x(void **state)
{
    (void)state;
    float whole;
    assert_true(same_float(sc_modff(-2.75f, &whole), -0.75f) && whole == -2.0f);
    assert_negative_zero(sc_modff(-3.0f, &whole));
    assert_true(whole == -3.0f);
    assert_negative_zero(sc_modff(-INFINITY, &whole));
    assert_true(whole == -INFINITY);
    assert_true(same_float(sc_modff(0x1p-149f, &whole), 0x1p-149f));
    assert_positive_zero(whole);
    assert_true(isnan(sc_modff(NAN, &whole)) && isnan(whole));
    assert_negative_zero(sc_truncf(-0.9f));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(radians_and_degrees_use_float_constants),
        cmocka_unit_test(abs_sign_floor_ceil_are_exact),
        cmocka_unit_test(sign_of_zero_keeps_the_sign_and_nan_stays_nan),
        cmocka_unit_test(fract_is_x_minus_floor_x),
        cmocka_unit_test(fract_of_tiny_negative_x_rounds_to_one),
        cmocka_unit_test(mod_takes_the_sign_of_y),
        cmocka_unit_test(mod_by_zero_is_nan),
        cmocka_unit_test(min_max_of_ordered_values),
        cmocka_unit_test(min_max_return_x_on_ties_and_unordered),
        cmocka_unit_test(clamp_is_min_of_max),
        cmocka_unit_test(clamp_with_lo_above_hi_returns_hi),
        cmocka_unit_test(mix_is_exact_at_both_ends),
        cmocka_unit_test(mix_is_the_glsl_formula),
        cmocka_unit_test(step_is_zero_below_the_edge_and_one_from_it),
        cmocka_unit_test(smoothstep_is_the_hermite_formula),
        cmocka_unit_test(smoothstep_with_reversed_or_equal_edges_is_the_formula),
        cmocka_unit_test(trunc_round_modf_match_c99_on_every_257th_float),
        cmocka_unit_test(halves_round_to_even),
        cmocka_unit_test(modf_parts_carry_the_sign_of_x),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
