/* The double references of the attenuation, spot and BRDF batch kernels: the library's double
 * functions (light.h, brdf.h) on the kernels' float inputs and parameters. */
#include <math.h>

#include "batch/reference.h"
#include "batch/reference_light.h"
#include "shadecalc/accuracy.h"
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

static const double pi = 3.14159265358979323846;

/* ---- attenuation and spot: relative bounds (out[1] = 1) ---- */

static void atten_ref(sc_atten_kind kind, const sc_batch_args *a, size_t i, double *out)
{
    sc_atten at = *(const sc_atten *)a->params;
    at.kind = kind;
    out[0] = sc_atten_eval(SC_DOUBLE, &at, (double)a->in[0][i]);
    out[1] = 1.0;
}

static void spot_ref(sc_spot_kind kind, const sc_batch_args *a, size_t i, double *out)
{
    sc_spot s = *(const sc_spot *)a->params;
    s.kind = kind;
    out[0] = sc_spot_eval(SC_DOUBLE, &s, (double)a->in[0][i]);
    out[1] = 1.0;
}

#define REF_OF(name, fn, kind)                                                                     \
    void sc_batch_ref_##name(const sc_batch_args *a, size_t i, double *out) { fn(kind, a, i, out); }
REF_OF(atten_none, atten_ref, SC_ATTEN_NONE)
REF_OF(atten_invsq, atten_ref, SC_ATTEN_INVERSE_SQUARE)
REF_OF(atten_clq, atten_ref, SC_ATTEN_CLQ)
REF_OF(atten_window, atten_ref, SC_ATTEN_WINDOW)
REF_OF(atten_pixar, atten_ref, SC_ATTEN_PIXAR)
REF_OF(atten_windowed, atten_ref, SC_ATTEN_WINDOWED)
REF_OF(spot_opengl, spot_ref, SC_SPOT_OPENGL)
REF_OF(spot_directx, spot_ref, SC_SPOT_DIRECTX)
REF_OF(spot_smoothstep, spot_ref, SC_SPOT_SMOOTHSTEP)

/* ---- BRDFs ---- */

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* in[first..first+2] at element i as a unit vector; 0 if it is the zero vector */
static int unit_input(const sc_batch_args *a, int first, size_t i, double v[3])
{
    for (int k = 0; k < 3; k++)
        v[k] = (double)a->in[first + k][i];
    double len = sqrt(dot3(v, v));
    if (!(len > 0.0) || !isfinite(len))
        return 0;
    for (int k = 0; k < 3; k++)
        v[k] /= len;
    return 1;
}

/* The peak of a cosine lobe's normalization (phong, blinn-phong), 0 for the other models: an
 * error δ in the lobe's cosine moves f by up to about m δ times it. */
static double lobe_peak(const sc_brdf *b, double cos_i)
{
    if (b->kind == SC_BRDF_PHONG)
        return b->form == SC_PHONG_NORMALIZED ? (b->m + 2.0) / (2.0 * pi)
               : b->form == SC_PHONG_ORIGINAL ? 1.0 / (pi * fmax(cos_i, 1e-6))
                                              : 1.0 / pi;
    if (b->kind == SC_BRDF_BLINN_PHONG)
        return b->form == SC_BLINN_PLAIN ? 1.0 : (b->m + 8.0) / (8.0 * pi);
    return 0.0;
}

/* out[0..2] = f; out[3], the scale of the absolute allowance: c_diff/π plus the diffuse and
 * specular terms plus the lobe's peak. */
void sc_batch_ref_brdf(const sc_batch_args *a, size_t i, double *out)
{
    const sc_brdf *b = a->params;
    double l[3], v[3], n[3];
    sc_frame frame;
    for (int c = 0; c < 4; c++)
        out[c] = 0.0;
    if (!unit_input(a, 0, i, l) || !unit_input(a, 3, i, v) || !unit_input(a, 6, i, n) ||
        sc_frame_make(n, NULL, &frame) != 0)
        return;
    sc_brdf_terms t;
    sc_brdf_eval(SC_DOUBLE, b, &frame, l, v, &t);
    double peak = lobe_peak(b, t.cos_i);
    for (int c = 0; c < 3; c++) {
        out[c] = t.f[c];
        out[3] = fmax(out[3],
                      b->diff[c] / pi + fabs(t.diffuse[c]) + t.specular[c] + b->spec[c] * peak);
    }
}

/* ---- area lights: out[3] = ambient + max_c L_e (c_diff + c_spec), the radiance of an
 * emitter that fills the hemisphere (the edge sums are sums of angles up to π) ---- */

static void area_ref(const sc_batch_args *a, size_t i, double *out)
{
    const sc_scene *s = a->params;
    sc_light_terms terms[1];
    if (sc_batch_shade_at(s, a, i, out, terms) != 0)
        return;
    const sc_brdf *b = &s->model.brdf;
    double scale = 0.0;
    for (int c = 0; c < 3; c++)
        scale = fmax(scale, s->lights[0].intensity[c] * (b->diff[c] + b->spec[c]));
    out[3] += scale;
}

#define AREA_REF(name)                                                                             \
    void sc_batch_ref_##name(const sc_batch_args *a, size_t i, double *out) { area_ref(a, i, out); }
AREA_REF(area_sphere)
AREA_REF(area_tube)
AREA_REF(area_disk)
AREA_REF(area_rect)

/* ---- generator ---- */

static double unit_random(uint64_t *rng) /* uniform in [−1, 1) */
{
    return (double)(sc_accuracy_random(rng) >> 11) * 0x1p-52 - 1.0;
}

/* A random direction (uniform in the unit ball, then scaled by 2^k, |k| <= 30). */
static void random_direction(uint64_t *rng, float *w)
{
    double d[3], dd;
    do {
        for (int k = 0; k < 3; k++)
            d[k] = unit_random(rng);
        dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (!(dd > 1e-6 && dd <= 1.0));
    int e = (int)(sc_accuracy_random(rng) % 61) - 30;
    for (int k = 0; k < 3; k++)
        w[k] = (float)ldexp(d[k], e);
}

static double cos_between(const float *a, const float *b)
{
    double ab = 0, aa = 0, bb = 0;
    for (int k = 0; k < 3; k++) {
        ab += (double)a[k] * b[k];
        aa += (double)a[k] * a[k];
        bb += (double)b[k] * b[k];
    }
    return ab / sqrt(aa * bb);
}

/* A direction w with |cos(n, w)| >= 2^-6 (the horizon, where f jumps to 0, is excluded as in
 * sc_batch_gen_shade), turned above the horizon 7 times in 8. */
static void direction_off_horizon(uint64_t *rng, const float *n, float *w)
{
    double c;
    do {
        random_direction(rng, w);
        c = cos_between(n, w);
    } while (!(fabs(c) >= 0x1p-6));
    if (c < 0.0 && (sc_accuracy_random(rng) & 7) != 0)
        for (int k = 0; k < 3; k++)
            w[k] = -w[k];
}

void sc_batch_gen_brdf(uint64_t *rng, float *in)
{
    random_direction(rng, in + 6);
    direction_off_horizon(rng, in + 6, in);
    direction_off_horizon(rng, in + 6, in + 3);
}

/* ---- the rows' parameters ---- */

const sc_atten sc_batch_test_atten = {.kind = SC_ATTEN_CLQ,
                                      .sc = 1.0,
                                      .sl = 0.5,
                                      .sq = 0.25,
                                      .r_start = 1.0,
                                      .r_end = 10.0,
                                      .f_max = 4.0,
                                      .f_c = 1.0,
                                      .r_c = 2.0,
                                      .s_e = 2.0,
                                      .r_max = 10.0};

const sc_spot sc_batch_test_spot = {
    .kind = SC_SPOT_OPENGL, .exponent = 8.0, .cutoff = 45.0, .inner = 20.0, .outer = 40.0};

const sc_brdf sc_batch_test_brdf = {.kind = SC_BRDF_COOK_TORRANCE,
                                    .form = SC_CT_WALTER,
                                    .D = SC_D_GGX,
                                    .G = SC_G_SMITH_CORRELATED,
                                    .F = SC_F_SCHLICK,
                                    .diff = {0.8, 0.5, 0.2},
                                    .spec = {0.2, 0.3, 0.4},
                                    .f0 = {0.04, 0.5, 0.9},
                                    .m = 32.0,
                                    .ax = 0.3,
                                    .ay = 0.3,
                                    .sigma = 0.5,
                                    .ior = 1.5};

/* cook-torrance walter, GGX α 0.3, Smith height-correlated, Schlick with F0 f0 */
#define AREA_GGX(...)                                                                              \
    {                                                                                              \
        .kind = SC_BRDF_COOK_TORRANCE, .form = SC_CT_WALTER, .D = SC_D_GGX,                        \
        .G = SC_G_SMITH_CORRELATED, .F = SC_F_SCHLICK, .diff = {0.8, 0.5, 0.2},                    \
        .spec = {1.0, 1.0, 1.0}, .f0 = {__VA_ARGS__}, .m = 32.0, .ax = 0.3, .ay = 0.3, .ior = 1.5  \
    }
#define AREA_LIGHT(k, m, x, y, z, ...)                                                             \
    {                                                                                              \
        .kind = k, .pos = {x, y, z}, .intensity = {2.0, 1.5, 1.0}, .range = HUGE_VAL, .area = {    \
            .method = m,                                                                           \
            __VA_ARGS__                                                                            \
        }                                                                                          \
    }

/* Around the generator's points p in [-3, 3]^3: some inside or behind, some across the
 * horizon. */
static const sc_light area_lights[4] = {
    AREA_LIGHT(SC_LIGHT_SPHERE, SC_AREA_REPRESENTATIVE, 0.3, 1.5, -0.2, .radius = 0.6),
    AREA_LIGHT(SC_LIGHT_TUBE, SC_AREA_REPRESENTATIVE, 0.0, 1.4, 0.2, .radius = 0.25,
               .p0 = {-1.0, 1.2, 0.0}, .p1 = {1.0, 1.6, 0.4}),
    AREA_LIGHT(SC_LIGHT_DISK, SC_AREA_LTC, 0.0, 1.5, 0.0, .radius = 0.8,
               .normal = {0.2, -1.0, 0.1}),
    AREA_LIGHT(SC_LIGHT_RECT, SC_AREA_LTC, 0.2, 1.4, -0.1, .edge1 = {1.5, 0.0, 0.2},
               .edge2 = {0.0, 0.3, 1.0}, .two_sided = 1)};

#define AREA_SCENE(k, brdf_init)                                                                   \
    {                                                                                              \
        &area_lights[k], 1, {.kind = SC_MODEL_BRDF, .brdf = brdf_init}, { 0.0, 0.0, 0.0 }          \
    }
const sc_scene sc_batch_test_area_sphere = AREA_SCENE(0, AREA_GGX(0.04, 0.04, 0.04));
const sc_scene sc_batch_test_area_tube = AREA_SCENE(1, AREA_GGX(0.04, 0.04, 0.04));
const sc_scene sc_batch_test_area_disk = AREA_SCENE(2, AREA_GGX(0.04, 0.5, 0.9));
const sc_scene sc_batch_test_area_rect = AREA_SCENE(3, AREA_GGX(0.04, 0.5, 0.9));
