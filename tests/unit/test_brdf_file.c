/* BRDF Explorer .brdf files (shadecalc/brdf_file.h): every built-in model exported and read back
 * gives the built-in f to rounding; the parser's errors name the line; parameters keep to their
 * types and ranges; a shader's run-time error is kept and gives NaN. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/brdf_file.h"

/* ---- export: every model, form, D, G and F against its file ---- */

static const double thetas[] = {0, 20, 45, 70, 85, 89.9, 89.999};
static const double phis[] = {0, 60, 135, 180, 290};
enum { N_THETA = sizeof thetas / sizeof thetas[0], N_PHI = sizeof phis / sizeof phis[0] };

/* x rounded to binary32 (volatile: gcc 12 -O2 vectorizes two such casts into one mulpd and
 * drops the conversion). */
static double binary32(double x)
{
    volatile float f = (float)x;
    return f;
}

/* A direction in binary32: the file's inputs are rounded to highp as a GPU's would be, while
 * the C model takes the double directions; rounded first, both see the same ones. */
static void direction(double theta_deg, double phi_deg, double out[3])
{
    double t = theta_deg * (3.14159265358979323846 / 180.0);
    double p = phi_deg * (3.14159265358979323846 / 180.0);
    out[0] = binary32(sin(t) * cos(p));
    out[1] = binary32(sin(t) * sin(p));
    out[2] = binary32(cos(t));
}

static sc_brdf_file *exported(const sc_brdf *b)
{
    char *text = NULL, err[512];
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    assert_non_null(mem);
    assert_int_equal(sc_brdf_export(mem, b), 0);
    fclose(mem);
    sc_brdf_file *f = sc_brdf_file_parse(text, "exported", err, sizeof err);
    if (!f)
        fail_msg("the export of %s does not compile: %s\n%s", sc_brdf_kind_name(b->kind), err,
                 text);
    free(text);
    return f;
}

/* The largest relative difference between b and its export over the (l, v) grid, in p. */
static double worst_difference(const sc_brdf *b, sc_prec p)
{
    sc_brdf_file *f = exported(b);
    sc_brdf fb;
    sc_brdf_file_defaults(f, &fb);
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
    sc_frame frame;
    assert_int_equal(sc_frame_make(n, t, &frame), 0);
    double worst = 0.0;
    for (int i = 0; i < N_THETA * N_PHI; i++)
        for (int o = 0; o < N_THETA * N_PHI; o++) {
            double l[3], v[3];
            direction(thetas[i / N_PHI], phis[i % N_PHI], l);
            direction(thetas[o / N_PHI], phis[o % N_PHI], v);
            sc_brdf_terms want, got;
            sc_brdf_eval(p, b, &frame, l, v, &want);
            sc_brdf_eval(p, &fb, &frame, l, v, &got);
            for (int c = 0; c < 3; c++) {
                double a = want.f[c], g = got.f[c];
                if (isnan(a) || isnan(g) || isinf(a) || isinf(g) || a < 0.0) {
                    if (!(a == g || (isnan(a) && isnan(g))))
                        fail_msg("%s form %d: f %.17g, file %.17g", sc_brdf_kind_name(b->kind),
                                 b->form, a, g);
                    continue;
                }
                double d = fabs(a - g) / (fabs(a) > 1e-300 ? fabs(a) : 1e-300);
                worst = d > worst ? d : worst;
            }
        }
    assert_null(sc_brdf_file_error(f));
    sc_brdf_file_free(f);
    return worst;
}

static void set_values(sc_brdf *b)
{
    const double diff[3] = {0.6, 0.3, 0.1}, spec[3] = {0.4, 0.5, 0.6}, f0[3] = {0.04, 0.5, 0.9};
    memcpy(b->diff, diff, sizeof diff);
    memcpy(b->spec, spec, sizeof spec);
    memcpy(b->f0, f0, sizeof f0);
    b->m = 20.0;
    b->ax = b->ay = 0.25;
    b->sigma = 0.5;
    b->ior = 1.45;
}

/* The configurations: every form of every model, and every D, G, F of Cook-Torrance, each also
 * anisotropic where the model has a roughness. */
static int configurations(sc_brdf *out)
{
    int n = 0;
    for (int k = SC_BRDF_LAMBERT; k <= SC_BRDF_COOK_TORRANCE; k++)
        for (int form = 0; sc_brdf_form_name((sc_brdf_kind)k, form); form++)
            for (int d = 0; d < 2; d++)
                for (int g = 0; g < 3; g++)
                    for (int fr = 0; fr < 3; fr++)
                        for (int aniso = 0; aniso < 2; aniso++) {
                            int ct = k == SC_BRDF_COOK_TORRANCE;
                            int rough = ct || k == SC_BRDF_WARD;
                            if ((!ct && (d || g || fr)) || (!rough && aniso))
                                continue;
                            sc_brdf *b = &out[n++];
                            sc_brdf_init(b, (sc_brdf_kind)k);
                            set_values(b);
                            b->form = form;
                            b->D = (sc_ndf)d;
                            b->G = (sc_masking)g;
                            b->F = (sc_fresnel)fr;
                            if (aniso)
                                b->ay = 0.6;
                        }
    return n;
}

/* With the same binary32 directions, double is bit for bit but for Beckmann's Smith G, whose
 * erf is libm's in C and a series in the file (measured: 1.3e-15): 1e-14. In highp the file's
 * constants are rounded before they meet a variable (Q(Q(π)·α), Q(s² + Q(0.33))) where the C
 * code rounds once (Q(π·α)): an ulp of 2^-24 here and there, measured at most 4.3e-7 (7 ulps)
 * but 2e-6 in Oren-Nayar's full model, whose tan β near 90° amplifies it: 1e-5. A wrong
 * operation (a missing factor, a swapped form) is off by far more than either. */
static void export_agrees_with_every_model(void **state)
{
    (void)state;
    static sc_brdf configs[128];
    int n = configurations(configs);
    assert_true(n >= 50);
    for (int i = 0; i < n; i++) {
        double dd = worst_difference(&configs[i], SC_DOUBLE);
        double dh = worst_difference(&configs[i], SC_HIGHP);
        if (dd > 1e-14 || dh > 1e-5)
            fail_msg("%s form %d D %d G %d F %d ay %g: worst relative difference %.3g "
                     "(double), %.3g (highp)",
                     sc_brdf_kind_name(configs[i].kind), configs[i].form, configs[i].D,
                     configs[i].G, configs[i].F, configs[i].ay, dd, dh);
    }
}

/* ---- the parser ---- */

static void assert_parse_error(const char *text, const char *want)
{
    char err[512];
    sc_brdf_file *f = sc_brdf_file_parse(text, "t.brdf", err, sizeof err);
    if (f) {
        sc_brdf_file_free(f);
        fail_msg("parsed; expected '%s'", want);
    }
    if (!strstr(err, want))
        fail_msg("got '%s', want '...%s...'", err, want);
}

static const char shader[] = "::begin shader\n"
                             "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return c * a; }\n"
                             "::end shader\n";

static void parser_errors_name_the_line(void **state)
{
    (void)state;
    assert_parse_error("", "t.brdf:1: the first line must be 'analytic'");
    assert_parse_error("analytic\n::begin parameters\nfloat a 0 1 0.5 7\n", "t.brdf:3: expected");
    assert_parse_error("analytic\n\n::begin parameters\nfloat a 0 1 inf\n", "t.brdf:4: float a");
    assert_parse_error("analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, "
                       "vec3 Y) { return 1 +; }\n::end shader\n",
                       "t.brdf:3:");
    assert_parse_error("analytic\n::begin parameters\nfloat L 0 1 0\n::end parameters\n", "L");
}

static sc_brdf_file *parse_ok(const char *params)
{
    char text[1024], err[512];
    snprintf(text, sizeof text, "analytic\n::begin parameters\n%s::end parameters\n%s", params,
             shader);
    sc_brdf_file *f = sc_brdf_file_parse(text, "t.brdf", err, sizeof err);
    if (!f)
        fail_msg("%s", err);
    return f;
}

static void parameters_keep_their_types_and_ranges(void **state)
{
    (void)state;
    sc_brdf_file *f = parse_ok("float a 0.5 2 1\ncolor c 0.1 0.2 0.3\nbool on 1\n");
    const sc_brdf_param *params;
    assert_int_equal(sc_brdf_file_params(f, &params), 3);
    assert_true(params[0].type == SC_BRDF_PARAM_FLOAT && params[0].min == 0.5 &&
                params[0].max == 2 && params[0].def[0] == 1 && params[0].line == 3);
    assert_true(params[1].type == SC_BRDF_PARAM_COLOR && params[1].offset == 1);
    assert_true(params[2].type == SC_BRDF_PARAM_BOOL && params[2].def[0] == 1);
    sc_brdf b;
    sc_brdf_file_defaults(f, &b);
    char err[256];
    assert_int_equal(sc_brdf_file_set(&b, "a", "2", err, sizeof err), 0);
    assert_int_equal(sc_brdf_file_set(&b, "c", "1,2,4", err, sizeof err), 0);
    assert_int_equal(sc_brdf_file_set(&b, "on", "false", err, sizeof err), 0);
    assert_true(b.file_values[0] == 2 && b.file_values[3] == 4 && b.file_values[4] == 0);
    assert_int_equal(sc_brdf_file_set(&b, "a", "2.5", err, sizeof err), -1);
    assert_non_null(strstr(err, "outside the file's range 0.5..2"));
    assert_int_equal(sc_brdf_file_set(&b, "a", "0x", err, sizeof err), -1);
    assert_int_equal(sc_brdf_file_set(&b, "cc", "1", err, sizeof err), -1);
    assert_non_null(strstr(err, "did you mean 'c'?"));
    /* f = c * a at (l, v) above the horizon */
    const double n[3] = {0, 0, 1};
    sc_frame frame;
    sc_frame_make(n, NULL, &frame);
    sc_brdf_terms t;
    sc_brdf_eval(SC_DOUBLE, &b, &frame, n, n, &t);
    assert_true(t.f[0] == 2.0 && t.f[1] == 4.0 && t.f[2] == 8.0);
    sc_brdf_file_free(f);
}

/* A runaway loop: NaN, the error kept, and every later evaluation NaN at once. */
static void runtime_errors_are_kept(void **state)
{
    (void)state;
    char err[512];
    sc_brdf_file *f = sc_brdf_file_parse(
        "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
        "{ float s = 0.0; for (int i = 0; i >= 0; i++) s += 1.0; return vec3(s); }\n"
        "::end shader\n",
        "loop.brdf", err, sizeof err);
    assert_non_null(f);
    sc_brdf b;
    sc_brdf_file_defaults(f, &b);
    const double n[3] = {0, 0, 1};
    sc_frame frame;
    sc_frame_make(n, NULL, &frame);
    double out[3];
    assert_null(sc_brdf_file_error(f));
    sc_brdf_file_eval(SC_HIGHP, &b, &frame, n, n, out);
    assert_true(isnan(out[0]) && isnan(out[2]));
    assert_non_null(strstr(sc_brdf_file_error(f), "loop.brdf:4:"));
    sc_brdf_file_eval(SC_HIGHP, &b, &frame, n, n, out);
    assert_true(isnan(out[1]));
    sc_brdf_file_free(f);
}

/* ---- many points at once: the same bits as one at a time ---- */

static uint64_t rng = 0x2545F4914F6CDD1Du;

static double uniform01(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* A random unit vector over the whole sphere (a quarter of the pairs above the horizon). */
static void random_direction(double out[3])
{
    double z = 2.0 * uniform01() - 1.0, phi = 6.283185307179586 * uniform01();
    double r = sqrt(1.0 - z * z);
    out[0] = r * cos(phi), out[1] = r * sin(phi), out[2] = z;
}

static int same_bits(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

static sc_brdf_file *load(const char *path)
{
    char err[512];
    sc_brdf_file *f = NULL;
    FILE *in = fopen(path, "r");
    if (!in)
        fail_msg("cannot open %s (run the unit tests from the source tree)", path);
    char *text = calloc(1, 1 << 20);
    assert_non_null(text);
    size_t len = fread(text, 1, (1 << 20) - 1, in);
    fclose(in);
    text[len] = '\0';
    f = sc_brdf_file_parse(text, path, err, sizeof err);
    if (!f)
        fail_msg("%s", err);
    free(text);
    return f;
}

enum { MANY = 2500 }; /* three chunks of the file's block execution, many blocks of lanes */

/* tests/brdf/principled.brdf with every lobe on, over random directions in two frames: every
 * term of sc_brdf_eval_many equals sc_brdf_eval's, in every precision. */
static void many_points_agree_with_one_at_a_time(void **state)
{
    (void)state;
    sc_brdf_file *f = load("tests/brdf/principled.brdf");
    sc_brdf b;
    sc_brdf_file_defaults(f, &b);
    char err[256];
    static const char *const set[][2] = {{"metal", "0.3"},
                                         {"aniso", "0.6"},
                                         {"sheen", "0.7"},
                                         {"coat", "0.5"},
                                         {"coat_gloss", "0.4"}};
    for (size_t i = 0; i < sizeof set / sizeof set[0]; i++)
        assert_int_equal(sc_brdf_file_set(&b, set[i][0], set[i][1], err, sizeof err), 0);
    sc_frame frames[2];
    const double n0[3] = {0, 0, 1}, n1[3] = {0.3, -0.2, 0.9}, t1[3] = {1, 1, 0};
    assert_int_equal(sc_frame_make(n0, NULL, &frames[0]), 0);
    assert_int_equal(sc_frame_make(n1, t1, &frames[1]), 0);
    sc_brdf_point *pts = malloc(MANY * sizeof *pts);
    sc_brdf_terms *many = malloc(MANY * sizeof *many);
    assert_non_null(pts);
    assert_non_null(many);
    for (int i = 0; i < MANY; i++) {
        pts[i].frame = &frames[i % 2];
        random_direction(pts[i].l);
        random_direction(pts[i].v);
    }
    for (int p = SC_DOUBLE; p <= SC_LOWP; p++) {
        assert_int_equal(sc_brdf_eval_many((sc_prec)p, &b, MANY, pts, many), MANY);
        for (int i = 0; i < MANY; i++) {
            sc_brdf_terms one;
            sc_brdf_eval((sc_prec)p, &b, pts[i].frame, pts[i].l, pts[i].v, &one);
            const double *x = &one.f[0], *y = &many[i].f[0];
            for (size_t k = 0; k < sizeof one / sizeof(double); k++)
                if (!same_bits(x[k], y[k]))
                    fail_msg("precision %d point %d term %zu: alone %a, many %a", p, i, k, x[k],
                             y[k]);
        }
    }
    assert_null(sc_brdf_file_error(f));
    free(pts);
    free(many);
    sc_brdf_file_free(f);
}

/* A loop that runs away where L.x > 0.9 only: sc_brdf_eval_many stops at the first such point,
 * as evaluations one at a time do, with the same message; the points before it keep their
 * values, it and the later ones are NaN; a later call fails at once. */
static void many_points_stop_at_the_first_error(void **state)
{
    (void)state;
    static const char text[] =
        "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
        "{ float s = L.x; while (L.x > 0.9) s += 1.0; return vec3(s, V.z, 1); }\n"
        "::end shader\n";
    char err[512];
    sc_brdf_file *alone = sc_brdf_file_parse(text, "runaway.brdf", err, sizeof err);
    sc_brdf_file *many = sc_brdf_file_parse(text, "runaway.brdf", err, sizeof err);
    assert_non_null(alone);
    assert_non_null(many);
    sc_brdf ba, bm;
    sc_brdf_file_defaults(alone, &ba);
    sc_brdf_file_defaults(many, &bm);
    sc_frame frame;
    const double n[3] = {0, 0, 1};
    sc_frame_make(n, NULL, &frame);
    enum { N = 700, BAD = 611 };
    sc_brdf_point pts[N];
    sc_brdf_terms out[N];
    for (int i = 0; i < N; i++) {
        double x = i == BAD || i == BAD + 40 ? 0.95 : 0.5 * uniform01();
        pts[i] = (sc_brdf_point){&frame, {x, 0.0, sqrt(1.0 - x * x)}, {0.0, 0.6, 0.8}};
    }
    pts[3].v[2] = -0.8; /* below the horizon: f = 0 without the shader */
    assert_int_equal(sc_brdf_eval_many(SC_HIGHP, &bm, N, pts, out), BAD);
    int first_failed = N;
    for (int i = 0; i < N; i++) {
        sc_brdf_terms one;
        sc_brdf_eval(SC_HIGHP, &ba, pts[i].frame, pts[i].l, pts[i].v, &one);
        if (first_failed == N && sc_brdf_file_error(alone))
            first_failed = i;
        for (int k = 0; k < 3; k++)
            assert_true(same_bits(one.f[k], out[i].f[k]));
        assert_true(i < BAD ? !isnan(out[i].f[0]) : isnan(out[i].f[0]));
    }
    assert_int_equal(first_failed, BAD);
    assert_string_equal(sc_brdf_file_error(alone), sc_brdf_file_error(many));
    assert_int_equal(sc_brdf_eval_many(SC_HIGHP, &bm, 4, pts, out), 0);
    sc_brdf_file_free(alone);
    sc_brdf_file_free(many);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(export_agrees_with_every_model),
        cmocka_unit_test(parser_errors_name_the_line),
        cmocka_unit_test(parameters_keep_their_types_and_ranges),
        cmocka_unit_test(runtime_errors_are_kept),
        cmocka_unit_test(many_points_agree_with_one_at_a_time),
        cmocka_unit_test(many_points_stop_at_the_first_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
