/*
 * shadecalc/vec.h — small by-value vectors with the GLSL ES geometric and common built-ins.
 *
 *   types           sc_vec2 {x,y}  sc_vec3 {x,y,z}  sc_vec4 {x,y,z,w}      (float, binary32)
 *                   sc_dvec3 {x,y,z}  sc_dvec4 {x,y,z,w}                   (double, the reference;
 *                   sc_dvec4 has no operations of its own: it is what sc_dmat4_mul_vec takes)
 *
 * For T = vec2, vec3, vec4 (float; a, b, x, lo, hi, i, n, nref are vectors, s, eta floats):
 *   sc_T_make(x, y[, z[, w]])   sc_T_splat(s)
 *   sc_T_add(a, b)  sc_T_sub(a, b)  sc_T_mul(a, b)  sc_T_div(a, b)     component-wise
 *   sc_T_scale(a, s)  sc_T_neg(a)
 *   sc_T_min(a, b)  sc_T_max(a, b)  sc_T_clamp(x, lo, hi)  sc_T_mix(a, b, t)  sc_T_abs(a)
 *                                   component-wise, each component as sc_minf ... sc_absf
 *   sc_T_dot(a, b)  sc_T_length(a)  sc_T_distance(a, b)  sc_T_normalize(a)
 *   sc_T_reflect(i, n)  sc_T_refract(i, n, eta)  sc_T_faceforward(n, i, nref)
 *   sc_vec3_cross(a, b)
 * For sc_dvec3 (double): make add sub scale dot length normalize cross reflect.
 *
 * Definitions (GLSL ES 3.00 §8.5; the same formulas, in the same order, as shadecalc/pmath.h,
 * so a float result here is bit-identical to `shadecalc eval` in highp):
 *   dot(a, b)        = ((a.x·b.x + a.y·b.y) + a.z·b.z) + a.w·b.w, summed left to right
 *   length(a)        = sqrt(dot(a, a))              sc_sqrtf (correctly rounded); libm sqrt
 *   distance(a, b)   = length(a − b)
 *   normalize(a)     = a / length(a), each component divided; the zero vector gives NaN (0/0:
 *                      GLSL ES leaves it undefined)
 *   reflect(I, N)    = I − (2·dot(N, I))·N          N is expected normalized; not renormalized
 *   refract(I, N, η) = k = 1 − η·η·(1 − dot(N,I)·dot(N,I)); the zero vector if k < 0, else
 *                      η·I − (η·dot(N,I) + sqrt(k))·N
 *   faceforward(N, I, Nref) = dot(Nref, I) < 0 ? N : −N
 *   cross(a, b)      = (a.y·b.z − b.y·a.z, a.z·b.x − b.z·a.x, a.x·b.y − b.x·a.y)
 *   mix(a, b, t)     = a·(1 − t) + b·t per component (sc_mixf)
 * Every operation is rounded to the vector's scalar type (FLT_EVAL_METHOD 0, no contraction).
 *
 * Choice: everything is `static inline` here (each is one expression per component) except
 * refract, which lives in src/vec.c. The bodies are generated per type by the SC_VEC_DEFINE_*
 * macros below from one definition each; SC_EACHn / SC_SUMn apply an expression to the
 * components of an n-vector (also used by shadecalc/mat.h).
 */
#ifndef SHADECALC_VEC_H
#define SHADECALC_VEC_H

#include <math.h>

#include "shadecalc/api.h"
#include "shadecalc/glsl.h"

SC_BEGIN_DECLS

typedef struct {
    float x, y;
} sc_vec2;
typedef struct {
    float x, y, z;
} sc_vec3;
typedef struct {
    float x, y, z, w;
} sc_vec4;
typedef struct {
    double x, y, z;
} sc_dvec3;
typedef struct {
    double x, y, z, w;
} sc_dvec4;

/* F(component, index) for each component, comma-separated; and their sum, left to right. */
#define SC_EACH2(F) F(x, 0), F(y, 1)
#define SC_EACH3(F) F(x, 0), F(y, 1), F(z, 2)
#define SC_EACH4(F) F(x, 0), F(y, 1), F(z, 2), F(w, 3)
#define SC_SUM2(F) (F(x, 0) + F(y, 1))
#define SC_SUM3(F) ((F(x, 0) + F(y, 1)) + F(z, 2))
#define SC_SUM4(F) (((F(x, 0) + F(y, 1)) + F(z, 2)) + F(w, 3))

/* Per-component expressions of the definitions below (arguments named as in those). */
// clang-format off
#define SC_VEC_SPLAT_(c, k) s
#define SC_VEC_ADD_(c, k) a.c + b.c
#define SC_VEC_SUB_(c, k) a.c - b.c
#define SC_VEC_MUL_(c, k) a.c * b.c
#define SC_VEC_DIV_(c, k) a.c / b.c
#define SC_VEC_SCALE_(c, k) a.c * s
#define SC_VEC_NEG_(c, k) -a.c
#define SC_VEC_DIV_LEN_(c, k) a.c / len
#define SC_VEC_REFLECT_(c, k) i.c - two_d * n.c
#define SC_VEC_FACE_(c, k) keep ? n.c : -n.c
#define SC_VEC_MIN_(c, k) sc_minf(a.c, b.c)
#define SC_VEC_MAX_(c, k) sc_maxf(a.c, b.c)
#define SC_VEC_CLAMP_(c, k) sc_clampf(x.c, lo.c, hi.c)
#define SC_VEC_MIX_(c, k) sc_mixf(a.c, b.c, t.c)
#define SC_VEC_ABS_(c, k) sc_absf(a.c)
// clang-format on

/* What both float and double vectors have: add sub scale dot length normalize reflect. */
#define SC_VEC_DEFINE_CORE(T, S, EACH, SUM, SQRT)                                                  \
    static inline T T##_add(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_ADD_)}; }                \
    static inline T T##_sub(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_SUB_)}; }                \
    static inline T T##_scale(T a, S s) { return SC_LITERAL_(T){EACH(SC_VEC_SCALE_)}; }            \
    static inline S T##_dot(T a, T b) { return SUM(SC_VEC_MUL_); }                                 \
    static inline S T##_length(T a) { return SQRT(T##_dot(a, a)); }                                \
    static inline T T##_normalize(T a)                                                             \
    {                                                                                              \
        S len = T##_length(a);                                                                     \
        return SC_LITERAL_(T){EACH(SC_VEC_DIV_LEN_)};                                              \
    }                                                                                              \
    static inline T T##_reflect(T i, T n)                                                          \
    {                                                                                              \
        S two_d = (S)2 * T##_dot(n, i);                                                            \
        return SC_LITERAL_(T){EACH(SC_VEC_REFLECT_)};                                              \
    }

/* The rest of the GLSL set, for the float vectors. */
#define SC_VEC_DEFINE_FLOAT(T, EACH, SUM)                                                          \
    SC_VEC_DEFINE_CORE(T, float, EACH, SUM, sc_sqrtf)                                              \
    static inline T T##_splat(float s) { return SC_LITERAL_(T){EACH(SC_VEC_SPLAT_)}; }             \
    static inline T T##_mul(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_MUL_)}; }                \
    static inline T T##_div(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_DIV_)}; }                \
    static inline T T##_neg(T a) { return SC_LITERAL_(T){EACH(SC_VEC_NEG_)}; }                     \
    static inline T T##_min(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_MIN_)}; }                \
    static inline T T##_max(T a, T b) { return SC_LITERAL_(T){EACH(SC_VEC_MAX_)}; }                \
    static inline T T##_clamp(T x, T lo, T hi) { return SC_LITERAL_(T){EACH(SC_VEC_CLAMP_)}; }     \
    static inline T T##_mix(T a, T b, T t) { return SC_LITERAL_(T){EACH(SC_VEC_MIX_)}; }           \
    static inline T T##_abs(T a) { return SC_LITERAL_(T){EACH(SC_VEC_ABS_)}; }                     \
    static inline float T##_distance(T a, T b) { return T##_length(T##_sub(a, b)); }               \
    static inline T T##_faceforward(T n, T i, T nref)                                              \
    {                                                                                              \
        int keep = T##_dot(nref, i) < 0.0f;                                                        \
        return SC_LITERAL_(T){EACH(SC_VEC_FACE_)};                                                 \
    }                                                                                              \
    T T##_refract(T i, T n, float eta);

/* cross(a, b) = (a.y·b.z − b.y·a.z, a.z·b.x − b.z·a.x, a.x·b.y − b.x·a.y), as GLSL ES. */
#define SC_VEC_DEFINE_CROSS(T)                                                                     \
    static inline T T##_cross(T a, T b)                                                            \
    {                                                                                              \
        return SC_LITERAL_(T){a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x,                        \
                              a.x * b.y - b.x * a.y};                                              \
    }

SC_VEC_DEFINE_FLOAT(sc_vec2, SC_EACH2, SC_SUM2)
SC_VEC_DEFINE_FLOAT(sc_vec3, SC_EACH3, SC_SUM3)
SC_VEC_DEFINE_FLOAT(sc_vec4, SC_EACH4, SC_SUM4)
SC_VEC_DEFINE_CROSS(sc_vec3)
SC_VEC_DEFINE_CORE(sc_dvec3, double, SC_EACH3, SC_SUM3, sqrt)
SC_VEC_DEFINE_CROSS(sc_dvec3)

static inline sc_vec2 sc_vec2_make(float x, float y) { return SC_LITERAL_(sc_vec2){x, y}; }
static inline sc_vec3 sc_vec3_make(float x, float y, float z)
{
    return SC_LITERAL_(sc_vec3){x, y, z};
}
static inline sc_vec4 sc_vec4_make(float x, float y, float z, float w)
{
    return SC_LITERAL_(sc_vec4){x, y, z, w};
}
static inline sc_dvec3 sc_dvec3_make(double x, double y, double z)
{
    return SC_LITERAL_(sc_dvec3){x, y, z};
}

SC_END_DECLS

#endif
