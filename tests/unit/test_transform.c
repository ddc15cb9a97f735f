/* Transforms from text and the normal matrix (shadecalc/transform.h): chains against matrices
 * written out by hand, the normal matrix against an explicit inverse-transpose computed here by
 * cofactors in long double on non-uniform scales and random matrices, the rigid shortcut, and
 * singular and malformed input rejected. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/transform.h"

static sc_dmat4 parse(const char *spec)
{
    char err[256];
    sc_dmat4 m;
    if (sc_transform_parse(spec, &m, err, sizeof err) < 0)
        fail_msg("'%s' rejected: %s", spec, err);
    return m;
}

/* Element (row r, column c) of a column-major 4×4. */
static double at(const sc_dmat4 *m, int r, int c) { return m->m[4 * c + r]; }

static void assert_rows(const sc_dmat4 *m, const double want[4][4], double tol)
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            if (!(fabs(at(m, r, c) - want[r][c]) <= tol))
                fail_msg("(%d,%d) = %.17g, want %.17g", r, c, at(m, r, c), want[r][c]);
}

/* scale(1,2,3)*translate(1,2,3): the translation is scaled, S·T = [S | S·t]. */
static void chain_multiplies_left_to_right(void **state)
{
    (void)state;
    sc_dmat4 m = parse(" scale(1, 2, 3) * translate(1,2,3) ");
    const double want[4][4] = {{1, 0, 0, 1}, {0, 2, 0, 4}, {0, 0, 3, 9}, {0, 0, 0, 1}};
    assert_rows(&m, want, 0);
    m = parse("translate(1,2,3)*scale(2)");
    const double want2[4][4] = {{2, 0, 0, 1}, {0, 2, 0, 2}, {0, 0, 2, 3}, {0, 0, 0, 1}};
    assert_rows(&m, want2, 0);
}

/* rotate(90, 0,0,1) takes x to y (counterclockwise seen from +z). */
static void rotate_is_counterclockwise_about_the_axis(void **state)
{
    (void)state;
    sc_dmat4 m = parse("rotate(90,0,0,2)*identity()");
    const double want[4][4] = {{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_rows(&m, want, 0);
}

static void sixteen_numbers_are_column_major(void **state)
{
    (void)state;
    sc_dmat4 m = parse("1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1");
    assert_true(at(&m, 0, 3) == 5 && at(&m, 1, 3) == 6 && at(&m, 2, 3) == 7 && at(&m, 3, 3) == 1);
    assert_true(at(&m, 3, 0) == 0);
}

/* (M₃⁻¹)ᵀ = cof(M₃)/det(M₃), the cofactor matrix, evaluated in long double. */
static void reference_normal_matrix(const sc_dmat4 *m, long double out[3][3])
{
    long double a[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = at(m, r, c);
    long double det = 0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            out[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
        }
    for (int c = 0; c < 3; c++)
        det += a[0][c] * out[0][c];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            out[r][c] /= det;
}

/* The computed inverse has a forward error below κ(M₃)·γ with a few dozen roundings; the cases
 * here have κ <= 1e3, so 1e-11 relative to the largest entry is a safe bound. */
static void check_normal_matrix(const char *spec)
{
    sc_dmat4 m = parse(spec);
    sc_dmat3 nm;
    int rigid;
    long double want[3][3], size = 0;
    assert_int_equal(sc_normal_matrix(&m, &nm, &rigid), 0);
    reference_normal_matrix(&m, want);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            size = fmaxl(size, fabsl(want[r][c]));
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            if (!(fabsl(nm.m[3 * c + r] - want[r][c]) <= 1e-11L * size))
                fail_msg("%s: R(%d,%d) = %.17g, want %.17Lg", spec, r, c, nm.m[3 * c + r],
                         want[r][c]);
}

static void normal_matrix_is_the_inverse_transpose_on_non_uniform_scales(void **state)
{
    (void)state;
    check_normal_matrix("scale(2,3,4)");
    check_normal_matrix("scale(1,2,3)*rotate(30,0,1,0)*translate(1,2,3)");
    check_normal_matrix("rotate(17,1,2,3)*scale(0.5,7,1)*rotate(-40,3,-1,2)");
    check_normal_matrix("1,2,0,0, 0.5,-1,3,0, 2,0,1,0, 9,9,9,1");
    /* diag(2,3,4): R = diag(1/2, 1/3, 1/4) exactly as rounded */
    sc_dmat4 m = parse("scale(2,3,4)");
    sc_dmat3 nm;
    int rigid;
    assert_int_equal(sc_normal_matrix(&m, &nm, &rigid), 0);
    assert_false(rigid);
    assert_true(nm.m[0] == 0.5 && nm.m[4] == 1.0 / 3 && nm.m[8] == 0.25);
}

/* A normal n of a surface stays perpendicular to the transformed tangents: (R n)·(M₃ t) =
 * n·t = 0 (the defining property of the normal matrix). */
static void transformed_normals_stay_perpendicular(void **state)
{
    (void)state;
    sc_dmat4 m = parse("scale(1,5,0.2)*rotate(33,1,1,0)");
    sc_dmat3 nm;
    int rigid;
    assert_int_equal(sc_normal_matrix(&m, &nm, &rigid), 0);
    const double n[3] = {0, 0, 1}, t[2][3] = {{1, 0, 0}, {0.6, 0.8, 0}};
    for (int k = 0; k < 2; k++) {
        double rn[3] = {0}, mt[3] = {0}, dot = 0;
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
                rn[r] += nm.m[3 * c + r] * n[c];
                mt[r] += at(&m, r, c) * t[k][c];
            }
        for (int r = 0; r < 3; r++)
            dot += rn[r] * mt[r];
        assert_true(fabs(dot) <= 1e-14);
    }
}

/* Rotations with translations: R is the upper-left 3×3 itself, bit for bit. */
static void rigid_transforms_take_the_shortcut(void **state)
{
    (void)state;
    sc_dmat4 m = parse("translate(4,5,6)*rotate(37,1,2,3)*rotate(-100,0,1,0)");
    sc_dmat3 nm;
    int rigid;
    assert_int_equal(sc_normal_matrix(&m, &nm, &rigid), 0);
    assert_true(rigid);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            assert_true(nm.m[3 * c + r] == at(&m, r, c));
    m = parse("scale(1,1,-1)"); /* a reflection is orthogonal too */
    assert_int_equal(sc_normal_matrix(&m, &nm, &rigid), 0);
    assert_true(rigid);
}

static void singular_matrices_are_rejected(void **state)
{
    (void)state;
    static const char *const singular[] = {"scale(1,0,1)", "1,2,3,0, 2,4,6,0, 0,0,1,0, 0,0,0,1",
                                           "scale(0)",
                                           "rotate(30,0,1,0)*scale(1,1,1e-300)*scale(1,1,1e-300)"};
    for (size_t i = 0; i < sizeof singular / sizeof singular[0]; i++) {
        sc_dmat4 m = parse(singular[i]);
        sc_dmat3 nm;
        int rigid;
        if (sc_normal_matrix(&m, &nm, &rigid) != -1)
            fail_msg("'%s' accepted", singular[i]);
    }
}

static void malformed_specs_are_rejected(void **state)
{
    (void)state;
    static const char *const bad[] = {"",
                                      "scale(1,2)",
                                      "rotate(30,0,0,0)",
                                      "translate(1,2,3)*",
                                      "foo(1)",
                                      "1,2,3",
                                      "scale(1,2,3) translate(1,2,3)",
                                      "scale(nan,1,1)",
                                      "scale(1e999,1,1)",
                                      "scale(1,2,3",
                                      "identity(1)",
                                      "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1,0",
                                      "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,x"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char err[256] = "";
        sc_dmat4 m;
        if (sc_transform_parse(bad[i], &m, err, sizeof err) != -1 || !strstr(err, "matrix: "))
            fail_msg("'%s': accepted or no message (%s)", bad[i], err);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(chain_multiplies_left_to_right),
        cmocka_unit_test(rotate_is_counterclockwise_about_the_axis),
        cmocka_unit_test(sixteen_numbers_are_column_major),
        cmocka_unit_test(normal_matrix_is_the_inverse_transpose_on_non_uniform_scales),
        cmocka_unit_test(transformed_normals_stay_perpendicular),
        cmocka_unit_test(rigid_transforms_take_the_shortcut),
        cmocka_unit_test(singular_matrices_are_rejected),
        cmocka_unit_test(malformed_specs_are_rejected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
