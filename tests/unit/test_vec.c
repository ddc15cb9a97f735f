/* The float and double vector types (shadecalc/vec.h) against independent references: each
 * function's GLSL ES formula evaluated in long double, with error bounds derived from the
 * standard model fl(a op b) = (a op b)(1 + δ), |δ| <= u (u = 2^-24 for float, 2^-53 for
 * double; γ_n = n·u / (1 − n·u), Higham, "Accuracy and Stability of Numerical Algorithms" §3),
 * the geometric identities (angle of reflection, Snell's law, orthogonality of the cross
 * product), and the contract with `shadecalc eval`: bit-identical to shadecalc/pmath.h in highp.
 * Every generic test runs over vec2, vec3 and vec4 through one adapter table per type. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "shadecalc/pmath.h"
#include "tests/support/splitmix.h"
#include "shadecalc/vec.h"

#define U_FLOAT 0x1p-24
#define U_DOUBLE 0x1p-53
/* Slack for the long double reference itself (exact enough on x86-64; where long double is
 * double, its own rounding error is of this size relative to the magnitudes involved). */
#define REF_SLACK 0x1p-50
#define N_RANDOM 20000

static double gamma_n(int n, double u) { return n * u / (1.0 - n * u); }

/* ---- deterministic random inputs (splitmix64) ------------------------------------------- */

static uint64_t rng_state = 0x243f6a8885a308d3u;

static uint64_t next_u64(void) { return splitmix_next(&rng_state); }

static double uniform(double lo, double hi) { return splitmix_uniform(&rng_state, lo, hi); }

/* A float of random sign and significand with its exponent uniform in [-8, 8]. */
static float random_float(void)
{
    float m = (float)uniform(1.0, 2.0);
    float x = ldexpf(m, (int)(next_u64() % 17) - 8);
    return next_u64() & 1 ? -x : x;
}

static void random_vector(int n, float *v)
{
    for (int k = 0; k < n; k++)
        v[k] = random_float();
}

/* A direction uniformly on the sphere (normalized in long double, then rounded to float). */
static void random_unit(int n, float *v)
{
    long double g[4], len2 = 0;
    do {
        len2 = 0;
        for (int k = 0; k < n; k++) {
            g[k] = uniform(-1.0, 1.0);
            len2 += g[k] * g[k];
        }
    } while (len2 < 0.01L || len2 > 1.0L);
    for (int k = 0; k < n; k++)
        v[k] = (float)(g[k] / sqrtl(len2));
}

static long double dot_ref(int n, const float *a, const float *b)
{
    long double s = 0;
    for (int k = 0; k < n; k++)
        s += (long double)a[k] * b[k];
    return s;
}

static double abs_dot(int n, const float *a, const float *b)
{
    double s = 0;
    for (int k = 0; k < n; k++)
        s += fabs((double)a[k] * b[k]);
    return s;
}

/* ---- one adapter table per vector type ---------------------------------------------------- */

typedef struct {
    int n;
    void (*add)(const float *, const float *, float *);
    void (*sub)(const float *, const float *, float *);
    void (*mul)(const float *, const float *, float *);
    void (*div)(const float *, const float *, float *);
    void (*min)(const float *, const float *, float *);
    void (*max)(const float *, const float *, float *);
    void (*scale)(const float *, float, float *);
    void (*neg)(const float *, float *);
    void (*abs)(const float *, float *);
    void (*clamp)(const float *, const float *, const float *, float *);
    void (*mix)(const float *, const float *, const float *, float *);
    float (*dot)(const float *, const float *);
    float (*length)(const float *);
    float (*distance)(const float *, const float *);
    void (*normalize)(const float *, float *);
    void (*reflect)(const float *, const float *, float *);
    void (*refract)(const float *, const float *, float, float *);
    void (*faceforward)(const float *, const float *, const float *, float *);
} vec_api;

#define LOAD_(c, k) p[k]
#define STORE_(c, k) p[k] = v.c
#define ADAPT_BINARY(T, OP)                                                                        \
    static void T##_t_##OP(const float *a, const float *b, float *o)                               \
    {                                                                                              \
        T##_t_store(T##_##OP(T##_t_load(a), T##_t_load(b)), o);                                    \
    }
#define ADAPT_UNARY(T, OP)                                                                         \
    static void T##_t_##OP(const float *a, float *o) { T##_t_store(T##_##OP(T##_t_load(a)), o); }
#define ADAPT(T, N, EACH)                                                                          \
    static T T##_t_load(const float *p) { return (T){EACH(LOAD_)}; }                               \
    static void T##_t_store(T v, float *p) { EACH(STORE_); }                                       \
    ADAPT_BINARY(T, add)                                                                           \
    ADAPT_BINARY(T, sub)                                                                           \
    ADAPT_BINARY(T, mul)                                                                           \
    ADAPT_BINARY(T, div)                                                                           \
    ADAPT_BINARY(T, min)                                                                           \
    ADAPT_BINARY(T, max)                                                                           \
    ADAPT_BINARY(T, reflect)                                                                       \
    ADAPT_UNARY(T, neg)                                                                            \
    ADAPT_UNARY(T, abs)                                                                            \
    ADAPT_UNARY(T, normalize)                                                                      \
    static void T##_t_scale(const float *a, float s, float *o)                                     \
    {                                                                                              \
        T##_t_store(T##_scale(T##_t_load(a), s), o);                                               \
    }                                                                                              \
    static void T##_t_clamp(const float *x, const float *lo, const float *hi, float *o)            \
    {                                                                                              \
        T##_t_store(T##_clamp(T##_t_load(x), T##_t_load(lo), T##_t_load(hi)), o);                  \
    }                                                                                              \
    static void T##_t_mix(const float *a, const float *b, const float *t, float *o)                \
    {                                                                                              \
        T##_t_store(T##_mix(T##_t_load(a), T##_t_load(b), T##_t_load(t)), o);                      \
    }                                                                                              \
    static void T##_t_faceforward(const float *n, const float *i, const float *r, float *o)        \
    {                                                                                              \
        T##_t_store(T##_faceforward(T##_t_load(n), T##_t_load(i), T##_t_load(r)), o);              \
    }                                                                                              \
    static void T##_t_refract(const float *i, const float *n, float eta, float *o)                 \
    {                                                                                              \
        T##_t_store(T##_refract(T##_t_load(i), T##_t_load(n), eta), o);                            \
    }                                                                                              \
    static float T##_t_dot(const float *a, const float *b)                                         \
    {                                                                                              \
        return T##_dot(T##_t_load(a), T##_t_load(b));                                              \
    }                                                                                              \
    static float T##_t_length(const float *a) { return T##_length(T##_t_load(a)); }                \
    static float T##_t_distance(const float *a, const float *b)                                    \
    {                                                                                              \
        return T##_distance(T##_t_load(a), T##_t_load(b));                                         \
    }                                                                                              \
    static const vec_api T##_api = {N,                                                             \
                                    T##_t_add,                                                     \
                                    T##_t_sub,                                                     \
                                    T##_t_mul,                                                     \
                                    T##_t_div,                                                     \
                                    T##_t_min,                                                     \
                                    T##_t_max,                                                     \
                                    T##_t_scale,                                                   \
                                    T##_t_neg,                                                     \
                                    T##_t_abs,                                                     \
                                    T##_t_clamp,                                                   \
                                    T##_t_mix,                                                     \
                                    T##_t_dot,                                                     \
                                    T##_t_length,                                                  \
                                    T##_t_distance,                                                \
                                    T##_t_normalize,                                               \
                                    T##_t_reflect,                                                 \
                                    T##_t_refract,                                                 \
                                    T##_t_faceforward};

ADAPT(sc_vec2, 2, SC_EACH2)
ADAPT(sc_vec3, 3, SC_EACH3)
ADAPT(sc_vec4, 4, SC_EACH4)

static const vec_api *const apis[] = {&sc_vec2_api, &sc_vec3_api, &sc_vec4_api};
#define FOR_EACH_API(api) for (const vec_api *const *api = apis; api < apis + 3; api++)

/* ---- component-wise operations ---------------------------------------------------------- */

/* One IEEE operation on floats, done in double and rounded once, is the correctly rounded
 * float result (53 >= 2·24 + 2), so + − × ÷ must match it exactly; min max abs clamp are exact. */
static void componentwise_operations_are_correctly_rounded(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], b[4], c[4], o[4];
        random_vector(n, a);
        random_vector(n, b);
        random_vector(n, c);
        float s = random_float(), lo[4], hi[4];
        for (int k = 0; k < n; k++)
            lo[k] = fminf(b[k], c[k]), hi[k] = fmaxf(b[k], c[k]);
#define CHECK_OP(FN, EXPR)                                                                         \
    do {                                                                                           \
        FN;                                                                                        \
        for (int k = 0; k < n; k++)                                                                \
            if (o[k] != (float)(EXPR))                                                             \
                fail_msg(#FN " component %d: %a, want %a", k, o[k], (float)(EXPR));                \
    } while (0)
        CHECK_OP((*api)->add(a, b, o), (double)a[k] + b[k]);
        CHECK_OP((*api)->sub(a, b, o), (double)a[k] - b[k]);
        CHECK_OP((*api)->mul(a, b, o), (double)a[k] * b[k]);
        CHECK_OP((*api)->div(a, b, o), (double)a[k] / b[k]);
        CHECK_OP((*api)->scale(a, s, o), (double)a[k] * s);
        CHECK_OP((*api)->neg(a, o), -(double)a[k]);
        CHECK_OP((*api)->abs(a, o), fabs(a[k]));
        CHECK_OP((*api)->min(a, b, o), fmin(a[k], b[k]));
        CHECK_OP((*api)->max(a, b, o), fmax(a[k], b[k]));
        CHECK_OP((*api)->clamp(a, lo, hi, o), fmin(fmax(a[k], lo[k]), hi[k]));
#undef CHECK_OP
    }
}

/* mix(a, b, t) = a·(1 − t) + b·t: four roundings, so within
 * u·|a(1−t)|·(2 + u) + u·|b·t| + u·(1 + 2u)·(|a(1−t)| + |b·t|) <= 3.01·u·(|a(1−t)| + |b·t|). */
static void mix_is_within_its_rounding_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], b[4], w[4], o[4];
        random_vector(n, a);
        random_vector(n, b);
        for (int k = 0; k < n; k++)
            w[k] = (float)uniform(-0.5, 1.5);
        (*api)->mix(a, b, w, o);
        for (int k = 0; k < n; k++) {
            long double pa = (long double)a[k] * (1.0L - w[k]), pb = (long double)b[k] * w[k];
            double bound = 3.01 * U_FLOAT * (double)(fabsl(pa) + fabsl(pb));
            if (!(fabsl(o[k] - (pa + pb)) <= bound))
                fail_msg("mix error %Lg > %g", fabsl(o[k] - (pa + pb)), bound);
        }
    }
}

/* ---- dot, length, distance, normalize ----------------------------------------------------- */

/* Recursive summation of n rounded products: |dot − exact| <= γ_n·Σ|a_k·b_k|. */
static void dot_is_within_the_summation_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], b[4];
        random_vector(n, a);
        random_vector(n, b);
        double err = (double)fabsl((*api)->dot(a, b) - dot_ref(n, a, b));
        double bound = (gamma_n(n, U_FLOAT) + REF_SLACK) * abs_dot(n, a, b);
        if (!(err <= bound))
            fail_msg("vec%d dot error %g > %g", n, err, bound);
    }
}

/* The stated order ((x·x' + y·y') + z·z') + w·w': 1e8 + 1 rounds back to 1e8 in binary32
 * (spacing 8 there), so the order decides between 0 and 1. */
static void dot_sums_left_to_right(void **state)
{
    (void)state;
    sc_vec3 ones3 = sc_vec3_splat(1.0f);
    assert_true(sc_vec3_dot(sc_vec3_make(1e8f, 1.0f, -1e8f), ones3) == 0.0f);
    assert_true(sc_vec3_dot(sc_vec3_make(1e8f, -1e8f, 1.0f), ones3) == 1.0f);
    assert_true(sc_vec4_dot(sc_vec4_make(1.0f, 1e8f, -1e8f, 1.0f), sc_vec4_splat(1.0f)) == 1.0f);
    assert_true(sc_vec2_dot(sc_vec2_make(3.0f, 4.0f), sc_vec2_make(5.0f, -6.0f)) == -9.0f);
}

/* length = sqrt(dot(a, a)): the sum of squares is within γ_n relative (all terms >= 0), the
 * square root halves that and adds one rounding: relative error <= γ_n/2 + u, to first order;
 * (1 + 2u) covers the rest. distance rounds each difference first (a relative 2u on each
 * square): γ_(n+2)/2 + u. */
static void length_and_distance_are_within_their_bounds(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], b[4];
        random_vector(n, a);
        random_vector(n, b);
        long double len = sqrtl(dot_ref(n, a, a)), d2 = 0;
        for (int k = 0; k < n; k++)
            d2 += ((long double)a[k] - b[k]) * ((long double)a[k] - b[k]);
        double rel_len = (double)(fabsl((*api)->length(a) - len) / len);
        double rel_dist = (double)(fabsl((*api)->distance(a, b) - sqrtl(d2)) / sqrtl(d2));
        double bound_len = (gamma_n(n, U_FLOAT) / 2 + U_FLOAT) * (1 + 2 * U_FLOAT) + REF_SLACK;
        double bound_dist = (gamma_n(n + 2, U_FLOAT) / 2 + U_FLOAT) * (1 + 2 * U_FLOAT) + REF_SLACK;
        if (!(rel_len <= bound_len && rel_dist <= bound_dist))
            fail_msg("vec%d length %g (<= %g), distance %g (<= %g)", n, rel_len, bound_len,
                     rel_dist, bound_dist);
    }
}

/* normalize = a / length(a): the length carries γ_n/2 + u, each division one more u, so every
 * component is within (γ_n/2 + 2u)(1 + 4u) relative of a_k/|a| and the result's length within
 * the same of 1 (a few units of 2^-24: 3u for vec2, 4u for vec4). */
static void normalize_gives_unit_length(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], o[4];
        random_vector(n, a);
        (*api)->normalize(a, o);
        long double len = sqrtl(dot_ref(n, a, a));
        double bound = (gamma_n(n, U_FLOAT) / 2 + 2 * U_FLOAT) * (1 + 4 * U_FLOAT) + REF_SLACK;
        for (int k = 0; k < n; k++) {
            long double want = a[k] / len;
            if (!(fabsl(o[k] - want) <= bound * fabsl(want)))
                fail_msg("vec%d normalize component %d off by %Lg", n, k, fabsl(o[k] - want));
        }
        double unit_err = (double)fabsl(sqrtl(dot_ref(n, o, o)) - 1.0L);
        if (!(unit_err <= bound))
            fail_msg("vec%d |normalize| - 1 = %g > %g", n, unit_err, bound);
    }
}

static void normalize_of_zero_is_nan(void **state)
{
    (void)state;
    sc_vec3 z = sc_vec3_normalize(sc_vec3_splat(0.0f));
    assert_true(isnan(z.x) && isnan(z.y) && isnan(z.z));
}

/* ---- reflect, refract, faceforward ---------------------------------------------------------- */

/* reflect: t = 2·dot(N, I) carries 2γ_n·S (S = Σ|N_k I_k|); then I_c − t·N_c adds two roundings:
 * |R_c − exact| <= u·|I_c| + (2γ_n + 4.01u)·S·|N_c|. */
static void reflect_is_within_its_rounding_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float i[4], nrm[4], r[4];
        random_vector(n, i);
        random_unit(n, nrm);
        (*api)->reflect(i, nrm, r);
        long double two_d = 2 * dot_ref(n, nrm, i);
        double s = abs_dot(n, nrm, i);
        for (int k = 0; k < n; k++) {
            long double want = i[k] - two_d * nrm[k];
            double bound = U_FLOAT * fabs(i[k]) +
                           (2 * gamma_n(n, U_FLOAT) + 4.01 * U_FLOAT) * s * fabs(nrm[k]) +
                           REF_SLACK * (fabs(i[k]) + 2 * s);
            if (!(fabsl(r[k] - want) <= bound))
                fail_msg("vec%d reflect component %d off by %Lg > %g", n, k, fabsl(r[k] - want),
                         bound);
        }
    }
}

/* For unit I and N (unit within ~2u after rounding to float) the angle of reflection equals
 * the angle of incidence, dot(R, N) = −dot(I, N), and |R| = |I| = 1. The component bound
 * above is at most ~(3n + 5)u here; 64u covers it and the non-unit rounding of N. */
static void reflect_angle_equals_incidence_angle(void **state)
{
    (void)state;
    const double tol = 64 * U_FLOAT;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float i[4], nrm[4], r[4];
        random_unit(n, i);
        random_unit(n, nrm);
        (*api)->reflect(i, nrm, r);
        assert_true(fabsl(dot_ref(n, r, nrm) + dot_ref(n, i, nrm)) <= tol);
        assert_true(fabsl(sqrtl(dot_ref(n, r, r)) - 1.0L) <= tol);
    }
    /* Worked: I = (1, −1, 0) against the floor N = (0, 1, 0) bounces to (1, 1, 0). */
    sc_vec3 r = sc_vec3_reflect(sc_vec3_make(1, -1, 0), sc_vec3_make(0, 1, 0));
    assert_true(r.x == 1.0f && r.y == 1.0f && r.z == 0.0f);
}

/* Error bound of refract by propagating absolute errors through each step of the formula
 * (first order, each rounding u relative to the magnitude of its result, ×1.01 for the
 * second-order terms). Valid for k >= 1/16, where sqrt amplifies an error in k by <= 2. */
static double refract_bound(int n, const float *i, const float *nrm, float eta, int c)
{
    const double u = U_FLOAT;
    double d = (double)dot_ref(n, nrm, i), ad = fabs(d), e2 = (double)eta * eta;
    double e_d = gamma_n(n, u) * abs_dot(n, nrm, i);
    double e_dd = 2 * ad * e_d + e_d * e_d + u * (ad + e_d) * (ad + e_d);
    double om = fabs(1 - d * d), e_om = e_dd + u * (om + e_dd);
    double e_ee = u * e2, e_pr = e2 * e_om + om * e_ee + e_ee * e_om + u * (e2 * om + e_om);
    double k = 1 - e2 * (1 - d * d), e_k = e_pr + u * (k + e_pr);
    double e_sq = e_k / sqrt(k) + u * (sqrt(k) + e_k);
    double s = fabs((double)eta * d) + sqrt(k);
    double e_s = fabs((double)eta) * e_d + u * fabs((double)eta) * (ad + e_d) + e_sq +
                 u * (s + e_sq + e_d);
    double ei = fabs((double)eta * i[c]), sn = (s + e_s) * fabs(nrm[c]);
    double e_out = u * ei + fabs(nrm[c]) * e_s + u * sn + u * (ei + sn) * (1 + u);
    return 1.01 * e_out + REF_SLACK * (ei + sn);
}

static void refract_is_within_its_rounding_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float i[4], nrm[4], o[4];
        random_unit(n, i);
        random_unit(n, nrm);
        float eta = (float)uniform(0.3, 2.0);
        long double d = dot_ref(n, nrm, i), k = 1 - (long double)eta * eta * (1 - d * d);
        if (k < 1.0L / 16)
            continue;
        (*api)->refract(i, nrm, eta, o);
        long double s = eta * d + sqrtl(k);
        for (int c = 0; c < n; c++) {
            long double want = eta * (long double)i[c] - s * nrm[c];
            double bound = refract_bound(n, i, nrm, eta, c);
            if (!(fabsl(o[c] - want) <= bound))
                fail_msg("vec%d refract component %d off by %Lg > %g", n, c, fabsl(o[c] - want),
                         bound);
        }
    }
}

/* Snell's law for unit I and N: sin θt = η·sin θi, i.e. |T × N| = η·|I × N|, with T unit and in
 * the plane of I and N, on the far side of the surface. Tolerance 64u as for reflect (the
 * per-component bound above is below ~30u for η <= 2, k >= 1/16). */
static void refract_obeys_snells_law(void **state)
{
    (void)state;
    const double tol = 64 * U_FLOAT;
    for (int t = 0; t < N_RANDOM; t++) {
        float i[3], nrm[3];
        random_unit(3, i);
        random_unit(3, nrm);
        if (dot_ref(3, nrm, i) > 0) /* light arrives against the normal */
            for (int k = 0; k < 3; k++)
                i[k] = -i[k];
        float eta = (float)uniform(0.3, 2.0);
        long double d = dot_ref(3, nrm, i), k = 1 - (long double)eta * eta * (1 - d * d);
        if (k < 1.0L / 16)
            continue;
        sc_vec3 tv = sc_vec3_refract(sc_vec3_make(i[0], i[1], i[2]),
                                     sc_vec3_make(nrm[0], nrm[1], nrm[2]), eta);
        sc_dvec3 T = {tv.x, tv.y, tv.z}, I = {i[0], i[1], i[2]}, N = {nrm[0], nrm[1], nrm[2]};
        double sin_t = sc_dvec3_length(sc_dvec3_cross(T, N));
        double sin_i = sc_dvec3_length(sc_dvec3_cross(I, N));
        assert_true(fabs(sin_t - eta * sin_i) <= tol);
        assert_true(fabs(sc_dvec3_length(T) - 1.0) <= tol);
        assert_true(fabs(sc_dvec3_dot(T, sc_dvec3_cross(I, N))) <= tol);
        assert_true(sc_dvec3_dot(T, N) < 0.0);
    }
}

/* k < 0 (sin θi > 1/η): total internal reflection, the zero vector. Worked: 60° incidence from
 * glass to air, η = 1.5: k = 1 − 2.25·0.75 < 0. At normal incidence T = I for every η. */
static void total_internal_reflection_gives_zero(void **state)
{
    (void)state;
    sc_vec3 nrm = sc_vec3_make(0, 1, 0);
    sc_vec3 i = sc_vec3_make(sc_sinf(1.0471975f), -sc_cosf(1.0471975f), 0);
    sc_vec3 t = sc_vec3_refract(i, nrm, 1.5f);
    assert_true(t.x == 0.0f && t.y == 0.0f && t.z == 0.0f);
    FOR_EACH_API(api)
    for (int c = 0; c < 200; c++) {
        int n = (*api)->n;
        float iv[4], nv[4], o[4];
        random_unit(n, iv);
        random_unit(n, nv);
        long double d = dot_ref(n, nv, iv);
        float eta = 1.0f / (float)sqrtl(1 - d * d) * 1.01f; /* η·sin θi = 1.01 > 1 */
        if (fabsl(d) > 0.99L)
            continue;
        (*api)->refract(iv, nv, eta, o);
        for (int k = 0; k < n; k++)
            assert_true(o[k] == 0.0f);
    }
    sc_vec3 down = sc_vec3_make(0, -1, 0);
    t = sc_vec3_refract(down, nrm, 1.33f);
    assert_true(t.x == 0.0f && t.y == -1.0f && t.z == 0.0f);
}

/* faceforward(N, I, Nref) = N when dot(Nref, I) < 0, else −N (exact). */
static void faceforward_turns_against_the_incident_direction(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float nv[4], iv[4], rv[4], o[4];
        random_vector(n, nv);
        random_vector(n, iv);
        random_vector(n, rv);
        long double d = dot_ref(n, rv, iv);
        if (fabsl(d) <= 2 * gamma_n(n, U_FLOAT) * abs_dot(n, rv, iv))
            continue; /* the rounded sign is not determined */
        (*api)->faceforward(nv, iv, rv, o);
        for (int k = 0; k < n; k++)
            assert_true(o[k] == (d < 0 ? nv[k] : -nv[k]));
    }
}

/* ---- cross ---------------------------------------------------------------------------------- */

/* Each component is x − y of two rounded products: |error| <= (2u + u²)(|x| + |y|). The
 * result is orthogonal to a and b up to that error, and e_x × e_y = e_z (right-handed). */
static void cross_is_orthogonal_and_within_its_bound(void **state)
{
    (void)state;
    for (int t = 0; t < N_RANDOM; t++) {
        float a[3], b[3];
        random_vector(3, a);
        random_vector(3, b);
        sc_vec3 c = sc_vec3_cross(sc_vec3_make(a[0], a[1], a[2]), sc_vec3_make(b[0], b[1], b[2]));
        float cv[3] = {c.x, c.y, c.z};
        double err_dot_a = 0, err_dot_b = 0;
        for (int k = 0; k < 3; k++) {
            int p = (k + 1) % 3, q = (k + 2) % 3;
            long double x = (long double)a[p] * b[q], y = (long double)b[p] * a[q];
            double bound = (2 * U_FLOAT + U_FLOAT * U_FLOAT) * (double)(fabsl(x) + fabsl(y));
            assert_true(fabsl(cv[k] - (x - y)) <=
                        bound + REF_SLACK * (double)(fabsl(x) + fabsl(y)));
            err_dot_a += bound * fabs(a[k]);
            err_dot_b += bound * fabs(b[k]);
        }
        assert_true(fabsl(dot_ref(3, cv, a)) <= err_dot_a * (1 + REF_SLACK) + 1e-300);
        assert_true(fabsl(dot_ref(3, cv, b)) <= err_dot_b * (1 + REF_SLACK) + 1e-300);
    }
    sc_vec3 z = sc_vec3_cross(sc_vec3_make(1, 0, 0), sc_vec3_make(0, 1, 0));
    assert_true(z.x == 0.0f && z.y == 0.0f && z.z == 1.0f);
}

/* ---- the contract with shadecalc eval ------------------------------------------------------ */

/* Same formulas, same order, each operation rounded to binary32: bit-identical to pmath highp. */
static void float_vectors_match_eval_highp_bit_for_bit(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        float a[4], b[4], c[4], o[4];
        double ad[4], bd[4], cd[4], od[4];
        random_vector(n, a);
        random_vector(n, b);
        random_vector(n, c);
        if (t % 2)
            random_unit(n, b);
        for (int k = 0; k < n; k++)
            ad[k] = a[k], bd[k] = b[k], cd[k] = c[k];
        float eta = (float)uniform(0.2, 2.5);
        assert_true((*api)->dot(a, b) == sc_p_dot(SC_HIGHP, ad, bd, n));
        assert_true((*api)->length(a) == sc_p_length(SC_HIGHP, ad, n));
        assert_true((*api)->distance(a, b) == sc_p_distance(SC_HIGHP, ad, bd, n));
#define SAME(CALL, PCALL)                                                                          \
    do {                                                                                           \
        CALL;                                                                                      \
        PCALL;                                                                                     \
        for (int k = 0; k < n; k++)                                                                \
            if (o[k] != od[k])                                                                     \
                fail_msg(#CALL " vec%d component %d: %a vs eval %a", n, k, o[k], od[k]);           \
    } while (0)
        SAME((*api)->normalize(a, o), sc_p_normalize(SC_HIGHP, ad, n, od));
        SAME((*api)->reflect(a, b, o), sc_p_reflect(SC_HIGHP, ad, bd, n, od));
        SAME((*api)->refract(a, b, eta, o), sc_p_refract(SC_HIGHP, ad, bd, eta, n, od));
        SAME((*api)->faceforward(a, b, c, o), sc_p_faceforward(SC_HIGHP, ad, bd, cd, n, od));
        if (n == 3) {
            sc_vec3 x = sc_vec3_cross(sc_vec3_make(a[0], a[1], a[2]),
                                      sc_vec3_make(b[0], b[1], b[2]));
            sc_p_cross(SC_HIGHP, ad, bd, od);
            assert_true(x.x == od[0] && x.y == od[1] && x.z == od[2]);
        }
#undef SAME
    }
}

/* ---- sc_dvec3 -------------------------------------------------------------------------------- */

/* The same formulas in binary64 (u = 2^-53), against long double: dot within γ_3·Σ|a_k b_k|,
 * normalize to unit length within (γ_3/2 + 2u)(1 + 4u), cross orthogonal within its bound,
 * reflect preserving length for unit N. On a platform whose long double is double, the
 * reference shares the bound, hence the factor 2. */
static void dvec3_meets_the_double_bounds(void **state)
{
    (void)state;
    const double u = U_DOUBLE, ref = LDBL_MANT_DIG > 53 ? 1.0 : 2.0;
    for (int t = 0; t < N_RANDOM; t++) {
        sc_dvec3 a = {uniform(-100, 100), uniform(-100, 100), uniform(-100, 100)};
        sc_dvec3 b = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        long double exact = (long double)a.x * b.x + (long double)a.y * b.y +
                            (long double)a.z * b.z;
        double mag = fabs(a.x * b.x) + fabs(a.y * b.y) + fabs(a.z * b.z);
        assert_true(fabsl(sc_dvec3_dot(a, b) - exact) <= ref * gamma_n(3, u) * mag * (1 + 4 * u));

        sc_dvec3 nrm = sc_dvec3_normalize(b);
        long double l2 = (long double)nrm.x * nrm.x + (long double)nrm.y * nrm.y +
                         (long double)nrm.z * nrm.z;
        double unit_bound = ref * (gamma_n(3, u) / 2 + 2 * u) * (1 + 4 * u);
        assert_true(fabsl(sqrtl(l2) - 1) <= unit_bound);

        sc_dvec3 c = sc_dvec3_cross(a, b);
        double mag_c = (fabs(a.y * b.z) + fabs(b.y * a.z)) * fabs(a.x) +
                       (fabs(a.z * b.x) + fabs(b.z * a.x)) * fabs(a.y) +
                       (fabs(a.x * b.y) + fabs(b.x * a.y)) * fabs(a.z);
        long double ca = (long double)c.x * a.x + (long double)c.y * a.y + (long double)c.z * a.z;
        assert_true(fabsl(ca) <= ref * 2.01 * u * mag_c + 1e-300);

        sc_dvec3 r = sc_dvec3_reflect(a, nrm);
        double la = sc_dvec3_length(a), lr = sc_dvec3_length(r);
        assert_true(fabs(lr - la) <= ref * 16 * u * la);
        /* (R − I) is along N: its component orthogonal to N vanishes up to rounding. */
        sc_dvec3 diff = sc_dvec3_sub(r, a);
        sc_dvec3 perp = sc_dvec3_cross(diff, nrm);
        assert_true(sc_dvec3_length(perp) <= ref * 32 * u * la);
    }
    sc_dvec3 m = sc_dvec3_make(3, 0, 4);
    assert_true(sc_dvec3_length(m) == 5.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(componentwise_operations_are_correctly_rounded),
        cmocka_unit_test(mix_is_within_its_rounding_bound),
        cmocka_unit_test(dot_is_within_the_summation_bound),
        cmocka_unit_test(dot_sums_left_to_right),
        cmocka_unit_test(length_and_distance_are_within_their_bounds),
        cmocka_unit_test(normalize_gives_unit_length),
        cmocka_unit_test(normalize_of_zero_is_nan),
        cmocka_unit_test(reflect_is_within_its_rounding_bound),
        cmocka_unit_test(reflect_angle_equals_incidence_angle),
        cmocka_unit_test(refract_is_within_its_rounding_bound),
        cmocka_unit_test(refract_obeys_snells_law),
        cmocka_unit_test(total_internal_reflection_gives_zero),
        cmocka_unit_test(faceforward_turns_against_the_incident_direction),
        cmocka_unit_test(cross_is_orthogonal_and_within_its_bound),
        cmocka_unit_test(float_vectors_match_eval_highp_bit_for_bit),
        cmocka_unit_test(dvec3_meets_the_double_bounds),
    };
    return cmocka_run_group_tests_name("vec", tests, NULL, NULL);
}
