/* The BRDFs (shadecalc/brdf.h) against the worked examples of docs/formulas.md §6.1–§6.6 (computed there
 * in IEEE double by an independent Python implementation), relative tolerance 1e-10 in double
 * and 1e-5 in highp; plus the extremes of docs/formulas.md §6 and reciprocity on random directions. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "shadecalc/brdf.h"

static const double pi = 3.14159265358979323846;

/* dir(θ°, φ°) = (sin θ cos φ, sin θ sin φ, cos θ) about n = z, t = x (docs/formulas.md §1). */
static void dir(double theta_deg, double phi_deg, double out[3])
{
    double t = theta_deg * pi / 180.0, f = phi_deg * pi / 180.0;
    out[0] = sin(t) * cos(f);
    out[1] = sin(t) * sin(f);
    out[2] = cos(t);
}

static sc_frame z_frame(void)
{
    sc_frame f;
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
    assert_int_equal(sc_frame_make(n, t, &f), 0);
    return f;
}

static void set3(double c[3], double x) { c[0] = c[1] = c[2] = x; }

/* A specular-only (ρ_s = k_s = 1) or diffuse-only model. */
static sc_brdf model(sc_brdf_kind kind, int form, double diff, double spec)
{
    sc_brdf b;
    sc_brdf_init(&b, kind);
    b.form = form;
    set3(b.diff, diff);
    set3(b.spec, spec);
    return b;
}

static sc_brdf_terms eval_at(sc_prec p, const sc_brdf *b, double ti, double pi_, double to,
                             double po)
{
    sc_frame f = z_frame();
    double l[3], v[3];
    dir(ti, pi_, l);
    dir(to, po, v);
    sc_brdf_terms t;
    sc_brdf_eval(p, b, &f, l, v, &t);
    return t;
}

static void assert_rel(double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol * fabs(want)))
        fail_msg("got %.15g, want %.15g (relative error %.3g > %.3g)", got, want,
                 fabs(got - want) / fabs(want), tol);
}

/* f at (θi, φi), (θo, φo) in double (1e-10) and highp (1e-5). */
static void check_f(const sc_brdf *b, double ti, double pi_, double to, double po, double want)
{
    assert_rel(eval_at(SC_DOUBLE, b, ti, pi_, to, po).f[0], want, 1e-10);
    assert_rel(eval_at(SC_HIGHP, b, ti, pi_, to, po).f[0], want, 1e-5);
}

static void lambert_is_rho_over_pi(void **state)
{
    (void)state;
    sc_brdf b = model(SC_BRDF_LAMBERT, 0, 0.8, 0);
    check_f(&b, 30, 0, 60, 120, 0.254647908947);
    check_f(&b, 0, 0, 89, 0, 0.254647908947);
}

/* Reference §7 tabulates the lobes without the 1/π that docs/formulas.md §6 puts on original and modified
 * Phong: those are divided by π here. */
static void phong_worked_examples(void **state)
{
    (void)state;
    sc_brdf orig = model(SC_BRDF_PHONG, SC_PHONG_ORIGINAL, 0, 1);
    sc_brdf mod = model(SC_BRDF_PHONG, SC_PHONG_MODIFIED, 0, 1);
    sc_brdf norm = model(SC_BRDF_PHONG, SC_PHONG_NORMALIZED, 0, 1);
    orig.m = mod.m = norm.m = 10;
    check_f(&orig, 30, 0, 30, 180, 1.15470053838 / pi);
    check_f(&mod, 30, 0, 30, 180, 1.0 / pi);
    check_f(&norm, 30, 0, 30, 180, 1.9098593171);
    orig.m = mod.m = norm.m = 20;
    check_f(&orig, 45, 0, 30, 180, 0.706953029481 / pi);
    check_f(&mod, 45, 0, 30, 180, 0.499891281126 / pi);
    check_f(&norm, 45, 0, 30, 180, 1.75032370479);
    mod.m = 100;
    assert_rel(eval_at(SC_DOUBLE, &mod, 60, 0, 0, 0).f[0], 7.88860905221e-31 / pi, 1e-9);
}

static void blinn_phong_worked_examples(void **state)
{
    (void)state;
    sc_brdf norm = model(SC_BRDF_BLINN_PHONG, SC_BLINN_NORMALIZED, 0, 1);
    sc_brdf plain = model(SC_BRDF_BLINN_PHONG, SC_BLINN_PLAIN, 0, 1);
    norm.m = plain.m = 32;
    check_f(&norm, 0, 0, 0, 0, 1.59154943092);
    check_f(&plain, 60, 0, 0, 0, 0.0100225957576);
    check_f(&norm, 60, 0, 0, 0, 0.0159514565744);
    norm.m = 100;
    check_f(&norm, 50, 0, 20, 150, 0.0368888518728);
}

static void ward_worked_examples(void **state)
{
    (void)state;
    const double want[3][3] = {
        {2.29720373092, 2.65258238486, 2.65258238486},
        {0.00996599797177, 0.0117462949812, 0.0125005111955},
        {113.99211884, 6531.59890872, 6531.59890872},
    };
    for (int form = SC_WARD_1992; form <= SC_WARD_GMD; form++) {
        sc_brdf b = model(SC_BRDF_WARD, form, 0, 1);
        b.ax = b.ay = 0.2;
        check_f(&b, 30, 0, 30, 180, want[0][form]);
        check_f(&b, 89, 0, 89, 180, want[2][form]);
        b.ax = 0.1;
        b.ay = 0.3;
        check_f(&b, 40, 0, 20, 135, want[1][form]);
    }
}

static void oren_nayar_worked_examples(void **state)
{
    (void)state;
    static const struct {
        double ti, pi_, to, po, qualitative, full;
    } rows[] = {
        {60, 0, 30, 0, 0.270006455602, 0.296435417531},
        {60, 0, 30, 180, 0.221479246627, 0.208063588002},
        {60, 0, 30, 90, 0.221479246627, 0.25254316512},
        {60, 0, 60, 0, 0.367060873552, 0.383578974758},
        {0, 0, 45, 0, 0.221479246627, 0.251211828797},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        sc_brdf q = model(SC_BRDF_OREN_NAYAR, SC_OREN_QUALITATIVE, 0.9, 0);
        sc_brdf f = model(SC_BRDF_OREN_NAYAR, SC_OREN_FULL, 0.9, 0);
        q.sigma = f.sigma = 30.0 * pi / 180.0;
        check_f(&q, rows[i].ti, rows[i].pi_, rows[i].to, rows[i].po, rows[i].qualitative);
        check_f(&f, rows[i].ti, rows[i].pi_, rows[i].to, rows[i].po, rows[i].full);
    }
    sc_brdf zero = model(SC_BRDF_OREN_NAYAR, SC_OREN_FULL, 0.9, 0);
    check_f(&zero, 60, 0, 30, 0, 0.286478897565); /* σ = 0 is Lambert */
}

static sc_brdf microfacet(sc_ndf D, sc_masking G, sc_fresnel F, double alpha)
{
    sc_brdf b = model(SC_BRDF_COOK_TORRANCE, SC_CT_WALTER, 0, 1);
    b.D = D;
    b.G = G;
    b.F = F;
    b.ax = b.ay = alpha;
    return b;
}

static void cook_torrance_worked_examples(void **state)
{
    (void)state;
    sc_brdf b = microfacet(SC_D_GGX, SC_G_SMITH_CORRELATED, SC_F_SCHLICK, 0.5);
    check_f(&b, 0, 0, 0, 0, 0.0127323954474); /* l = v = n: F0/(4πα²) */
    check_f(&b, 45, 0, 45, 180, 0.023954666271);
    sc_brdf_terms t = eval_at(SC_DOUBLE, &b, 45, 0, 45, 180);
    assert_rel(t.G, 0.894427191, 1e-9);
    assert_rel(t.F[0], 0.0420692731244, 1e-10);
    b.G = SC_G_SMITH;
    assert_rel(eval_at(SC_DOUBLE, &b, 45, 0, 45, 180).G, 0.891649440013, 1e-10);
    b.D = SC_D_BECKMANN;
    b.G = SC_G_SMITH_CORRELATED;
    assert_rel(eval_at(SC_DOUBLE, &b, 45, 0, 45, 180).G, 0.999511227658, 1e-10);
    b.F = SC_F_EXACT;
    assert_rel(eval_at(SC_DOUBLE, &b, 45, 0, 45, 180).F[0], 0.0502399110122, 1e-10);

    sc_brdf bv = microfacet(SC_D_BECKMANN, SC_G_VCAVITY, SC_F_SCHLICK, 0.5);
    check_f(&bv, 45, 0, 45, 180, 0.0267821310801);
    bv.form = SC_CT_1982;
    check_f(&bv, 45, 0, 45, 180, 0.10712852432);

    sc_brdf g = microfacet(SC_D_GGX, SC_G_SMITH_CORRELATED, SC_F_EXACT, 0.3);
    check_f(&g, 60, 0, 30, 200, 0.0256271923424);
    t = eval_at(SC_DOUBLE, &g, 60, 0, 30, 200);
    assert_rel(t.D, 0.96201640125, 1e-10);
    assert_rel(t.G, 0.933780087077, 1e-10);
    assert_rel(t.F[0], 0.049412243301, 1e-10);
    assert_rel(t.cos_h, 0.953555555986, 1e-10);
    g.G = SC_G_SMITH;
    assert_rel(eval_at(SC_DOUBLE, &g, 60, 0, 30, 200).G, 0.933368259239, 1e-10);
    sc_brdf bs = microfacet(SC_D_BECKMANN, SC_G_VCAVITY, SC_F_SCHLICK, 0.3);
    check_f(&bs, 60, 0, 30, 200, 0.0340376864431);
    t = eval_at(SC_DOUBLE, &bs, 60, 0, 30, 200);
    assert_rel(t.D, 1.41159188473, 1e-10);
    assert_true(t.G == 1.0);
}

/* F(θ) at the mirror configuration (h = n, v·h = cos θ), η = 1.5: docs/formulas.md §6.6 table. */
static void fresnel_table(void **state)
{
    (void)state;
    static const double theta[] = {0, 30, 45, 60, 80, 89};
    static const double exact[] = {
        0.04, 0.0415226259758, 0.0502399110122, 0.0891867128022, 0.387704354691, 0.90418494978};
    static const double schlick[] = {0.04, 0.0400414365431, 0.0420692731244,
                                     0.07, 0.409910091022,  0.9191018918};
    for (int i = 0; i < 6; i++) {
        sc_brdf e = microfacet(SC_D_GGX, SC_G_VCAVITY, SC_F_EXACT, 0.3);
        sc_brdf s = microfacet(SC_D_GGX, SC_G_VCAVITY, SC_F_SCHLICK, 0.3);
        assert_rel(eval_at(SC_DOUBLE, &e, theta[i], 0, theta[i], 180).F[0], exact[i], 1e-9);
        assert_rel(eval_at(SC_DOUBLE, &s, theta[i], 0, theta[i], 180).F[0], schlick[i], 1e-9);
    }
    sc_brdf inside = microfacet(SC_D_GGX, SC_G_VCAVITY, SC_F_EXACT, 0.3);
    inside.ior = 1.0 / 1.5;
    assert_rel(eval_at(SC_DOUBLE, &inside, 30, 0, 30, 180).F[0], 0.0551901672954, 1e-9);
    assert_true(eval_at(SC_DOUBLE, &inside, 45, 0, 45, 180).F[0] == 1.0); /* TIR */
    sc_brdf brewster = microfacet(SC_D_GGX, SC_G_VCAVITY, SC_F_EXACT, 0.3);
    double tb = atan(1.5) * 180.0 / pi;
    assert_rel(eval_at(SC_DOUBLE, &brewster, tb, 0, tb, 180).F[0], 0.0739644970414, 1e-9);
}

/* Never NaN or negative; finite in double and highp. In mediump an intermediate beyond the
 * binary16 range (65504) overflows to +Inf, as the precision does: allowed when the double
 * value is at least 1 (the grazing 1/cos θ blow-ups), never for small values. */
static int acceptable(const sc_brdf_terms *t, const sc_brdf_terms *ref, sc_prec p)
{
    for (int c = 0; c < 3; c++) {
        if (isnan(t->f[c]) || t->f[c] < 0.0)
            return 0;
        if (!isfinite(t->f[c]) && !(p == SC_MEDIUMP && ref->f[c] >= 1.0))
            return 0;
    }
    return 1;
}

/* Every model and form, at every precision, on the extremes of docs/formulas.md §6. */
static void extremes_stay_finite(void **state)
{
    (void)state;
    static const double cases[][4] = {
        {89.9999, 0, 30, 180},    {30, 0, 89.9999, 180}, {89.9999, 0, 89.9999, 180},
        {45, 0, 45, 0},           {60, 0, 60, 180},      {0, 0, 0, 0},
        {89.9999, 0, 89.9999, 0}, {1e-30, 0, 1e-30, 90}, {90, 0, 90, 180},
    };
    static const double params[][2] = {{0, 0}, {1e6, 1e-30}, {1e4, 1e-4}, {1, 1}, {32, 0.3}};
    for (int kind = SC_BRDF_LAMBERT; kind <= SC_BRDF_COOK_TORRANCE; kind++)
        for (int form = 0; sc_brdf_form_name((sc_brdf_kind)kind, form); form++)
            for (size_t pi_ = 0; pi_ < sizeof params / sizeof params[0]; pi_++)
                for (int D = 0; D < 2; D++)
                    for (int G = 0; G < 3; G++)
                        for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
                            for (int prec = SC_DOUBLE; prec <= SC_MEDIUMP; prec++) {
                                sc_brdf b = model((sc_brdf_kind)kind, form, 0.5, 0.5);
                                b.m = params[pi_][0];
                                b.ax = b.ay = params[pi_][1];
                                b.sigma = params[pi_][1];
                                b.D = (sc_ndf)D;
                                b.G = (sc_masking)G;
                                sc_brdf_terms t = eval_at((sc_prec)prec, &b, cases[c][0],
                                                          cases[c][1], cases[c][2], cases[c][3]);
                                sc_brdf_terms ref = eval_at(SC_DOUBLE, &b, cases[c][0], cases[c][1],
                                                            cases[c][2], cases[c][3]);
                                if (!acceptable(&t, &ref, (sc_prec)prec))
                                    fail_msg(
                                        "%s form %d m=%g a=%g D%d G%d case %zu prec %d: f = %g",
                                        sc_brdf_kind_name((sc_brdf_kind)kind), form, b.m, b.ax, D,
                                        G, c, prec, t.f[0]);
                            }
}

static void below_horizon_is_zero(void **state)
{
    (void)state;
    sc_brdf b = model(SC_BRDF_BLINN_PHONG, SC_BLINN_NORMALIZED, 0.5, 0.5);
    assert_true(eval_at(SC_DOUBLE, &b, 100, 0, 30, 0).f[0] == 0.0);
    assert_true(eval_at(SC_DOUBLE, &b, 30, 0, 100, 0).f[0] == 0.0);
}

/* Helmholtz reciprocity f(l, v) = f(v, l) on random directions, every model except original
 * Phong (docs/formulas.md §6.9), anisotropic where the model is. */
static void reciprocity_on_random_directions(void **state)
{
    (void)state;
    srand(12345);
    for (int kind = SC_BRDF_LAMBERT; kind <= SC_BRDF_COOK_TORRANCE; kind++)
        for (int form = 0; sc_brdf_form_name((sc_brdf_kind)kind, form); form++) {
            if (kind == SC_BRDF_PHONG && form == SC_PHONG_ORIGINAL)
                continue;
            sc_brdf b = model((sc_brdf_kind)kind, form, 0.5, 0.5);
            b.ax = 0.2;
            b.ay = 0.45;
            b.sigma = 0.4;
            for (int i = 0; i < 2000; i++) {
                double ti = 89.0 * rand() / RAND_MAX, to = 89.0 * rand() / RAND_MAX;
                double pi_ = 360.0 * rand() / RAND_MAX, po = 360.0 * rand() / RAND_MAX;
                double a = eval_at(SC_DOUBLE, &b, ti, pi_, to, po).f[0];
                double c = eval_at(SC_DOUBLE, &b, to, po, ti, pi_).f[0];
                if (!(fabs(a - c) <= 1e-12 * fabs(a) + 1e-300))
                    fail_msg("%s/%s not reciprocal at (%g,%g),(%g,%g): %.17g vs %.17g",
                             sc_brdf_kind_name((sc_brdf_kind)kind),
                             sc_brdf_form_name((sc_brdf_kind)kind, form), ti, pi_, to, po, a, c);
            }
        }
    sc_brdf orig = model(SC_BRDF_PHONG, SC_PHONG_ORIGINAL, 0, 1);
    orig.m = 1;
    assert_true(fabs(eval_at(SC_DOUBLE, &orig, 60, 0, 20, 180).f[0] -
                     eval_at(SC_DOUBLE, &orig, 20, 180, 60, 0).f[0]) > 1e-3);
}

static void frame_rejects_degenerate_input(void **state)
{
    (void)state;
    sc_frame f;
    const double zero[3] = {0, 0, 0}, n[3] = {0, 0, 2}, parallel[3] = {0, 0, 5};
    assert_int_equal(sc_frame_make(zero, NULL, &f), -1);
    assert_int_equal(sc_frame_make(n, parallel, &f), -1);
    assert_int_equal(sc_frame_make(n, NULL, &f), 0);
    assert_true(f.n[2] == 1.0 && fabs(f.t[0] * f.n[0] + f.t[1] * f.n[1] + f.t[2] * f.n[2]) < 1e-15);
}

/* No undocumented clamps at grazing angles. Ward GMD at the mirror pair with n·l = n·v = c:
 * h_u = (0, 0, 2c), f = (h_u·h_u)/(π α² (h_u·n)^4) = 1/(4π α² c²) (it was capped where
 * (h_u·n)^4/(h_u·h_u) < 10⁻⁶: 795.8 for 19894.4 at α = 20, c = 10⁻⁴). The V-cavity G is
 * min(1, 2 n·h n·v / v·h, 2 n·h n·l / v·h) with v·h unfloored: 1 at the mirror pair (it was
 * 0.2 at c = 10⁻⁷, v·h floored at 10⁻⁶), and the formula off the mirror. */
static void no_clamps_at_grazing_angles(void **state)
{
    (void)state;
    const double cs[] = {1e-4, 1e-7};
    for (int i = 0; i < 2; i++) {
        double theta = acos(cs[i]) * 180.0 / pi, l[3], v[3];
        dir(theta, 0, l);
        dir(theta, 180, v);
        double c = l[2]; /* = v[2], as dir computes it */
        for (int alpha = 0; alpha < 2; alpha++) {
            sc_brdf gmd = model(SC_BRDF_WARD, SC_WARD_GMD, 0, 1);
            gmd.ax = gmd.ay = alpha ? 20.0 : 0.2;
            double want = 1.0 / (4.0 * pi * gmd.ax * gmd.ax * c * c);
            assert_rel(eval_at(SC_DOUBLE, &gmd, theta, 0, theta, 180).f[0], want, 1e-9);
            assert_rel(eval_at(SC_HIGHP, &gmd, theta, 0, theta, 180).f[0], want, 1e-3);
        }
        sc_brdf ct = model(SC_BRDF_COOK_TORRANCE, SC_CT_WALTER, 0, 1);
        ct.D = SC_D_BECKMANN;
        ct.G = SC_G_VCAVITY;
        assert_true(eval_at(SC_DOUBLE, &ct, theta, 0, theta, 180).G == 1.0);
        /* off the mirror: v at 60°, l grazing */
        double v2[3], h[3];
        dir(60, 180, v2);
        for (int k = 0; k < 3; k++)
            h[k] = l[k] + v2[k];
        double len = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        double nh = h[2] / len, vh = (v2[0] * h[0] + v2[1] * h[1] + v2[2] * h[2]) / len;
        double g = fmin(1.0, fmin(2.0 * nh * v2[2] / vh, 2.0 * nh * l[2] / vh));
        assert_rel(eval_at(SC_DOUBLE, &ct, theta, 0, 60, 180).G, g, 1e-12);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lambert_is_rho_over_pi),
        cmocka_unit_test(phong_worked_examples),
        cmocka_unit_test(blinn_phong_worked_examples),
        cmocka_unit_test(ward_worked_examples),
        cmocka_unit_test(oren_nayar_worked_examples),
        cmocka_unit_test(cook_torrance_worked_examples),
        cmocka_unit_test(fresnel_table),
        cmocka_unit_test(extremes_stay_finite),
        cmocka_unit_test(no_clamps_at_grazing_angles),
        cmocka_unit_test(below_horizon_is_zero),
        cmocka_unit_test(reciprocity_on_random_directions),
        cmocka_unit_test(frame_rejects_degenerate_input),
    };
    return cmocka_run_group_tests_name("brdf", tests, NULL, NULL);
}
