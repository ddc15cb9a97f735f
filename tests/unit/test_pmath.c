/* Built-ins in a chosen precision (shadecalc/pmath.h): each operation rounded to the precision,
 * the geometric functions evaluated as their GLSL ES formulas in a fixed order. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "shadecalc/glsl.h"
#include "shadecalc/pmath.h"

static void double_precision_is_libm(void **state)
{
    (void)state;
    for (double x = -3.0; x <= 3.0; x += 0.37) {
        assert_true(sc_p_exp(SC_DOUBLE, x) == exp(x));
        assert_true(sc_p_sin(SC_DOUBLE, x) == sin(x));
        assert_true(sc_p_atan2(SC_DOUBLE, x, 0.5) == atan2(x, 0.5));
    }
    assert_true(sc_p_inversesqrt(SC_DOUBLE, 4.0) == 0.5);
}

static void highp_is_the_binary32_builtin(void **state)
{
    (void)state;
    for (float x = 0.01f; x < 50.0f; x *= 1.7f) {
        assert_true(sc_p_log2(SC_HIGHP, x) == (double)sc_log2f(x));
        assert_true(sc_p_pow(SC_HIGHP, x, 2.5) == (double)sc_powf(x, 2.5f));
    }
    assert_true(sc_p_add(SC_HIGHP, 1.0, 0x1p-30) == 1.0);
}

static void mediump_results_are_binary16_values(void **state)
{
    (void)state;
    for (double x = 0.001; x < 30.0; x *= 1.3) {
        double r = sc_p_exp2(SC_MEDIUMP, sc_round_half(x));
        assert_true(sc_round_half(r) == r);
        double l = sc_p_log(SC_MEDIUMP, sc_round_half(x));
        assert_true(sc_round_half(l) == l);
    }
    assert_true(sc_p_mul(SC_MEDIUMP, 300.0, 300.0) == INFINITY);
}

static void lowp_results_are_fixed_point(void **state)
{
    (void)state;
    double s = sc_p_sin(SC_LOWP, 0.5);
    assert_true(s * 256.0 == rint(s * 256.0));
    assert_true(fabs(s - sin(0.5)) <= 0x1p-9 + 1e-7);
    assert_true(sc_p_exp(SC_LOWP, 1.0) == SC_LOWP_MAX);
}

static void dot_rounds_each_operation_left_to_right(void **state)
{
    (void)state;
    const double a[3] = {1, 1, 1}, b[3] = {1e8, 1, -1e8};
    /* highp: 1e8 + 1 rounds back to 1e8 (binary32 spacing 8 there), so the sum is 0. */
    assert_true(sc_p_dot(SC_HIGHP, a, b, 3) == 0.0);
    assert_true(sc_p_dot(SC_DOUBLE, a, b, 3) == 1.0);
    /* double: left to right, each step rounded, as GLSL ES §8.5 writes it (1e16 + 1 is 1e16) */
    const double c[3] = {1e16, 1, -1e16};
    assert_true(sc_p_dot(SC_DOUBLE, a, c, 3) == 0.0);
}

static void length_overflows_in_mediump(void **state)
{
    (void)state;
    const double v[3] = {200, 200, 200};
    assert_true(sc_p_length(SC_MEDIUMP, v, 3) == INFINITY);
    assert_true(fabs(sc_p_length(SC_HIGHP, v, 3) - 200.0 * sqrt(3.0)) < 1e-4);
}

static void normalize_gives_unit_vectors_and_nan_for_zero(void **state)
{
    (void)state;
    const double v[3] = {3, 0, 4}, zero[3] = {0, 0, 0};
    double out[3];
    sc_p_normalize(SC_HIGHP, v, 3, out);
    assert_true(out[0] == (double)0.6f && out[1] == 0.0 && out[2] == (double)0.8f);
    sc_p_normalize(SC_HIGHP, zero, 3, out);
    assert_true(isnan(out[0]) && isnan(out[1]) && isnan(out[2]));
}

static void cross_follows_the_right_hand_rule(void **state)
{
    (void)state;
    const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    double z[3];
    sc_p_cross(SC_DOUBLE, x, y, z);
    assert_true(z[0] == 0 && z[1] == 0 && z[2] == 1);
    sc_p_cross(SC_DOUBLE, y, x, z);
    assert_true(z[2] == -1);
}

static void reflect_mirrors_about_the_normal(void **state)
{
    (void)state;
    const double i[3] = {1, -1, 0}, n[3] = {0, 1, 0};
    double r[3];
    sc_p_reflect(SC_HIGHP, i, n, 3, r);
    assert_true(r[0] == 1 && r[1] == 1 && r[2] == 0);
}

static void refract_bends_and_reflects_totally(void **state)
{
    (void)state;
    const double n[3] = {0, 1, 0}, straight[3] = {0, -1, 0};
    double t[3];
    sc_p_refract(SC_DOUBLE, straight, n, 0.75, 3, t); /* normal incidence: eta·I - (eta·d + 1)·N */
    assert_true(t[0] == 0 && fabs(t[1] + 1.0) < 1e-15 && t[2] == 0);
    const double grazing[3] = {0.99498743710662, -0.1, 0}; /* sin θ = 0.995, eta = 1.5: TIR */
    sc_p_refract(SC_DOUBLE, grazing, n, 1.5, 3, t);
    assert_true(t[0] == 0 && t[1] == 0 && t[2] == 0);
    /* Snell: eta·sin θ_i = sin θ_t */
    const double oblique[3] = {0.6, -0.8, 0};
    sc_p_refract(SC_DOUBLE, oblique, n, 1.0 / 1.5, 3, t);
    assert_true(fabs(t[0] - 0.6 / 1.5) < 1e-15);
    assert_true(fabs(t[0] * t[0] + t[1] * t[1] - 1.0) < 1e-15);
}

static void faceforward_flips_toward_the_viewer(void **state)
{
    (void)state;
    const double n[3] = {0, 0, 1}, i_in[3] = {0, 0, -1}, i_out[3] = {0, 0, 1};
    double r[3];
    sc_p_faceforward(SC_DOUBLE, n, i_in, n, 3, r);
    assert_true(r[2] == 1);
    sc_p_faceforward(SC_DOUBLE, n, i_out, n, 3, r);
    assert_true(r[2] == -1);
}

/* The stated bounds of the geometric functions (man page, ACCURACY), on random vectors:
 * |dot_highp − dot| <= γ_n Σ|a_i b_i| with γ_n = n·u/(1 − n·u), u = 2^-24 (Higham, Accuracy and
 * Stability of Numerical Algorithms, §3.1); normalize within (n + 2)·u relative per component
 * of the exact unit vector, plus u of the largest component for the cancellation-free case. */
static double uniform(unsigned *seed) { return (double)rand_r(seed) / RAND_MAX * 2.0 - 1.0; }

static void geometric_functions_meet_their_stated_bounds(void **state)
{
    (void)state;
    unsigned seed = 7;
    const double u = 0x1p-24;
    for (int trial = 0; trial < 200000; trial++) {
        int n = 2 + trial % 3;
        double a[4], b[4], exact = 0.0, mag = 0.0, len2 = 0.0;
        for (int k = 0; k < n; k++) {
            a[k] = (double)(float)(uniform(&seed) * 100.0);
            b[k] = (double)(float)(uniform(&seed) * 100.0);
            exact += a[k] * b[k]; /* exact enough: products of floats are exact in double */
            mag += fabs(a[k] * b[k]);
            len2 += a[k] * a[k];
        }
        double gamma = n * u / (1.0 - n * u);
        double got = sc_p_dot(SC_HIGHP, a, b, n);
        if (!(fabs(got - exact) <= gamma * mag + 1e-300))
            fail_msg("dot error %g > bound %g", fabs(got - exact), gamma * mag);
        double unit[4];
        sc_p_normalize(SC_HIGHP, a, n, unit);
        double len = sqrt(len2);
        for (int k = 0; k < n; k++) {
            double want = a[k] / len;
            if (!(fabs(unit[k] - want) <= (n + 2) * u * (fabs(want) + 0x1p-24)))
                fail_msg("normalize component error %g", fabs(unit[k] - want));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(double_precision_is_libm),
        cmocka_unit_test(highp_is_the_binary32_builtin),
        cmocka_unit_test(mediump_results_are_binary16_values),
        cmocka_unit_test(lowp_results_are_fixed_point),
        cmocka_unit_test(dot_rounds_each_operation_left_to_right),
        cmocka_unit_test(length_overflows_in_mediump),
        cmocka_unit_test(normalize_gives_unit_vectors_and_nan_for_zero),
        cmocka_unit_test(cross_follows_the_right_hand_rule),
        cmocka_unit_test(reflect_mirrors_about_the_normal),
        cmocka_unit_test(refract_bends_and_reflects_totally),
        cmocka_unit_test(faceforward_flips_toward_the_viewer),
        cmocka_unit_test(geometric_functions_meet_their_stated_bounds),
    };
    return cmocka_run_group_tests_name("pmath", tests, NULL, NULL);
}
