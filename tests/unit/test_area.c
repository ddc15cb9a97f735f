/* Area lights (shadecalc/area.h) against closed forms computed here independently: Lambert's
 * polygon irradiance (Lambert 1760, Arvo 1995) with the polygon clipped to the horizon, the
 * sphere above the horizon (π L sin²σ cos θ), the sphere across the horizon (Snyder 1996), the
 * disk on its axis; the convergence of the quadrature; the exact limits; the documented
 * results for degenerate configurations. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/area.h"
#include "shadecalc/scene.h"

static const double pi = 3.14159265358979323846;

static void assert_rel(double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol * fabs(want)))
        fail_msg("got %.15g, want %.15g (relative %.3g)", got, want, fabs(got - want) / fabs(want));
}

static sc_light parsed(const char *spec)
{
    sc_light l;
    char err[256];
    if (sc_light_parse(spec, &l, err, sizeof err) < 0)
        fail_msg("%s: %s", spec, err);
    return l;
}

static sc_brdf brdf_of(const char *spec)
{
    sc_model m;
    char err[256];
    if (sc_model_parse(spec, &m, err, sizeof err) < 0)
        fail_msg("%s: %s", spec, err);
    return m.brdf;
}

/* L_o (red channel) of `light` at the origin with normal n, viewer v. */
static double shade_area(const sc_light *light, sc_area_method method, const char *brdf,
                         const double n[3], const double v[3], sc_area_result *out)
{
    sc_brdf b = brdf_of(brdf);
    sc_frame f;
    sc_area_result r;
    static const double origin[3] = {0, 0, 0};
    assert_int_equal(sc_frame_make(n, NULL, &f), 0);
    assert_int_equal(sc_area_eval(light, method, &b, &f, origin, v, out ? out : &r), 0);
    return (out ? out : &r)->L[0];
}

/* Irradiance E / L of a uniform Lambertian emitter by the reference (lambert diff=π gives
 * L_o = E). */
static double irradiance(const char *spec, const double n[3])
{
    sc_light l = parsed(spec);
    double up[3] = {0, 0, 1};
    sc_area_result r;
    double E = shade_area(&l, SC_AREA_REFERENCE, "lambert diff=3.14159265358979323846", n, up, &r);
    assert_true(r.converged);
    return E;
}

/* ---- independent closed forms ---- */

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The polygon v[0..k) clipped to the half-space n·x >= 0 (Sutherland–Hodgman); its count. */
static int clip_to_horizon(const double (*v)[3], int k, const double n[3], double (*out)[3])
{
    int m = 0;
    for (int i = 0; i < k; i++) {
        const double *a = v[i], *b = v[(i + 1) % k];
        double fa = dot(n, a), fb = dot(n, b);
        if (fa >= 0)
            memcpy(out[m++], a, sizeof out[0]);
        if ((fa >= 0) != (fb >= 0)) {
            double t = fa / (fa - fb);
            for (int c = 0; c < 3; c++)
                out[m][c] = a[c] + t * (b[c] - a[c]);
            m++;
        }
    }
    return m;
}

/* Lambert: E/L = ½ |Σ acos(û_i·û_{i+1}) n·normalize(û_i × û_{i+1})| for the polygon seen from
 * the origin, after clipping it to the horizon. */
static double lambert_polygon(const double (*v)[3], int k, const double n[3])
{
    double clipped[8][3], sum = 0;
    int m = clip_to_horizon(v, k, n, clipped);
    for (int i = 0; i < m; i++) {
        double a[3], b[3], x[3];
        memcpy(a, clipped[i], sizeof a);
        memcpy(b, clipped[(i + 1) % m], sizeof b);
        double la = sqrt(dot(a, a)), lb = sqrt(dot(b, b));
        for (int c = 0; c < 3; c++) {
            a[c] /= la;
            b[c] /= lb;
        }
        x[0] = a[1] * b[2] - a[2] * b[1];
        x[1] = a[2] * b[0] - a[0] * b[2];
        x[2] = a[0] * b[1] - a[1] * b[0];
        double lx = sqrt(dot(x, x));
        if (lx > 0)
            sum += acos(fmax(-1, fmin(1, dot(a, b)))) * dot(n, x) / lx;
    }
    return 0.5 * fabs(sum);
}

/* Snyder 1996 (Lagarde & de Rousiers 2014): E/L of a sphere at angle θ from the normal with
 * sin σ = R/d, written from the spherical-cap geometry. */
static double snyder(double theta, double sigma)
{
    double ct = cos(theta), st = sin(theta), s2 = sin(sigma) * sin(sigma);
    if (theta + sigma <= pi / 2)
        return pi * s2 * ct;
    if (theta - sigma >= pi / 2)
        return 0;
    double x = sqrt(1 / s2 - 1), y = -x * ct / st, root = st * sqrt(1 - y * y);
    return (ct * acos(y) - x * root) * s2 + atan(root / x);
}

static void unit(double v[3])
{
    double l = sqrt(dot(v, v));
    for (int c = 0; c < 3; c++)
        v[c] /= l;
}

/* ---- tests ---- */

static void unit_square_at_height_one(void **state)
{
    (void)state;
    const char *square = "rect center=0,0,1 edge1=1,0,0 edge2=0,-1,0";
    double up[3] = {0, 0, 1}, tilted[3] = {sin(pi / 3), 0, cos(pi / 3)};
    assert_rel(irradiance(square, up), 0.752274688454, 1e-10);
    assert_rel(irradiance(square, tilted), 0.752274688454 / 2, 1e-10);
}

/* Rects in several poses, some across the horizon: the reference, and the ltc method (exact
 * for Lambert), against Lambert's formula. */
static void lambert_polygon_irradiance(void **state)
{
    (void)state;
    static const struct {
        double c[3], e1[3], e2[3], n[3];
    } cases[] = {
        {{0.3, -0.2, 1.5}, {1, 0.2, 0}, {0, -0.7, 0.1}, {0, 0, 1}},
        {{1.0, 0.5, 0.4}, {0.5, 0, 0.8}, {0, -1.2, 0}, {0.3, -0.2, 1}},
        {{0, 0, 0.05}, {2, 0, 0}, {0, -3, 0}, {1, 0, 0.2}}, /* close, across the horizon */
        {{2, 0, 0.2}, {0, 1, 0}, {0, 0, 1}, {0, 0.1, 1}},   /* a wall across the horizon */
        {{-0.5, 1, 1}, {0.3, 0.3, 0}, {-0.1, 0.1, 0.5}, {0.5, 0.5, 1}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const double *c = cases[i].c, *e1 = cases[i].e1, *e2 = cases[i].e2;
        double n[3], v[4][3], up[3] = {0, 0, 1};
        memcpy(n, cases[i].n, sizeof n);
        unit(n);
        static const double s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; k++)
            for (int j = 0; j < 3; j++)
                v[k][j] = c[j] + 0.5 * (s[k][0] * e1[j] + s[k][1] * e2[j]);
        char spec[256];
        snprintf(spec, sizeof spec,
                 "rect center=%.17g,%.17g,%.17g edge1=%.17g,%.17g,%.17g "
                 "edge2=%.17g,%.17g,%.17g two-sided=1",
                 c[0], c[1], c[2], e1[0], e1[1], e1[2], e2[0], e2[1], e2[2]);
        double exact = lambert_polygon((const double(*)[3])v, 4, n);
        assert_rel(irradiance(spec, n), exact, 1e-10);
        sc_light l = parsed(spec);
        assert_rel(shade_area(&l, SC_AREA_LTC, "lambert diff=3.14159265358979323846", n, up, NULL),
                   exact, 1e-10);
    }
}

/* GGX under the unit square (α = 0.3, F = 1): the LTC fit within 10 % of the converged
 * reference 0.278533661701, a disk within 10 % of its reference; nothing from behind. */
static void ltc_close_to_the_reference(void **state)
{
    (void)state;
    double n[3] = {0, 0, 1}, v[3] = {-0.5, 0, sqrt(0.75)};
    const char *ggx = "cook-torrance diff=0 alpha=0.3 F=none";
    sc_light square = parsed("rect center=0,0,1 edge1=1,0,0 edge2=0,-1,0");
    assert_rel(shade_area(&square, SC_AREA_LTC, ggx, n, v, NULL), 0.278533661701, 0.1);
    sc_light disk = parsed("disk center=0.3,0,1 normal=0,0,-1 radius=0.6");
    assert_rel(shade_area(&disk, SC_AREA_LTC, ggx, n, v, NULL),
               shade_area(&disk, SC_AREA_REFERENCE, ggx, n, v, NULL), 0.1);
    sc_light behind = parsed("rect center=0,0,1 edge1=1,0,0 edge2=0,1,0");
    assert_true(shade_area(&behind, SC_AREA_LTC, ggx, n, v, NULL) == 0.0);
}

static void sphere_above_horizon_is_a_point_light(void **state)
{
    (void)state;
    double up[3] = {0, 0, 1};
    const double R = 0.5, d = 2, theta = pi / 6;
    char spec[200];
    snprintf(spec, sizeof spec, "sphere center=%.17g,0,%.17g radius=0.5", d * sin(theta),
             d * cos(theta));
    double E = irradiance(spec, up);
    assert_rel(E, pi * (R / d) * (R / d) * cos(theta), 1e-10);
    assert_rel(E, 0.170043690397, 1e-11);
    sc_light l = parsed(spec);
    assert_rel(shade_area(&l, SC_AREA_POINT, "lambert diff=3.14159265358979323846", up, up, NULL),
               E, 1e-14);
}

/* Across the horizon: the reference and the representative point's diffuse term (exact for
 * Lambert) against Snyder's formula. */
static void sphere_across_horizon(void **state)
{
    (void)state;
    double up[3] = {0, 0, 1};
    static const double cases[][2] = {{80, 20}, {95, 30}, {60, 45}, {100, 12}, {89, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double theta = cases[i][0] * pi / 180, sigma = cases[i][1] * pi / 180, d = 3;
        char spec[200];
        snprintf(spec, sizeof spec, "sphere center=%.17g,0,%.17g radius=%.17g", d * sin(theta),
                 d * cos(theta), d * sin(sigma));
        assert_rel(irradiance(spec, up), snyder(theta, sigma), 1e-10);
        sc_light l = parsed(spec);
        assert_rel(shade_area(&l, SC_AREA_REPRESENTATIVE, "lambert diff=3.14159265358979323846", up,
                              up, NULL),
                   snyder(theta, sigma), 1e-12);
    }
}

static void disk_on_its_axis(void **state)
{
    (void)state;
    double up[3] = {0, 0, 1};
    const double R = 0.7, h = 0.3;
    assert_rel(irradiance("disk center=0,0,0.3 normal=0,0,-1 radius=0.7", up),
               pi * R * R / (R * R + h * h), 1e-10);
}

/* Gauss–Legendre panels: the error falls at least geometrically as the nodes double (a smooth
 * integrand: each doubling gains more than a factor 40, then 500, until round-off; measured
 * 0.019, 4e-4, 4.7e-7, 1e-12 at 2, 4, 8, 16 nodes). */
static void quadrature_converges_geometrically(void **state)
{
    (void)state;
    double n[3] = {0, 0, 1}, v[3] = {-0.5, 0, sqrt(0.75)};
    const double exact = 0.278533661701; /* GGX α = 0.3, F = 1 under the unit square */
    double error[4];
    for (int k = 0; k < 4; k++) {
        char spec[160];
        snprintf(spec, sizeof spec, "rect center=0,0,1 edge1=1,0,0 edge2=0,-1,0 samples=%d",
                 2 << k);
        sc_light l = parsed(spec);
        error[k] = fabs(
            shade_area(&l, SC_AREA_REFERENCE, "cook-torrance diff=0 alpha=0.3 F=none", n, v, NULL) -
            exact);
    }
    for (int k = 0; k + 1 < 3; k++)
        if (!(error[k + 1] < error[k] / (k ? 500 : 40)))
            fail_msg("N=%d: error %.3g, N=%d: %.3g", 2 << k, error[k], 4 << k, error[k + 1]);
    assert_true(error[3] < 1e-10);
}

/* The error estimate bounds the true error of the sphere across the horizon (from 8 nodes, where
 * the adaptive rule starts: with 4 or fewer, Q(N) and Q(N/2) may agree by chance). */
static void error_estimate_bounds_the_error(void **state)
{
    (void)state;
    double up[3] = {0, 0, 1};
    for (int samples = 8; samples <= 32; samples *= 2) {
        char spec[200];
        snprintf(spec, sizeof spec, "sphere center=%.17g,0,%.17g radius=1.5 samples=%d",
                 3 * sin(1.5), 3 * cos(1.5), samples);
        sc_light l = parsed(spec);
        sc_area_result r;
        shade_area(&l, SC_AREA_REFERENCE, "lambert diff=3.14159265358979323846", up, up, &r);
        double error = fabs(r.L[0] - snyder(1.5, asin(0.5)));
        if (!(error <= r.error[0] + 1e-15))
            fail_msg("samples=%d: error %.3g above its estimate %.3g", samples, error, r.error[0]);
    }
}

/* A tiny sphere is a point light of I = πR²L (every method); so is the representative point
 * as R -> 0 for GGX; a very short tube is a sphere. */
static void exact_limits(void **state)
{
    (void)state;
    double n[3] = {0, 0, 1}, v[3] = {0.6, 0, 0.8};
    const char *ggx = "cook-torrance diff=0.3 alpha=0.2";
    sc_light tiny = parsed("sphere center=0.5,0.2,2 radius=1e-4 L=31830.988618379067");
    double point = shade_area(&tiny, SC_AREA_POINT, ggx, n, v, NULL);
    assert_rel(shade_area(&tiny, SC_AREA_REFERENCE, ggx, n, v, NULL), point, 1e-6);
    assert_rel(shade_area(&tiny, SC_AREA_REPRESENTATIVE, ggx, n, v, NULL), point, 1e-3);
    sc_light tiny_tube = parsed("tube p0=0.5,0.2,2 p1=0.5,0.2,2 radius=1e-4 L=31830.988618379067");
    assert_rel(shade_area(&tiny_tube, SC_AREA_REPRESENTATIVE, ggx, n, v, NULL),
               shade_area(&tiny, SC_AREA_REPRESENTATIVE, ggx, n, v, NULL), 1e-14);
    sc_light ball = parsed("sphere center=0.5,0,2 radius=0.4");
    sc_light capsule = parsed("tube p0=0.4999999,0,2 p1=0.5000001,0,2 radius=0.4");
    assert_rel(shade_area(&capsule, SC_AREA_REFERENCE, ggx, n, v, NULL),
               shade_area(&ball, SC_AREA_REFERENCE, ggx, n, v, NULL), 1e-6);
}

/* Inside a sphere or tube: L_e times the directional albedo (Lambert: c_diff), by the reference
 * and the representative point (also inside a tube's capsule far from the ball about its
 * centre: an end cap, the cylinder); behind, zero size, in the plane of a disk or rect: 0;
 * never NaN. */
static void documented_results(void **state)
{
    (void)state;
    double n[3] = {0, 0, 1};
    const char *inside[] = {"sphere center=0,0,0.5 radius=1",
                            "sphere center=0,0,1 radius=1",
                            "tube p0=-1,0,0 p1=1,0,0 radius=0.5",
                            "tube p0=1,0,0 p1=3,0,0 radius=1",
                            "tube p0=0.3,0,-0.2 p1=4,0,-0.2 radius=0.5",
                            "tube p0=-3,0,-0.2 p1=1,0,-0.2 radius=0.5"};
    for (size_t i = 0; i < sizeof inside / sizeof inside[0]; i++) {
        sc_light l = parsed(inside[i]);
        assert_rel(shade_area(&l, SC_AREA_REFERENCE, "lambert diff=0.5", n, n, NULL), 0.5, 1e-12);
        assert_rel(shade_area(&l, SC_AREA_REPRESENTATIVE, "lambert diff=0.5", n, n, NULL), 0.5,
                   1e-12);
        for (int m = SC_AREA_REFERENCE; m <= SC_AREA_POINT; m++)
            assert_false(isnan(shade_area(&l, (sc_area_method)m, "cook-torrance", n, n, NULL)));
    }
    const char *dark[] = {"sphere center=0,0,-2 radius=1",
                          "sphere center=0,0,2 radius=0",
                          "tube p0=-1,0,-1 p1=1,0,-1 radius=0.5",
                          "disk center=0,0,0 normal=0,0,-1 radius=1",
                          "disk center=0,0,1 normal=0,0,1 radius=1",
                          "rect center=0,0,0 edge1=1,0,0 edge2=0,1,0 two-sided=1",
                          "rect center=0,0,-1 edge1=1,0,0 edge2=0,1,0 two-sided=1"};
    for (size_t i = 0; i < sizeof dark / sizeof dark[0]; i++) {
        sc_light l = parsed(dark[i]);
        double L = shade_area(&l, SC_AREA_REFERENCE, "cook-torrance", n, n, NULL);
        if (L != 0.0)
            fail_msg("%s: %.17g, want 0", dark[i], L);
    }
}

static void bad_specs_name_the_key(void **state)
{
    (void)state;
    static const struct {
        const char *spec, *key;
    } cases[] = {
        {"sphere center=0,0,2 radius=-1", "radius"},
        {"disk center=0,0,1 normal=0,0,0 radius=1", "normal"},
        {"rect center=0,0,1 edge1=1,0,0 edge2=2,0,0", "edge1"},
        {"rect center=0,0,1 normal=0,0,-1 width=1 height=0", "height"},
        {"sphere center=0,0,2 radius=1 method=ltcx", "method"},
        {"disk center=0,0,1 normal=0,0,-1 radius=1 method=representative-point", "method"},
        {"sphere center=0,0,2 radius=1 samples=1", "samples"},
        {"sphere center=0,0,2 radius=1 tol=0", "tol"},
        {"tube p0=0,0,1 radius=1", "p1"},
        {"sphere center=0,0,2 radius=1 method=ltc", "method"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sc_light l;
        char err[256];
        assert_int_equal(sc_light_parse(cases[i].spec, &l, err, sizeof err), -1);
        if (!strstr(err, cases[i].key))
            fail_msg("%s: '%s' does not name %s", cases[i].spec, err, cases[i].key);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unit_square_at_height_one),
        cmocka_unit_test(lambert_polygon_irradiance),
        cmocka_unit_test(ltc_close_to_the_reference),
        cmocka_unit_test(sphere_above_horizon_is_a_point_light),
        cmocka_unit_test(sphere_across_horizon),
        cmocka_unit_test(disk_on_its_axis),
        cmocka_unit_test(quadrature_converges_geometrically),
        cmocka_unit_test(error_estimate_bounds_the_error),
        cmocka_unit_test(exact_limits),
        cmocka_unit_test(documented_results),
        cmocka_unit_test(bad_specs_name_the_key),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
