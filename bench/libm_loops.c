/* The loops a user would write with libm, one per batch kernel: the baseline of `shadecalc
 * bench` ("speedup vs libm loop"), compiled here with the project's ordinary flags (-O2, no
 * -ffast-math). bench/fastmath_gcc.c and bench/fastmath_clang.c compile this same source with
 * -O3 -march=native -ffast-math (peer rows), defining BENCH_LOOPS_LOOKUP to their own name.
 * The loops are written so that compilers vectorise them: restrict arrays, no short-circuit
 * in the body (checked with gcc -fopt-info-vec and clang -Rpass=loop-vectorize). */
#include <math.h>
#include <string.h>

#include "bench/bench.h"
#include "simd/uniforms.h"

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

/* ---- vec3 values of the per-element functions below ----
 * The per-element functions are inlined into the loops (as a user who checked
 * -fopt-info-vec would mark them): a call in the body keeps the loop scalar. */
#if defined(__GNUC__)
#define LOOP_INLINE inline __attribute__((always_inline))
#else
#define LOOP_INLINE inline
#endif

typedef struct {
    float x, y, z;
} f3;

static LOOP_INLINE f3 f3_of(const float *v) { return (f3){v[0], v[1], v[2]}; }
static LOOP_INLINE f3 f3_sub(f3 a, f3 b) { return (f3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static LOOP_INLINE f3 f3_axpy(float t, f3 a, f3 b)
{
    return (f3){t * a.x + b.x, t * a.y + b.y, t * a.z + b.z};
}
static LOOP_INLINE float f3_dot(f3 a, f3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static LOOP_INLINE f3 f3_cross(f3 a, f3 b)
{
    return (f3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/* a / |a|; the zero vector stays zero */
static LOOP_INLINE f3 f3_unit(f3 a)
{
    float d = f3_dot(a, a), k = d > 0.0f ? 1.0f / sqrtf(d) : 0.0f;
    return (f3){a.x * k, a.y * k, a.z * k};
}
static LOOP_INLINE f3 f3_pick(int c, f3 a, f3 b)
{
    return (f3){c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

/* ---- the shading equation as a user writes it: float, sqrtf, powf ----
 * What is uniform over the scene (the BRDF, each light's kind and spot kind, the number of
 * lights) is decided outside the element loops. The elements go in L1-sized chunks: one loop
 * normalises the chunk's n and v into scratch arrays and sets the outputs to the ambient term,
 * then one loop per light, its body specialised for that light and the BRDF, adds the light's
 * term. The bodies are branch-free (selects, every operand computed). */

/* GGX D V = α²/(π d²) / (2 (n·l √(n·v² (1 − α²) + α²) + n·v √(n·l² (1 − α²) + α²))) */
static LOOP_INLINE float ggx_dv(float a2, float nh, float nl, float nv)
{
    float d = nh * nh * (a2 - 1.0f) + 1.0f;
    return a2 / (SC_PI_F * d * d) * 0.5f /
           (nl * sqrtf(nv * nv * (1.0f - a2) + a2) + nv * sqrtf(nl * nl * (1.0f - a2) + a2));
}

/* Schlick's (1 − v·h)⁵ */
static LOOP_INLINE float schlick_m5(f3 v, f3 h)
{
    return powf(1.0f - fmaxf(f3_dot(v, h), 0.0f), 5.0f);
}

/* The scene in float, as a user's program keeps it: lights, and the BRDF (lambert, normalized
 * blinn-phong or GGX: the bench's scenes). An OpenGL spot of cutoff 180° is a point light. */
typedef struct {
    int kind, spot; /* sc_light_kind, sc_spot_kind */
    float dir[3], pos[3], color[3], cos_outer, cos_inner, exponent;
} user_light;

typedef struct {
    user_light lights[SC_BATCH_MAX_LIGHTS];
    int n_lights, brdf; /* sc_brdf_kind */
    float diff_pi[3], spec[3], amb_term[3], m, blinn_norm, a2, f0;
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
        int uncut = l->spot.kind == SC_SPOT_OPENGL && l->spot.cutoff == 180.0;
        ul->kind = l->kind == SC_LIGHT_SPOT && uncut ? SC_LIGHT_POINT : (int)l->kind;
        ul->spot = (int)l->spot.kind;
        for (int c = 0; c < 3; c++) {
            ul->dir[c] = (float)l->dir[c];
            ul->pos[c] = (float)l->pos[c];
            ul->color[c] = (float)l->intensity[c];
        }
        ul->cos_outer = cosf(
            (float)(l->spot.kind == SC_SPOT_OPENGL ? l->spot.cutoff : l->spot.outer) * deg);
        ul->cos_inner = cosf((float)l->spot.inner * deg);
        ul->exponent = (float)l->spot.exponent;
    }
    for (int c = 0; c < 3; c++) {
        u->diff_pi[c] = (float)b->diff[c] / SC_PI_F;
        u->spec[c] = (float)b->spec[c];
        u->amb_term[c] = (float)(b->amb[c] * s->ambient[c]);
    }
    u->m = (float)b->m;
    u->blinn_norm = (u->m + 8.0f) / (8.0f * SC_PI_F);
    u->a2 = (float)(b->ax * b->ax);
    u->f0 = (float)b->f0[0];
}

/* The spot factor at cos_s = −l·d, spot a constant (sc_spot_kind) */
static LOOP_INLINE float spot_factor(const user_light *lt, int spot, float cos_s)
{
    if (spot == SC_SPOT_OPENGL)
        return cos_s >= lt->cos_outer ? powf(cos_s, lt->exponent) : 0.0f;
    float t = (cos_s - lt->cos_outer) / (lt->cos_inner - lt->cos_outer);
    float f = spot == SC_SPOT_SMOOTHSTEP ? t * t * (3.0f - 2.0f * t) : powf(t, lt->exponent);
    return cos_s >= lt->cos_inner ? 1.0f : cos_s <= lt->cos_outer ? 0.0f : f;
}

/* The unit direction to the light from p; *e its falloff × spot factor. kind, spot: constants */
static LOOP_INLINE f3 to_light(const user_light *lt, int kind, int spot, f3 p, float *e)
{
    if (kind == SC_LIGHT_DIRECTIONAL) {
        *e = 1.0f;
        return f3_of(lt->dir);
    }
    f3 d = f3_sub(f3_of(lt->pos), p), l = f3_unit(d);
    float falloff = 1.0f / fmaxf(f3_dot(d, d), 1e-4f);
    *e = kind == SC_LIGHT_SPOT ? falloff * spot_factor(lt, spot, -f3_dot(l, f3_of(lt->dir)))
                               : falloff;
    return l;
}

/* (c_diff/π + c_spec f_s) E e cos θ_i of one light at unit n, v; 0 where unlit. brdf: constant */
static LOOP_INLINE f3 light_term(const user_scene *s, const user_light *lt, int brdf, f3 n, f3 v,
                                 f3 l, float e)
{
    float nl = f3_dot(n, l), nv = f3_dot(n, v), sp = 0.0f;
    if (brdf != SC_BRDF_LAMBERT) {
        f3 h = f3_unit(f3_axpy(1.0f, l, v));
        float nh = fmaxf(f3_dot(n, h), 0.0f);
        sp = brdf == SC_BRDF_BLINN_PHONG
                 ? s->blinn_norm * powf(nh, s->m)
                 : ggx_dv(s->a2, nh, nl, nv) * (s->f0 + (1.0f - s->f0) * schlick_m5(v, h));
    }
    float w = e * nl;
    f3 t = {(s->diff_pi[0] + s->spec[0] * sp) * lt->color[0] * w,
            (s->diff_pi[1] + s->spec[1] * sp) * lt->color[1] * w,
            (s->diff_pi[2] + s->spec[2] * sp) * lt->color[2] * w};
    return f3_pick(fminf(nl, nv) > 0.0f, t, (f3){0.0f, 0.0f, 0.0f});
}

/* out += light lt's term over n elements of unit n and v; kind, spot, brdf: constants */
static LOOP_INLINE void light_loop(const user_scene *s, const user_light *lt, int kind, int spot,
                                   int brdf, VEC3_PARAMS(nx, ny, nz), VEC3_PARAMS(vx, vy, vz),
                                   VEC3_PARAMS(px, py, pz), VEC3_OUTS, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        f3 nn = {nx[i], ny[i], nz[i]}, vv = {vx[i], vy[i], vz[i]};
        float e;
        f3 l = to_light(lt, kind, spot, (f3){px[i], py[i], pz[i]}, &e);
        f3 t = light_term(s, lt, brdf, nn, vv, l, e);
        ox[i] += t.x;
        oy[i] += t.y;
        oz[i] += t.z;
    }
}

#define SHADE_PARAMS                                                                               \
    VEC3_PARAMS(nx, ny, nz), VEC3_PARAMS(vx, vy, vz), VEC3_PARAMS(px, py, pz), VEC3_OUTS, size_t n
#define SHADE_ARGS nx, ny, nz, vx, vy, vz, px, py, pz, ox, oy, oz, n

/* light_loop of lt's kind and spot kind, brdf a constant */
static LOOP_INLINE void light_loop_of(const user_scene *s, const user_light *lt, int brdf,
                                      SHADE_PARAMS)
{
    if (lt->kind == SC_LIGHT_DIRECTIONAL)
        light_loop(s, lt, SC_LIGHT_DIRECTIONAL, 0, brdf, SHADE_ARGS);
    else if (lt->kind == SC_LIGHT_POINT)
        light_loop(s, lt, SC_LIGHT_POINT, 0, brdf, SHADE_ARGS);
    else if (lt->spot == SC_SPOT_OPENGL)
        light_loop(s, lt, SC_LIGHT_SPOT, SC_SPOT_OPENGL, brdf, SHADE_ARGS);
    else if (lt->spot == SC_SPOT_DIRECTX)
        light_loop(s, lt, SC_LIGHT_SPOT, SC_SPOT_DIRECTX, brdf, SHADE_ARGS);
    else
        light_loop(s, lt, SC_LIGHT_SPOT, SC_SPOT_SMOOTHSTEP, brdf, SHADE_ARGS);
}

/* out += light lt's term over n elements, in the loop of the scene's BRDF and lt's kind */
static void add_light(const user_scene *restrict s, const user_light *restrict lt, SHADE_PARAMS)
{
    if (s->brdf == SC_BRDF_LAMBERT)
        light_loop_of(s, lt, SC_BRDF_LAMBERT, SHADE_ARGS);
    else if (s->brdf == SC_BRDF_BLINN_PHONG)
        light_loop_of(s, lt, SC_BRDF_BLINN_PHONG, SHADE_ARGS);
    else
        light_loop_of(s, lt, SC_BRDF_COOK_TORRANCE, SHADE_ARGS);
}

static void fill3(const float *v, VEC3_OUTS, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        ox[i] = v[0];
        oy[i] = v[1];
        oz[i] = v[2];
    }
}

/* Elements per chunk: its 12 arrays (24 KB) stay in L1 across the lights' loops */
enum { SHADE_CHUNK = 512 };

/* params: the scene's plan (batch.h), whose double scene the loop copies to floats first */
static void loop_shade(const sc_batch_args *a)
{
    static _Thread_local user_scene s;
    static _Thread_local float unit[6][SHADE_CHUNK]; /* n and v of the chunk, normalised */
    user_scene_of(sc_batch_plan_scene(a->params), &s);
    for (size_t i = 0; i < a->n; i += SHADE_CHUNK) {
        size_t n = a->n - i < SHADE_CHUNK ? a->n - i : SHADE_CHUNK;
        const float *p[3] = {a->in[6] + i, a->in[7] + i, a->in[8] + i};
        float *out[3] = {a->out[0] + i, a->out[1] + i, a->out[2] + i};
        for (int j = 0; j < 2; j++)
            normalize_arrays(a->in[3 * j] + i, a->in[3 * j + 1] + i, a->in[3 * j + 2] + i,
                             unit[3 * j], unit[3 * j + 1], unit[3 * j + 2], n);
        fill3(s.amb_term, out[0], out[1], out[2], n);
        for (int k = 0; k < s.n_lights; k++)
            add_light(&s, &s.lights[k], unit[0], unit[1], unit[2], unit[3], unit[4], unit[5], p[0],
                      p[1], p[2], out[0], out[1], out[2], n);
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

/* f of cook-torrance GGX, Smith height-correlated, Schlick per channel; b: sc_brdf_uniforms-like
 * floats of the row's BRDF (kd = c_diff/π) */
typedef struct {
    float a2, f0[3], kd[3], spec[3];
} user_ggx;

static void brdf_arrays(const user_ggx *restrict b, VEC3_PARAMS(lx, ly, lz),
                        VEC3_PARAMS(vx, vy, vz), VEC3_PARAMS(nx, ny, nz), VEC3_OUTS, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        f3 l = f3_unit((f3){lx[i], ly[i], lz[i]}), v = f3_unit((f3){vx[i], vy[i], vz[i]});
        f3 nn = f3_unit((f3){nx[i], ny[i], nz[i]}), h = f3_unit(f3_axpy(1.0f, l, v));
        float nl = f3_dot(nn, l), nv = f3_dot(nn, v);
        float dv = ggx_dv(b->a2, fmaxf(f3_dot(nn, h), 0.0f), nl, nv), m5 = schlick_m5(v, h);
        f3 f = {b->kd[0] + b->spec[0] * dv * (b->f0[0] + (1.0f - b->f0[0]) * m5),
                b->kd[1] + b->spec[1] * dv * (b->f0[1] + (1.0f - b->f0[1]) * m5),
                b->kd[2] + b->spec[2] * dv * (b->f0[2] + (1.0f - b->f0[2]) * m5)};
        f = f3_pick(fminf(nl, nv) > 0.0f, f, (f3){0.0f, 0.0f, 0.0f});
        ox[i] = f.x;
        oy[i] = f.y;
        oz[i] = f.z;
    }
}

static void loop_brdf(const sc_batch_args *a)
{
    const sc_brdf *p = a->params;
    user_ggx b = {.a2 = (float)(p->ax * p->ax)};
    for (int c = 0; c < 3; c++) {
        b.f0[c] = (float)p->f0[c];
        b.kd[c] = (float)p->diff[c] / SC_PI_F;
        b.spec[c] = (float)p->spec[c];
    }
    brdf_arrays(&b, VEC3_IN(a), a->in[3], a->in[4], a->in[5], a->in[6], a->in[7], a->in[8],
                VEC3_OUT(a), a->n);
}

/* ---- the area lights' approximations (area_* kernels) as a user writes them ----
 * The float formulas of light/area.c (representative point: sphere, tube) and light/ltc.c (LTC:
 * rect, disk as the 64-gon of equal area), with the BRDF of the kernels' scenes (GGX, Smith
 * height-correlated, Schlick with a grey F0 for the representative point). The uniforms are
 * the kernels' own (sc_uniforms_shade: the light's geometry in float, the LTC table at the
 * scene's α), computed once per call as the kernels do. Branches are selects, every operand
 * computed: the loop bodies have no short-circuit. */

/* Snyder's sphere irradiance at cos θ = ct, distance d > R (light/area.c) */
static LOOP_INLINE float sphere_irradiance(float ct, float d, float R)
{
    float sr = R / d, s2 = sr * sr, above = ct > 0.0f ? SC_PI_F * s2 * ct : 0.0f;
    float st = sqrtf(fmaxf(1.0f - ct * ct, 0.0f)), x = sqrtf(fmaxf((d - R) * (d + R), 0.0f)) / R;
    float y = fminf(fmaxf(-x * ct / fmaxf(st, 1e-30f), -1.0f), 1.0f);
    float s = st * sqrtf(fmaxf(1.0f - y * y, 0.0f));
    float e = (ct * acosf(y) - x * s) * s2 + atan2f(s, x);
    return ct * ct < s2 ? fmaxf(e, 0.0f) : above;
}

/* The emitter's irradiance over L_e on a plane of unit normal w (c: centre − p, dc = |c|):
 * the ball, plus a tube's line of width 2R; π inside the ball. */
static LOOP_INLINE float rp_irradiance(const sc_area_uniforms *u, int tube, f3 w, f3 c, float dc,
                                       f3 p)
{
    float e = sphere_irradiance(f3_dot(w, c) / dc, dc, u->radius);
    f3 l0 = f3_sub(f3_of(u->p0), p), l1 = f3_axpy(1.0f, f3_of(u->axis), l0);
    float a0 = sqrtf(f3_dot(l0, l0)), a1 = sqrtf(f3_dot(l1, l1)), den = a0 * a1 + f3_dot(l0, l1);
    float line = den > 0.0f ? (f3_dot(w, l0) / a0 + f3_dot(w, l1) / a1) / den : 0.0f;
    e += tube ? fmaxf(0.0f, u->line * line) : 0.0f;
    return dc <= u->radius ? SC_PI_F : e;
}

/* L_e ⊙ (c_diff/π E(n) + c_spec f_s(l_s) N E(l_s) cos θ_s) at one element (light/area.c) */
static LOOP_INLINE f3 representative(const sc_shade_uniforms *s, int tube, f3 n, f3 v, f3 p)
{
    const sc_area_uniforms *u = &s->lights[0].area;
    float R = u->radius, a2 = s->alpha * s->alpha;
    n = f3_unit(n);
    v = f3_unit(v);
    float nv = f3_dot(n, v);
    f3 c = f3_sub(f3_of(u->centre), p), r = f3_axpy(2.0f * nv, n, (f3){-v.x, -v.y, -v.z});
    float dc = sqrtf(f3_dot(c, c)), e_diffuse = rp_irradiance(u, tube, n, c, dc, p);
    /* the point of the axis closest to the reflected ray (the centre for a sphere) */
    f3 l0 = f3_sub(f3_of(u->p0), p), ld = f3_of(u->axis);
    float rd = f3_dot(r, ld), den = f3_dot(ld, ld) - rd * rd;
    float t = den > 0.0f ? fminf(fmaxf((f3_dot(r, l0) * rd - f3_dot(l0, ld)) / den, 0.0f), 1.0f)
                         : 0.5f;
    f3 L = tube ? f3_axpy(t, ld, l0) : c;
    float d = sqrtf(f3_dot(L, L));
    f3 C = f3_sub((f3){r.x * f3_dot(L, r), r.y * f3_dot(L, r), r.z * f3_dot(L, r)}, L);
    float cl = sqrtf(f3_dot(C, C)), toward = cl > 0.0f ? fminf(1.0f, R / cl) : 0.0f;
    f3 P = f3_axpy(toward, C, L);
    float pp = f3_dot(P, P);
    f3 ls = f3_pick((d <= R) | (pp == 0.0f), r, f3_unit(P));
    f3 h = f3_unit(f3_axpy(1.0f, ls, v));
    float cos_s = f3_dot(n, ls), nh = fmaxf(f3_dot(n, h), 0.0f);
    float F = s->f0 + (1.0f - s->f0) * powf(1.0f - fmaxf(f3_dot(v, h), 0.0f), 5.0f);
    float across = fminf(1.0f, s->alpha + R / (2.0f * d));
    float along = fminf(1.0f, s->alpha + u->half_along / (2.0f * d));
    float norm = d > 0.0f ? a2 / (across * along) : a2;
    float w = cos_s > 0.0f ? ggx_dv(a2, nh, cos_s, nv) * F * norm *
                                 rp_irradiance(u, tube, ls, c, dc, p) * cos_s
                           : 0.0f;
    f3 e = f3_of(s->lights[0].color), kd = f3_of(s->diff_pi), ks = f3_of(s->spec);
    f3 out = {e.x * (kd.x * e_diffuse + ks.x * w), e.y * (kd.y * e_diffuse + ks.y * w),
              e.z * (kd.z * e_diffuse + ks.z * w)};
    return f3_pick(nv > 0.0f, out, (f3){0.0f, 0.0f, 0.0f});
}

/* θ ẑ·ĉ/|c| of edge a→b (c = a × b, θ = atan2(|c|, a·b)); 0 for parallel ends */
static LOOP_INLINE float edge_term(f3 a, f3 b)
{
    f3 c = f3_cross(a, b);
    float s = sqrtf(f3_dot(c, c));
    return s > 0.0f ? atan2f(s, f3_dot(a, b)) * c.z / s : 0.0f;
}

/* A convex polygon's clipped edge sum, edge by edge (as the kernels clip it): each edge a→b
 * clipped to z >= 0, and the horizon edge from where the boundary leaves to where it enters. */
typedef struct {
    float sum;
    f3 exit, entry;
    int crossed;
} clip_sum;

/* Adds edge a→b where `valid`; *a2, *b2 its clipped ends; returns whether it is a segment. */
static LOOP_INLINE int clip_edge(f3 a, f3 b, int valid, clip_sum *cs, f3 *a2, f3 *b2)
{
    float den = a.z - b.z, t = a.z / (den == 0.0f ? 1.0f : den);
    f3 x = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0f};
    int a_out = a.z < 0.0f, b_out = b.z < 0.0f;
    int leaves = valid & !a_out & b_out, enters = valid & a_out & !b_out;
    *a2 = f3_pick(a_out, x, a);
    *b2 = f3_pick(b_out, x, b);
    cs->exit = f3_pick(leaves, x, cs->exit);
    cs->entry = f3_pick(enters, x, cs->entry);
    cs->crossed |= leaves;
    int seg = valid & (!a_out | !b_out);
    cs->sum += seg ? edge_term(*a2, *b2) : 0.0f;
    return seg;
}

/* M⁻¹ w, M⁻¹ = [[m00, 0, m02], [0, m11, 0], [m20, 0, 1]] */
static LOOP_INLINE f3 ltc_carry(const float *m, f3 w)
{
    return (f3){m[0] * w.x + m[1] * w.z, m[2] * w.y, m[3] * w.x + w.z};
}

/* L_e ⊙ (c_diff/π ∫cos̄ + (c_spec F0 A + c_spec (1 − F0) B) lobe share / mass) (light/ltc.c) */
static LOOP_INLINE f3 ltc(const sc_shade_uniforms *s, const float *ring, int sides, f3 n, f3 v,
                          f3 p)
{
    const sc_area_uniforms *u = &s->lights[0].area;
    n = f3_unit(n);
    v = f3_unit(v);
    float nv = f3_dot(n, v);
    f3 q = f3_sub(f3_of(u->centre), p);
    float h = -f3_dot(q, f3_of(u->normal));
    int seen = (h > 0.0f) | (u->two_sided & (h < 0.0f));
    /* the view frame: x = v in the tangent plane (a tangent where v is along n), y = n × x */
    f3 x = f3_axpy(-nv, n, v), t = {1.0f - n.x * n.x, -n.x * n.y, -n.x * n.z};
    f3 t_y = {-n.y * n.x, 1.0f - n.y * n.y, -n.y * n.z};
    x = f3_unit(f3_pick(f3_dot(x, x) < 0x1p-40f, f3_pick(fabsf(n.x) < 0.9f, t, t_y), x));
    f3 y = f3_cross(n, x), e1 = f3_of(u->e1), e2 = f3_of(u->e2);
    q = (f3){f3_dot(q, x), f3_dot(q, y), f3_dot(q, n)};
    e1 = (f3){f3_dot(e1, x), f3_dot(e1, y), f3_dot(e1, n)};
    e2 = (f3){f3_dot(e2, x), f3_dot(e2, y), f3_dot(e2, n)};
    /* the table's row at cos θ_v */
    float ty = sqrtf(1.0f - fminf(fmaxf(nv, 0.0f), 1.0f)) * (float)(SC_LTC_ROWS - 1), m[SC_LTC_ROW];
    int j = (int)ty > SC_LTC_ROWS - 2 ? SC_LTC_ROWS - 2 : (int)ty;
    const float *lo = s->ltc_rows[j], *hi = s->ltc_rows[j + 1], fy = ty - (float)j;
    m[0] = lo[0] + fy * (hi[0] - lo[0]), m[1] = lo[1] + fy * (hi[1] - lo[1]);
    m[2] = lo[2] + fy * (hi[2] - lo[2]), m[3] = lo[3] + fy * (hi[3] - lo[3]);
    m[4] = lo[4] + fy * (hi[4] - lo[4]), m[5] = lo[5] + fy * (hi[5] - lo[5]);
    /* both edge sums: the polygon clipped to the horizon, and its image under M⁻¹ clipped */
    f3 o = {0.0f, 0.0f, 0.0f}, a2, b2, c2, d2;
    clip_sum first = {0.0f, o, o, 0}, second = first;
    f3 v0 = f3_axpy(ring[0], e1, f3_axpy(ring[sides], e2, q)), a = v0;
    for (int k = 1; k <= sides; k++) {
        f3 b = k == sides ? v0 : f3_axpy(ring[k], e1, f3_axpy(ring[sides + k], e2, q));
        int seg = clip_edge(a, b, 1, &first, &a2, &b2);
        clip_edge(ltc_carry(m, a2), ltc_carry(m, b2), seg, &second, &c2, &d2);
        a = b;
    }
    first.sum += first.crossed ? edge_term(first.exit, first.entry) : 0.0f;
    clip_edge(ltc_carry(m, first.exit), ltc_carry(m, first.entry), first.crossed, &second, &c2,
              &d2);
    second.sum += second.crossed ? edge_term(second.exit, second.entry) : 0.0f;
    float cosine = fminf(0.5f * fabsf(first.sum), SC_PI_F);
    float lobe = fminf(0.5f / SC_PI_F * fabsf(second.sum), 1.0f);
    float det = m[0] - m[1] * m[3], len = sqrtf(m[0] * m[0] + m[3] * m[3]);
    float mass = ((det != 0.0f) & (len > 0.0f)) ? 0.5f * (1.0f + (det > 0.0f ? m[0] : -m[0]) / len)
                                                : 0.0f;
    float share = ((nv > 0.0f) & (mass > 1e-6f)) ? lobe / mass : 0.0f;
    f3 e = f3_of(s->lights[0].color), kd = f3_of(s->diff_pi);
    f3 spec = f3_axpy(m[4], f3_of(s->ltc_sa),
                      (f3){s->ltc_sb[0] * m[5], s->ltc_sb[1] * m[5], s->ltc_sb[2] * m[5]});
    f3 out = {e.x * (kd.x * cosine + spec.x * share), e.y * (kd.y * cosine + spec.y * share),
              e.z * (kd.z * cosine + spec.z * share)};
    return f3_pick(seen, out, (f3){0.0f, 0.0f, 0.0f});
}

/* The loop of one area kernel, element(s, n, v, p) the colour at each element, over restrict
 * parameters (see VEC3_PARAMS). params: an sc_scene of one area light (the kernels' NaN for
 * another is not repeated). */
#define AREA_LOOP(name, element)                                                                   \
    static void name##_arrays(const sc_shade_uniforms *restrict s, VEC3_PARAMS(nx, ny, nz),        \
                              VEC3_PARAMS(vx, vy, vz), VEC3_PARAMS(px, py, pz), VEC3_OUTS,         \
                              size_t n)                                                            \
    {                                                                                              \
        for (size_t i = 0; i < n; i++) {                                                           \
            f3 nn = {nx[i], ny[i], nz[i]}, vv = {vx[i], vy[i], vz[i]}, pp = {px[i], py[i], pz[i]}; \
            f3 rgb = element(s, nn, vv, pp);                                                       \
            ox[i] = rgb.x;                                                                         \
            oy[i] = rgb.y;                                                                         \
            oz[i] = rgb.z;                                                                         \
        }                                                                                          \
    }                                                                                              \
    static void loop_##name(const sc_batch_args *a)                                                \
    {                                                                                              \
        static _Thread_local sc_shade_uniforms s;                                                  \
        char why[8];                                                                               \
        if (sc_uniforms_shade(a->params, &s, why, sizeof why) == 0)                                \
            name##_arrays(&s, VEC3_IN(a), a->in[3], a->in[4], a->in[5], a->in[6], a->in[7],        \
                          a->in[8], VEC3_OUT(a), a->n);                                            \
    }
#define SPHERE(s, n, v, p) representative(s, 0, n, v, p)
#define TUBE(s, n, v, p) representative(s, 1, n, v, p)
#define RECT(s, n, v, p) ltc(s, &sc_area_ring_rect[0][0], 4, n, v, p)
#define DISK(s, n, v, p) ltc(s, &sc_area_ring_disk[0][0], 64, n, v, p)
AREA_LOOP(area_sphere, SPHERE)
AREA_LOOP(area_tube, TUBE)
AREA_LOOP(area_rect, RECT)
AREA_LOOP(area_disk, DISK)

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
    {"area_sphere", loop_area_sphere},
    {"area_tube", loop_area_tube},
    {"area_disk", loop_area_disk},
    {"area_rect", loop_area_rect},
};

sc_batch_fn BENCH_LOOPS_LOOKUP(const char *kernel)
{
    for (size_t i = 0; i < sizeof loops / sizeof loops[0]; i++)
        if (strcmp(loops[i].kernel, kernel) == 0)
            return loops[i].fn;
    return NULL;
}
