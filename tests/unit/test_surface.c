/* Surfaces and their normals (shadecalc/surface.h) and forward-mode AD through the expression
 * evaluator (sc_expr_eval_dual), against independent references:
 *   - the built-ins' points, derivatives and normals against their closed forms, written here
 *     with libm's sin/cos of 2πu (not the library's quarter-turn reduction);
 *   - AD derivatives of one expression per built-in function against the derivative by hand,
 *     and against the central difference (f(u+h) − f(u−h))/2h within its error bound
 *     h²·|f'''|/6 + rounding (|f'''| estimated by a wider fourth-order difference, doubled);
 *   - user surfaces against the same built-ins written as expressions;
 *   - the poles: the documented limit normal, never NaN. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/expr.h"
#include "shadecalc/surface.h"

#define EPS 0x1p-53
#define TWO_PI 6.28318530717958647692
#define PI 3.14159265358979323846

static sc_surface *parse(const char *spec)
{
    char err[256];
    sc_surface *s = sc_surface_parse(spec, err, sizeof err);
    if (!s)
        fail_msg("'%s' rejected: %s", spec, err);
    return s;
}

static void assert_vec_near(const double *got, const double *want, double tol, const char *what)
{
    for (int k = 0; k < 3; k++)
        if (!(fabs(got[k] - want[k]) <= tol))
            fail_msg("%s[%d] = %.17g, want %.17g (tolerance %g)", what, k, got[k], want[k], tol);
}

/* The computed unit normal: the cross product of derivatives that are each within a few ε
 * of exact, normalized: a few dozen ε per component. */
#define NORMAL_TOL (64 * EPS)
/* Points and derivatives: a product of three rounded factors (libm sin/cos within 1 ulp, the
 * argument 2πu rounded) relative to the size of the surface. */
#define POINT_TOL (32 * EPS)

typedef struct {
    double p[3], dpdu[3], dpdv[3], n[3];
} closed_form;

/* sphere r: θ = πv, φ = 2πu, S = r(sin θ cos φ, sin θ sin φ, −cos θ), n = S/r. */
static closed_form sphere_at(double r, double u, double v)
{
    double f = TWO_PI * u, t = PI * v;
    closed_form c = {{r * sin(t) * cos(f), r * sin(t) * sin(f), -r * cos(t)},
                     {-TWO_PI * r * sin(t) * sin(f), TWO_PI * r * sin(t) * cos(f), 0},
                     {PI * r * cos(t) * cos(f), PI * r * cos(t) * sin(f), PI * r * sin(t)},
                     {sin(t) * cos(f), sin(t) * sin(f), -cos(t)}};
    return c;
}

/* torus R, r: ψ = 2πv, n = (cos φ cos ψ, sin φ cos ψ, sin ψ). */
static closed_form torus_at(double R, double r, double u, double v)
{
    double f = TWO_PI * u, w = TWO_PI * v, ring = R + r * cos(w);
    closed_form c = {
        {ring * cos(f), ring * sin(f), r * sin(w)},
        {-TWO_PI * ring * sin(f), TWO_PI * ring * cos(f), 0},
        {-TWO_PI * r * sin(w) * cos(f), -TWO_PI * r * sin(w) * sin(f), TWO_PI * r * cos(w)},
        {cos(f) * cos(w), sin(f) * cos(w), sin(w)}};
    return c;
}

/* cylinder r, h: S = (r cos φ, r sin φ, h(v − ½)), n = (cos φ, sin φ, 0). */
static closed_form cylinder_at(double r, double h, double u, double v)
{
    double f = TWO_PI * u;
    closed_form c = {{r * cos(f), r * sin(f), h * (v - 0.5)},
                     {-TWO_PI * r * sin(f), TWO_PI * r * cos(f), 0},
                     {0, 0, h},
                     {cos(f), sin(f), 0}};
    return c;
}

static void check_against(const sc_surface *s, double u, double v, closed_form c, double size)
{
    sc_surface_point q;
    sc_surface_eval(s, u, v, &q);
    assert_int_equal(q.degenerate, 0);
    assert_vec_near(q.p, c.p, POINT_TOL * size, "p");
    assert_vec_near(q.dpdu, c.dpdu, POINT_TOL * TWO_PI * size, "dpdu");
    assert_vec_near(q.dpdv, c.dpdv, POINT_TOL * TWO_PI * size, "dpdv");
    assert_vec_near(q.n, c.n, NORMAL_TOL, "n");
}

/* A 13 × 13 grid strictly inside the square (the poles are tested on their own). */
#define FOR_GRID(u, v)                                                                             \
    for (int gi_ = 1; gi_ < 14; gi_++)                                                             \
        for (int gj_ = 1; gj_ < 14; gj_++)                                                         \
            for (double u = gi_ / 14.0, v = gj_ / 14.0; u >= 0; u = -1)

static void sphere_matches_its_closed_form(void **state)
{
    (void)state;
    sc_surface *s = parse("sphere r=2.5");
    FOR_GRID(u, v) check_against(s, u, v, sphere_at(2.5, u, v), 2.5);
    sc_surface_free(s);
}

static void torus_matches_its_closed_form(void **state)
{
    (void)state;
    sc_surface *s = parse("torus R=2 r=0.5");
    FOR_GRID(u, v) check_against(s, u, v, torus_at(2, 0.5, u, v), 2.5);
    sc_surface_free(s);
}

static void cylinder_matches_its_closed_form(void **state)
{
    (void)state;
    sc_surface *s = parse("cylinder r=0.5 h=3");
    FOR_GRID(u, v) check_against(s, u, v, cylinder_at(0.5, 3, u, v), 3);
    sc_surface_free(s);
}

static void plane_is_the_square_facing_z(void **state)
{
    (void)state;
    sc_surface *s = parse("plane size=4");
    sc_surface_point q;
    sc_surface_eval(s, 0.25, 1.0, &q);
    assert_vec_near(q.p, (double[3]){-1, 2, 0}, 0, "p");
    assert_vec_near(q.n, (double[3]){0, 0, 1}, 0, "n");
    assert_false(sc_surface_closed_u(s) || sc_surface_closed_v(s));
    sc_surface_free(s);
}

/* The issue's example: torus R=1 r=0.3 at (0.25, 0.5) is φ = 90°, ψ = 180°: the inner equator
 * on the +y axis, p = (0, R − r, 0), n = −y. Quarter turns are exact. */
static void torus_example_of_the_issue_is_exact(void **state)
{
    (void)state;
    sc_surface *s = parse("torus R=1 r=0.3");
    sc_surface_point q;
    sc_surface_eval(s, 0.25, 0.5, &q);
    assert_vec_near(q.p, (double[3]){0, 0.7, 0}, 0, "p");
    assert_vec_near(q.n, (double[3]){0, -1, 0}, 0, "n");
    sc_surface_free(s);
}

/* Outside [0, 1] the formulas extend periodically in the angles: u = 1.25 is u = 0.25, and a
 * tiny negative u (whose reduction rounds up to a whole turn) is u = 0. */
static void parameters_outside_the_square_extend_the_formulas(void **state)
{
    (void)state;
    sc_surface *s = parse("torus");
    sc_surface_point a, b;
    sc_surface_eval(s, 1.25, 0.5, &a);
    sc_surface_eval(s, 0.25, 0.5, &b);
    assert_memory_equal(a.p, b.p, sizeof a.p);
    sc_surface_eval(s, -1e-20, 0.5, &a);
    sc_surface_eval(s, 0.0, 0.5, &b);
    assert_memory_equal(a.p, b.p, sizeof a.p);
    sc_surface_free(s);
}

/* The poles: ∂S/∂u = 0, so degenerate = 1 and n is the limit from inside: (0, 0, −1) at v = 0,
 * (0, 0, 1) at v = 1. The documented step δ = 2⁻³⁰ moves the normal by sin(πδ) <= πδ < 4e-9. */
static void sphere_poles_give_the_limit_normal(void **state)
{
    (void)state;
    sc_surface *s = parse("sphere");
    for (int i = 0; i <= 8; i++) {
        sc_surface_point south, north;
        sc_surface_eval(s, i / 8.0, 0.0, &south);
        sc_surface_eval(s, i / 8.0, 1.0, &north);
        assert_int_equal(south.degenerate, 1);
        assert_int_equal(north.degenerate, 1);
        assert_vec_near(south.n, (double[3]){0, 0, -1}, 4e-9, "south n");
        assert_vec_near(north.n, (double[3]){0, 0, 1}, 4e-9, "north n");
        assert_vec_near(south.p, (double[3]){0, 0, -1}, 0, "south p");
    }
    sc_surface_free(s);
}

static closed_form unit_sphere(double u, double v) { return sphere_at(1.0, u, v); }
static closed_form unit_cylinder(double u, double v) { return cylinder_at(1.0, 1.0, u, v); }

/* The normal does not depend on the size: sphere r = 1e308 (∂S/∂u beyond the double range),
 * r = 1e-308 (a cross product below it), and a user surface scaled by 1e200 or 1e-200 have the
 * closed-form normal of their unit-size twins. */
static void extreme_sizes_keep_the_closed_form_normal(void **state)
{
    (void)state;
    static const struct {
        const char *spec;
        closed_form (*unit)(double u, double v);
    } cases[] = {
        {"sphere r=1e308", unit_sphere},
        {"sphere r=1e-308", unit_sphere},
        {"sphere r=4e-320", unit_sphere},
        {"user x=1e200*cos(6.283185307179586*u) y=1e200*sin(6.283185307179586*u) z=1e200*v",
         unit_cylinder},
        {"user x=1e-200*cos(6.283185307179586*u) y=1e-200*sin(6.283185307179586*u) z=1e-200*v",
         unit_cylinder},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sc_surface *s = parse(cases[i].spec);
        sc_surface_point q;
        FOR_GRID(u, v)
        {
            sc_surface_eval(s, u, v, &q);
            assert_int_equal(q.degenerate, 0);
            assert_vec_near(q.n, cases[i].unit(u, v).n, NORMAL_TOL, cases[i].spec);
        }
        sc_surface_free(s);
    }
}

/* A surface that is a point everywhere: every step of the fallback is degenerate too. */
static void surface_without_area_falls_back_to_z(void **state)
{
    (void)state;
    sc_surface *s = parse("user x=1 y=2 z=3");
    sc_surface_point q;
    sc_surface_eval(s, 0.3, 0.6, &q);
    assert_int_equal(q.degenerate, 1);
    assert_vec_near(q.n, (double[3]){0, 0, 1}, 0, "n");
    sc_surface_free(s);
}

/* NaN from the user's expression: p is NaN, the normal still is not. */
static void nan_surface_never_gives_a_nan_normal(void **state)
{
    (void)state;
    sc_surface *s = parse("user x=sqrt(-u-1.) y=v z=log(-1.)");
    sc_surface_point q;
    sc_surface_eval(s, 0.5, 0.5, &q);
    assert_true(isnan(q.p[0]));
    assert_int_equal(q.degenerate, 1);
    for (int k = 0; k < 3; k++)
        assert_false(isnan(q.n[k]));
    sc_surface_free(s);
}

/* The built-in sphere and torus written as user expressions: AD reproduces the closed forms. */
static void user_sphere_and_torus_match_the_closed_forms(void **state)
{
    (void)state;
    sc_surface *sph = parse("user x=0.5*sin(3.14159265358979323846*v)*cos(6.28318530717958647692*u)"
                            " y=0.5*sin(3.14159265358979323846*v)*sin(6.28318530717958647692*u)"
                            " z=-0.5*cos(3.14159265358979323846*v)");
    sc_surface *tor = parse("user x=w = 3. + cos(6.28318530717958647692*v); "
                            "w*cos(6.28318530717958647692*u) y=(3.+cos(6.28318530717958647692*v))"
                            "*sin(6.28318530717958647692*u) z=sin(6.28318530717958647692*v)");
    FOR_GRID(u, v)
    {
        check_against(sph, u, v, sphere_at(0.5, u, v), 0.5);
        check_against(tor, u, v, torus_at(3, 1, u, v), 4);
    }
    assert_true(sc_surface_closed_u(sph));
    assert_false(sc_surface_closed_v(sph));
    assert_true(sc_surface_closed_u(tor) && sc_surface_closed_v(tor));
    sc_surface_free(sph);
    sc_surface_free(tor);
}

/* ---- AD of every built-in function ---- */

static sc_expr *compile_u(const char *src)
{
    static const sc_expr_input in[1] = {{"u", SC_FLOAT}};
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, in, 1, &err);
    if (!e)
        fail_msg("'%s': column %d: %s", src, err.column, err.message);
    return e;
}

static double value_at(const sc_expr *e, double u)
{
    sc_value in = {SC_FLOAT, {u}};
    return sc_expr_eval(e, SC_DOUBLE, &in, NULL, NULL).v[0];
}

static double derivative_at(const sc_expr *e, double u)
{
    sc_dual_value in = {{SC_FLOAT, {u}}, {{SC_FLOAT, {1.0}}, {SC_FLOAT, {0.0}}}};
    sc_dual_value out = sc_expr_eval_dual(e, &in);
    assert_true(out.x.v[0] == value_at(e, u) || (isnan(out.x.v[0]) && isnan(value_at(e, u))));
    assert_true(out.d[1].v[0] == 0.0); /* the second direction was not seeded */
    return out.d[0].v[0];
}

typedef struct {
    const char *src;
    double u;
    double want; /* d/du by hand, evaluated in double */
} derivative_case;

#define U 0.3
/* clang-format off */
static const derivative_case cases[] = {
    {"radians(u)", U, PI / 180},
    {"degrees(u)", U, 180 / PI},
    {"sin(2.*u)", U, 2 * 0.82533561490967829 /* cos(0.6) */},
    {"cos(u*u)", U, -2 * U * 0.089878549198011 /* sin(0.09) */},
    {"tan(u)", U, 1.095688915322547 /* 1/cos²(0.3) */},
    {"asin(u)", U, 1.0482848367219182 /* 1/sqrt(0.91) */},
    {"acos(u)", U, -1.0482848367219182},
    {"atan(u)", U, 1 / 1.09},
    {"atan(u, 2.)", U, 2 / 4.09},
    {"atan(1., u)", U, -1 / 1.09},
    {"pow(u, 2.5)", U, 2.5 * 0.16431676725154984 /* 0.3^1.5 */},
    {"pow(2., u)", U, 1.2311444133449163 * 0.69314718055994531 /* 2^0.3 ln 2 */},
    {"exp(3.*u)", U, 3 * 2.4596031111569497 /* e^0.9 */},
    {"log(u)", U, 1 / U},
    {"exp2(u)", U, 1.2311444133449163 * 0.69314718055994531},
    {"log2(u)", U, 1 / (U * 0.69314718055994531)},
    {"sqrt(u)", U, 0.5 / 0.54772255750516612},
    {"inversesqrt(u)", U, -0.5 / (U * 0.54772255750516612)},
    {"sinh(2.*u)", U, 2 * 1.1854652182422676 /* cosh(0.6) */},
    {"cosh(u)", U, 0.3045202934471426 /* sinh(0.3) */},
    {"tanh(u)", U, 0.9151369618266292 /* 1 − tanh²(0.3) */},
    {"asinh(u)", U, 0.9578262852211513 /* 1/sqrt(1.09) */},
    {"acosh(u + 1.)", U, 1.2038585308576921 /* 1/sqrt(1.3² − 1) */},
    {"atanh(u)", U, 1 / 0.91},
    {"abs(u - 1.)", U, -1},
    {"sign(u) + floor(u) + ceil(u) + step(0.5, u)", U, 0},
    {"trunc(u) + round(u) + roundEven(u)", U, 0},
    {"fract(u + 2.)", U, 1},
    {"mod(5.*u, u*u)", U, 5 - 16 * 2 * U /* floor(1.5/0.09) = 16 */},
    {"min(u, 0.5) + max(u*u, 0.05)", U, 1 + 2 * U},
    {"clamp(3.*u, 0., 1.) + clamp(u, 0.5, 1.)", U, 3},
    {"mix(u, u*u, u)", U, (1 - U) + U * 2 * U + (U * U - U) /* ∂x(1−a)+∂y·a+(y−x)∂a */},
    {"smoothstep(0., 1., u)", U, 6 * U * (1 - U)},
    {"smoothstep(u, 1., 0.5)", U, -6 * (2. / 7) * (5. / 7) * 0.5 / 0.49 /* t=2/7, w=0.7 */},
    {"length(vec2(u, 1.))", U, U / 1.0440306508910551 /* sqrt(1.09) */},
    {"distance(vec3(u, 0., 0.), vec3(0., 2.*u, 1.))", U, (U + 4 * U) / 1.2041594578792296 /* sqrt(1.45) */},
    {"dot(vec2(u, 2.), vec2(u*u, u))", U, 3 * U * U + 2},
    {"cross(vec3(u, 1., 0.), vec3(0., u, 1.)).z", U, 2 * U},
    {"normalize(vec2(u, 1.)).x", U, 1 / (1.09 * 1.0440306508910551) /* (1+u²)^-3/2 */},
    {"faceforward(vec2(u, 1.), vec2(1., 1.), vec2(-1., 0.)).x", U, 1},
    {"faceforward(vec2(u, 1.), vec2(1., 1.), vec2(1., 0.)).x", U, -1},
    {"reflect(vec2(1., u), vec2(0., 1.)).y", U, -1},
    {"reflect(vec2(1., 0.), vec2(u, 0.)).x", U, -4 * U /* 1 − 2u² */},
    {"refract(vec2(0., -1.), vec2(0., 1.), u).y", U, 0 /* −1 for every η at normal incidence */},
    {"refract(vec2(0.6, -0.8), vec2(0., 1.), u).x", U, 0.6},
    {"matrixCompMult(mat2(u), mat2(u, 1., 1., 2.))[0][0]", U, 2 * U},
    {"outerProduct(vec2(u, 1.), vec2(2., u))[1][0]", U, 2 * U /* u·u */},
    {"transpose(mat2(1., u*u, 3., 4.))[1][0]", U, 2 * U},
    {"determinant(mat2(u, 1., 2., u))", U, 2 * U},
    {"determinant(mat3(u, 0., 0., 0., 2., 1., 0., 3., u))", U, 4 * U - 3 /* u(2u − 3) */},
    {"inverse(mat2(u, 1., 2., u))[0][0]", U, -(U * U + 2) / ((U * U - 2) * (U * U - 2))},
    {"u / (1. + u*u)", U, (1 - U * U) / (1.09 * 1.09)},
    {"(vec2(u) / vec2(2., u*u)).y", U, -1 / (U * U)},
    {"(mat2(u, 0., 0., 1.) * vec2(u, 3.)).x", U, 2 * U},
    {"-u*u + (vec3(u, 2.*u, 0.)).yx.x", U, -2 * U + 2},
    {"a = u*u; b = a*u; b - a", U, 3 * U * U - 2 * U},
    {"mat3(mat2(u))[2].z + mat3(mat2(u))[0].x", U, 1 /* the identity fill is constant */},
};
/* clang-format on */

/* AD's derivative against the hand-derived one: a few dozen roundings of quantities of the
 * size of the result. */
static void ad_matches_derivatives_by_hand(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sc_expr *e = compile_u(cases[i].src);
        double got = derivative_at(e, cases[i].u), want = cases[i].want;
        if (!(fabs(got - want) <= 1e-14 * fmax(1.0, fabs(want))))
            fail_msg("d/du %s at u=%g: AD %.17g, by hand %.17g", cases[i].src, cases[i].u, got,
                     want);
        sc_expr_free(e);
    }
}

/* Central difference D = (f(u+h) − f(u−h))/2h = f' + h²f'''(ξ)/6, plus the rounding of the two
 * values (each within 8ε of the largest quantity its evaluation computes — max(|f|, 1) here: the
 * cases' intermediates are of order 1 — doubled by the difference, divided by 2h). |f'''| is
 * estimated by the fourth-order stencil with step k = 16h and doubled. */
static double difference_bound(const sc_expr *e, double u, double h)
{
    double k = 16 * h;
    double f3 = (value_at(e, u + 2 * k) - 2 * value_at(e, u + k) + 2 * value_at(e, u - k) -
                 value_at(e, u - 2 * k)) /
                (2 * k * k * k);
    double f = fmax(1.0, fmax(fabs(value_at(e, u + h)), fabs(value_at(e, u - h))));
    return h * h * 2 * fabs(f3) / 6 + 8 * EPS * f / h;
}

static void ad_matches_central_differences_within_their_bound(void **state)
{
    (void)state;
    const double h = 1e-5;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sc_expr *e = compile_u(cases[i].src);
        double u = cases[i].u;
        double diff = (value_at(e, u + h) - value_at(e, u - h)) / (2 * h);
        double ad = derivative_at(e, u), bound = difference_bound(e, u, h);
        if (!(fabs(diff - ad) <= bound))
            fail_msg("d/du %s at u=%g: AD %.17g, difference %.17g, bound %.3g", cases[i].src, u, ad,
                     diff, bound);
        sc_expr_free(e);
    }
}

/* At a kink the derivative of the branch the value took; never a silent mix. */
static void kinks_take_the_branch_of_the_value(void **state)
{
    (void)state;
    static const derivative_case kinks[] = {
        {"abs(u)", -0.5, -1},
        {"abs(u)", 0.0, 0},
        {"clamp(u, 0., 1.)", 2.0, 0},
        {"max(u, 1.)", 1.0, 1},
        {"min(u, 1.)", 1.0, 1},
        {"clamp(u, 0., 1.)", -1.0, 0},
        {"refract(vec2(0.8, -0.6), vec2(0., 1.), u).x", 2.0, 0}, /* total reflection: 0 */
    };
    for (size_t i = 0; i < sizeof kinks / sizeof kinks[0]; i++) {
        sc_expr *e = compile_u(kinks[i].src);
        double got = derivative_at(e, kinks[i].u);
        if (got != kinks[i].want)
            fail_msg("d/du %s at u=%g: %g, want %g", kinks[i].src, kinks[i].u, got, kinks[i].want);
        sc_expr_free(e);
    }
}

/* A left-deep chain u + u + ... as long as the parser allows: its depth is the number of terms,
 * and the walk must not run out of stack (d/du = the number of terms). */
static void long_chains_are_differentiated_without_exhausting_the_stack(void **state)
{
    (void)state;
    enum { TERMS = 20000 };
    static char src[2 * TERMS];
    src[0] = 'u';
    for (int i = 1; i < TERMS; i++)
        memcpy(&src[2 * i - 1], "+u", 2);
    src[2 * TERMS - 1] = '\0';
    sc_expr *e = compile_u(src);
    sc_dual_value in = {{SC_FLOAT, {0.5}}, {{SC_FLOAT, {1.0}}, {SC_FLOAT, {0.0}}}};
    sc_dual_value out = sc_expr_eval_dual(e, &in); /* not sc_expr_eval: its frames are larger */
    assert_true(out.x.v[0] == TERMS / 2.0 && out.d[0].v[0] == TERMS);
    sc_expr_free(e);
}

/* ---- the spec parser ---- */

static void bad_specs_are_rejected_with_the_offending_word(void **state)
{
    (void)state;
    static const char *const bad[][2] = {
        {"cube", "'cube'"},
        {"sphere r=0", "'r=0'"},
        {"sphere r=1 r=2", "given twice"},
        {"sphere R=1", "'R=1'"},
        {"torus R=1 r=1", "below R"},
        {"cylinder h=inf", "'h=inf'"},
        {"plane size=", "'size='"},
        {"user x=u y=v", "missing z"},
        {"user x=u y=v z=u+", "z=u+"},
        {"user x=u y=v z=vec2(u)", "expected float"},
        {"user x=u y=v z=w", "z=w"},
        {"user x=u x=v y=v z=u", "given twice"},
        {"user q=1 x=u y=v z=u", "'q=1'"},
        {"", "unknown"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char err[256] = "";
        sc_surface *s = sc_surface_parse(bad[i][0], err, sizeof err);
        if (s || !strstr(err, bad[i][1]))
            fail_msg("'%s': %s, message '%s' should name %s", bad[i][0],
                     s ? "accepted" : "rejected", err, bad[i][1]);
    }
}

static void defaults_and_closedness_of_the_built_ins(void **state)
{
    (void)state;
    sc_surface *s = parse("  torus  ");
    sc_surface_point q;
    sc_surface_eval(s, 0.0, 0.0, &q);
    assert_vec_near(q.p, (double[3]){1.3, 0, 0}, 0, "p"); /* R=1 r=0.3 */
    assert_true(sc_surface_closed_u(s) && sc_surface_closed_v(s));
    sc_surface_free(s);
    s = parse("cylinder");
    sc_surface_eval(s, 0.0, 1.0, &q);
    assert_vec_near(q.p, (double[3]){1, 0, 1}, 0, "p"); /* r=1 h=2 */
    assert_true(sc_surface_closed_u(s) && !sc_surface_closed_v(s));
    sc_surface_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_matches_its_closed_form),
        cmocka_unit_test(extreme_sizes_keep_the_closed_form_normal),
        cmocka_unit_test(torus_matches_its_closed_form),
        cmocka_unit_test(cylinder_matches_its_closed_form),
        cmocka_unit_test(plane_is_the_square_facing_z),
        cmocka_unit_test(torus_example_of_the_issue_is_exact),
        cmocka_unit_test(parameters_outside_the_square_extend_the_formulas),
        cmocka_unit_test(sphere_poles_give_the_limit_normal),
        cmocka_unit_test(surface_without_area_falls_back_to_z),
        cmocka_unit_test(nan_surface_never_gives_a_nan_normal),
        cmocka_unit_test(user_sphere_and_torus_match_the_closed_forms),
        cmocka_unit_test(ad_matches_derivatives_by_hand),
        cmocka_unit_test(ad_matches_central_differences_within_their_bound),
        cmocka_unit_test(kinks_take_the_branch_of_the_value),
        cmocka_unit_test(long_chains_are_differentiated_without_exhausting_the_stack),
        cmocka_unit_test(bad_specs_are_rejected_with_the_offending_word),
        cmocka_unit_test(defaults_and_closedness_of_the_built_ins),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
