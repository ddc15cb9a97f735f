/* The attenuation, spot and BRDF batch kernels beyond the parameters of their table rows
 * (tests/unit/test_batch.c checks those on 10^6 inputs): every BRDF model, form, D × G × F
 * combination and roughness, anisotropic ones on 10^6 inputs (a sample under the sanitizers:
 * tests/unit/scale.h), and the edge rules of light.h (r = 0 finite,
 * f_c = f_max flat, r_start = r_end a step, cutoff 180, inner = outer a hard edge, exponent 0),
 * on every tier and instruction set, against the library's double functions (the references of
 * src/batch/reference_light.c) within each row's stated bound. SHADECALC_BATCH_SEED=k, as for
 * tests/unit/test_batch.c, draws another set of random inputs (a failure names the seed). */
#include <float.h>
#include <pthread.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/batch.h"
#include "shadecalc/brdf.h"
#include "shadecalc/scene.h"

#include "batch/reference.h"
#include "batch/reference_light.h"
#include "simd/uniforms.h"
#include "tests/support/batch_buffers.h"
#include "tests/unit/scale.h"

enum { N_BRDF = 2003, N_FUNC = 4001 }; /* not multiples of 8: the tails run too */

static const double pi = 3.14159265358979323846;

static uint64_t rng = 0x2545F4914F6CDD1DULL;

/* Runs every tier and instruction set of `kernel` on the inputs in b (references already in
 * b->ref) and fails on an error beyond a row's bound or a NaN. */
static void check_all_rows(const char *kernel, batch_buffers *b, const char *what)
{
    int rows = 0;
    for (int r = 0; r < sc_batch_count; r++) {
        const sc_batch_entry *e = &sc_batch_table[r];
        if (strcmp(e->kernel, kernel) != 0 || !sc_isa_supported(e->isa))
            continue;
        rows++;
        e->fn(&b->args);
        sc_batch_error acc;
        sc_batch_error_init(&acc);
        for (size_t i = 0; i < b->args.n; i++) {
            sc_batch_error_against(e, &b->args, i, b->ref + 4 * i, &acc);
            for (int j = 0; j < e->n_out; j++)
                if (isnan(b->out[j][i]))
                    fail_msg("%s %s %s (%s): NaN at element %zu", kernel, e->tier,
                             sc_isa_name(e->isa), what, i);
        }
        if (acc.max_ratio > 1.0) {
            size_t w = acc.worst;
            fail_msg("%s %s %s (%s): %.3g× the bound at in[0] = %a, out[0] = %a, ref %a", kernel,
                     e->tier, sc_isa_name(e->isa), what, acc.max_ratio, (double)b->in[0][w],
                     (double)b->out[0][w], b->ref[4 * w]);
        }
    }
    assert_true(rows > 0);
}

static const sc_batch_entry *scalar_row(const char *kernel)
{
    for (int r = 0; r < sc_batch_count; r++)
        if (strcmp(sc_batch_table[r].kernel, kernel) == 0 && sc_batch_table[r].isa == SC_ISA_SCALAR)
            return &sc_batch_table[r];
    fail_msg("no kernel %s", kernel);
    return NULL;
}

static void fill_references(const sc_batch_entry *e, batch_buffers *b)
{
    for (size_t i = 0; i < b->args.n; i++)
        e->ref(&b->args, i, b->ref + 4 * i);
}

/* ---- BRDFs ---- */

/* The table's test BRDF (GGX, smith-correlated, Schlick, coloured terms) as another model. */
static sc_brdf brdf_params(sc_brdf_kind model, int form)
{
    sc_brdf p = sc_batch_test_brdf;
    p.kind = model;
    p.form = form;
    return p;
}

/* n random inputs of e's domain in b */
static void sampled_buffers(batch_buffers *b, const sc_batch_entry *e, size_t n, const void *params)
{
    batch_buffers_alloc(b, n, params);
    for (size_t i = 0; i < n; i++) {
        float v[9];
        sc_batch_sample(e, &rng, v);
        for (int j = 0; j < e->n_in; j++)
            b->in[j][i] = v[j];
    }
}

/* n random inputs of kernel's domain, every row of it with params against the reference */
static void check_rows_on(const char *kernel, const void *params, size_t n, const char *what)
{
    const sc_batch_entry *e = scalar_row(kernel);
    batch_buffers b;
    sampled_buffers(&b, e, n, params);
    fill_references(e, &b);
    check_all_rows(kernel, &b, what);
    batch_buffers_release(&b);
}

static void check_brdf_on(const sc_brdf *p, size_t n, const char *what)
{
    check_rows_on("brdf", p, n, what);
}

static void check_brdf(const sc_brdf *p, const char *what) { check_brdf_on(p, N_BRDF, what); }

static void every_brdf_form_within_bounds(void **state)
{
    (void)state;
    static const int forms[] = {1, 3, 2, 3, 2, 2}; /* by sc_brdf_kind */
    for (int model = SC_BRDF_LAMBERT; model < SC_BRDF_COOK_TORRANCE; model++)
        for (int form = 0; form < forms[model]; form++) {
            sc_brdf p = brdf_params((sc_brdf_kind)model, form);
            check_brdf(&p, sc_brdf_form_name((sc_brdf_kind)model, form));
        }
}

/* D × G × F × form, at two roughnesses */
static void every_cook_torrance_within_bounds(void **state)
{
    (void)state;
    static const double alphas[] = {0.2, 0.6};
    for (int D = 0; D < 2; D++)
        for (int G = 0; G < 3; G++)
            for (int F = 0; F < 3; F++)
                for (int k = 0; k < 2; k++) {
                    sc_brdf p = brdf_params(SC_BRDF_COOK_TORRANCE,
                                            k & 1 ? SC_CT_1982 : SC_CT_WALTER);
                    p.D = (sc_ndf)D;
                    p.G = (sc_masking)G;
                    p.F = (sc_fresnel)F;
                    p.ax = p.ay = alphas[(D + G + F + k) & 1];
                    char what[64];
                    snprintf(what, sizeof what, "D %d G %d F %d alpha %g", D, G, F, p.ax);
                    check_brdf(&p, what);
                }
}

static void set_exponent(sc_brdf *b, double m) { b->m = m; }
static void isotropic_alpha(sc_brdf *b, double alpha) { b->ax = b->ay = alpha; }
static void beckmann_alpha(sc_brdf *b, double alpha)
{
    b->D = SC_D_BECKMANN;
    isotropic_alpha(b, alpha);
}
static void oren_nayar_sigma(sc_brdf *b, double sigma) { b->sigma = sigma; }
static void exact_fresnel_ior(sc_brdf *b, double ior)
{
    b->F = SC_F_EXACT;
    b->ior = ior;
}

/* Other exponents (integer ones by binary powering, the others, and those beyond
 * SC_LOBE_INT_MAX, by the tiers' pow: src/simd/light_impl.h, cos_lobe), σ, η, narrow Gaussian
 * lobes (e^−x beyond x = 87 flushes: exp_minus), and m = 0 (pow(0, 0) = 1). */
static void brdf_parameter_extremes_within_bounds(void **state)
{
    (void)state;
    static const struct {
        sc_brdf_kind kind;
        int form;
        void (*change)(sc_brdf *, double);
        double x;
        const char *what;
    } cases[] = {
        {SC_BRDF_BLINN_PHONG, SC_BLINN_PLAIN, set_exponent, 0.0, "blinn m 0"},
        {SC_BRDF_BLINN_PHONG, SC_BLINN_PLAIN, set_exponent, 200.0, "blinn m 200"},
        {SC_BRDF_BLINN_PHONG, SC_BLINN_PLAIN, set_exponent, 33.0, "blinn m 33 (m/2 = 16.5)"},
        {SC_BRDF_PHONG, SC_PHONG_MODIFIED, set_exponent, 1.0, "phong m 1"},
        {SC_BRDF_PHONG, SC_PHONG_MODIFIED, set_exponent, 20.5, "phong m 20.5"},
        {SC_BRDF_PHONG, SC_PHONG_MODIFIED, set_exponent, 300.0, "phong m 300"},
        {SC_BRDF_COOK_TORRANCE, SC_CT_WALTER, beckmann_alpha, 0.05, "beckmann smith alpha 0.05"},
        {SC_BRDF_WARD, SC_WARD_1992, isotropic_alpha, 0.05, "ward alpha 0.05"},
        {SC_BRDF_WARD, SC_WARD_GMD, isotropic_alpha, 0.2, "ward gmd alpha 0.2"},
        {SC_BRDF_OREN_NAYAR, SC_OREN_FULL, oren_nayar_sigma, 1.2, "oren-nayar sigma 1.2"},
        {SC_BRDF_OREN_NAYAR, SC_OREN_FULL, oren_nayar_sigma, 0.0, "oren-nayar sigma 0"},
        {SC_BRDF_COOK_TORRANCE, SC_CT_WALTER, exact_fresnel_ior, 2.4, "exact fresnel eta 2.4"}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sc_brdf p = brdf_params(cases[k].kind, cases[k].form);
        cases[k].change(&p, cases[k].x);
        check_brdf(&p, cases[k].what);
    }
}

/* Worked example: l = v = n (normal incidence), Lambert and Blinn-Phong by hand. */
static void brdf_normal_incidence_by_hand(void **state)
{
    (void)state;
    float one[1] = {1.0f}, zero[1] = {0.0f}, r[1], g[1], bl[1];
    sc_brdf p = brdf_params(SC_BRDF_BLINN_PHONG, SC_BLINN_NORMALIZED);
    sc_batch_args a = {{zero, zero, one, zero, zero, one, zero, zero, one}, {r, g, bl}, 1, &p};
    assert_int_equal(sc_batch_run("brdf", "bits16", &a), 0);
    /* c_diff/π + c_spec (m+8)/(8π) */
    double want = 0.8 / pi + 0.2 * 40.0 / (8.0 * pi);
    assert_true(fabs(r[0] - want) <= 1e-6 * want);
    p.kind = SC_BRDF_LAMBERT;
    assert_int_equal(sc_batch_run("brdf", "bits12", &a), 0);
    assert_true(fabs(bl[0] - 0.2 / pi) <= 1e-6);
    p.kind = (sc_brdf_kind)99; /* out of range: lambert */
    assert_int_equal(sc_batch_run("brdf", "bits12", &a), 0);
    assert_true(fabs(g[0] - 0.5 / pi) <= 1e-6);
}

/* ---- attenuation and spot ---- */

/* Random r in [0, hi] plus the given points; every row of kernel. */
static void check_function(const char *kernel, const void *params, double hi, const float *points,
                           int n_points, const char *what)
{
    const sc_batch_entry *e = scalar_row(kernel);
    batch_buffers b;
    batch_buffers_alloc(&b, N_FUNC, params);
    for (size_t i = 0; i < N_FUNC; i++)
        b.in[0][i] = (size_t)n_points > i ? points[i]
                                          : (float)(hi *
                                                    (double)(rng = rng * 6364136223846793005ULL +
                                                                   1442695040888963407ULL) /
                                                    0x1p64);
    fill_references(e, &b);
    check_all_rows(kernel, &b, what);
    batch_buffers_release(&b);
}

/* Parameters at the edges of every attenuation function: a pure quadratic clq, a window with
 * r_start = r_end (a step), a flat pixar (f_c = f_max), r_max = 5. */
static sc_atten edge_atten(void)
{
    sc_atten a = sc_batch_test_atten;
    a.sc = a.sl = 0.0, a.sq = 1.0;      /* pure quadratic */
    a.r_start = a.r_end = 5.0;          /* a step */
    a.f_max = a.f_c = 3.0, a.r_c = 5.0; /* flat inside r_c */
    a.s_e = 1.5, a.r_max = 5.0;
    return a;
}

static void attenuation_edges(void **state)
{
    (void)state;
    const float points[] = {0.0f, 0x1p-149f, 1e-3f, 5.0f, 0x1.3ffffep+2f, 0x1.400002p+2f, 10.0f};
    sc_atten p = edge_atten();
    int n = (int)(sizeof points / sizeof points[0]);
    check_function("atten_invsq", &p, 20.0, points, n, "r = 0");
    check_function("atten_clq", &p, 20.0, points, n, "pure quadratic, r = 0");
    check_function("atten_window", &p, 20.0, points, n, "r_start = r_end: a step");
    check_function("atten_pixar", &p, 20.0, points, n, "f_c = f_max: flat");
    check_function("atten_windowed", &p, 20.0, points, n, "r = r_max");
    check_function("atten_none", &p, 20.0, points, n, "none");
    p.f_c = 0.25;
    p.s_e = 0.5;
    check_function("atten_pixar", &p, 20.0, points, n, "f_c < f_max");
}

/* Windows whose width r_end − r_start is subnormal in float (1/w overflows) or far above 1:
 * the ramp's quotient still within the bound on every row (the kernels scale it to [1, 2)). */
static void window_widths_far_from_one(void **state)
{
    (void)state;
    sc_atten p = sc_batch_test_atten;
    p.r_start = 0x1p-140, p.r_end = 0x1p-138; /* w = 3 2^-140 */
    const float tiny[] = {0x1p-140f, 0x1.8p-140f, 0x1p-139f, 0x1.8p-139f, 0x1.fffffcp-139f};
    check_function("atten_window", &p, 0x1p-137, tiny, 5, "subnormal width");
    p.r_start = 0x1p100, p.r_end = 0x1.8p120;
    const float huge[] = {0x1p100f, 0x1.000002p100f, 0x1p120f, 0x1.7ffffep120f};
    check_function("atten_window", &p, 0x1p121, huge, 4, "width 2^120");
}

/* By hand: the step, the flat pixar, r = 0 finite. */
static void attenuation_by_hand(void **state)
{
    (void)state;
    sc_atten p = edge_atten();
    float r[4] = {0.0f, 5.0f, 0x1.400002p+2f, 20.0f}, out[4];
    sc_batch_args a = {{r}, {out}, 4, &p};
    assert_int_equal(sc_batch_run("atten_window", "u2", &a), 0);
    assert_true(out[0] == 1.0f && out[1] == 1.0f && out[2] == 0.0f && out[3] == 0.0f);
    assert_int_equal(sc_batch_run("atten_invsq", "u2", &a), 0);
    assert_true(out[0] == 1e4f && out[3] == 1.0f / 400.0f);
    assert_int_equal(sc_batch_run("atten_pixar", "u4", &a), 0);
    assert_true(out[0] == 3.0f && out[1] == 3.0f);
    assert_true(fabs(out[3] - 3.0 * pow(0.25, 1.5)) <= 1e-6);
}

/* |got − want| in units of the binary32 ULP at want (normal want) */
static double ulps_from(float got, double want)
{
    int e;
    frexp(want, &e);
    return fabs((double)got - want) / ldexp(1.0, e - 24);
}

/* Whether an integer power beyond r_c is within what src/simd/light_impl.h states: the accurate
 * tiers' (in double) 0.5 ULP and 2^-20 for the double products, the fast tiers' (in float) 3m
 * 2^-24 relative. */
static int pixar_power_within(const sc_batch_entry *e, float got, double want, double m)
{
    if (e->bound_ulp > 0)
        return ulps_from(got, want) <= 0.5 + 0x1p-20;
    return fabs((double)got - want) <= 3 * m * 0x1p-24 * want;
}

/* Integer falloff exponents beyond r_c, raised by binary powering (src/simd/light_impl.h):
 * every tier and instruction set within its pixar_power_within of the closed form
 * f_c (r_c/r)^s_e, r from r_c's float successor to 1000; the lanes inside r_c, in the same
 * vectors, within the rows' bounds. */
static void pixar_integer_exponents_round_once(void **state)
{
    (void)state;
    /* 13: the fast tiers' float powers down to 2^-116.6 at r = 1000; 14: below 2^-125 there,
     * the lanes raised again in double */
    static const double exponents[] = {1, 2, 3, 7, 13, 14};
    for (int k = 0; k < (int)(sizeof exponents / sizeof exponents[0]); k++) {
        sc_atten p = sc_batch_test_atten;
        p.s_e = exponents[k];
        float r_c = (float)p.r_c, points[] = {r_c, nextafterf(r_c, 0.0f), nextafterf(r_c, 2 * r_c)};
        char what[64];
        snprintf(what, sizeof what, "s_e = %g", p.s_e);
        check_function("atten_pixar", &p, 1000.0, points, 3, what);
        batch_buffers b;
        batch_buffers_alloc(&b, N_FUNC, &p);
        for (size_t i = 0; i < N_FUNC; i++)
            b.in[0][i] = i == 0 ? nextafterf(r_c, 2 * r_c)
                                : (float)(p.r_c + (1000.0 - p.r_c) * (double)(i % 997) / 996.0);
        for (int r = 0; r < sc_batch_count; r++) {
            const sc_batch_entry *e = &sc_batch_table[r];
            if (strcmp(e->kernel, "atten_pixar") != 0 || !sc_isa_supported(e->isa))
                continue;
            e->fn(&b.args);
            for (size_t i = 0; i < N_FUNC; i++) {
                double want = p.f_c * pow(p.r_c / (double)b.in[0][i], p.s_e);
                if (b.in[0][i] > r_c && !pixar_power_within(e, b.out[0][i], want, p.s_e))
                    fail_msg("atten_pixar %s %s (%s): r = %a gives %a, (r_c/r)^s_e = %a", e->tier,
                             sc_isa_name(e->isa), what, (double)b.in[0][i], (double)b.out[0][i],
                             want);
            }
        }
        batch_buffers_release(&b);
    }
}

static void spot_edges(void **state)
{
    (void)state;
    /* cos 30° and its float neighbours: the hard edge of inner = outer decides as in double */
    float c30 = (float)cos(30.0 * pi / 180.0);
    const float points[] = {-1.0f, 0.0f, 1.0f, c30, nextafterf(c30, 0.0f), nextafterf(c30, 2.0f)};
    int n = (int)(sizeof points / sizeof points[0]);
    sc_spot p = {.exponent = 0.0, .cutoff = 180.0, .inner = 30.0, .outer = 30.0};
    check_function("spot_opengl", &p, 1.0, points, n, "cutoff 180");
    check_function("spot_directx", &p, 1.0, points, n, "inner = outer");
    check_function("spot_smoothstep", &p, 1.0, points, n, "inner = outer");
    p.cutoff = 30.0;
    check_function("spot_opengl", &p, 1.0, points, n, "exponent 0");
    p.cutoff = 90.0;
    p.exponent = 3.0;
    p.inner = 0.0;
    p.outer = 90.0;
    check_function("spot_opengl", &p, 1.0, points, n, "cutoff 90");
    check_function("spot_directx", &p, 1.0, points, n, "0..90");
    check_function("spot_smoothstep", &p, 1.0, points, n, "0..90");
}

/* Integer exponents, raised by binary powering (src/simd/spot_impl.h): every tier
 * within its bound up to the largest such exponent, and just past it (the tiers' pow); cones
 * narrow enough that no result inside underflows. */
static void spot_integer_exponents(void **state)
{
    (void)state;
    static const struct {
        double exponent, cutoff;
    } cases[] = {{1, 60}, {2, 60}, {5, 60}, {64, 60}, {1024, 5}, {1025, 5}};
    for (int k = 0; k < (int)(sizeof cases / sizeof cases[0]); k++) {
        sc_spot p = {.exponent = cases[k].exponent, .cutoff = cases[k].cutoff};
        float edge = (float)cos(p.cutoff * pi / 180.0);
        const float points[] = {edge, nextafterf(edge, 2.0f), 0x1.fffffep-1f, 1.0f};
        char what[64];
        snprintf(what, sizeof what, "exponent %g", p.exponent);
        check_function("spot_opengl", &p, 1.0, points, 4, what);
    }
}

static void spot_by_hand(void **state)
{
    (void)state;
    float c30 = (float)cos(30.0 * pi / 180.0);
    float c[4] = {-1.0f, c30, nextafterf(c30, 0.0f), 1.0f}, out[4];
    sc_spot p = {.exponent = 2.0, .cutoff = 180.0, .inner = 30.0, .outer = 30.0};
    sc_batch_args a = {{c}, {out}, 4, &p};
    assert_int_equal(sc_batch_run("spot_opengl", "u1", &a), 0);
    assert_true(out[0] == 1.0f && out[3] == 1.0f);
    for (int t = 0; t < 2; t++) {
        assert_int_equal(sc_batch_run(t ? "spot_smoothstep" : "spot_directx", t ? "u8" : "u16", &a),
                         0);
        /* cos 30° rounded to float is below or above the double cosine: 1 exactly when above */
        float at_edge = (double)c30 >= cos(30.0 * pi / 180.0) ? 1.0f : 0.0f;
        assert_true(out[0] == 0.0f && out[1] == at_edge && out[2] == 0.0f && out[3] == 1.0f);
    }
}

/* ---- anisotropic BRDFs ---- */

/* b with α_x = 0.25, α_y = 0.6 (the tangent frame: sc_frame_make's from n) */
static void make_anisotropic(sc_brdf *b, double unused)
{
    (void)unused;
    b->ax = 0.25;
    b->ay = 0.6;
}

/* Anisotropic Ward and Cook-Torrance (GGX and Beckmann, both Smith forms) on 10^6 inputs
 * each, every tier and instruction set, against brdf.c in double. */
static void anisotropic_brdfs_within_bounds(void **state)
{
    (void)state;
    const size_t N_ANISO = sc_test_inputs(1000000);
    sc_brdf p = brdf_params(SC_BRDF_WARD, SC_WARD_1992);
    make_anisotropic(&p, 0.0);
    check_brdf_on(&p, N_ANISO, "anisotropic ward");
    p = brdf_params(SC_BRDF_COOK_TORRANCE, SC_CT_WALTER);
    make_anisotropic(&p, 0.0);
    check_brdf_on(&p, N_ANISO, "anisotropic ggx smith-correlated");
    p.D = SC_D_BECKMANN;
    p.G = SC_G_SMITH;
    p.ax = 0.35; /* the stated domain of anisotropic Beckmann */
    check_brdf_on(&p, N_ANISO, "anisotropic beckmann smith");
}

/* Every form of ward and cook-torrance anisotropic, fewer inputs. */
static void anisotropic_forms_within_bounds(void **state)
{
    (void)state;
    for (int form = 0; form < 3; form++) {
        sc_brdf p = brdf_params(SC_BRDF_WARD, form);
        make_anisotropic(&p, 0.0);
        check_brdf(&p, sc_brdf_form_name(SC_BRDF_WARD, form));
    }
    for (int D = 0; D < 2; D++)
        for (int G = 0; G < 3; G++) {
            sc_brdf p = brdf_params(SC_BRDF_COOK_TORRANCE, (D + G) & 1);
            make_anisotropic(&p, 0.0);
            p.D = (sc_ndf)D;
            p.G = (sc_masking)G;
            char what[64];
            snprintf(what, sizeof what, "anisotropic D %d G %d", D, G);
            check_brdf(&p, what);
        }
}

/* ---- the shading kernel through plans of the standard scene (1 directional, 1 point and 3
 * spot lights) with other BRDFs ---- */

/* n inputs of the shade rows' domain, the standard scene with BRDF kind changed by change(b,
 * x), every shade row (tier, instruction set) against sc_shade in double. */
static void check_shade_scene(sc_brdf_kind kind, void (*change)(sc_brdf *, double), double x,
                              size_t n, const char *what)
{
    sc_light lights[SC_BATCH_MAX_LIGHTS];
    sc_scene scene;
    char why[256];
    sc_batch_example_scene(kind, 1, 1, 3, lights, &scene);
    change(&scene.model.brdf, x);
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why, sizeof why);
    if (!plan)
        fail_msg("%s: %s", what, why);
    check_rows_on("shade", plan, n, what);
    sc_batch_plan_free(plan);
}

/* The shading kernel with anisotropic Ward and Cook-Torrance (through the BRDF kernel's
 * models) on 10^6 inputs each. */
static void anisotropic_shading_within_bounds(void **state)
{
    (void)state;
    const size_t N_ANISO = sc_test_inputs(1000000);
    check_shade_scene(SC_BRDF_WARD, make_anisotropic, 0.0, N_ANISO, "anisotropic ward");
    check_shade_scene(SC_BRDF_COOK_TORRANCE, make_anisotropic, 0.0, N_ANISO,
                      "anisotropic cook-torrance");
}

/* ---- the tangent frame's seam ----
 *
 * Without a tangent, sc_frame_make builds t from e_x or from e_y, whichever its rule picks for
 * n; the kernels must pick the same axis for the same input (batch.h), or an anisotropic lobe
 * is evaluated in a frame turned by up to 90°. Along n(s) = (s, y, z), s growing, the double
 * frame switches from e_x to e_y once: the float s of the switch is found by bisection on
 * sc_frame_make itself (whatever its rule), and the kernels are checked on the SEAM_ULPS
 * floats either side of it, every tier and instruction set. */

enum { SEAM_ULPS = 48, SEAM_DIRS = 6 };

/* Whether sc_frame_make's tangent for n (as given, in double) comes from e_y: t lies in the
 * plane of n and its axis, so (t × n)·e_x vanishes for e_x and is n_z/|t| for e_y (n_z != 0). */
static int frame_from_e_y(const float n[3])
{
    double nd[3] = {n[0], n[1], n[2]};
    sc_frame f;
    assert_int_equal(sc_frame_make(nd, NULL, &f), 0);
    return fabs(f.t[1] * f.n[2] - f.t[2] * f.n[1]) > 1e-6;
}

/* The smallest positive float s with the frame of (s, y, z) from e_y (one switch in (0, 1e4]) */
static float seam_of(float y, float z)
{
    uint32_t lo, hi;
    float a = 1e-3f, b = 1e4f;
    assert_false(frame_from_e_y((float[3]){a, y, z}));
    assert_true(frame_from_e_y((float[3]){b, y, z}));
    memcpy(&lo, &a, sizeof lo), memcpy(&hi, &b, sizeof hi);
    while (hi - lo > 1) { /* positive floats are ordered as their bit patterns */
        uint32_t mid = lo + (hi - lo) / 2;
        float s;
        memcpy(&s, &mid, sizeof s);
        if (frame_from_e_y((float[3]){s, y, z}))
            hi = mid;
        else
            lo = mid;
    }
    memcpy(&b, &hi, sizeof b);
    return b;
}

/* The normal (±s, y, z) of element i: s the seam's float stepped by k ulps, k in ±SEAM_ULPS */
static void seam_normal(float y, float z, float sign, size_t i, float n[3])
{
    float s = seam_of(y, z);
    uint32_t bits;
    memcpy(&bits, &s, sizeof bits);
    bits += (uint32_t)((int)(i / SEAM_DIRS) - SEAM_ULPS);
    memcpy(&s, &bits, sizeof s);
    n[0] = sign * s, n[1] = y, n[2] = z;
}

/* in[first..first+2] at i: unit n plus offset d (|d| < 1, so above the horizon) */
static void store_above(batch_buffers *b, int first, size_t i, const float n[3], const double d[3])
{
    double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
    for (int c = 0; c < 3; c++)
        b->in[first + c][i] = (float)(n[c] / len + d[c]);
}

/* Seam inputs of `kernel` (brdf: l, v, n; shade: n, v, p) on two paths, n_y or n_z the larger,
 * and n_x of either sign, each n with SEAM_DIRS pairs of l and v. */
static void seam_buffers(batch_buffers *b, const sc_batch_entry *e, const void *params)
{
    static const float paths[2][3] = {{0.3f, 0.2f, 1.0f}, {-0.1f, 0.35f, -1.0f}};
    static const double offsets[SEAM_DIRS][3] = {{0.5, 0.3, -0.2}, {-0.4, 0.2, 0.5},
                                                 {0.1, -0.6, 0.3}, {-0.2, -0.3, -0.6},
                                                 {0.0, 0.7, 0.1},  {0.3, 0.0, -0.5}};
    size_t per_path = (2 * SEAM_ULPS + 1) * SEAM_DIRS;
    int shade = strcmp(e->kernel, "shade") == 0;
    batch_buffers_alloc(b, 2 * per_path, params);
    for (size_t i = 0; i < 2 * per_path; i++) {
        const float *path = paths[i / per_path];
        float n[3];
        seam_normal(path[0], path[1], path[2], i % per_path, n);
        const double *dl = offsets[i % SEAM_DIRS], *dv = offsets[(i + 1) % SEAM_DIRS];
        for (int c = 0; c < 3; c++)
            b->in[(shade ? 0 : 6) + c][i] = n[c];
        store_above(b, 3, i, n, dv);
        if (shade)
            for (int c = 0; c < 3; c++)
                b->in[6 + c][i] = 0.0f;
        else
            store_above(b, 0, i, n, dl);
    }
}

static void check_seam(const char *kernel, const void *params, const char *what)
{
    const sc_batch_entry *e = scalar_row(kernel);
    batch_buffers b;
    seam_buffers(&b, e, params);
    fill_references(e, &b);
    check_all_rows(kernel, &b, what);
    batch_buffers_release(&b);
}

/* Anisotropic Ward by the BRDF kernel and by the shading kernel (one directional light near
 * the normals) at the seam. */
static void anisotropic_frame_seam(void **state)
{
    (void)state;
    sc_brdf p = brdf_params(SC_BRDF_WARD, SC_WARD_1992);
    make_anisotropic(&p, 0.0);
    check_seam("brdf", &p, "anisotropic ward at the frame's seam");
    sc_light lights[SC_BATCH_MAX_LIGHTS];
    sc_scene scene;
    char why[256];
    sc_batch_example_scene(SC_BRDF_WARD, 1, 0, 0, lights, &scene);
    make_anisotropic(&scene.model.brdf, 0.0);
    static const double toward_normals[3] = {0.9, 0.2, 0.1};
    memcpy(lights[0].dir, toward_normals, sizeof toward_normals);
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why, sizeof why);
    if (!plan)
        fail_msg("%s", why);
    check_seam("shade", plan, "anisotropic ward shading at the frame's seam");
    sc_batch_plan_free(plan);
}

/* ---- the shading kernel's lobe exponents ---- */

/* The shading kernel raises n·h to an integer m by binary powering (up to 64 in the accurate
 * tier, 256 in the fast ones; the fast tiers raise (n·h)² to m/2 where m is even) and to other
 * m by its pow: tests/unit/test_batch.c checks m = 32 on 10^6 inputs; here the other paths, on
 * 10^6 inputs each, every tier and instruction set: m = 40.5 (pow everywhere), 128 (pow in the
 * accurate tier, powering in the fast ones; the largest m of the stated domain), 64 (the
 * largest of the accurate tier's powering), 33 (odd: n·h itself powered), 2 ((n·h)² alone). */
static void shade_lobe_exponents_within_bounds(void **state)
{
    (void)state;
    const size_t N_SHADE = sc_test_inputs(1000000);
    static const double exponents[] = {40.5, 128.0, 64.0, 33.0, 2.0};
    for (size_t k = 0; k < sizeof exponents / sizeof exponents[0]; k++) {
        char what[32];
        snprintf(what, sizeof what, "m = %g", exponents[k]);
        check_shade_scene(SC_BRDF_BLINN_PHONG, set_exponent, exponents[k], N_SHADE, what);
    }
}

/* A point lit mostly through a smoothstep spot 0.006 inside its 40° outer cone, where the spot
 * factor (about 3t², t = 0.043) carries a relative error of 2 δ/(cos θ_s − cos θ_u) from a
 * rounding δ of cos θ_s, under the peak of an m = 128 lobe: the standard scene's inputs at which
 * the accurate tier measured 1.16 times the bound while the allowance scaled with the spotted
 * E (src/batch/reference.c, unspotted_E). Every tier and instruction set, 16 copies of it. */
static void spot_outer_edge_within_bounds(void **state)
{
    (void)state;
    static const float at[9] = {0x1.964a1cp-5f,  0x1.127aa6p-2f, 0x1.7450c4p-4f,
                                -0x1.b67802p-5f, 0x1.9c9952p-4f, -0x1.563cdep-4f,
                                0x1.30b1a8p-3f,  0x1.767b88p+1f, -0x1.3336f4p+1f};
    enum { COPIES = 16 };
    sc_light lights[SC_BATCH_MAX_LIGHTS];
    sc_scene scene;
    char why[256];
    sc_batch_example_scene(SC_BRDF_BLINN_PHONG, 1, 1, 3, lights, &scene);
    scene.model.brdf.m = 128.0;
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why, sizeof why);
    assert_non_null(plan);
    float in[9][COPIES], out[3][COPIES];
    double ref[4];
    sc_batch_args a = {.n = COPIES, .params = plan};
    for (int j = 0; j < 9; j++) {
        for (int e = 0; e < COPIES; e++)
            in[j][e] = at[j];
        a.in[j] = in[j];
    }
    for (int j = 0; j < 3; j++)
        a.out[j] = out[j];
    const sc_batch_entry *e = sc_batch_plan_entry(plan);
    e->ref(&a, 0, ref);
    for (int r = 0; r < sc_batch_count; r++) {
        const sc_batch_entry *row = &sc_batch_table[r];
        if (strcmp(row->kernel, "shade") != 0 || !sc_isa_supported(row->isa))
            continue;
        row->fn(&a);
        sc_batch_error acc;
        sc_batch_error_init(&acc);
        for (size_t i = 0; i < COPIES; i++)
            sc_batch_error_against(row, &a, i, ref, &acc);
        if (acc.max_ratio > 1.0)
            fail_msg("shade %s %s: %.3g times the bound", row->tier, sc_isa_name(row->isa),
                     acc.max_ratio);
    }
    sc_batch_plan_free(plan);
}

/* ---- scene plans ---- */

enum { N_PLAN = 1001, PLAN_THREADS = 4 };

typedef struct {
    float *in[9], *out[3];
} plan_arrays;

/* Uniform in [-1, 1) from the test's generator. */
static double signed_unit(void)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return 2.0 * ((double)(rng >> 11) * 0x1p-53) - 1.0;
}

/* Random shading points: unit n, a viewer at distance 2..4 with n·v >= 0.2, p near the origin. */
static void plan_points(plan_arrays *a, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        double nv[3], vv[3], dot = 0.0;
        do {
            double len_n = 0.0, len_v = 0.0;
            for (int c = 0; c < 3; c++) {
                nv[c] = signed_unit();
                vv[c] = signed_unit();
                len_n += nv[c] * nv[c];
                len_v += vv[c] * vv[c];
            }
            dot = 0.0;
            for (int c = 0; c < 3; c++) {
                nv[c] /= sqrt(len_n);
                vv[c] /= sqrt(len_v);
                dot += nv[c] * vv[c];
            }
        } while (dot < 0.2);
        for (int c = 0; c < 3; c++) {
            a->in[c][i] = (float)nv[c];
            a->in[3 + c][i] = (float)(3.0 * vv[c]);
            a->in[6 + c][i] = (float)(0.5 * (signed_unit()));
        }
    }
}

static const char *const tiers[] = {"accurate", "bits12"};
enum { N_TIERS = sizeof tiers / sizeof tiers[0] };

static void plan_arrays_alloc(plan_arrays *a)
{
    for (int j = 0; j < 9; j++)
        assert_non_null(a->in[j] = malloc(N_PLAN * sizeof(float)));
    for (int j = 0; j < 3; j++)
        assert_non_null(a->out[j] = malloc(N_PLAN * sizeof(float)));
}

static void plan_arrays_free(plan_arrays *a)
{
    for (int j = 0; j < 9; j++)
        free(a->in[j]);
    for (int j = 0; j < 3; j++)
        free(a->out[j]);
}

/* L at point i of a by sc_shade in double, from the same float inputs. */
static void shade_double(const sc_scene *scene, const plan_arrays *a, size_t i, double L[3])
{
    sc_shade_point at;
    double n[3], v[3], len = 0.0;
    for (int c = 0; c < 3; c++) {
        n[c] = a->in[c][i];
        v[c] = a->in[3 + c][i];
        at.pos[c] = a->in[6 + c][i];
        len += v[c] * v[c];
    }
    for (int c = 0; c < 3; c++)
        at.v[c] = v[c] / sqrt(len);
    assert_int_equal(sc_frame_make(n, NULL, &at.frame), 0);
    sc_shade_result r = {.per_light = NULL};
    sc_shade(SC_DOUBLE, scene, &at, &r);
    memcpy(L, r.L, sizeof r.L);
}

static void make_plan_scene(const char *model, sc_light lights[4], sc_scene *scene)
{
    static const char *const specs[] = {
        "directional dir=-1,-1,2 E=0.7", "point pos=2,-3,3 I=20",
        "spot pos=0,-4,1 dir=0,1,0 I=30 spot=smoothstep inner=10 outer=40",
        "point pos=-3,1,2 I=4,8,12 atten=clq sc=1 sl=0.5 sq=0.25"};
    char err[256];
    for (int k = 0; k < 4; k++)
        if (sc_light_parse(specs[k], &lights[k], err, sizeof err) != 0)
            fail_msg("%s: %s", specs[k], err);
    *scene = (sc_scene){lights, 4, {0}, {0.05, 0.05, 0.05}};
    if (sc_model_parse(model, &scene->model, err, sizeof err) != 0)
        fail_msg("%s: %s", model, err);
}

/* The scale of the shading rows' absolute allowance at each point (sc_batch_ref_shade's out[3]:
 * from the lights' E before cos θ_i and the spot factor), for the scene of `plan` */
static void absolute_scales(const sc_batch_plan *plan, const plan_arrays *a, double *scale)
{
    sc_batch_args args = {.n = N_PLAN, .params = plan};
    for (int j = 0; j < 9; j++)
        args.in[j] = a->in[j];
    for (size_t i = 0; i < N_PLAN; i++) {
        double out[4];
        sc_batch_ref_shade(&args, i, out);
        scale[i] = out[3];
    }
}

/* A plan of each tier on each instruction set shades within the tier's bound of sc_shade in
 * double (relative, plus the same allowance times the largest channel, plus the absolute term
 * of the bound, which covers a cos θ_i that cancels at grazing; twice, for the float rounding
 * of the uniforms), for each BRDF model, lights with inverse-square and clq falloff. */
static void plans_match_sc_shade(void **state)
{
    (void)state;
    static const char *const models[] = {"lambert",
                                         "blinn-phong m=40 spec=0.4",
                                         "blinn-phong m=40.5 spec=0.4 form=plain",
                                         "cook-torrance alpha=0.3 f0=0.04",
                                         "phong m=20 spec=0.3",
                                         "ward ax=0.2 ay=0.5 spec=0.3",
                                         "oren-nayar sigma=30 form=full",
                                         "cook-torrance D=beckmann G=smith F=exact ax=0.3 ay=0.5"};
    enum { N_MODELS = sizeof models / sizeof models[0] };
    plan_arrays a;
    plan_arrays_alloc(&a);
    plan_points(&a, N_PLAN);
    for (int m = 0; m < N_MODELS; m++) {
        sc_light lights[4];
        sc_scene scene;
        make_plan_scene(models[m], lights, &scene);
        double(*ref)[3] = malloc(N_PLAN * sizeof *ref), *scale = malloc(N_PLAN * sizeof *scale);
        assert_non_null(ref);
        assert_non_null(scale);
        for (size_t i = 0; i < N_PLAN; i++)
            shade_double(&scene, &a, i, ref[i]);
        char why[256] = "";
        sc_batch_plan *any = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why,
                                                   sizeof why);
        if (!any)
            fail_msg("%s: %s", models[m], why);
        absolute_scales(any, &a, scale);
        sc_batch_plan_free(any);
        for (int isa = 0; isa < SC_ISA_COUNT; isa++)
            for (int t = 0; t < N_TIERS && sc_isa_supported((sc_isa)isa); t++) {
                sc_batch_plan *plan = sc_batch_plan_compile(&scene, tiers[t], (sc_isa)isa, why,
                                                            sizeof why);
                if (!plan)
                    fail_msg("%s %s: %s", models[m], tiers[t], why);
                const sc_batch_entry *e = sc_batch_plan_entry(plan);
                assert_int_equal(e->isa, isa);
                assert_string_equal(e->tier, tiers[t]);
                sc_batch_plan_shade(plan, (const float *const *)a.in, a.out, N_PLAN);
                for (size_t i = 0; i < N_PLAN; i++) {
                    double peak = fmax(ref[i][0], fmax(ref[i][1], ref[i][2]));
                    for (int c = 0; c < 3; c++) {
                        double err = fabs(a.out[c][i] - ref[i][c]);
                        if (err > 2.0 * e->bound_rel * (fabs(ref[i][c]) + peak) + 1e-6 * peak +
                                      2.0 * e->bound_abs * scale[i])
                            fail_msg("%s %s %s point %zu channel %d: %.9g, sc_shade %.9g",
                                     models[m], tiers[t], sc_isa_name(e->isa), i, c,
                                     (double)a.out[c][i], ref[i][c]);
                    }
                }
                sc_batch_plan_free(plan);
            }
        free(ref);
        free(scale);
    }
    plan_arrays_free(&a);
}

/* A plan of scene for tier and isa, through which a's inputs are shaded into a's outputs; the
 * caller frees it. */
static sc_batch_plan *shade_through_plan(const sc_scene *scene, const char *tier, sc_isa isa,
                                         plan_arrays *a)
{
    char why[256] = "";
    sc_batch_plan *plan = sc_batch_plan_compile(scene, tier, isa, why, sizeof why);
    if (!plan)
        fail_msg("%s %s: %s", tier, sc_isa_name(isa), why);
    sc_batch_plan_shade(plan, (const float *const *)a->in, a->out, N_PLAN);
    return plan;
}

/* a's inputs shaded through a plan of scene in every tier and instruction set: every output
 * finite (what: the scene, for the message) */
static void assert_plans_finite(const sc_scene *scene, plan_arrays *a, const char *what)
{
    for (int isa = 0; isa < SC_ISA_COUNT; isa++)
        for (int t = 0; t < N_TIERS && sc_isa_supported((sc_isa)isa); t++) {
            sc_batch_plan *plan = shade_through_plan(scene, tiers[t], (sc_isa)isa, a);
            for (size_t i = 0; i < N_PLAN; i++)
                for (int c = 0; c < 3; c++)
                    if (!isfinite(a->out[c][i]))
                        fail_msg("%s %s %s point %zu (n %g,%g,%g v %g,%g,%g): %g", what, tiers[t],
                                 sc_isa_name((sc_isa)isa), i, (double)a->in[0][i],
                                 (double)a->in[1][i], (double)a->in[2][i], (double)a->in[3][i],
                                 (double)a->in[4][i], (double)a->in[5][i], (double)a->out[c][i]);
            sc_batch_plan_free(plan);
        }
}

/* Normals within 3·10^-8 of a directional light's terminator (n·l of either sign), Beckmann
 * with Smith masking in every tier and instruction set: the fast tiers decide "lit" from n·l
 * of the loaded vectors, and their Λ once saw n·l <= 0 in such a lit lane and gave NaN
 * (src/simd/light_impl.h, beckmann_lambda). Every output finite. */
static void plans_at_the_terminator_are_finite(void **state)
{
    (void)state;
    static const char *const models[] = {"cook-torrance D=beckmann G=smith alpha=0.3",
                                         "cook-torrance D=beckmann G=smith-correlated alpha=0.3"};
    sc_light light;
    char err[256];
    assert_int_equal(sc_light_parse("directional dir=0,0.6,0.8 E=1", &light, err, sizeof err), 0);
    plan_arrays a;
    plan_arrays_alloc(&a);
    static const double l[3] = {0.0, 0.6, 0.8};
    for (size_t i = 0; i < N_PLAN; i++) {
        /* n: a random direction ⊥ l tilted by up to ±3·10^-8 rad; v: n plus noise */
        double r[3] = {signed_unit(), signed_unit(), signed_unit()}, rl = 0.0, len = 0.0;
        for (int c = 0; c < 3; c++)
            rl += r[c] * l[c];
        for (int c = 0; c < 3; c++)
            r[c] -= rl * l[c], len += r[c] * r[c];
        double t = 3e-8 * signed_unit();
        for (int c = 0; c < 3; c++) {
            double n = r[c] / sqrt(len) * cos(t) + l[c] * sin(t);
            a.in[c][i] = (float)n;
            a.in[3 + c][i] = (float)(n + 0.3 * signed_unit());
            a.in[6 + c][i] = 0.0f;
        }
    }
    for (size_t m = 0; m < sizeof models / sizeof models[0]; m++) {
        sc_scene scene = {&light, 1, {0}, {0.05, 0.05, 0.05}};
        assert_int_equal(sc_model_parse(models[m], &scene.model, err, sizeof err), 0);
        assert_plans_finite(&scene, &a, models[m]);
    }
    plan_arrays_free(&a);
}

/* GGX lit at grazing from both sides: n·l and n·v between 2^-123 and 2^-100, a bright light
 * (E = 10^5). V = 1/(2 (g_v + g_l)) grows as 1/(n·l + n·v), up to about 10^37 here, and the
 * specular term E ⊙ c_spec f_s alone exceeds FLT_MAX: the kernel forms w f_s = n·l f_s first
 * (src/simd/scene_impl.h, light_term), where n·l/(g_v + g_l) <= 1/α. Every output finite, in
 * every tier and instruction set. */
static void ggx_grazing_from_both_sides_is_finite(void **state)
{
    (void)state;
    sc_light light;
    char err[256];
    assert_int_equal(sc_light_parse("directional dir=1,0,1e-37 E=1e5", &light, err, sizeof err), 0);
    plan_arrays a;
    plan_arrays_alloc(&a);
    for (size_t i = 0; i < N_PLAN; i++) {
        double phi = 1.5 * (double)i / N_PLAN; /* v·l >= 0: |l + v|² >= 2 */
        float grazing = ldexpf(1.0f, -123 + (int)(i % 24));
        float n[3] = {0.0f, 0.0f, 1.0f}, v[3] = {(float)cos(phi), (float)sin(phi), grazing};
        for (int c = 0; c < 3; c++) {
            a.in[c][i] = n[c];
            a.in[3 + c][i] = v[c];
            a.in[6 + c][i] = 0.0f;
        }
    }
    sc_scene scene = {&light, 1, {0}, {0.05, 0.05, 0.05}};
    assert_int_equal(
        sc_model_parse("cook-torrance alpha=0.3 f0=0.04", &scene.model, err, sizeof err), 0);
    assert_plans_finite(&scene, &a, "ggx");
    plan_arrays_free(&a);
}

/* Points at the extremes of a point or spot light's distance, every tier on every instruction
 * set against sc_shade in double: at the light (r = 0: l = n), inside the clamp of 1/r² (r² <
 * 10^-4), r² next to FLT_MAX, and r² overflowing binary32 (the fast tiers' 1/r² from 1/|d|:
 * src/simd/scene_impl.h, unit_and_inverse_square), where the light adds about 10^-39. The
 * spots' cones (the three kinds) hold every point, so that their factor is not 0. */
static void plans_at_point_light_extremes(void **state)
{
    (void)state;
    /* p − the light's position; each lit (n = +z) */
    static const float offsets[][3] = {
        {0, 0, 0},      {0.003f, 0, -0.004f}, {-1e19f, -1e19f, -1e19f},
        {0, 0, -1e20f}, {0, -3e19f, -3e19f},  {-1, -1, -1}};
    enum { N_OFFSETS = sizeof offsets / sizeof offsets[0] };
    static const char *const models[] = {"lambert", "blinn-phong m=32 spec=0.4",
                                         "cook-torrance alpha=0.3 f0=0.04"};
    static const char *const lights[] = {
        "point pos=2,-3,3 I=20", "spot pos=2,-3,3 dir=0,0,-1 I=20 cutoff=60 exp=3",
        "spot pos=2,-3,3 dir=0,0,-1 I=20 spot=directx inner=30 outer=70",
        "spot pos=2,-3,3 dir=0,0,-1 I=20 spot=smoothstep inner=30 outer=70"};
    sc_light light;
    char err[256];
    plan_arrays a;
    plan_arrays_alloc(&a);
    for (size_t i = 0; i < N_PLAN; i++) /* n toward the light, v beside it */
        for (int c = 0; c < 3; c++) {
            static const double light_pos[3] = {2, -3, 3};
            a.in[c][i] = (float)(c == 2 ? 1.0 : 0.0);
            a.in[3 + c][i] = (float)(c == 0 ? 0.5 : c == 1 ? 0.25 : 1.0);
            a.in[6 + c][i] = (float)light_pos[c] + offsets[i % N_OFFSETS][c];
        }
    for (int k = 0; k < (int)(sizeof lights / sizeof lights[0]); k++)
        for (int m = 0; m < (int)(sizeof models / sizeof models[0]); m++) {
            assert_int_equal(sc_light_parse(lights[k], &light, err, sizeof err), 0);
            sc_scene scene = {&light, 1, {0}, {0.05, 0.05, 0.05}};
            assert_int_equal(sc_model_parse(models[m], &scene.model, err, sizeof err), 0);
            for (int isa = 0; isa < SC_ISA_COUNT; isa++)
                for (int t = 0; t < N_TIERS && sc_isa_supported((sc_isa)isa); t++) {
                    sc_batch_plan *plan = shade_through_plan(&scene, tiers[t], (sc_isa)isa, &a);
                    double bound = sc_batch_plan_entry(plan)->bound_rel;
                    for (size_t i = 0; i < N_OFFSETS; i++) {
                        double ref[3];
                        shade_double(&scene, &a, i, ref);
                        for (int c = 0; c < 3; c++)
                            if (!(fabs(a.out[c][i] - ref[c]) <= 2.0 * bound * fabs(ref[c]) + 1e-30))
                                fail_msg("%s, %s %s %s offset %zu channel %d: %.9g, sc_shade %.9g",
                                         lights[k], models[m], tiers[t], sc_isa_name((sc_isa)isa),
                                         i, c, (double)a.out[c][i], ref[c]);
                    }
                    sc_batch_plan_free(plan);
                }
        }
    plan_arrays_free(&a);
}

/* ---- the shading kernel at the mirror direction, at grazing ---- */

/* Inputs of the shade rows with v the mirror of l (the scene's one directional light) about n
 * and n·l = n·v in [2^-6, 2^-3]: h = l + v is short (2 n·v) and the lobe at its peak, where
 * n·h computed as n·l + n·v put the accurate tier at 8.8 times its bound (src/simd/
 * scene_impl.h, n_dot_h). */
static void mirror_buffers(batch_buffers *b, const double l[3], size_t n, const void *plan)
{
    batch_buffers_alloc(b, n, plan);
    double len = hypot(l[0], l[1]), t0[3] = {-l[1] / len, l[0] / len, 0.0};
    double t1[3] = {-l[2] * t0[1], l[2] * t0[0], l[0] * t0[1] - l[1] * t0[0]}; /* l × t0 */
    for (size_t i = 0; i < n; i++) {
        double c = exp2(-6.0 + 3.0 * (signed_unit() + 1.0) / 2.0), s = sqrt(1.0 - c * c);
        double phi = pi * signed_unit(), nrm[3], v[3];
        for (int k = 0; k < 3; k++) {
            nrm[k] = c * l[k] + s * (cos(phi) * t0[k] + sin(phi) * t1[k]);
            v[k] = 2.0 * c * nrm[k] - l[k];
        }
        for (int k = 0; k < 3; k++) {
            b->in[k][i] = (float)nrm[k];
            b->in[3 + k][i] = (float)v[k];
            b->in[6 + k][i] = (float)signed_unit();
        }
    }
}

static void ggx_lobe(sc_brdf *b, double alpha)
{
    b->form = SC_CT_WALTER;
    b->D = SC_D_GGX;
    b->G = SC_G_SMITH_CORRELATED;
    b->F = SC_F_SCHLICK;
    b->ax = b->ay = alpha;
    for (int c = 0; c < 3; c++)
        b->f0[c] = 0.04;
}

/* Every shade row (tier, instruction set) at the grazing mirror, GGX at α 0.3 and 0.2 (the
 * least of the stated domain: at α 0.1 the lobe's slope times the ~2^-19 error of h's
 * direction is 2.5 times the accurate bound) and Blinn-Phong at m 32 and 128, against sc_shade
 * in double. */
static void shade_grazing_mirror_within_bounds(void **state)
{
    (void)state;
    static const struct {
        sc_brdf_kind kind;
        void (*change)(sc_brdf *, double);
        double x;
        const char *what;
    } lobes[] = {{SC_BRDF_COOK_TORRANCE, ggx_lobe, 0.3, "ggx 0.3"},
                 {SC_BRDF_COOK_TORRANCE, ggx_lobe, 0.2, "ggx 0.2"},
                 {SC_BRDF_BLINN_PHONG, set_exponent, 32.0, "blinn-phong 32"},
                 {SC_BRDF_BLINN_PHONG, set_exponent, 128.0, "blinn-phong 128"}};
    for (size_t k = 0; k < sizeof lobes / sizeof lobes[0]; k++) {
        sc_light lights[SC_BATCH_MAX_LIGHTS];
        sc_scene scene;
        char why[256];
        sc_batch_example_scene(lobes[k].kind, 1, 0, 0, lights, &scene);
        lobes[k].change(&scene.model.brdf, lobes[k].x);
        sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why,
                                                    sizeof why);
        if (!plan)
            fail_msg("%s: %s", lobes[k].what, why);
        batch_buffers b;
        mirror_buffers(&b, lights[0].dir, sc_test_inputs(100003), plan);
        fill_references(scalar_row("shade"), &b);
        check_all_rows("shade", &b, lobes[k].what);
        batch_buffers_release(&b);
        sc_batch_plan_free(plan);
    }
}

/* ---- the straight-line variants ---- */

/* A plan of k lights of one shape (1..4 directional, point or spot, these two with
 * inverse-square falloff; the spots of the three kinds in turn) runs straight-line code; the
 * same lights plus one of another kind with intensity 0 run the generic loop, whose extra term
 * adds exactly 0: both give the same bits, every tier and instruction set, for each of the
 * kernel's own lobes (the generic loop is the one tests/unit/test_batch.c bounds on 10^6
 * inputs). */
static void fixed_variants_match_the_loop(void **state)
{
    (void)state;
    static const sc_brdf_kind kinds[] = {SC_BRDF_LAMBERT, SC_BRDF_BLINN_PHONG,
                                         SC_BRDF_COOK_TORRANCE};
    plan_arrays a, loop;
    plan_arrays_alloc(&a);
    for (int j = 0; j < 3; j++)
        assert_non_null(loop.out[j] = malloc(N_PLAN * sizeof(float)));
    plan_points(&a, N_PLAN);
    static const char *const shape_names[] = {"directional", "point", "spot"};
    for (int shape = 0; shape < 3; shape++)
        for (int count = 1; count <= 4; count++)
            for (size_t b = 0; b < sizeof kinds / sizeof kinds[0]; b++) {
                sc_light lights[SC_BATCH_MAX_LIGHTS];
                sc_scene fixed, generic;
                sc_batch_example_scene(kinds[b], shape == 0 ? count + 1 : 0,
                                       shape == 1 ? count + 1 : 0, shape == 2 ? count + 1 : 0,
                                       lights, &generic);
                sc_light *extra = &lights[count];
                sc_light_init(extra, shape ? SC_LIGHT_DIRECTIONAL : SC_LIGHT_POINT);
                extra->pos[2] = 1.0;
                extra->intensity[0] = extra->intensity[1] = extra->intensity[2] = 0.0;
                extra->ambient[0] = extra->ambient[1] = extra->ambient[2] = 0.0;
                fixed = generic;
                fixed.n_lights = count;
                for (int isa = 0; isa < SC_ISA_COUNT; isa++)
                    for (int t = 0; t < N_TIERS && sc_isa_supported((sc_isa)isa); t++) {
                        char why[256];
                        sc_batch_plan *pf = sc_batch_plan_compile(&fixed, tiers[t], (sc_isa)isa,
                                                                  why, sizeof why);
                        sc_batch_plan *pg = sc_batch_plan_compile(&generic, tiers[t], (sc_isa)isa,
                                                                  why, sizeof why);
                        assert_non_null(pf);
                        assert_non_null(pg);
                        assert_int_equal(sc_batch_plan_uniforms(pf)->variant,
                                         1 + SC_SHADE_FIXED_MAX * shape + count - 1);
                        assert_int_equal(sc_batch_plan_uniforms(pg)->variant, 0);
                        sc_batch_plan_shade(pf, (const float *const *)a.in, a.out, N_PLAN);
                        sc_batch_plan_shade(pg, (const float *const *)a.in, loop.out, N_PLAN);
                        for (int j = 0; j < 3; j++)
                            if (memcmp(a.out[j], loop.out[j], N_PLAN * sizeof(float)) != 0)
                                fail_msg("%d %s lights, %s, %s %s: the variant's bits differ",
                                         count, shape_names[shape], sc_brdf_kind_name(kinds[b]),
                                         tiers[t], sc_isa_name((sc_isa)isa));
                        sc_batch_plan_free(pf);
                        sc_batch_plan_free(pg);
                    }
            }
    plan_arrays_free(&a);
    for (int j = 0; j < 3; j++)
        free(loop.out[j]);
}

/* The reason a plan is refused names the model, the light or its kind. */
static void plans_refuse_with_reasons(void **state)
{
    (void)state;
    sc_light lights[4];
    sc_scene scene;
    char why[256];
    make_plan_scene("ads", lights, &scene);
    assert_null(sc_batch_plan_compile(&scene, "bits12", SC_ISA_SCALAR, why, sizeof why));
    assert_non_null(strstr(why, "model ads"));
    make_plan_scene("lambert", lights, &scene);
    lights[1].range = 10.0;
    assert_null(sc_batch_plan_compile(&scene, "bits12", SC_ISA_SCALAR, why, sizeof why));
    assert_string_equal(why, "light 2: range=10 (direct3d9) is not covered by the batch kernels");
    lights[1].range = INFINITY;
    lights[2].kind = (sc_light_kind)7; /* a kind added to light.h after the kernels */
    assert_null(sc_batch_plan_compile(&scene, "bits12", SC_ISA_SCALAR, why, sizeof why));
    assert_string_equal(why, "light 3: light kind 7 not covered by the batch kernels");
    lights[2].kind = SC_LIGHT_POINT;
    scene.n_lights = SC_BATCH_MAX_LIGHTS + 1;
    assert_null(sc_batch_plan_compile(&scene, "bits12", SC_ISA_SCALAR, why, sizeof why));
    assert_string_equal(why, "65 lights: the batch kernels take at most 64");
    scene.n_lights = 4;
    assert_null(sc_batch_plan_compile(&scene, "u1", SC_ISA_SCALAR, why, sizeof why));
    assert_non_null(strstr(why, "tier u1"));
    /* the shading kernel's bits8 was removed (src/simd/shade_impl.h), though exp2, exp, log2,
     * log and pow keep theirs */
    assert_null(sc_batch_plan_compile(&scene, "bits8", SC_ISA_SCALAR, why, sizeof why));
    assert_string_equal(why, "tier bits8: the shading kernel's tiers are accurate, bits12");
    assert_non_null(sc_batch_find("pow", "bits8", SC_ISA_SCALAR));
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "bits12", SC_ISA_SCALAR, why, sizeof why);
    assert_non_null(plan);
    sc_batch_plan_free(plan);
}

typedef struct {
    const sc_batch_plan *plan;
    const plan_arrays *a;
    float *out[3];
    size_t from, n;
} plan_slice;

static void *shade_slice(void *arg)
{
    plan_slice *s = arg;
    const float *in[9];
    float *out[3];
    for (int j = 0; j < 9; j++)
        in[j] = s->a->in[j] + s->from;
    for (int j = 0; j < 3; j++)
        out[j] = s->out[j] + s->from;
    sc_batch_plan_shade(s->plan, in, out, s->n);
    return NULL;
}

/* One plan shared by threads shading slices gives the bits of one thread shading all. */
static void one_plan_many_threads(void **state)
{
    (void)state;
    sc_light lights[4];
    sc_scene scene;
    make_plan_scene("cook-torrance alpha=0.3 f0=0.04", lights, &scene);
    char why[256];
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "bits12", sc_isa_active(), why, sizeof why);
    assert_non_null(plan);
    plan_arrays a;
    float *shared[3];
    for (int j = 0; j < 9; j++)
        assert_non_null(a.in[j] = malloc(N_PLAN * sizeof(float)));
    for (int j = 0; j < 3; j++) {
        assert_non_null(a.out[j] = malloc(N_PLAN * sizeof(float)));
        assert_non_null(shared[j] = malloc(N_PLAN * sizeof(float)));
    }
    plan_points(&a, N_PLAN);
    sc_batch_plan_shade(plan, (const float *const *)a.in, a.out, N_PLAN);
    pthread_t threads[PLAN_THREADS];
    plan_slice slices[PLAN_THREADS];
    size_t per = N_PLAN / PLAN_THREADS + 1;
    for (int t = 0; t < PLAN_THREADS; t++) {
        size_t from = (size_t)t * per, to = from + per < N_PLAN ? from + per : N_PLAN;
        slices[t] = (plan_slice){plan, &a, {shared[0], shared[1], shared[2]}, from, to - from};
        assert_int_equal(pthread_create(&threads[t], NULL, shade_slice, &slices[t]), 0);
    }
    for (int t = 0; t < PLAN_THREADS; t++)
        assert_int_equal(pthread_join(threads[t], NULL), 0);
    for (int j = 0; j < 3; j++)
        assert_memory_equal(a.out[j], shared[j], N_PLAN * sizeof(float));
    sc_batch_plan_free(plan);
    for (int j = 0; j < 9; j++)
        free(a.in[j]);
    for (int j = 0; j < 3; j++) {
        free(a.out[j]);
        free(shared[j]);
    }
}

int main(void)
{
    rng = sc_test_seeded(rng);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(brdf_normal_incidence_by_hand),
        cmocka_unit_test(every_brdf_form_within_bounds),
        cmocka_unit_test(every_cook_torrance_within_bounds),
        cmocka_unit_test(brdf_parameter_extremes_within_bounds),
        cmocka_unit_test(attenuation_by_hand),
        cmocka_unit_test(attenuation_edges),
        cmocka_unit_test(window_widths_far_from_one),
        cmocka_unit_test(pixar_integer_exponents_round_once),
        cmocka_unit_test(spot_by_hand),
        cmocka_unit_test(spot_edges),
        cmocka_unit_test(anisotropic_brdfs_within_bounds),
        cmocka_unit_test(anisotropic_forms_within_bounds),
        cmocka_unit_test(anisotropic_shading_within_bounds),
        cmocka_unit_test(anisotropic_frame_seam),
        cmocka_unit_test(shade_lobe_exponents_within_bounds),
        cmocka_unit_test(shade_grazing_mirror_within_bounds),
        cmocka_unit_test(spot_outer_edge_within_bounds),
        cmocka_unit_test(plans_match_sc_shade),
        cmocka_unit_test(plans_refuse_with_reasons),
        cmocka_unit_test(fixed_variants_match_the_loop),
        cmocka_unit_test(one_plan_many_threads),
        cmocka_unit_test(spot_integer_exponents),
        cmocka_unit_test(plans_at_point_light_extremes),
        cmocka_unit_test(plans_at_the_terminator_are_finite),
        cmocka_unit_test(ggx_grazing_from_both_sides_is_finite),
    };
    return cmocka_run_group_tests_name("batch_light", tests, NULL, NULL);
}
