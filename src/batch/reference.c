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

/* The scene's BRDF as the library's double model (brdf.h). */
static void scene_brdf(const sc_batch_scene *s, sc_brdf *b)
{
    static const sc_brdf_kind kinds[] = {SC_BRDF_LAMBERT, SC_BRDF_BLINN_PHONG,
                                         SC_BRDF_COOK_TORRANCE};
    sc_brdf_init(b, kinds[s->brdf]);
    for (int c = 0; c < 3; c++) {
        b->diff[c] = s->diff[c];
        b->spec[c] = s->brdf == SC_BATCH_LAMBERT ? 0.0 : s->spec[c];
        b->f0[c] = s->f0;
    }
    b->m = s->m;
    b->ax = b->ay = s->alpha;
    b->D = SC_D_GGX;
    b->G = SC_G_SMITH_CORRELATED;
    b->F = SC_F_SCHLICK;
}

static double degrees_of(double cosine)
{
    return acos(fmax(-1.0, fmin(1.0, cosine))) * 57.29577951308232;
}

/* The batch light as light.h's light: the reference evaluates it with sc_light_eval. */
static void light_of(const sc_batch_light *b, sc_light *out)
{
    static const sc_light_kind kinds[] = {SC_LIGHT_DIRECTIONAL, SC_LIGHT_POINT, SC_LIGHT_SPOT};
    static const sc_spot_kind spots[] = {SC_SPOT_OPENGL, SC_SPOT_DIRECTX, SC_SPOT_SMOOTHSTEP};
    sc_light_init(out, kinds[b->kind]);
    for (int c = 0; c < 3; c++) {
        out->dir[c] = b->dir[c];
        out->pos[c] = b->pos[c];
        out->intensity[c] = b->color[c];
    }
    out->spot.kind = spots[b->spot];
    out->spot.exponent = b->exponent;
    out->spot.cutoff = b->cos_outer <= -1.0f ? 180.0 : degrees_of(b->cos_outer);
    out->spot.outer = degrees_of(b->cos_outer);
    out->spot.inner = degrees_of(b->cos_inner);
}

/* 1 if cos θ_s lies within 2^-16 of a hard edge of the light's cone, where the spot factor
 * jumps (opengl's cutoff, directx and smoothstep with inner = outer): there a rounding of l
 * decides between the lit and the unlit value, so no error bound can hold. */
static int at_hard_edge(const sc_batch_light *lt, double cos_s)
{
    double edge;
    if (lt->kind != SC_BATCH_SPOT)
        return 0;
    if (lt->spot == SC_BATCH_SPOT_OPENGL)
        edge = lt->cos_outer > -1.0f ? lt->cos_outer : 2.0;
    else
        edge = lt->cos_inner > lt->cos_outer ? 2.0 : lt->cos_inner;
    return fabs(cos_s - edge) < 0x1p-16;
}

/* out[0..2] the radiance; out[3] the scale of the allowance: ambient plus Σ E f without the
 * cosine (an error of ε in n·l, inevitable in float, moves the result by about ε E f); +Inf
 * (outside the stated domain) at a hard edge of a spot cone. */
void sc_batch_ref_shade(const sc_batch_args *a, size_t i, double *out)
{
    const sc_batch_scene *s = a->scene;
    double n[3], v[3], p[3];
    load3(a, 0, i, n);
    load3(a, 3, i, v);
    load3(a, 6, i, p);
    sc_brdf b;
    scene_brdf(s, &b);
    sc_frame frame;
    double vlen = sqrt(dot3(v, v));
    out[3] = 0.0;
    for (int c = 0; c < 3; c++) {
        out[c] = s->amb_term[c];
        out[3] = fmax(out[3], fabs(s->amb_term[c]));
    }
    if (sc_frame_make(n, NULL, &frame) != 0 || vlen == 0.0)
        return;
    for (int c = 0; c < 3; c++)
        v[c] /= vlen;
    double scale = 0.0;
    for (int k = 0; k < s->n_lights; k++) {
        sc_light light;
        sc_light_sample ls;
        light_of(&s->lights[k], &light);
        sc_light_eval(SC_DOUBLE, &light, p, frame.n, &ls);
        sc_brdf_terms t;
        sc_brdf_eval(SC_DOUBLE, &b, &frame, ls.l, v, &t);
        double cos_i = dot3(frame.n, ls.l);
        if (at_hard_edge(&s->lights[k], ls.cos_s))
            scale = INFINITY;
        for (int c = 0; c < 3; c++) {
            out[c] += cos_i > 0.0 ? t.f[c] * ls.E[c] * cos_i : 0.0;
            scale = fmax(scale, ls.E[c] * (b.diff[c] / 3.141592653589793 + t.specular[c]));
        }
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

static const char *const brdf_names[] = {"lambert", "blinn-phong", "ggx"};
const char *sc_batch_brdf_name(sc_batch_brdf brdf) { return brdf_names[brdf]; }

void sc_batch_scene_example(sc_batch_brdf brdf, int n_dir, int n_point, int n_spot,
                            sc_batch_scene *out)
{
    memset(out, 0, sizeof *out);
    out->brdf = brdf;
    for (int k = 0; k < n_dir + n_point + n_spot && k < SC_BATCH_MAX_LIGHTS; k++) {
        sc_batch_light *lt = &out->lights[out->n_lights++];
        double a = 2.399963 * k; /* golden-angle spread around +y */
        double d[3] = {0.6 * cos(a), 0.8, 0.6 * sin(a)};
        lt->kind = k < n_dir             ? SC_BATCH_DIRECTIONAL
                   : k < n_dir + n_point ? SC_BATCH_POINT
                                         : SC_BATCH_SPOT;
        for (int c = 0; c < 3; c++) {
            lt->pos[c] = (float)(4.0 * d[c]);
            lt->dir[c] = (float)(lt->kind == SC_BATCH_SPOT ? -d[c] : d[c]); /* spots aim back */
            lt->color[c] = lt->kind == SC_BATCH_DIRECTIONAL ? 1.0f : 16.0f;
        }
        lt->spot = (sc_batch_spot)(k % 3); /* the three kinds in turn; cones of 25° to 40° */
        lt->cos_inner = 0.906307787f;
        lt->cos_outer = 0.766044443f;
        lt->exponent = 2.0f;
    }
    const float diff[3] = {0.8f, 0.5f, 0.2f};
    for (int c = 0; c < 3; c++) {
        out->diff[c] = diff[c];
        out->spec[c] = brdf == SC_BATCH_GGX ? 1.0f : 0.2f;
        out->amb_term[c] = 0.02f;
    }
    out->m = 32.0f;
    out->alpha = 0.3f;
    out->f0 = 0.04f;
}
