/* The legacy lighting models (shadecalc/shade.h: ads, opengl, direct3d9) against closed forms
 * and against a double-precision recomputation of their equations written here from reference
 * §3 (GL 2.1 §2.14.1) and §4 (D3D9 "Mathematics of Lighting") and the man page's MODELS:
 *
 *   ads      k_a ⊙ (L_A + Σ L_A,k) + Σ att·[I⊙c_d,k ⊙ k_d (n·l)⁺ + I⊙c_s,k ⊙ k_s S]
 *   opengl   e + a_cm ⊙ a_cs + Σ att·[I⊙a_cl ⊙ a_cm + (n·l)⁺ I⊙d_cl ⊙ d_cm
 *                                      + [n·l > 0] (n·ĥ)⁺^m I⊙s_cl ⊙ s_cm]
 *   direct3d9 the same without the n·l gate, att = 0 beyond the range, specular separate
 *
 * with pow(0, 0) = 1 (shadecalc/light.h) and ĥ = n where l + v vanishes. The lights are
 * directional or point lights with clq attenuation, whose att is 1/(s_c + s_l d + s_q d²). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/shade.h"

enum { MAX_LIGHTS = 3 };

static const double pi = 3.14159265358979323846;

static double cos_deg(double a) { return cos(a * pi / 180.0); }

/* ---- the reference, in double precision ---- */

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit3(const double a[3], double out[3])
{
    double len = sqrt(dot3(a, a));
    for (int c = 0; c < 3; c++)
        out[c] = a[c] / len;
}

/* x^m with pow(0, 0) = 1 and nothing for a base at or below 0 */
static double lobe(double x, double m) { return m == 0.0 ? 1.0 : x <= 0.0 ? 0.0 : pow(x, m); }

static double clamp01(double x) { return fmin(fmax(x, 0.0), 1.0); }

/* unit(a + b), or n when a + b = 0 */
static void half_vector(const double a[3], const double b[3], const double n[3], double h[3])
{
    double sum[3] = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    if (dot3(sum, sum) > 0.0)
        unit3(sum, h);
    else
        memcpy(h, n, sizeof sum);
}

/* l, the distance and the attenuation of a directional or clq point light at pos */
static double light_at(const sc_light *light, const double pos[3], double l[3], double *dist)
{
    if (light->kind == SC_LIGHT_DIRECTIONAL) {
        unit3(light->dir, l);
        *dist = 0.0;
        return 1.0;
    }
    double d[3] = {light->pos[0] - pos[0], light->pos[1] - pos[1], light->pos[2] - pos[2]};
    *dist = sqrt(dot3(d, d));
    unit3(d, l);
    const sc_atten *a = &light->atten;
    return 1.0 / (a->sc + a->sl * *dist + a->sq * *dist * *dist);
}

static void ref_ads(const sc_scene *s, const sc_shade_point *at, double L[3])
{
    const sc_brdf *k = &s->model.brdf;
    const double *n = at->frame.n;
    for (int c = 0; c < 3; c++)
        L[c] = k->amb[c] * s->ambient[c];
    for (int i = 0; i < s->n_lights; i++) {
        const sc_light *light = &s->lights[i];
        double l[3], dist, att = light_at(light, at->pos, l, &dist), S = 0.0, h[3];
        double cos_i = dot3(n, l), r[3];
        for (int c = 0; c < 3; c++)
            r[c] = 2.0 * cos_i * n[c] - l[c];
        half_vector(l, at->v, n, h);
        if (s->model.ads_form == SC_ADS_PHONG)
            S = lobe(fmax(dot3(r, at->v), 0.0), k->m);
        else if (s->model.ads_form == SC_ADS_BLINN_PHONG)
            S = lobe(fmax(dot3(n, h), 0.0), k->m);
        for (int c = 0; c < 3; c++) {
            double I = light->intensity[c];
            L[c] += k->amb[c] * light->ambient[c] +
                    att * (I * light->diffuse[c] * k->diff[c] * fmax(cos_i, 0.0) +
                           I * light->specular[c] * k->spec[c] * S);
        }
    }
}

typedef struct {
    double primary[3], secondary[3], L[3];
} fixed_colours;

static void ref_fixed_function(const sc_scene *s, const sc_shade_point *at, fixed_colours *out)
{
    const sc_model *m = &s->model;
    const double *n = at->frame.n;
    int d3d9 = m->kind == SC_MODEL_D3D9;
    double prim[3], sec[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++)
        prim[c] = m->emission[c] + m->brdf.amb[c] * s->ambient[c];
    for (int i = 0; i < s->n_lights; i++) {
        const sc_light *light = &s->lights[i];
        double l[3], dist, att = light_at(light, at->pos, l, &dist), h[3];
        if (d3d9 && light->kind != SC_LIGHT_DIRECTIONAL && dist > light->range)
            att = 0.0;
        half_vector(l, m->local_viewer ? at->v : m->viewer_dir, n, h);
        double cos_i = dot3(n, l);
        double spec = d3d9 || cos_i > 0.0 ? lobe(fmax(dot3(n, h), 0.0), m->brdf.m) : 0.0;
        for (int c = 0; c < 3; c++) {
            double I = light->intensity[c];
            prim[c] += att * (m->brdf.amb[c] * I * light->ambient[c] +
                              fmax(cos_i, 0.0) * m->brdf.diff[c] * I * light->diffuse[c]);
            sec[c] += att * spec * m->brdf.spec[c] * I * light->specular[c];
        }
    }
    int separate = d3d9 || m->separate_specular;
    for (int c = 0; c < 3; c++) {
        double a = separate ? prim[c] : prim[c] + sec[c], b = separate ? sec[c] : 0.0;
        out->primary[c] = m->clamp ? clamp01(a) : a;
        out->secondary[c] = m->clamp ? clamp01(b) : b;
        double sum = out->primary[c] + out->secondary[c];
        out->L[c] = m->clamp ? clamp01(sum) : sum;
    }
}

/* ---- set-up ---- */

static void assert_close3(const double got[3], const double want[3], double tol)
{
    for (int c = 0; c < 3; c++)
        if (!(fabs(got[c] - want[c]) <= tol * fmax(fabs(want[c]), 1e-300)))
            fail_msg("channel %d: got %.17g, want %.17g", c, got[c], want[c]);
}

static void set3(double out[3], double x, double y, double z)
{
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* dir(θ°, φ°) of reference §0 */
static void dir(double theta, double phi, double out[3])
{
    double t = theta * pi / 180.0, f = phi * pi / 180.0;
    set3(out, sin(t) * cos(f), sin(t) * sin(f), cos(t));
}

static sc_shade_point point_at(const double pos[3], const double n[3], const double v[3])
{
    sc_shade_point at;
    memcpy(at.pos, pos, sizeof at.pos);
    assert_int_equal(sc_frame_make(n, NULL, &at.frame), 0);
    unit3(v, at.v);
    return at;
}

/* a point on z = 0 with n = +z, viewed along v */
static sc_shade_point up_point(const double v[3])
{
    const double origin[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    return point_at(origin, up, v);
}

static sc_light directional(const double d[3])
{
    sc_light light;
    sc_light_init(&light, SC_LIGHT_DIRECTIONAL);
    memcpy(light.dir, d, sizeof light.dir);
    return light;
}

/* a directional light from l = dir(θ, 0), and l's mirror about n = +z, dir(θ, 180) */
static sc_light light_and_mirror(double theta, double l[3], double mirror[3])
{
    dir(theta, 0, l);
    dir(theta, 180, mirror);
    return directional(l);
}

static sc_light clq_point(double x, double y, double z, double sc, double sl, double sq)
{
    sc_light light;
    sc_light_init(&light, SC_LIGHT_POINT);
    set3(light.pos, x, y, z);
    light.atten = (sc_atten){.kind = SC_ATTEN_CLQ, .sc = sc, .sl = sl, .sq = sq};
    return light;
}

static sc_scene scene_of(const sc_light *lights, int n, sc_model_kind kind)
{
    sc_scene s = {.lights = lights, .n_lights = n};
    sc_model_init(&s.model, kind);
    return s;
}

/* one light; the material without ambient: diffuse and specular grey, shininess m */
static sc_scene grey_scene(const sc_light *light, sc_model_kind kind, double diff, double spec,
                           double m)
{
    sc_scene s = scene_of(light, 1, kind);
    set3(s.model.brdf.amb, 0, 0, 0);
    set3(s.model.brdf.diff, diff, diff, diff);
    set3(s.model.brdf.spec, spec, spec, spec);
    s.model.brdf.m = m;
    return s;
}

/* distinct material and light colours, so a swapped term shows */
static void colour_everything(sc_scene *s, sc_light *lights)
{
    set3(s->model.brdf.diff, 0.7, 0.5, 0.3);
    set3(s->model.brdf.spec, 0.4, 0.6, 0.2);
    set3(s->model.brdf.amb, 0.3, 0.2, 0.1);
    set3(s->model.emission, 0.05, 0.0, 0.02);
    set3(s->ambient, 0.2, 0.3, 0.4);
    s->model.brdf.m = 7;
    for (int i = 0; i < s->n_lights; i++) {
        set3(lights[i].intensity, 1.5 - 0.25 * i, 1.0, 0.75 + 0.5 * i);
        set3(lights[i].ambient, 0.1, 0.2 * i, 0.3);
        set3(lights[i].diffuse, 0.9, 0.6 + 0.1 * i, 0.4);
        set3(lights[i].specular, 0.8, 1.0, 0.5 * i);
    }
}

/* ---- ads ---- */

/* l = dir(60, 0): with v its mirror dir(60, 180), r = v and h = n, so S = 1 for phong and
 * blinn-phong; with v = n, r·v = cos 60° and n·h = cos 30°. */
static void ads_closed_forms(void **state)
{
    (void)state;
    double l[3], mirror[3];
    sc_light light = light_and_mirror(60, l, mirror);
    sc_scene s = grey_scene(&light, SC_MODEL_ADS, 0.5, 0.25, 32);
    const double up[3] = {0, 0, 1};
    struct {
        sc_ads_form form;
        const double *v;
        double want; /* k_d cos 60° + k_s S */
    } cases[] = {
        {SC_ADS_LAMBERT, mirror, 0.25},
        {SC_ADS_PHONG, mirror, 0.25 + 0.25},
        {SC_ADS_BLINN_PHONG, mirror, 0.25 + 0.25},
        {SC_ADS_PHONG, up, 0.25 + 0.25 * pow(0.5, 32)},
        {SC_ADS_BLINN_PHONG, up, 0.25 + 0.25 * pow(sqrt(3.0) / 2, 32)},
        {SC_ADS_LAMBERT, up, 0.25},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        s.model.ads_form = cases[i].form;
        sc_shade_point at = up_point(cases[i].v);
        sc_shade_result r = {.per_light = NULL};
        sc_shade(SC_DOUBLE, &s, &at, &r);
        const double want[3] = {cases[i].want, cases[i].want, cases[i].want};
        assert_close3(r.L, want, 1e-14);
    }
}

/* v = l: r·v = cos 120° < 0, so phong has no highlight (and a full one with m = 0, pow(0,0) =
 * 1); blinn-phong's h = l gives (n·l)^m. */
static void ads_highlight_behind_the_reflection(void **state)
{
    (void)state;
    double l[3];
    dir(60, 0, l);
    sc_light light = directional(l);
    sc_scene s = grey_scene(&light, SC_MODEL_ADS, 0, 1, 4);
    sc_shade_point at = up_point(l);
    sc_shade_result r = {.per_light = NULL};
    s.model.ads_form = SC_ADS_PHONG;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    const double none[3] = {0, 0, 0}, one[3] = {1, 1, 1}, quartic[3] = {0.0625, 0.0625, 0.0625};
    assert_memory_equal(r.L, none, sizeof none);
    s.model.brdf.m = 0;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    assert_close3(r.L, one, 0);
    s.model.brdf.m = 4;
    s.model.ads_form = SC_ADS_BLINN_PHONG;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    assert_close3(r.L, quartic, 1e-14);
}

/* The global and per-light ambient terms: k_a ⊙ (L_A + Σ L_A,k), not attenuated, and the light
 * behind the surface (n·l < 0) adds nothing else. */
static void ads_ambient_and_light_behind(void **state)
{
    (void)state;
    sc_light lights[2] = {clq_point(0, 0, -3, 1, 0, 1), clq_point(1, 0, -1, 2, 0, 0)};
    sc_scene s = scene_of(lights, 2, SC_MODEL_ADS);
    set3(s.model.brdf.amb, 0.5, 0.25, 1);
    set3(s.ambient, 0.2, 0.4, 0.1);
    set3(lights[0].ambient, 0.1, 0.1, 0.1);
    set3(lights[1].ambient, 0.3, 0, 0.2);
    s.model.ads_form = SC_ADS_LAMBERT;
    const double up[3] = {0, 0, 1};
    sc_shade_point at = up_point(up);
    sc_light_terms terms[2];
    sc_shade_result r = {.per_light = terms};
    sc_shade(SC_DOUBLE, &s, &at, &r);
    const double global[3] = {0.1, 0.1, 0.1}, first[3] = {0.05, 0.025, 0.1},
                 second[3] = {0.15, 0, 0.2}, L[3] = {0.3, 0.125, 0.4};
    assert_close3(r.ambient, global, 1e-15);
    assert_close3(terms[0].ambient, first, 1e-15);
    assert_close3(terms[1].ambient, second, 1e-15);
    assert_close3(r.L, L, 1e-15);
    assert_true(terms[0].brdf.cos_i < 0.0 && terms[1].brdf.cos_i < 0.0);
}

/* v = −l: l + v vanishes and ĥ = n, a full blinn-phong highlight although n ≠ l */
static void ads_half_vector_of_opposite_directions(void **state)
{
    (void)state;
    const double l[3] = {0, 0, 1}, v[3] = {0, 0, -1}, origin[3] = {0, 0, 0};
    double n[3];
    dir(30, 0, n);
    sc_light light = directional(l);
    sc_scene s = grey_scene(&light, SC_MODEL_ADS, 0, 0.5, 32);
    sc_shade_point at = point_at(origin, n, v);
    sc_shade_result r = {.per_light = NULL};
    sc_shade(SC_DOUBLE, &s, &at, &r);
    const double half[3] = {0.5, 0.5, 0.5};
    assert_close3(r.L, half, 1e-14);
}

/* A deterministic spread of geometries (normals, views, two lights, every form) against the
 * recomputation, in double and in highp (rounded to binary32 at every step: within 1e-5). */
typedef struct {
    sc_light lights[MAX_LIGHTS];
    sc_shade_point at;
} random_case;

static uint64_t next_random(uint64_t *x)
{
    *x = *x * 6364136223846793005u + 1442695040888963407u;
    return *x >> 11;
}

static double uniform(uint64_t *x, double lo, double hi)
{
    return lo + (hi - lo) * (double)next_random(x) / 9007199254740992.0;
}

static random_case random_geometry(uint64_t *x)
{
    random_case k;
    double n[3], v[3], d[3], pos[3] = {uniform(x, -1, 1), uniform(x, -1, 1), uniform(x, -1, 1)};
    dir(uniform(x, 0, 60), uniform(x, 0, 360), n);
    dir(uniform(x, 0, 85), uniform(x, 0, 360), v);
    dir(uniform(x, 0, 120), uniform(x, 0, 360), d);
    k.lights[0] = directional(d);
    k.lights[1] = clq_point(uniform(x, -4, 4), uniform(x, -4, 4), uniform(x, 1, 5), 1,
                            uniform(x, 0, 0.2), uniform(x, 0, 0.1));
    k.lights[2] = clq_point(uniform(x, -4, 4), uniform(x, -4, 4), uniform(x, -2, 5), 0.5, 0.1, 0);
    k.at = point_at(pos, n, v);
    return k;
}

static void ads_matches_the_equation(void **state)
{
    (void)state;
    uint64_t x = 11;
    for (int i = 0; i < 300; i++) {
        random_case k = random_geometry(&x);
        sc_scene s = scene_of(k.lights, MAX_LIGHTS, SC_MODEL_ADS);
        colour_everything(&s, k.lights);
        s.model.ads_form = (sc_ads_form)(i % 3);
        double want[3];
        ref_ads(&s, &k.at, want);
        sc_shade_result r = {.per_light = NULL};
        sc_shade(SC_DOUBLE, &s, &k.at, &r);
        assert_close3(r.L, want, 1e-12);
        sc_shade(SC_HIGHP, &s, &k.at, &r);
        assert_close3(r.L, want, 1e-5);
    }
}

/* ---- opengl and direct3d9 ---- */

static void fixed_function_matches_the_equation(void **state)
{
    (void)state;
    uint64_t x = 7;
    for (int i = 0; i < 400; i++) {
        random_case k = random_geometry(&x);
        sc_scene s = scene_of(k.lights, MAX_LIGHTS, i % 2 ? SC_MODEL_D3D9 : SC_MODEL_OPENGL);
        colour_everything(&s, k.lights);
        s.model.local_viewer = (i / 2) % 2;
        s.model.clamp = (i / 4) % 2;
        s.model.separate_specular = (i / 8) % 2;
        k.lights[1].range = uniform(&x, 0, 8);
        k.lights[0].range = 0; /* no effect on a directional light */
        fixed_colours want;
        ref_fixed_function(&s, &k.at, &want);
        sc_light_terms terms[MAX_LIGHTS];
        sc_shade_result r = {.per_light = i % 3 ? terms : NULL};
        sc_shade(SC_DOUBLE, &s, &k.at, &r);
        assert_close3(r.L, want.L, 1e-12);
        assert_close3(r.primary, want.primary, 1e-12);
        assert_close3(r.secondary, want.secondary, 1e-12);
        sc_shade(SC_HIGHP, &s, &k.at, &r);
        assert_close3(r.L, want.L, 1e-5);
    }
}

/* A light below the horizon (θ_i = 100°) seen along n with the viewer at +z: GL gates the
 * specular term by n·l > 0, Direct3D 9 keeps s (n·ĥ)^m with ĥ at 50°. Neither has a diffuse
 * term; the ambient is e + a_cm a_cs + a_cm a_cl. */
static void specular_gate_opengl_not_direct3d9(void **state)
{
    (void)state;
    double l[3];
    dir(100, 0, l);
    sc_light light = directional(l);
    set3(light.ambient, 0.5, 0.5, 0.5);
    const double up[3] = {0, 0, 1};
    sc_shade_point at = up_point(up);
    double lit = 0.1 + 0.2 * 0.3 + 0.2 * 0.5, highlight = 0.5 * pow(cos_deg(50), 2);
    for (int kind = SC_MODEL_OPENGL; kind <= SC_MODEL_D3D9; kind++) {
        sc_scene s = scene_of(&light, 1, (sc_model_kind)kind);
        set3(s.model.emission, 0.1, 0.1, 0.1);
        set3(s.ambient, 0.3, 0.3, 0.3);
        set3(s.model.brdf.spec, 0.5, 0.5, 0.5);
        s.model.brdf.m = 2;
        sc_light_terms t;
        sc_shade_result r = {.per_light = &t};
        sc_shade(SC_DOUBLE, &s, &at, &r);
        double spec = kind == SC_MODEL_D3D9 ? highlight : 0.0;
        const double want[3] = {lit + spec, lit + spec, lit + spec};
        assert_close3(r.L, want, 1e-14);
        assert_true(t.brdf.cos_i < 0.0);
        assert_true(fabs(t.brdf.cos_h - cos_deg(50)) <= 1e-14);
    }
}

/* Direct3D 9's range cuts a point light off — its ambient too — beyond the range, inclusive at
 * it; a directional light has no range. The specular goes to the secondary colour. */
static void direct3d9_range_and_separate_specular(void **state)
{
    (void)state;
    sc_light point = clq_point(0, 0, 5, 1, 0, 0);
    set3(point.ambient, 1, 1, 1);
    sc_scene s = scene_of(&point, 1, SC_MODEL_D3D9);
    set3(s.model.brdf.amb, 0.1, 0.1, 0.1);
    set3(s.model.brdf.diff, 0.3, 0.3, 0.3);
    set3(s.model.brdf.spec, 0.25, 0.25, 0.25);
    const double up[3] = {0, 0, 1};
    sc_shade_point at = up_point(up); /* l = v = n: n·h = 1 */
    sc_shade_result r = {.per_light = NULL};
    const double dark[3] = {0, 0, 0}, primary[3] = {0.4, 0.4, 0.4},
                 secondary[3] = {0.25, 0.25, 0.25}, L[3] = {0.65, 0.65, 0.65};
    point.range = 4.999;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    assert_close3(r.L, dark, 0);
    point.range = 5;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    assert_close3(r.primary, primary, 1e-15);
    assert_close3(r.secondary, secondary, 1e-15);
    assert_close3(r.L, L, 1e-15);
    point.kind = SC_LIGHT_DIRECTIONAL;
    set3(point.dir, 0, 0, 1);
    point.range = 0;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    assert_close3(r.L, L, 1e-15);
}

/* Colours clamp to [0, 1] (each of the separate colours on its own) unless clamp=0. */
static void clamping(void **state)
{
    (void)state;
    const double up[3] = {0, 0, 1};
    sc_light light = directional(up);
    set3(light.intensity, 3, 0.5, 1);
    sc_scene s = grey_scene(&light, SC_MODEL_OPENGL, 0.5, 0.5, 0);
    s.model.separate_specular = 1;
    sc_shade_point at = up_point(up);
    sc_shade_result r = {.per_light = NULL};
    sc_shade(SC_DOUBLE, &s, &at, &r);
    const double clamped[3] = {1, 0.25, 0.5}, sum[3] = {1, 0.5, 1};
    assert_close3(r.primary, clamped, 0);
    assert_close3(r.secondary, clamped, 0);
    assert_close3(r.L, sum, 0);
    s.model.clamp = 0;
    sc_shade(SC_DOUBLE, &s, &at, &r);
    const double free_primary[3] = {1.5, 0.25, 0.5}, free_sum[3] = {3, 0.5, 1};
    assert_close3(r.primary, free_primary, 0);
    assert_close3(r.L, free_sum, 0);
}

/* Non-local viewer: ĥ from l and the model's viewer direction, whatever v is; local: from v. */
static void viewer_direction(void **state)
{
    (void)state;
    double l[3], v[3];
    sc_light light = light_and_mirror(40, l, v);
    sc_scene s = grey_scene(&light, SC_MODEL_D3D9, 0, 1, 10);
    s.model.clamp = 0;
    sc_shade_point at = up_point(v);
    sc_shade_result r = {.per_light = NULL};
    sc_shade(SC_DOUBLE, &s, &at, &r); /* local (the default): ĥ = n */
    const double full[3] = {1, 1, 1};
    assert_close3(r.L, full, 1e-15);
    s.model.local_viewer = 0;
    memcpy(s.model.viewer_dir, l, sizeof l); /* ĥ = l at 40° */
    sc_shade(SC_DOUBLE, &s, &at, &r);
    double c = pow(cos_deg(40), 10);
    const double want[3] = {c, c, c};
    assert_close3(r.L, want, 1e-14);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ads_closed_forms),
        cmocka_unit_test(ads_highlight_behind_the_reflection),
        cmocka_unit_test(ads_ambient_and_light_behind),
        cmocka_unit_test(ads_half_vector_of_opposite_directions),
        cmocka_unit_test(ads_matches_the_equation),
        cmocka_unit_test(fixed_function_matches_the_equation),
        cmocka_unit_test(specular_gate_opengl_not_direct3d9),
        cmocka_unit_test(direct3d9_range_and_separate_specular),
        cmocka_unit_test(clamping),
        cmocka_unit_test(viewer_direction),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
