/* The loops a user would write with libm, one per batch kernel: the baseline of `shadecalc
 * bench` ("speedup vs libm loop"), compiled here with the project's ordinary flags (-O2, no
 * -ffast-math). bench/fastmath_gcc.c and bench/fastmath_clang.c compile this same source with
 * -O3 -march=native -ffast-math (peer rows), defining BENCH_LOOPS_LOOKUP to their own name.
 * The loops are written so that compilers vectorise them: restrict arrays, no short-circuit
 * in the body (checked with gcc -fopt-info-vec and clang -Rpass=loop-vectorize). */
#include <math.h>
#include <string.h>

#include "bench/bench.h"

#ifndef BENCH_LOOPS_LOOKUP
#define BENCH_LOOPS_LOOKUP bench_libm_loop
#endif

static const float SC_PI_F = 3.14159265358979323846f;

#define LOOP1(name, expr)                                                                          \
    static void loop_##name(const sc_batch_args *a)                                                \
    {                                                                                              \
        const float *restrict x = a->in[0];                                                        \
        float *restrict out = a->out[0];                                                           \
        size_t n = a->n;                                                                           \
        for (size_t i = 0; i < n; i++)                                                             \
            out[i] = (expr);                                                                       \
    }
LOOP1(exp2, exp2f(x[i]))
LOOP1(exp, expf(x[i]))
LOOP1(log2, log2f(x[i]))
LOOP1(log, logf(x[i]))
LOOP1(inversesqrt, 1.0f / sqrtf(x[i]))
LOOP1(sqrt, sqrtf(x[i]))
LOOP1(sin, sinf(x[i]))
LOOP1(cos, cosf(x[i]))
LOOP1(acos, acosf(x[i]))

#define LOOP2(name, expr)                                                                          \
    static void loop_##name(const sc_batch_args *a)                                                \
    {                                                                                              \
        const float *restrict x = a->in[0], *restrict y = a->in[1];                                \
        float *restrict out = a->out[0];                                                           \
        size_t n = a->n;                                                                           \
        for (size_t i = 0; i < n; i++)                                                             \
            out[i] = (expr);                                                                       \
    }
LOOP2(atan2, atan2f(x[i], y[i]))
LOOP2(pow, powf(x[i], y[i]))

/* The vec3 loops take their arrays as restrict parameters: gcc 12 does not vectorise them
 * through restrict locals of three outputs. a = in[0..2], b = in[3..5]. */
#define VEC3_IN(a) (a)->in[0], (a)->in[1], (a)->in[2]
#define VEC3_OUT(a) (a)->out[0], (a)->out[1], (a)->out[2]
#define VEC3_PARAMS(x, y, z)                                                                       \
    const float *restrict x, const float *restrict y, const float *restrict z
#define VEC3_OUTS float *restrict ox, float *restrict oy, float *restrict oz

static void dot_arrays(VEC3_PARAMS(ax, ay, az), VEC3_PARAMS(bx, by, bz), float *restrict out,
                       size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = ax[i] * bx[i] + ay[i] * by[i] + az[i] * bz[i];
}
static void loop_dot(const sc_batch_args *a)
{
    dot_arrays(VEC3_IN(a), a->in[3], a->in[4], a->in[5], a->out[0], a->n);
}

static void reflect_arrays(VEC3_PARAMS(ax, ay, az), VEC3_PARAMS(bx, by, bz), VEC3_OUTS, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        float d = bx[i] * ax[i] + by[i] * ay[i] + bz[i] * az[i];
        ox[i] = ax[i] - 2.0f * d * bx[i];
        oy[i] = ay[i] - 2.0f * d * by[i];
        oz[i] = az[i] - 2.0f * d * bz[i];
    }
}
static void loop_reflect(const sc_batch_args *a)
{
    reflect_arrays(VEC3_IN(a), a->in[3], a->in[4], a->in[5], VEC3_OUT(a), a->n);
}

static void normalize_arrays(VEC3_PARAMS(x, y, z), VEC3_OUTS, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        float len = sqrtf(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
        ox[i] = x[i] / len;
        oy[i] = y[i] / len;
        oz[i] = z[i] / len;
    }
}
static void loop_normalize(const sc_batch_args *a)
{
    normalize_arrays(VEC3_IN(a), VEC3_OUT(a), a->n);
}

static void length_arrays(VEC3_PARAMS(x, y, z), float *restrict out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = sqrtf(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
}
static void loop_length(const sc_batch_args *a) { length_arrays(VEC3_IN(a), a->out[0], a->n); }

/* ---- the shading equation as a user writes it: float, sqrtf, powf ---- */

static float dot3(const float *a, const float *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit(float *v)
{
    float len = sqrtf(dot3(v, v));
    if (len > 0.0f)
        for (int c = 0; c < 3; c++)
            v[c] /= len;
}

/* The scene in float, as a user's program keeps it: lights, and the BRDF (lambert, normalized
 * blinn-phong or GGX: the bench's scenes). */
typedef struct {
    int kind, spot; /* sc_light_kind, sc_spot_kind */
    float dir[3], pos[3], color[3], cos_outer, cos_inner, exponent;
} user_light;

typedef struct {
    user_light lights[SC_BATCH_MAX_LIGHTS];
    int n_lights, brdf; /* sc_brdf_kind */
    float diff[3], spec[3], amb_term[3], m, alpha, f0;
} user_scene;

static void user_scene_of(const sc_scene *s, user_scene *u)
{
    const sc_brdf *b = &s->model.brdf;
    const float deg = SC_PI_F / 180.0f;
    u->n_lights = s->n_lights;
    u->brdf = (int)b->kind;
    for (int k = 0; k < s->n_lights; k++) {
        const sc_light *l = &s->lights[k];
        user_light *ul = &u->lights[k];
        ul->kind = (int)l->kind;
        ul->spot = (int)l->spot.kind;
        for (int c = 0; c < 3; c++) {
            ul->dir[c] = (float)l->dir[c];
            ul->pos[c] = (float)l->pos[c];
            ul->color[c] = (float)l->intensity[c];
        }
        ul->cos_outer = l->spot.kind == SC_SPOT_OPENGL
                            ? (l->spot.cutoff == 180.0 ? -2.0f : cosf((float)l->spot.cutoff * deg))
                            : cosf((float)l->spot.outer * deg);
        ul->cos_inner = cosf((float)l->spot.inner * deg);
        ul->exponent = (float)l->spot.exponent;
    }
    for (int c = 0; c < 3; c++) {
        u->diff[c] = (float)b->diff[c];
        u->spec[c] = (float)b->spec[c];
        u->amb_term[c] = (float)(b->amb[c] * s->ambient[c]);
    }
    u->m = (float)b->m;
    u->alpha = (float)b->ax;
    u->f0 = (float)b->f0[0];
}

static float specular(const user_scene *s, const float *n, const float *v, const float *l, float nl,
                      float nv)
{
    float h[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    unit(h);
    float nh = fmaxf(dot3(n, h), 0.0f);
    if (s->brdf == SC_BRDF_BLINN_PHONG)
        return (s->m + 8.0f) / (8.0f * SC_PI_F) * powf(nh, s->m);
    float a2 = s->alpha * s->alpha, d = nh * nh * (a2 - 1.0f) + 1.0f;
    float D = a2 / (SC_PI_F * d * d);
    float V = 0.5f /
              (nl * sqrtf(nv * nv * (1.0f - a2) + a2) + nv * sqrtf(nl * nl * (1.0f - a2) + a2));
    float F = s->f0 + (1.0f - s->f0) * powf(1.0f - fmaxf(dot3(v, h), 0.0f), 5.0f);
    return D * V * F;
}

static float spot(const user_light *lt, const float *l)
{
    float cos_s = -dot3(l, lt->dir);
    if (lt->spot == SC_SPOT_OPENGL)
        return lt->cos_outer <= -1.0f   ? 1.0f
               : cos_s >= lt->cos_outer ? powf(cos_s, lt->exponent)
                                        : 0.0f;
    if (cos_s >= lt->cos_inner)
        return 1.0f;
    if (cos_s <= lt->cos_outer)
        return 0.0f;
    float t = (cos_s - lt->cos_outer) / (lt->cos_inner - lt->cos_outer);
    return lt->spot == SC_SPOT_SMOOTHSTEP ? t * t * (3.0f - 2.0f * t) : powf(t, lt->exponent);
}

static void shade_one(const user_scene *s, float n[3], float v[3], const float p[3], float *rgb)
{
    unit(n);
    unit(v);
    float nv = dot3(n, v);
    for (int c = 0; c < 3; c++)
        rgb[c] = s->amb_term[c];
    for (int k = 0; k < s->n_lights; k++) {
        const user_light *lt = &s->lights[k];
        float l[3], e = 1.0f;
        memcpy(l, lt->dir, sizeof l);
        if (lt->kind != SC_LIGHT_DIRECTIONAL) {
            for (int c = 0; c < 3; c++)
                l[c] = lt->pos[c] - p[c];
            e = 1.0f / fmaxf(dot3(l, l), 1e-4f);
            unit(l);
            if (lt->kind == SC_LIGHT_SPOT)
                e *= spot(lt, l);
        }
        float nl = dot3(n, l);
        if (nl <= 0.0f || nv <= 0.0f)
            continue;
        float sp = s->brdf == SC_BRDF_LAMBERT ? 0.0f : specular(s, n, v, l, nl, nv);
        for (int c = 0; c < 3; c++)
            rgb[c] += (s->diff[c] / SC_PI_F + s->spec[c] * sp) * lt->color[c] * e * nl;
    }
}

/* params: the scene's plan (batch.h), whose double scene the loop copies to floats first */
static void loop_shade(const sc_batch_args *a)
{
    static _Thread_local user_scene s;
    user_scene_of(sc_batch_plan_scene(a->params), &s);
    for (size_t i = 0; i < a->n; i++) {
        float n[3], v[3], p[3], rgb[3];
        for (int c = 0; c < 3; c++) {
            n[c] = a->in[c][i];
            v[c] = a->in[3 + c][i];
            p[c] = a->in[6 + c][i];
        }
        shade_one(&s, n, v, p, rgb);
        for (int c = 0; c < 3; c++)
            a->out[c][i] = rgb[c];
    }
}

/* ---- attenuation, spot, and the BRDF of the table's row (cook-torrance GGX) ---- */

/* The parameters in float, as a user's program keeps them. */
typedef struct {
    float sc, sl, sq, r_start, r_end, f_max, f_c, r_c, s_e, r_max;
} user_atten;

static user_atten user_atten_of(const sc_atten *a)
{
    return (user_atten){(float)a->sc,    (float)a->sl,    (float)a->sq,  (float)a->r_start,
                        (float)a->r_end, (float)a->f_max, (float)a->f_c, (float)a->r_c,
                        (float)a->s_e,   (float)a->r_max};
}

typedef struct {
    float exponent, cutoff, inner, outer;
} user_spot;

static user_spot user_spot_of(const sc_spot *s)
{
    return (user_spot){(float)s->exponent, (float)s->cutoff, (float)s->inner, (float)s->outer};
}

#define ATTEN_LOOP(name, expr)                                                                     \
    static void loop_##name(const sc_batch_args *a)                                                \
    {                                                                                              \
        const user_atten p = user_atten_of(a->params);                                             \
        const float *restrict in = a->in[0];                                                       \
        float *restrict out = a->out[0];                                                           \
        size_t n = a->n;                                                                           \
        (void)p;                                                                                   \
        for (size_t i = 0; i < n; i++) {                                                           \
            float r = in[i];                                                                       \
            (void)r;                                                                               \
            out[i] = (expr);                                                                       \
        }                                                                                          \
    }
ATTEN_LOOP(atten_none, 1.0f)
ATTEN_LOOP(atten_invsq, 1.0f / fmaxf(r * r, 1e-4f))
ATTEN_LOOP(atten_clq, 1.0f / fmaxf(p.sc + p.sl * r + p.sq * r * r, 1e-4f))
ATTEN_LOOP(atten_window, r <= p.r_start ? 1.0f
                         : r >= p.r_end ? 0.0f
                                        : (p.r_end - r) / (p.r_end - p.r_start))
ATTEN_LOOP(atten_windowed, powf(fminf(fmaxf(1.0f - powf(r / p.r_max, 4.0f), 0.0f), 1.0f), 2.0f) /
                               fmaxf(r * r, 1e-4f))

static void loop_atten_pixar(const sc_batch_args *a)
{
    const user_atten p = user_atten_of(a->params);
    const float *restrict in = a->in[0];
    float *restrict out = a->out[0];
    float k0 = logf(p.f_c / p.f_max), k1 = p.s_e / k0;
    for (size_t i = 0; i < a->n; i++) {
        float r = in[i];
        out[i] = r > p.r_c          ? p.f_c * powf(p.r_c / r, p.s_e)
                 : p.f_c == p.f_max ? p.f_max
                                    : p.f_max * expf(k0 * powf(r / p.r_c, -k1));
    }
}

static const float deg_f = SC_PI_F / 180.0f;

static void loop_spot_opengl(const sc_batch_args *a)
{
    const user_spot p = user_spot_of(a->params);
    const float *restrict in = a->in[0];
    float *restrict out = a->out[0];
    float cu = cosf(p.cutoff * deg_f);
    for (size_t i = 0; i < a->n; i++) {
        float c = in[i];
        out[i] = p.cutoff == 180.0f ? 1.0f : c >= cu ? powf(fmaxf(c, 0.0f), p.exponent) : 0.0f;
    }
}

static void spot_loop(const sc_batch_args *a, int smooth)
{
    const user_spot p = user_spot_of(a->params);
    const float *restrict in = a->in[0];
    float *restrict out = a->out[0];
    float cp = cosf(p.inner * deg_f), cu = cosf(p.outer * deg_f);
    for (size_t i = 0; i < a->n; i++) {
        float c = in[i], t = (c - cu) / (cp - cu);
        float f = smooth ? t * t * (3.0f - 2.0f * t) : powf(t, p.exponent);
        out[i] = c >= cp ? 1.0f : c <= cu ? 0.0f : f;
    }
}
static void loop_spot_directx(const sc_batch_args *a) { spot_loop(a, 0); }
static void loop_spot_smoothstep(const sc_batch_args *a) { spot_loop(a, 1); }

/* f (or f cos θ_i) of cook-torrance GGX, Smith height-correlated, Schlick per channel */
static void loop_brdf(const sc_batch_args *a)
{
    const sc_brdf *p = a->params;
    float a2 = (float)(p->ax * p->ax), f0[3], diff[3], spec[3];
    for (int c = 0; c < 3; c++) {
        f0[c] = (float)p->f0[c];
        diff[c] = (float)p->diff[c];
        spec[c] = (float)p->spec[c];
    }
    for (size_t i = 0; i < a->n; i++) {
        float l[3], v[3], n[3];
        for (int c = 0; c < 3; c++) {
            l[c] = a->in[c][i];
            v[c] = a->in[3 + c][i];
            n[c] = a->in[6 + c][i];
        }
        unit(l);
        unit(v);
        unit(n);
        float nl = dot3(n, l), nv = dot3(n, v), h[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
        unit(h);
        float nh = fmaxf(dot3(n, h), 0.0f), d = nh * nh * (a2 - 1.0f) + 1.0f;
        float D = a2 / (SC_PI_F * d * d);
        float V = 0.5f /
                  (nl * sqrtf(nv * nv * (1.0f - a2) + a2) + nv * sqrtf(nl * nl * (1.0f - a2) + a2));
        float m5 = powf(1.0f - fmaxf(dot3(v, h), 0.0f), 5.0f);
        for (int c = 0; c < 3; c++) {
            float F = f0[c] + (1.0f - f0[c]) * m5;
            float f = diff[c] / SC_PI_F + spec[c] * D * V * F;
            a->out[c][i] = ((nl > 0.0f) & (nv > 0.0f)) ? f : 0.0f;
        }
    }
}

static const struct {
    const char *kernel;
    sc_batch_fn fn;
} loops[] = {
    {"exp2", loop_exp2},
    {"exp", loop_exp},
    {"log2", loop_log2},
    {"log", loop_log},
    {"pow", loop_pow},
    {"inversesqrt", loop_inversesqrt},
    {"sqrt", loop_sqrt},
    {"dot", loop_dot},
    {"reflect", loop_reflect},
    {"normalize", loop_normalize},
    {"length", loop_length},
    {"shade", loop_shade},
    {"sin", loop_sin},
    {"cos", loop_cos},
    {"acos", loop_acos},
    {"atan2", loop_atan2},
    {"atten_none", loop_atten_none},
    {"atten_invsq", loop_atten_invsq},
    {"atten_clq", loop_atten_clq},
    {"atten_window", loop_atten_window},
    {"atten_pixar", loop_atten_pixar},
    {"atten_windowed", loop_atten_windowed},
    {"spot_opengl", loop_spot_opengl},
    {"spot_directx", loop_spot_directx},
    {"spot_smoothstep", loop_spot_smoothstep},
    {"brdf", loop_brdf},
};

sc_batch_fn BENCH_LOOPS_LOOKUP(const char *kernel)
{
    for (size_t i = 0; i < sizeof loops / sizeof loops[0]; i++)
        if (strcmp(loops[i].kernel, kernel) == 0)
            return loops[i].fn;
    return NULL;
}
