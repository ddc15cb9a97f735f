/* Linearly transformed cosines (light/ltc.h; docs/ltc.md) against independent references:
 * the closed forms of the unit square light (docs/ltc.md: E = 0.752274688454 at height 1, half of
 * it with the normal tilted 60°) and of a disk on its axis (π R²/(R² + h²)), and a tensor
 * Gauss–Legendre quadrature over the emitter written here (nodes by Newton's method) of
 * max(cos θ_i, 0) and of sc_brdf_eval's GGX f cos θ_i. The GGX tolerance is the fit's measured
 * error (docs/ltc.md). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "light/ltc.h"

static const double pi = 3.14159265358979323846;

/* ---- the reference quadrature ---- */

enum { GL_N = 16 };
static double gl_x[GL_N], gl_w[GL_N];

/* Nodes and weights of the GL_N-point Gauss–Legendre rule on [−1, 1] (Newton on P_n). */
static void gauss_legendre(void)
{
    for (int i = 0; i < GL_N; i++) {
        double x = cos(pi * (i + 0.75) / (GL_N + 0.5)), dp = 0.0;
        for (int it = 0; it < 100; it++) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= GL_N; k++) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1.0);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16)
                break;
        }
        gl_x[i] = x;
        gl_w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

static int setup(void **state)
{
    (void)state;
    gauss_legendre();
    return 0;
}

/* What is integrated over the solid angle: g(l) for a unit direction l, view frame n = z. */
typedef struct {
    int ggx; /* 0: max(l_z, 0); 1: f_spec(l, v) l_z of `brdf` */
    sc_brdf brdf;
    sc_frame frame;
    double v[3];
} integrand;

static double integrand_at(const integrand *g, const double l[3])
{
    if (l[2] <= 0.0)
        return 0.0;
    if (!g->ggx)
        return l[2];
    sc_brdf_terms t;
    sc_brdf_eval(SC_DOUBLE, &g->brdf, &g->frame, l, g->v, &t);
    return t.specular[0] * l[2];
}

/* ∫ g(l) |n_e·l| / r² dA over the parallelogram corner + s e1 + t e2, s, t in [0, 1], on
 * panels x panels tensor Gauss–Legendre panels; s restricted to [s0, s1]. */
static double quad_rect(const integrand *g, const double corner[3], const double e1[3],
                        const double e2[3], double s0, double s1, int panels)
{
    double ne[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0]};
    double area = sqrt(ne[0] * ne[0] + ne[1] * ne[1] + ne[2] * ne[2]), sum = 0.0;
    for (int a = 0; a < panels; a++)
        for (int b = 0; b < panels; b++)
            for (int i = 0; i < GL_N; i++)
                for (int j = 0; j < GL_N; j++) {
                    double s = s0 + (s1 - s0) * (a + 0.5 * (gl_x[i] + 1.0)) / panels;
                    double t = (b + 0.5 * (gl_x[j] + 1.0)) / panels, q[3];
                    for (int c = 0; c < 3; c++)
                        q[c] = corner[c] + s * e1[c] + t * e2[c];
                    double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2], r = sqrt(r2);
                    double l[3] = {q[0] / r, q[1] / r, q[2] / r};
                    double cos_e = fabs(ne[0] * l[0] + ne[1] * l[1] + ne[2] * l[2]) / area;
                    double w = gl_w[i] * gl_w[j] * 0.25 * (s1 - s0) / (panels * panels);
                    sum += w * area * integrand_at(g, l) * cos_e / r2;
                }
    return sum;
}

/* The same over a disk (centre, orthonormal e1, e2, radius), in polar coordinates. */
static double quad_disk(const integrand *g, const double centre[3], const double e1[3],
                        const double e2[3], double radius, int panels)
{
    double ne[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0]};
    double sum = 0.0;
    for (int a = 0; a < panels; a++)
        for (int b = 0; b < 4 * panels; b++)
            for (int i = 0; i < GL_N; i++)
                for (int j = 0; j < GL_N; j++) {
                    double rho = radius * (a + 0.5 * (gl_x[i] + 1.0)) / panels;
                    double phi = 2.0 * pi * (b + 0.5 * (gl_x[j] + 1.0)) / (4 * panels), q[3];
                    for (int c = 0; c < 3; c++)
                        q[c] = centre[c] + rho * (cos(phi) * e1[c] + sin(phi) * e2[c]);
                    double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2], r = sqrt(r2);
                    double l[3] = {q[0] / r, q[1] / r, q[2] / r};
                    double cos_e = fabs(ne[0] * l[0] + ne[1] * l[1] + ne[2] * l[2]);
                    double w = gl_w[i] * gl_w[j] * 0.25 * (radius / panels) *
                               (2.0 * pi / (4 * panels)) * rho;
                    sum += w * integrand_at(g, l) * cos_e / r2;
                }
    return sum;
}

/* ∫ g over the hemisphere, ∫∫ g(θ, φ) sin θ dθ dφ on panels x panels Gauss–Legendre panels:
 * the whole lobe, the scale of the LTC's absolute error (docs/ltc.md). */
static double quad_hemisphere(const integrand *g, int panels)
{
    double sum = 0.0, dt = 0.5 * pi / panels, dp = 2.0 * pi / panels;
    for (int a = 0; a < panels; a++)
        for (int b = 0; b < panels; b++)
            for (int i = 0; i < GL_N; i++)
                for (int j = 0; j < GL_N; j++) {
                    double t = dt * (a + 0.5 * (gl_x[i] + 1.0));
                    double p = dp * (b + 0.5 * (gl_x[j] + 1.0));
                    double l[3] = {sin(t) * cos(p), sin(t) * sin(p), cos(t)};
                    sum += gl_w[i] * gl_w[j] * 0.25 * dt * dp * sin(t) * integrand_at(g, l);
                }
    return sum;
}

/* ---- helpers ---- */

static sc_frame frame_about(const double n[3])
{
    sc_frame f;
    assert_int_equal(sc_frame_make(n, NULL, &f), 0);
    return f;
}

static const double up[3] = {0, 0, 1};

/* dir(θ°, φ°) about z. */
static void dir(double theta_deg, double phi_deg, double out[3])
{
    double t = theta_deg * pi / 180.0, f = phi_deg * pi / 180.0;
    out[0] = sin(t) * cos(f);
    out[1] = sin(t) * sin(f);
    out[2] = cos(t);
}

/* GGX Cook–Torrance of the library, Smith height-correlated, Schlick F0 f0 (specular only). */
static integrand ggx(double alpha, const double v[3], double f0)
{
    integrand g = {.ggx = 1, .frame = frame_about(up)};
    const double f0s[3] = {f0, f0, f0};
    sc_ltc_brdf(alpha, f0s, &g.brdf);
    memcpy(g.v, v, sizeof g.v);
    return g;
}

static void assert_rel(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol * fabs(want)))
        fail_msg("%s: got %.15g, want %.15g (relative error %.3g > %.3g)", what, got, want,
                 fabs(got - want) / fabs(want), tol);
}

/* The LTC's measured error for views up to 80° (docs/ltc.md, `make ltc-error`, rounded up):
 * for any emitter at most `of_lobe` of the whole lobe (the integral over the hemisphere); for
 * an emitter centred on the mirror direction holding at least 1% of the lobe, a relative error
 * of at most `relative`. With F0 = 1 the fit alone; with F0 = 0.04 also the Fresnel split,
 * which spreads Schlick's F over the lobe as the LTC's shape. */
typedef struct {
    double f0, of_lobe, relative;
} ltc_bound;
static const ltc_bound metal = {1.0, 0.15, 0.3}, dielectric = {0.04, 0.27, 0.85};

static void assert_ltc(double got, double want, double whole, const ltc_bound *bound, int on_mirror,
                       const char *what)
{
    double err = fabs(got - want);
    if (!(err <= bound->of_lobe * whole))
        fail_msg("%s: got %.9g, want %.9g: error %.3g > %g of the lobe %.9g", what, got, want, err,
                 bound->of_lobe, whole);
    if (on_mirror && want >= 0.01 * whole && !(err <= bound->relative * want))
        fail_msg("%s: got %.9g, want %.9g: relative error %.3g > %g", what, got, want, err / want,
                 bound->relative);
}

static void assert_zero_result(const sc_ltc_result *r)
{
    assert_true(r->cosine == 0.0);
    for (int k = 0; k < 3; k++)
        assert_true(r->spec[k] == 0.0);
}

/* The square [−½, ½]² at height 1, seen from below counter-clockwise (it faces the origin). */
static const double unit_square[4][3] = {
    {-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}};
static const double unit_square_e = 0.752274688454; /* its irradiance for n = +z, L = 1 */

static sc_ltc_result polygon(const double n[3], const double v[3], double alpha, double f0,
                             const double (*verts)[3], int count, int two_sided)
{
    sc_frame f = frame_about(n);
    const double f0s[3] = {f0, f0, f0};
    sc_ltc_result r;
    assert_int_equal(sc_ltc_polygon(&f, v, alpha, f0s, verts, count, two_sided, &r), 0);
    return r;
}

/* ---- the clamped cosine ---- */

static void unit_square_form_factor(void **state)
{
    (void)state;
    double tilted[3];
    dir(60, 0, tilted);
    sc_ltc_result r = polygon(up, up, 0.5, 0.04, unit_square, 4, 0);
    assert_rel(r.cosine, unit_square_e, 1e-12, "n = +z");
    r = polygon(tilted, up, 0.5, 0.04, unit_square, 4, 0);
    assert_rel(r.cosine, unit_square_e / 2, 1e-12, "n tilted 60°");
}

/* One-sided: the square's back gives nothing; two-sided: the same from either side. */
static void sidedness_follows_the_winding(void **state)
{
    (void)state;
    double reversed[4][3];
    for (int k = 0; k < 4; k++)
        memcpy(reversed[k], unit_square[3 - k], sizeof reversed[k]);
    sc_ltc_result r = polygon(up, up, 0.5, 0.04, (const double(*)[3])reversed, 4, 0);
    assert_zero_result(&r);
    r = polygon(up, up, 0.5, 0.04, (const double(*)[3])reversed, 4, 1);
    assert_rel(r.cosine, unit_square_e, 1e-12, "two-sided, back");
    sc_ltc_result front = polygon(up, up, 0.5, 0.04, unit_square, 4, 0);
    assert_rel(r.spec[0], front.spec[0], 1e-12, "two-sided spec, back against front");
}

/* A wall y = 1, x in [−1, 1], z in [−0.5, 1], cut by the horizon z = 0 along an edge-parallel
 * line: the quadrature over its upper part alone is smooth. */
static void horizon_clipping_against_quadrature(void **state)
{
    (void)state;
    const double wall[4][3] = {{-1, 1, -0.5}, {1, 1, -0.5}, {1, 1, 1}, {-1, 1, 1}};
    const double corner[3] = {-1, 1, 0}, e1[3] = {0, 0, 1}, e2[3] = {2, 0, 0};
    integrand lambert = {.ggx = 0};
    double want = quad_rect(&lambert, corner, e1, e2, 0.0, 1.0, 8);
    sc_ltc_result r = polygon(up, up, 0.5, 0.04, wall, 4, 1);
    assert_rel(r.cosine, want, 1e-10, "wall crossing the horizon");
    /* the normal tilted about x: the horizon cuts the wall along a slanted line (a kink in the
     * integrand: many panels) */
    double n[3];
    dir(20, 90, n);
    /* the quadrature works in the frame n = z: the wall rotated by −20° about x instead */
    const double whole[3] = {-1, 1, -0.5}, f1[3] = {0, 0, 1.5};
    double c = cos(20 * pi / 180), s = sin(20 * pi / 180), rw[4][3], rc[3], r1[3], r2[3];
    const double *src[3] = {whole, f1, e2};
    double *dst[3] = {rc, r1, r2};
    for (int k = 0; k < 3; k++) {
        dst[k][0] = src[k][0];
        dst[k][1] = c * src[k][1] - s * src[k][2];
        dst[k][2] = s * src[k][1] + c * src[k][2];
    }
    for (int k = 0; k < 4; k++) {
        rw[k][0] = wall[k][0];
        rw[k][1] = c * wall[k][1] - s * wall[k][2];
        rw[k][2] = s * wall[k][1] + c * wall[k][2];
    }
    double want_tilted = quad_rect(&lambert, rc, r1, r2, 0.0, 1.0, 64);
    sc_ltc_result in_world = polygon(n, up, 0.5, 0.04, wall, 4, 1);
    sc_ltc_result rotated = polygon(up, up, 0.5, 0.04, (const double(*)[3])rw, 4, 1);
    assert_rel(in_world.cosine, rotated.cosine, 1e-12, "the same configuration rotated");
    assert_rel(in_world.cosine, want_tilted, 1e-5, "slanted horizon");
}

/* ∫ max(cos θ_i, 0) cos θ_e / r² dA over {(x, 1, z): x in [x0, x1], lower(x) <= z <= 1}, lower
 * linear from z0 to z1 and >= 0: Gauss–Legendre in x, and in z between the limits. */
static double quad_wall_strip(double x0, double x1, double z0, double z1)
{
    double sum = 0.0;
    for (int i = 0; i < GL_N; i++) {
        double x = x0 + 0.5 * (gl_x[i] + 1.0) * (x1 - x0);
        double lo = z0 + 0.5 * (gl_x[i] + 1.0) * (z1 - z0);
        for (int j = 0; j < GL_N; j++) {
            double z = lo + 0.5 * (gl_x[j] + 1.0) * (1.0 - lo), r2 = x * x + 1.0 + z * z;
            double w = 0.25 * gl_w[i] * gl_w[j] * (x1 - x0) * (1.0 - lo);
            sum += w * z / sqrt(r2) * (1.0 / sqrt(r2)) / r2; /* cos θ_i = z/r, cos θ_e = 1/r */
        }
    }
    return sum;
}

/* A comb in the wall y = 1: 254 vertices zigzagging across the horizon (z = ±0.5), closed along
 * z = 1. Non-convex, clipped into 127 teeth: against the quadrature of its part above z = 0,
 * strip by strip, each strip split where the zigzag crosses z = 0. */
static void comb_crossing_the_horizon(void **state)
{
    (void)state;
    enum { TEETH = 254 };
    static double comb[TEETH + 2][3];
    const double width = 4.0;
    for (int k = 0; k < TEETH; k++) {
        comb[k][0] = -width / 2 + width * k / (TEETH - 1);
        comb[k][1] = 1.0;
        comb[k][2] = k % 2 ? 0.5 : -0.5;
    }
    const double top[2][3] = {{width / 2, 1, 1}, {-width / 2, 1, 1}};
    memcpy(comb[TEETH], top, sizeof top);
    double want = 0.0;
    for (int k = 0; k + 1 < TEETH; k++) {
        double x0 = comb[k][0], x1 = comb[k + 1][0], z0 = comb[k][2], z1 = comb[k + 1][2];
        double xc = x0 + (x1 - x0) * z0 / (z0 - z1); /* where the zigzag crosses z = 0 */
        want += z0 < 0 ? quad_wall_strip(x0, xc, 0, 0) + quad_wall_strip(xc, x1, 0, z1)
                       : quad_wall_strip(x0, xc, z0, 0) + quad_wall_strip(xc, x1, 0, 0);
    }
    double v[3];
    dir(60, 270, v); /* the mirror direction toward the wall */
    sc_ltc_result r = polygon(up, v, 0.2, 0.04, (const double(*)[3])comb, TEETH + 2, 1);
    assert_rel(r.cosine, want, 1e-10, "comb");
    assert_true(isfinite(r.spec[0]) && r.spec[0] > 0.0);
}

/* ---- the GGX lobe ---- */

/* The square at height 1 against the quadrature, at several α, view angles and F0 (the
 * Fresnel split F0 (A − B) + B included). */
static void ggx_square_against_quadrature(void **state)
{
    (void)state;
    const double corner[3] = {-0.5, -0.5, 1}, e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0};
    const double alphas[] = {0.1, 0.3, 0.6, 1.0}, views[] = {0, 30, 60, 80};
    const ltc_bound *bounds[2] = {&metal, &dielectric};
    for (size_t a = 0; a < sizeof alphas / sizeof *alphas; a++)
        for (size_t t = 0; t < sizeof views / sizeof *views; t++)
            for (size_t k = 0; k < 2; k++) {
                double v[3];
                dir(views[t], 180, v);
                double f0 = bounds[k]->f0;
                integrand g = ggx(alphas[a], v, f0);
                double want = quad_rect(&g, corner, e1, e2, 0.0, 1.0, 16);
                sc_ltc_result r = polygon(up, v, alphas[a], f0, unit_square, 4, 0);
                char what[96];
                snprintf(what, sizeof what, "α %g, θ_v %g°, F0 %g", alphas[a], views[t], f0);
                assert_ltc(r.spec[0], want, quad_hemisphere(&g, 8), bounds[k], views[t] == 0, what);
            }
}

/* Squares of half-size 0.4 at distance 2 on the mirror direction, facing the point, at
 * several α and view angles up to 80°. */
static void ggx_mirror_square_against_quadrature(void **state)
{
    (void)state;
    const double alphas[] = {0.05, 0.15, 0.4, 0.8}, views[] = {10, 45, 70, 80};
    for (size_t a = 0; a < sizeof alphas / sizeof *alphas; a++)
        for (size_t t = 0; t < sizeof views / sizeof *views; t++) {
            double v[3], m[3], centre[3], e1[3] = {0, 0.8, 0}, e2[3], corner[3], verts[4][3];
            dir(views[t], 0, v);
            dir(views[t], 180, m);
            dir(views[t] + 90, 180, e2); /* in the plane of incidence, ⟂ m */
            for (int c = 0; c < 3; c++) {
                centre[c] = 2.0 * m[c];
                e2[c] *= 0.8;
                corner[c] = centre[c] - 0.5 * (e1[c] + e2[c]);
            }
            for (int k = 0; k < 4; k++) /* counter-clockwise seen from the point */
                for (int c = 0; c < 3; c++)
                    verts[k][c] = corner[c] + (k == 1 || k == 2) * e2[c] + (k >= 2) * e1[c];
            const ltc_bound *bounds[2] = {&metal, &dielectric};
            for (int k = 0; k < 2; k++) {
                integrand g = ggx(alphas[a], v, bounds[k]->f0);
                double want = quad_rect(&g, corner, e1, e2, 0.0, 1.0, 16);
                sc_ltc_result r = polygon(up, v, alphas[a], bounds[k]->f0,
                                          (const double(*)[3])verts, 4, 0);
                char what[64];
                snprintf(what, sizeof what, "α %g, θ_v %g°, F0 %g", alphas[a], views[t],
                         bounds[k]->f0);
                assert_ltc(r.spec[0], want, quad_hemisphere(&g, 8), bounds[k], 1, what);
            }
        }
}

/* The worked example of docs/ltc.md: α = 0.3, F = 1, v = dir(30°, 180°): 0.278533661701. */
static void ggx_worked_example(void **state)
{
    (void)state;
    const double corner[3] = {-0.5, -0.5, 1}, e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0};
    double v[3];
    dir(30, 180, v);
    integrand g = ggx(0.3, v, 1.0);
    assert_rel(quad_rect(&g, corner, e1, e2, 0.0, 1.0, 16), 0.278533661701, 1e-10, "quadrature");
    sc_ltc_result r = polygon(up, v, 0.3, 1.0, unit_square, 4, 0);
    assert_ltc(r.spec[0], 0.278533661701, quad_hemisphere(&g, 8), &metal, 0, "LTC");
}

/* Mirrored across the plane of n and v, and the whole scene rotated: the same integrals. */
static void symmetric_configurations_agree(void **state)
{
    (void)state;
    const double quad[4][3] = {
        {0.2, 0.3, 0.8}, {-0.4, 0.5, 1.1}, {-0.6, 1.4, 0.6}, {0.3, 1.0, 0.2}};
    double mirrored[4][3], rotated[4][3], v[3], rv[3], rn[3];
    dir(40, 20, v);
    double vm[3] = {v[0], -v[1], v[2]};
    for (int k = 0; k < 4; k++) { /* y → −y reverses the winding: reverse the order back */
        memcpy(mirrored[k], quad[3 - k], sizeof mirrored[k]);
        mirrored[k][1] = -mirrored[k][1];
    }
    sc_ltc_result a = polygon(up, v, 0.4, 0.3, quad, 4, 1);
    sc_ltc_result b = polygon(up, vm, 0.4, 0.3, (const double(*)[3])mirrored, 4, 1);
    assert_true(a.spec[0] > 0.0);
    assert_rel(b.cosine, a.cosine, 1e-12, "mirrored, cosine");
    assert_rel(b.spec[0], a.spec[0], 1e-12, "mirrored, spec");
    /* rotation by 50° about the axis (1, 1, 1)/√3 (Rodrigues) */
    double axis[3] = {1 / sqrt(3.0), 1 / sqrt(3.0), 1 / sqrt(3.0)}, c = cos(0.87), s = sin(0.87);
    const double *src[6] = {quad[0], quad[1], quad[2], quad[3], v, up};
    double *dst[6] = {rotated[0], rotated[1], rotated[2], rotated[3], rv, rn};
    for (int k = 0; k < 6; k++) {
        const double *p = src[k];
        double d = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
        double x[3] = {axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
                       axis[0] * p[1] - axis[1] * p[0]};
        for (int j = 0; j < 3; j++)
            dst[k][j] = p[j] * c + x[j] * s + axis[j] * d * (1 - c);
    }
    sc_ltc_result r = polygon(rn, rv, 0.4, 0.3, (const double(*)[3])rotated, 4, 1);
    assert_rel(r.cosine, a.cosine, 1e-12, "rotated, cosine");
    assert_rel(r.spec[0], a.spec[0], 1e-9, "rotated, spec");
}

/* ---- degenerate input ---- */

static void degenerate_input_is_refused(void **state)
{
    (void)state;
    sc_frame f = frame_about(up);
    const double f0[3] = {0.04, 0.04, 0.04}, nan_f0[3] = {NAN, 0, 0};
    const double line[3][3] = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
    const double point[4][3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    double with_nan[4][3];
    memcpy(with_nan, unit_square, sizeof with_nan);
    with_nan[2][1] = NAN;
    sc_ltc_result r;
    memset(&r, 0xff, sizeof r);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.3, f0, line, 3, 0, &r), -1);
    assert_zero_result(&r);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.3, f0, point, 4, 0, &r), -1);
    assert_zero_result(&r);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.3, f0, unit_square, 2, 0, &r), -1);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.3, f0, (const double(*)[3])with_nan, 4, 0, &r), -1);
    assert_zero_result(&r);
    assert_int_equal(sc_ltc_polygon(&f, up, NAN, f0, unit_square, 4, 0, &r), -1);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.0, f0, unit_square, 4, 0, &r), -1);
    assert_int_equal(sc_ltc_polygon(&f, up, 0.3, nan_f0, unit_square, 4, 0, &r), -1);
    const double zero[3] = {0, 0, 0};
    assert_int_equal(sc_ltc_polygon(&f, zero, 0.3, f0, unit_square, 4, 0, &r), -1);
    assert_zero_result(&r);
    const double c[3] = {0, 0, 1}, n[3] = {0, 0, -1};
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, c, zero, 1.0, 0, &r), -1);
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, c, n, 0.0, 0, &r), -1);
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, c, n, -1.0, 0, &r), -1);
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, c, n, INFINITY, 0, &r), -1);
    assert_zero_result(&r);
}

/* Below the horizon, on the emitter's plane, a viewer below the horizon: 0, not -1, never NaN. */
static void unlit_configurations_give_zero(void **state)
{
    (void)state;
    double below[4][3], on_plane[4][3];
    for (int k = 0; k < 4; k++) {
        memcpy(below[k], unit_square[k], sizeof below[k]);
        below[k][2] = -1.0;
        memcpy(on_plane[k], unit_square[k], sizeof on_plane[k]);
        on_plane[k][2] = 0.0;
    }
    sc_ltc_result r = polygon(up, up, 0.3, 0.04, (const double(*)[3])below, 4, 1);
    assert_zero_result(&r);
    r = polygon(up, up, 0.3, 0.04, (const double(*)[3])on_plane, 4, 1);
    assert_zero_result(&r);
    double v_below[3];
    dir(120, 0, v_below);
    r = polygon(up, v_below, 0.3, 0.04, unit_square, 4, 0);
    assert_rel(r.cosine, unit_square_e, 1e-12, "cosine with the viewer below");
    assert_true(r.spec[0] == 0.0 && r.spec[1] == 0.0 && r.spec[2] == 0.0);
}

/* Tiny, far, huge and grazing emitters stay finite; the tiny one is a point light. */
static void extreme_emitters_stay_finite(void **state)
{
    (void)state;
    const double scales[] = {1e-150, 1e-8, 1e8, 1e150};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        double scaled[4][3];
        for (int i = 0; i < 4; i++)
            for (int c = 0; c < 3; c++)
                scaled[i][c] = unit_square[i][c] * scales[k];
        sc_ltc_result r = polygon(up, up, 0.3, 0.04, (const double(*)[3])scaled, 4, 0);
        assert_rel(r.cosine, unit_square_e, 1e-12, "scaled square");
    }
    /* 1e-6 × 1e-6 at distance 1, 45° away: cos θ cos θ_e A / d² */
    const double s = 1e-6 / 2, h = sqrt(0.5);
    const double tiny[4][3] = {{h - s * h, -s, h + s * h},
                               {h + s * h, -s, h - s * h},
                               {h + s * h, s, h - s * h},
                               {h - s * h, s, h + s * h}};
    sc_ltc_result r = polygon(up, up, 0.3, 0.04, tiny, 4, 1);
    assert_rel(r.cosine, h * 1e-12, 1e-6, "tiny square, 45°");
    assert_true(isfinite(r.spec[0]) && r.spec[0] > 0.0);
    /* grazing: a square seen almost edge-on, and a viewer at the horizon */
    const double sliver[4][3] = {
        {-1, 1, 0.5}, {1, 1, 0.5}, {1, 1 + 1e-13, 1.5}, {-1, 1 + 1e-13, 1.5}};
    double v[3];
    dir(90, 0, v);
    r = polygon(up, v, 1e-6, 0.04, sliver, 4, 1);
    assert_true(isfinite(r.cosine) && isfinite(r.spec[0]) && r.cosine >= 0.0 && r.spec[0] >= 0.0);
}

/* ---- disks ---- */

/* On the axis: ∫ cos dω = π R²/(R² + h²) (a spherical cap); off the axis, tilted and crossing
 * the horizon against the quadrature; GGX against the quadrature. */
static void disk_against_closed_form_and_quadrature(void **state)
{
    (void)state;
    sc_frame f = frame_about(up);
    const double f0[3] = {1, 1, 1}, centre[3] = {0, 0, 1}, down[3] = {0, 0, -1};
    sc_ltc_result r;
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, centre, down, 0.5, 0, &r), 0);
    assert_rel(r.cosine, pi * 0.25 / 1.25, 1e-6, "disk on its axis");
    /* the back of a one-sided disk */
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, centre, up, 0.5, 0, &r), 0);
    assert_zero_result(&r);
    /* tilted and off the axis, crossing the horizon */
    const double c2[3] = {0.8, 0.3, 0.2}, e1[3] = {0, 1, 0};
    double n2[3] = {-1, 0, -0.4}, len = sqrt(1.16);
    for (int k = 0; k < 3; k++)
        n2[k] /= len;
    double e2[3] = {n2[1] * e1[2] - n2[2] * e1[1], n2[2] * e1[0] - n2[0] * e1[2],
                    n2[0] * e1[1] - n2[1] * e1[0]};
    integrand lambert = {.ggx = 0};
    assert_int_equal(sc_ltc_disk(&f, up, 0.3, f0, c2, n2, 0.6, 0, &r), 0);
    assert_rel(r.cosine, quad_disk(&lambert, c2, e1, e2, 0.6, 32), 1e-6, "tilted disk");
    double v[3];
    dir(50, 0, v);
    const double alphas[] = {0.2, 0.5, 0.9};
    for (size_t a = 0; a < sizeof alphas / sizeof *alphas; a++) {
        integrand g = ggx(alphas[a], v, 1.0);
        assert_int_equal(sc_ltc_disk(&f, v, alphas[a], f0, centre, down, 0.5, 0, &r), 0);
        const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
        assert_ltc(r.spec[0], quad_disk(&g, centre, ex, ey, 0.5, 16), quad_hemisphere(&g, 8),
                   &metal, 0, "GGX disk");
    }
}

/* The disk against a polygon of SC_LTC_MAX_VERTS sides of the disk's area (n sin(2π/n) R'²/2 =
 * π R²): the 64-sided stand-in agrees with the finer polygon. */
static void disk_agrees_with_a_many_sided_polygon(void **state)
{
    (void)state;
    enum { SIDES = SC_LTC_MAX_VERTS };
    static double ring[SIDES][3];
    const double centre[3] = {0.3, -0.2, 0.3}, down[3] = {0, 0, -1}, f0[3] = {0.5, 0.5, 0.5};
    const double radius = 0.7, r = radius * sqrt(2.0 * pi / (SIDES * sin(2.0 * pi / SIDES)));
    for (int k = 0; k < SIDES; k++) { /* clockwise seen from above: it faces down */
        double phi = -2.0 * pi * k / SIDES;
        ring[k][0] = centre[0] + r * cos(phi);
        ring[k][1] = centre[1] + r * sin(phi);
        ring[k][2] = centre[2];
    }
    sc_frame f = frame_about(up);
    double v[3];
    dir(35, 200, v);
    sc_ltc_result disk, poly;
    assert_int_equal(sc_ltc_disk(&f, v, 0.25, f0, centre, down, radius, 0, &disk), 0);
    assert_int_equal(sc_ltc_polygon(&f, v, 0.25, f0, (const double(*)[3])ring, SIDES, 0, &poly), 0);
    assert_rel(disk.cosine, poly.cosine, 1e-4, "cosine");
    assert_rel(disk.spec[0], poly.spec[0], 1e-4, "spec");
    assert_int_equal(sc_ltc_polygon(&f, v, 0.25, f0, (const double(*)[3])ring, SIDES + 1, 0, &poly),
                     -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unit_square_form_factor),
        cmocka_unit_test(sidedness_follows_the_winding),
        cmocka_unit_test(horizon_clipping_against_quadrature),
        cmocka_unit_test(comb_crossing_the_horizon),
        cmocka_unit_test(ggx_square_against_quadrature),
        cmocka_unit_test(ggx_mirror_square_against_quadrature),
        cmocka_unit_test(ggx_worked_example),
        cmocka_unit_test(symmetric_configurations_agree),
        cmocka_unit_test(degenerate_input_is_refused),
        cmocka_unit_test(unlit_configurations_give_zero),
        cmocka_unit_test(extreme_emitters_stay_finite),
        cmocka_unit_test(disk_against_closed_form_and_quadrature),
        cmocka_unit_test(disk_agrees_with_a_many_sided_polygon),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
