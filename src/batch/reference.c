/* The double-precision references of the batch kernels (evaluated on the float inputs), the
 * generators of their random inputs, and the standard scenes. The shading reference goes
 * through the library's double BRDFs (src/brdf/), not through the kernels' formulas. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "batch/reference.h"
#include "shadecalc/accuracy.h"
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"
#include "shadecalc/vec.h"

#define REF1(name, expr)                                                                           \
    void sc_batch_ref_##name(const sc_batch_args *a, size_t i, double *out)                        \
    {                                                                                              \
        double x = (double)a->in[0][i];                                                            \
        out[0] = (expr);                                                                           \
        out[1] = 1.0;                                                                              \
    }
REF1(exp2, exp2(x))
REF1(exp, exp(x))
REF1(log2, log2(x))
REF1(log, log(x))
REF1(inversesqrt, 1.0 / sqrt(x))
REF1(sqrt, sqrt(x))

void sc_batch_ref_pow(const sc_batch_args *a, size_t i, double *out)
{
    out[0] = pow((double)a->in[0][i], (double)a->in[1][i]);
    out[1] = 1.0;
}

static void load3(const sc_batch_args *a, int first, size_t i, double v[3])
{
    for (int k = 0; k < 3; k++)
        v[k] = (double)a->in[first + k][i];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* components first..first+2 of element i, as the library's double vector (vec.h), whose
 * dot, length, normalize and reflect are the references of the vec3 kernels */
static sc_dvec3 vec_at(const sc_batch_args *a, int first, size_t i)
{
    return sc_dvec3_make(a->in[first][i], a->in[first + 1][i], a->in[first + 2][i]);
}

/* Σ|a_k b_k|: the dot product's error allowance scales with it (cancellation) */
static double abs_dot(sc_dvec3 u, sc_dvec3 v)
{
    return fabs(u.x * v.x) + fabs(u.y * v.y) + fabs(u.z * v.z);
}

void sc_batch_ref_dot(const sc_batch_args *a, size_t i, double *out)
{
    sc_dvec3 u = vec_at(a, 0, i), v = vec_at(a, 3, i);
    out[0] = sc_dvec3_dot(u, v);
    out[1] = abs_dot(u, v);
}

/* allowance per component: |I_c| + 2 Σ|N_k I_k| |N_c|, the largest */
void sc_batch_ref_reflect(const sc_batch_args *a, size_t i, double *out)
{
    sc_dvec3 I = vec_at(a, 0, i), N = vec_at(a, 3, i), r = sc_dvec3_reflect(I, N);
    double k = 2.0 * abs_dot(N, I);
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.z;
    out[3] = fmax(fabs(I.x) + k * fabs(N.x),
                  fmax(fabs(I.y) + k * fabs(N.y), fabs(I.z) + k * fabs(N.z)));
}

void sc_batch_ref_normalize(const sc_batch_args *a, size_t i, double *out)
{
    sc_dvec3 u = sc_dvec3_normalize(vec_at(a, 0, i));
    out[0] = u.x;
    out[1] = u.y;
    out[2] = u.z;
    out[3] = 1.0; /* components: a relative bound against the unit vector's largest */
}

void sc_batch_ref_length(const sc_batch_args *a, size_t i, double *out)
{
    out[0] = sc_dvec3_length(vec_at(a, 0, i));
    out[1] = 1.0;
}

/* 1 if cos θ_s lies within 2^-16 of a hard edge of the light's cone, where the spot factor
 * jumps (opengl's cutoff, directx and smoothstep with inner = outer): there a rounding of l
 * decides between the lit and the unlit value, so no error bound can hold. */
static int at_hard_edge(const sc_light *lt, double cos_s)
{
    const double radians = 0.017453292519943295;
    double edge = 2.0;
    if (lt->kind != SC_LIGHT_SPOT)
        return 0;
    if (lt->spot.kind == SC_SPOT_OPENGL && lt->spot.cutoff != 180.0)
        edge = cos(lt->spot.cutoff * radians);
    else if (lt->spot.kind != SC_SPOT_OPENGL && lt->spot.inner == lt->spot.outer)
        edge = cos(lt->spot.inner * radians);
    return fabs(cos_s - edge) < 0x1p-16;
}

/* E_L of a light before its spot factor: the factor's error is absolute in cos θ_s (a rounding
 * of l moves cos θ_s by a few 2^-24), so where a smooth cone falls to 0 at its outer edge the
 * factor's relative error grows without bound: 2 δ/(cos θ_s − cos θ_u) for smoothstep. With
 * the spotted E the allowance vanished there, and a lobe that lit the point mostly through such
 * a spot broke the bound (1.16 times it at m = 128, cos θ_s 0.006 inside the 40° cone). */
static double unspotted_E(const sc_light *lt, const sc_light_sample *ls, int c)
{
    return lt->kind == SC_LIGHT_SPOT ? lt->intensity[c] * ls->f_d : ls->E[c];
}

/* out[0..2] the radiance of the plan's scene (sc_shade's equation in double, on the float
 * inputs); out[3] the scale of the allowance: ambient plus Σ E (c_diff/π + |diffuse| +
 * specular) without the cosine, a spot's E without its spot factor (unspotted_E) (an error of ε in n·l, inevitable in float, moves the result by
 * about ε E f); +Inf (outside the stated domain) at a hard edge of a spot cone. */
int sc_batch_shade_at(const sc_scene *s, const sc_batch_args *a, size_t i, double out[4],
                      sc_light_terms *terms)
{
    sc_shade_point at;
    double n[3], v[3];
    load3(a, 0, i, n);
    load3(a, 3, i, v);
    load3(a, 6, i, at.pos);
    const sc_brdf *b = &s->model.brdf;
    double vlen = sqrt(dot3(v, v)), amb[3];
    out[3] = 0.0;
    for (int c = 0; c < 3; c++) {
        amb[c] = s->ambient[c];
        for (int k = 0; k < s->n_lights; k++)
            amb[c] += s->lights[k].ambient[c];
        out[c] = b->amb[c] * amb[c];
        out[3] = fmax(out[3], fabs(out[c]));
    }
    if (sc_frame_make(n, NULL, &at.frame) != 0 || vlen == 0.0)
        return -1;
    for (int c = 0; c < 3; c++)
        at.v[c] = v[c] / vlen;
    sc_shade_result r = {.per_light = terms};
    sc_shade(SC_DOUBLE, s, &at, &r);
    for (int c = 0; c < 3; c++)
        out[c] = r.L[c];
    return 0;
}

void sc_batch_ref_shade(const sc_batch_args *a, size_t i, double *out)
{
    const sc_scene *s = sc_batch_plan_scene(a->params);
    const sc_brdf *b = &s->model.brdf;
    sc_light_terms terms[SC_BATCH_MAX_LIGHTS];
    if (sc_batch_shade_at(s, a, i, out, terms) != 0)
        return;
    double scale = 0.0;
    for (int k = 0; k < s->n_lights; k++) {
        const sc_light_terms *t = &terms[k];
        if (at_hard_edge(&s->lights[k], t->light.cos_s))
            scale = INFINITY;
        for (int c = 0; c < 3; c++)
            scale = fmax(scale, unspotted_E(&s->lights[k], &t->light, c) *
                                    (b->diff[c] / 3.141592653589793 + fabs(t->brdf.diffuse[c]) +
                                     t->brdf.specular[c]));
    }
    out[3] += scale;
}

/* ---- generators ---- */

static double uniform(uint64_t *rng, double lo, double hi)
{
    return lo + (hi - lo) * ((double)(sc_accuracy_random(rng) >> 11) * 0x1p-53);
}

/* A direction uniform on the sphere, times 2^e with e uniform in [−emax, emax]. */
static void random_vector(uint64_t *rng, double emax, float *out)
{
    double z = uniform(rng, -1.0, 1.0), phi = uniform(rng, 0.0, 6.283185307179586);
    double r = sqrt(1.0 - z * z), m = exp2(uniform(rng, -emax, emax));
    out[0] = (float)(m * r * cos(phi));
    out[1] = (float)(m * r * sin(phi));
    out[2] = (float)(m * z);
}

void sc_batch_gen_pair(uint64_t *rng, float *in)
{
    random_vector(rng, 8.0, in);
    random_vector(rng, 8.0, in + 3);
}

void sc_batch_gen_reflect(uint64_t *rng, float *in)
{
    random_vector(rng, 8.0, in);
    random_vector(rng, 0.0, in + 3);
}

void sc_batch_gen_vector(uint64_t *rng, float *in) { random_vector(rng, 60.0, in); }

/* |cos θ_o| >= 2^-6: f jumps to 0 at the horizon n·v = 0, where an error of one rounding in
 * n·v decides between the full value and nothing. */
void sc_batch_gen_shade(uint64_t *rng, float *in)
{
    random_vector(rng, 4.0, in);
    double cos_o;
    do {
        random_vector(rng, 4.0, in + 3);
        double nv = (double)in[0] * in[3] + (double)in[1] * in[4] + (double)in[2] * in[5];
        double nn = (double)in[0] * in[0] + (double)in[1] * in[1] + (double)in[2] * in[2];
        double vv = (double)in[3] * in[3] + (double)in[4] * in[4] + (double)in[5] * in[5];
        cos_o = nv / sqrt(nn * vv);
    } while (fabs(cos_o) < 0x1p-6);
    for (int c = 6; c < 9; c++)
        in[c] = (float)uniform(rng, -3.0, 3.0);
}

void sc_batch_sample(const sc_batch_entry *e, uint64_t *rng, float *in)
{
    if (e->gen) {
        e->gen(rng, in);
        return;
    }
    for (int j = 0; j < e->n_in; j++)
        in[j] = sc_accuracy_random(rng) & 1 ? (float)uniform(rng, e->lo[j], e->hi[j])
                                            : sc_accuracy_sample(rng, e->lo[j], e->hi[j]);
}

/* ---- the standard scenes ---- */

void sc_batch_example_scene(sc_brdf_kind brdf, int n_dir, int n_point, int n_spot,
                            sc_light lights[SC_BATCH_MAX_LIGHTS], sc_scene *out)
{
    static const sc_spot_kind spots[] = {SC_SPOT_OPENGL, SC_SPOT_DIRECTX, SC_SPOT_SMOOTHSTEP};
    int n = 0;
    for (int k = 0; k < n_dir + n_point + n_spot && k < SC_BATCH_MAX_LIGHTS; k++) {
        sc_light *lt = &lights[n++];
        double a = 2.399963 * k; /* golden-angle spread around +y */
        double d[3] = {0.6 * cos(a), 0.8, 0.6 * sin(a)};
        sc_light_init(lt, k < n_dir             ? SC_LIGHT_DIRECTIONAL
                          : k < n_dir + n_point ? SC_LIGHT_POINT
                                                : SC_LIGHT_SPOT);
        for (int c = 0; c < 3; c++) {
            lt->pos[c] = 4.0 * d[c];
            lt->dir[c] = lt->kind == SC_LIGHT_SPOT ? -d[c] : d[c]; /* spots aim back */
            lt->intensity[c] = lt->kind == SC_LIGHT_DIRECTIONAL ? 1.0 : 16.0;
            lt->ambient[c] = 0.0;
        }
        lt->spot.kind = spots[k % 3]; /* the three kinds in turn; cones of 25° to 40° */
        lt->spot.cutoff = 40.0;
        lt->spot.inner = 25.0;
        lt->spot.outer = 40.0;
        lt->spot.exponent = 2.0;
    }
    *out = (sc_scene){lights, n, {0}, {0.02, 0.02, 0.02}};
    sc_model_init(&out->model, SC_MODEL_BRDF);
    sc_brdf_init(&out->model.brdf, brdf);
    static const double diff[3] = {0.8, 0.5, 0.2};
    for (int c = 0; c < 3; c++) {
        out->model.brdf.diff[c] = diff[c];
        out->model.brdf.spec[c] = brdf == SC_BRDF_COOK_TORRANCE ? 1.0 : 0.2;
        out->model.brdf.amb[c] = 1.0;
    }
}
