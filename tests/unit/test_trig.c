/* Semantics of the binary32 trigonometric, sqrt and inversesqrt built-ins (shadecalc/glsl.h):
 * special values (signed zeros, infinities, NaN, GLSL ES undefined inputs), C99 Annex F for
 * atan2, and agreement within 1 ULP with double libm rounded once, on grids and random inputs,
 * including the hard cases of the π/2 range reduction. The >= 10^6-input accuracy sweep is
 * tests/unit/test_math_accuracy.c. */
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

/* ---- helpers ---------------------------------------------------------------------------- */

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

/* xorshift64*: a fixed sequence, so a failure reproduces. */
static uint32_t random_u32(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (uint32_t)((rng_state * 0x2545f4914f6cdd1du) >> 32);
}

static float float_of_bits(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* A random finite binary32 with |x| <= limit, every exponent equally likely. */
static float random_float(float limit)
{
    for (;;) {
        float x = float_of_bits(random_u32());
        if (fabsf(x) <= limit)
            return x;
    }
}

/* Fails with the input when got is not within `bound` ULPs of the double reference. */
static void assert_within_ulps(const char *fn, float x, float got, double ref, double bound)
{
    double err = sc_ulp_error(SC_HIGHP, (double)got, ref);
    if (!(err <= bound))
        fail_msg("%s(%a) = %a, reference %a: %.3f ULP > %.1f", fn, (double)x, (double)got, ref, err,
                 bound);
}

typedef float (*unary_f)(float);
typedef double (*unary_d)(double);

static void check_random_unary(const char *fn, unary_f f, unary_d ref, float limit, int count)
{
    for (int i = 0; i < count; i++) {
        float x = random_float(limit);
        assert_within_ulps(fn, x, f(x), ref((double)x), 1.0);
    }
}

static void assert_negative_zero(float x) { assert_true(x == 0.0f && signbit(x)); }
static void assert_positive_zero(float x) { assert_true(x == 0.0f && !signbit(x)); }

/* ---- sin, cos, tan ---------------------------------------------------------------------- */

static void sin_cos_tan_of_signed_zero(void **state)
{
    (void)state;
    assert_positive_zero(sc_sinf(0.0f));
    assert_negative_zero(sc_sinf(-0.0f));
    assert_positive_zero(sc_tanf(0.0f));
    assert_negative_zero(sc_tanf(-0.0f));
    assert_true(sc_cosf(0.0f) == 1.0f && sc_cosf(-0.0f) == 1.0f);
}

static void sin_cos_tan_of_infinity_and_nan_are_nan(void **state)
{
    (void)state;
    const float inputs[3] = {INFINITY, -INFINITY, NAN};
    for (int i = 0; i < 3; i++) {
        assert_true(isnan(sc_sinf(inputs[i])));
        assert_true(isnan(sc_cosf(inputs[i])));
        assert_true(isnan(sc_tanf(inputs[i])));
    }
}

static void sin_of_tiny_x_is_x(void **state)
{
    (void)state;
    const float tiny[4] = {FLT_MIN, -FLT_MIN, 0x1p-149f, 0x1p-20f};
    for (int i = 0; i < 4; i++) {
        assert_true(sc_sinf(tiny[i]) == tiny[i]);
        assert_true(sc_tanf(tiny[i]) == tiny[i]);
        assert_true(sc_cosf(tiny[i]) == 1.0f);
    }
}

static void sin_cos_tan_match_libm_on_a_grid_to_1e4(void **state)
{
    (void)state;
    for (float x = -1e4f; x <= 1e4f; x += 0.0625f + fabsf(x) * 0x1p-12f) {
        assert_within_ulps("sin", x, sc_sinf(x), sin((double)x), 1.0);
        assert_within_ulps("cos", x, sc_cosf(x), cos((double)x), 1.0);
        assert_within_ulps("tan", x, sc_tanf(x), tan((double)x), 1.0);
    }
}

static void sin_cos_tan_match_libm_for_random_x_to_1e4(void **state)
{
    (void)state;
    check_random_unary("sin", sc_sinf, sin, 1e4f, 100000);
    check_random_unary("cos", sc_cosf, cos, 1e4f, 100000);
    check_random_unary("tan", sc_tanf, tan, 1e4f, 100000);
}

/* Beyond the Cody–Waite range (2^19·π/2) the Payne–Hanek reduction takes over. */
static void sin_cos_tan_match_libm_for_every_finite_magnitude(void **state)
{
    (void)state;
    check_random_unary("sin", sc_sinf, sin, FLT_MAX, 100000);
    check_random_unary("cos", sc_cosf, cos, FLT_MAX, 100000);
    check_random_unary("tan", sc_tanf, tan, FLT_MAX, 100000);
    const float big[5] = {823549.0f, 823550.0f, 0x1p24f, 1e30f, FLT_MAX};
    for (int i = 0; i < 5; i++) {
        assert_within_ulps("sin", big[i], sc_sinf(big[i]), sin((double)big[i]), 1.0);
        assert_within_ulps("sin", -big[i], sc_sinf(-big[i]), sin(-(double)big[i]), 1.0);
        assert_within_ulps("cos", -big[i], sc_cosf(-big[i]), cos(-(double)big[i]), 1.0);
    }
}

/* The floats nearest k·π/2 leave the smallest remainders r, where an inexact reduction shows;
 * tan has its poles there. k runs through small values and through powers of 2 up to 2^120. */
static void check_near_multiple_of_half_pi(double multiple)
{
    float x = (float)multiple;
    float around[3] = {nextafterf(x, -INFINITY), x, nextafterf(x, INFINITY)};
    for (int i = 0; i < 3; i++) {
        float v = around[i];
        assert_within_ulps("sin", v, sc_sinf(v), sin((double)v), 1.0);
        assert_within_ulps("cos", v, sc_cosf(v), cos((double)v), 1.0);
        assert_within_ulps("tan", v, sc_tanf(v), tan((double)v), 1.0);
    }
}

static void reduction_is_exact_near_multiples_of_half_pi(void **state)
{
    (void)state;
    for (int k = -20000; k <= 20000; k++)
        check_near_multiple_of_half_pi(k * (pi / 2));
    for (int e = 0; e <= 120; e++)
        for (int k = 1; k < 64; k++)
            check_near_multiple_of_half_pi(ldexp(k * (pi / 2), e));
}

static void known_values_of_sin_cos_tan(void **state)
{
    (void)state;
    const float pi_f = (float)pi; /* π − 8.74e-8: sin(π_f) is that difference */
    assert_within_ulps("sin", pi_f, sc_sinf(pi_f), pi - (double)pi_f, 1.0);
    assert_true(sc_cosf(pi_f) == -1.0f);
    assert_true(sc_sinf((float)(pi / 2)) == 1.0f);
    assert_true(sc_sinf((float)(pi / 6)) == 0.5f);
    assert_true(sc_tanf((float)(pi / 4)) == 1.0f);
}

/* ---- atan, atan2 ------------------------------------------------------------------------ */

static void atan_special_values(void **state)
{
    (void)state;
    assert_positive_zero(sc_atanf(0.0f));
    assert_negative_zero(sc_atanf(-0.0f));
    assert_true(sc_atanf(INFINITY) == (float)(pi / 2));
    assert_true(sc_atanf(-INFINITY) == -(float)(pi / 2));
    assert_true(sc_atanf(1.0f) == (float)(pi / 4));
    assert_true(isnan(sc_atanf(NAN)));
    assert_true(sc_atanf(0x1p-140f) == 0x1p-140f);
}

static void atan_matches_libm(void **state)
{
    (void)state;
    check_random_unary("atan", sc_atanf, atan, FLT_MAX, 200000);
    for (float x = -4.0f; x <= 4.0f; x += 0x1p-10f)
        assert_within_ulps("atan", x, sc_atanf(x), atan((double)x), 1.0);
}

static void check_atan2_equals_annex_f(float y, float x)
{
    float got = sc_atan2f(y, x), want = (float)atan2((double)y, (double)x);
    if (!(got == want && signbit(got) == signbit(want)))
        fail_msg("atan2(%a, %a) = %a, C99 Annex F gives %a", (double)y, (double)x, (double)got,
                 (double)want);
}

static void atan2_signs_place_every_quadrant(void **state)
{
    (void)state;
    assert_true(sc_atan2f(1.0f, 1.0f) == (float)(pi / 4));
    assert_true(sc_atan2f(1.0f, -1.0f) == (float)(3 * pi / 4));
    assert_true(sc_atan2f(-1.0f, -1.0f) == -(float)(3 * pi / 4));
    assert_true(sc_atan2f(-1.0f, 1.0f) == -(float)(pi / 4));
    assert_true(sc_atan2f(1.0f, 0.0f) == (float)(pi / 2));
    assert_true(sc_atan2f(-1.0f, 0.0f) == -(float)(pi / 2));
    assert_true(sc_atan2f(0.0f, -1.0f) == (float)pi);
}

/* C99 Annex F.9.1.4, every signed zero and infinity against every class of the other
 * argument. atan2(±0, ±0), undefined in GLSL ES, gives Annex F's ±0 and ±π. */
static void atan2_special_cases_follow_c99_annex_f(void **state)
{
    (void)state;
    const float v[] = {0.0f, -0.0f, 1.5f, -1.5f, 0x1p-149f, FLT_MAX, INFINITY, -INFINITY};
    const int n = (int)(sizeof v / sizeof v[0]);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            check_atan2_equals_annex_f(v[i], v[j]);
    assert_positive_zero(sc_atan2f(0.0f, 0.0f));
    assert_negative_zero(sc_atan2f(-0.0f, 0.0f));
    assert_true(sc_atan2f(0.0f, -0.0f) == (float)pi);
    assert_true(sc_atan2f(-0.0f, -0.0f) == -(float)pi);
    assert_true(isnan(sc_atan2f(NAN, 1.0f)) && isnan(sc_atan2f(1.0f, NAN)));
}

static void atan2_matches_libm_on_random_pairs(void **state)
{
    (void)state;
    for (int i = 0; i < 200000; i++) {
        float y = random_float(FLT_MAX), x = random_float(FLT_MAX);
        if (i % 2) /* also pairs of similar magnitude, where the angle is not near 0 or π/2 */
            x = random_float(4.0f) * (y + 1.0f);
        double ref = atan2((double)y, (double)x);
        float got = sc_atan2f(y, x);
        if (!(sc_ulp_error(SC_HIGHP, got, ref) <= 1.0))
            fail_msg("atan2(%a, %a) = %a, reference %a", (double)y, (double)x, (double)got, ref);
    }
}

/* ---- asin, acos ------------------------------------------------------------------------- */

static void asin_acos_special_values(void **state)
{
    (void)state;
    assert_positive_zero(sc_asinf(0.0f));
    assert_negative_zero(sc_asinf(-0.0f));
    assert_true(sc_asinf(1.0f) == (float)(pi / 2) && sc_asinf(-1.0f) == -(float)(pi / 2));
    assert_positive_zero(sc_acosf(1.0f));
    assert_true(sc_acosf(-1.0f) == (float)pi);
    assert_true(sc_acosf(0.0f) == (float)(pi / 2) && sc_acosf(-0.0f) == (float)(pi / 2));
    assert_true(sc_asinf(0.5f) == (float)(pi / 6));
    assert_true(sc_acosf(0.5f) == (float)(pi / 3));
}

/* GLSL ES leaves |x| > 1 undefined; we return NaN, as the IEEE formula does. */
static void asin_acos_outside_unit_interval_are_nan(void **state)
{
    (void)state;
    const float outside[6] = {1.5f, -1.5f, 0x1.000002p0f, -0x1.000002p0f, INFINITY, NAN};
    for (int i = 0; i < 6; i++) {
        assert_true(isnan(sc_asinf(outside[i])));
        assert_true(isnan(sc_acosf(outside[i])));
    }
}

static void asin_acos_match_libm(void **state)
{
    (void)state;
    check_random_unary("asin", sc_asinf, asin, 1.0f, 200000);
    check_random_unary("acos", sc_acosf, acos, 1.0f, 200000);
    for (float x = -1.0f; x <= 1.0f; x += 0x1p-12f) {
        assert_within_ulps("asin", x, sc_asinf(x), asin((double)x), 1.0);
        assert_within_ulps("acos", x, sc_acosf(x), acos((double)x), 1.0);
    }
    for (float x = 1.0f; x > 0.999f; x = nextafterf(x, 0.0f)) { /* steepest part */
        assert_within_ulps("asin", x, sc_asinf(x), asin((double)x), 1.0);
        assert_within_ulps("acos", -x, sc_acosf(-x), acos(-(double)x), 1.0);
    }
}

/* ---- sqrt, inversesqrt ------------------------------------------------------------------ */

static void sqrt_special_values(void **state)
{
    (void)state;
    assert_positive_zero(sc_sqrtf(0.0f));
    assert_negative_zero(sc_sqrtf(-0.0f)); /* IEEE 754: sqrt(−0) = −0 */
    assert_true(isnan(sc_sqrtf(-1.0f)) && isnan(sc_sqrtf(-INFINITY)) && isnan(sc_sqrtf(NAN)));
    assert_true(sc_sqrtf(INFINITY) == INFINITY);
    assert_true(sc_sqrtf(0x1p-149f) == 0x1.6a09e6p-75f);
}

/* libm's sqrtf is correctly rounded (IEEE 754 requires it), so equality is the check. */
static void sqrt_is_correctly_rounded(void **state)
{
    (void)state;
    for (int i = 0; i < 300000; i++) {
        float x = fabsf(random_float(FLT_MAX));
        if (sc_sqrtf(x) != sqrtf(x))
            fail_msg("sqrt(%a) = %a, correctly rounded %a", (double)x, (double)sc_sqrtf(x),
                     (double)sqrtf(x));
    }
    for (float k = 1.0f; k < 4096.0f; k += 1.0f)
        assert_true(sc_sqrtf(k * k) == k);
}

/* GLSL ES leaves x <= 0 undefined; we return the IEEE 1/√x. */
static void inversesqrt_special_values(void **state)
{
    (void)state;
    assert_true(sc_inversesqrtf(0.0f) == INFINITY);
    assert_true(sc_inversesqrtf(-0.0f) == -INFINITY);
    assert_true(isnan(sc_inversesqrtf(-1.0f)) && isnan(sc_inversesqrtf(-INFINITY)));
    assert_true(isnan(sc_inversesqrtf(NAN)));
    assert_positive_zero(sc_inversesqrtf(INFINITY));
    assert_true(sc_inversesqrtf(4.0f) == 0.5f && sc_inversesqrtf(0.25f) == 2.0f);
    assert_true(sc_inversesqrtf(0x1p-148f) == 0x1p74f);
}

/* Within 1 ULP means the exact 1/√x lies strictly between the float neighbours of the result:
 * lo²·x < 1 < hi²·x. lo² and hi² are exact in double, the product is rounded by 2^-53, far
 * less than the distance of either side from 1 (about 2^-23). */
static void inversesqrt_is_within_one_ulp(void **state)
{
    (void)state;
    for (int i = 0; i < 300000; i++) {
        float x = fabsf(random_float(FLT_MAX));
        if (x == 0.0f)
            continue;
        float r = sc_inversesqrtf(x);
        double lo = nextafterf(r, 0.0f), hi = nextafterf(r, INFINITY);
        if (!(lo * lo * (double)x < 1.0 && hi * hi * (double)x > 1.0))
            fail_msg("inversesqrt(%a) = %a is more than 1 ULP away", (double)x, (double)r);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sin_cos_tan_of_signed_zero),
        cmocka_unit_test(sin_cos_tan_of_infinity_and_nan_are_nan),
        cmocka_unit_test(sin_of_tiny_x_is_x),
        cmocka_unit_test(sin_cos_tan_match_libm_on_a_grid_to_1e4),
        cmocka_unit_test(sin_cos_tan_match_libm_for_random_x_to_1e4),
        cmocka_unit_test(sin_cos_tan_match_libm_for_every_finite_magnitude),
        cmocka_unit_test(reduction_is_exact_near_multiples_of_half_pi),
        cmocka_unit_test(known_values_of_sin_cos_tan),
        cmocka_unit_test(atan_special_values),
        cmocka_unit_test(atan_matches_libm),
        cmocka_unit_test(atan2_signs_place_every_quadrant),
        cmocka_unit_test(atan2_special_cases_follow_c99_annex_f),
        cmocka_unit_test(atan2_matches_libm_on_random_pairs),
        cmocka_unit_test(asin_acos_special_values),
        cmocka_unit_test(asin_acos_outside_unit_interval_are_nan),
        cmocka_unit_test(asin_acos_match_libm),
        cmocka_unit_test(sqrt_special_values),
        cmocka_unit_test(sqrt_is_correctly_rounded),
        cmocka_unit_test(inversesqrt_special_values),
        cmocka_unit_test(inversesqrt_is_within_one_ulp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
