/* The matrix types (shadecalc/mat.h) against independent references: products, determinants
 * (Leibniz's permutation sum) and inverses evaluated in long double, with error bounds derived
 * from the standard model fl(a op b) = (a op b)(1 + δ), |δ| <= u (Higham, "Accuracy and
 * Stability of Numerical Algorithms" §3): γ_n = n·u/(1 − n·u) for a length-n dot product,
 * γ_k·per(|A|) for a Laplace determinant with k = (n − 1)(n + 2)/2 roundings per product. Then
 * the layout (GLSL column-major, checked on hand-built matrices), the singular rule, the
 * contract with `shadecalc eval` (bit-identical to pmath highp), and the transforms: rotations
 * orthonormal and right-handed, look-at and perspective by the points they must map, the normal
 * matrix against its closed form R·S⁻¹ for M = T·R·S. Generic tests run over mat2, mat3, mat4,
 * dmat3 and dmat4 through one adapter table per type. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/mat.h"
#include "shadecalc/pmath.h"
#include "tests/support/splitmix.h"

#define U_FLOAT 0x1p-24
#define U_DOUBLE 0x1p-53
/* The long double reference's own error, relative to the magnitudes involved (2^-64 on
 * x86-64; where long double is double this is of the order of its rounding). */
#define REF_SLACK (LDBL_MANT_DIG > 53 ? 0x1p-60 : 0x1p-50)
#define N_RANDOM 5000

static double gamma_n(int n, double u) { return n * u / (1.0 - n * u); }
static int laplace_roundings(int n) { return (n - 1) * (n + 2) / 2; }

/* ---- deterministic random inputs (splitmix64) ------------------------------------------- */

static uint64_t rng_state = 0x13198a2e03707344u;

static uint64_t next_u64(void) { return splitmix_next(&rng_state); }

static double uniform(double lo, double hi) { return splitmix_uniform(&rng_state, lo, hi); }

/* ---- one adapter table per matrix type: everything travels as double arrays -------------- */

typedef struct {
    int n;
    double u;
    double (*round)(double);
    void (*identity)(double *);
    void (*mul)(const double *, const double *, double *);
    void (*mul_vec)(const double *, const double *, double *);
    void (*transpose)(const double *, double *);
    double (*determinant)(const double *);
    int (*inverse)(const double *, double *);
    void (*comp_mult)(const double *, const double *, double *);
} mat_api;

static double round_float(double x) { return (float)x; }
static double round_double(double x) { return x; }

#define TO_ARRAY_(c, k) v.c
#define FROM_ARRAY_(c, k) p[k]
#define ADAPT(T, V, S, N, EACH, ROUND, U)                                                          \
    static T T##_t_load(const double *p)                                                           \
    {                                                                                              \
        T m;                                                                                       \
        for (int k = 0; k < N * N; k++)                                                            \
            m.m[k] = (S)p[k];                                                                      \
        return m;                                                                                  \
    }                                                                                              \
    static void T##_t_store(T m, double *p)                                                        \
    {                                                                                              \
        for (int k = 0; k < N * N; k++)                                                            \
            p[k] = m.m[k];                                                                         \
    }                                                                                              \
    static void T##_t_identity(double *o) { T##_t_store(T##_identity(), o); }                      \
    static void T##_t_mul(const double *a, const double *b, double *o)                             \
    {                                                                                              \
        T##_t_store(T##_mul(T##_t_load(a), T##_t_load(b)), o);                                     \
    }                                                                                              \
    static void T##_t_mul_vec(const double *m, const double *p, double *o)                         \
    {                                                                                              \
        V v = T##_mul_vec(T##_t_load(m), (V){EACH(FROM_ARRAY_)});                                  \
        const double r[N] = {EACH(TO_ARRAY_)};                                                     \
        memcpy(o, r, sizeof r);                                                                    \
    }                                                                                              \
    static void T##_t_transpose(const double *m, double *o)                                        \
    {                                                                                              \
        T##_t_store(T##_transpose(T##_t_load(m)), o);                                              \
    }                                                                                              \
    static double T##_t_determinant(const double *m) { return T##_determinant(T##_t_load(m)); }    \
    static int T##_t_inverse(const double *m, double *o)                                           \
    {                                                                                              \
        T in = T##_t_load(m), out;                                                                 \
        int rc = T##_inverse(&in, &out);                                                           \
        if (rc == 0)                                                                               \
            T##_t_store(out, o);                                                                   \
        return rc;                                                                                 \
    }                                                                                              \
    static void T##_t_comp_mult(const double *a, const double *b, double *o)                       \
    {                                                                                              \
        T##_t_store(T##_comp_mult(T##_t_load(a), T##_t_load(b)), o);                               \
    }                                                                                              \
    static const mat_api T##_api = {N,                                                             \
                                    U,                                                             \
                                    ROUND,                                                         \
                                    T##_t_identity,                                                \
                                    T##_t_mul,                                                     \
                                    T##_t_mul_vec,                                                 \
                                    T##_t_transpose,                                               \
                                    T##_t_determinant,                                             \
                                    T##_t_inverse,                                                 \
                                    T##_t_comp_mult};

ADAPT(sc_mat2, sc_vec2, float, 2, SC_EACH2, round_float, U_FLOAT)
ADAPT(sc_mat3, sc_vec3, float, 3, SC_EACH3, round_float, U_FLOAT)
ADAPT(sc_mat4, sc_vec4, float, 4, SC_EACH4, round_float, U_FLOAT)
ADAPT(sc_dmat3, sc_dvec3, double, 3, SC_EACH3, round_double, U_DOUBLE)
ADAPT(sc_dmat4, sc_dvec4, double, 4, SC_EACH4, round_double, U_DOUBLE)

static const mat_api *const apis[] = {&sc_mat2_api, &sc_mat3_api, &sc_mat4_api, &sc_dmat3_api,
                                      &sc_dmat4_api};
#define FOR_EACH_API(api) for (const mat_api *const *api = apis; api < apis + 5; api++)
#define FOR_EACH_FLOAT_API(api) for (const mat_api *const *api = apis; api < apis + 3; api++)

/* Entries uniform in [lo, hi], rounded to the matrix's scalar type. */
static void random_matrix(const mat_api *api, double lo, double hi, double *m)
{
    for (int k = 0; k < api->n * api->n; k++)
        m[k] = api->round(uniform(lo, hi));
}

/* ---- long double references -------------------------------------------------------------- */

/* out = a·b and mag = |a|·|b| (column-major n×n). */
static void matmul_ref(const double *a, const double *b, int n, long double *out, long double *mag)
{
    for (int c = 0; c < n; c++)
        for (int r = 0; r < n; r++) {
            long double s = 0, m = 0;
            for (int k = 0; k < n; k++) {
                s += (long double)a[k * n + r] * b[c * n + k];
                m += fabsl((long double)a[k * n + r] * b[c * n + k]);
            }
            out[c * n + r] = s;
            mag[c * n + r] = m;
        }
}

/* Leibniz: det = Σ_σ sgn σ·Π_c m[σ(c)][c], and the permanent of |m| (the same sum of |products|
 * without signs), over the permutations completing rows `used` from column col on. */
static void leibniz(const double *m, int n, int col, unsigned used, long double prod, int sign,
                    long double *det, long double *per)
{
    if (col == n) {
        *det += sign * prod;
        *per += fabsl(prod);
        return;
    }
    for (int r = 0; r < n; r++) {
        if (used & (1u << r))
            continue;
        int inversions = 0;
        for (int q = r + 1; q < n; q++)
            inversions += (used >> q) & 1u;
        leibniz(m, n, col + 1, used | (1u << r), prod * m[col * n + r],
                inversions % 2 ? -sign : sign, det, per);
    }
}

static long double det_ref(const double *m, int n, long double *per)
{
    long double det = 0, p = 0;
    leibniz(m, n, 0, 0u, 1.0L, 1, &det, &p);
    *per = p;
    return det;
}

static void minor_ref(const double *m, int n, int skip_r, int skip_c, double *out)
{
    int k = 0;
    for (int c = 0; c < n; c++)
        for (int r = 0; r < n; r++)
            if (r != skip_r && c != skip_c)
                out[k++] = m[c * n + r];
}

/* ---- layout --------------------------------------------------------------------------------- */

/* GLSL: mat3(c0, c1, c2) * v = v.x·c0 + v.y·c1 + v.z·c2, element [col][row] = m[col·3 + row]. */
static void matrices_are_column_major_as_glsl(void **state)
{
    (void)state;
    sc_mat3 m = {{1, 2, 3, /* column 0 */ 4, 5, 6, /* column 1 */ 7, 8, 10}};
    sc_vec3 x = sc_mat3_mul_vec(m, sc_vec3_make(1, 0, 0));
    assert_true(x.x == 1 && x.y == 2 && x.z == 3);
    sc_vec3 v = sc_mat3_mul_vec(m, sc_vec3_make(1, 10, 100));
    assert_true(v.x == 741 && v.y == 852 && v.z == 1063);
    sc_mat3 t = sc_mat3_transpose(m);
    assert_true(t.m[1] == 4 && t.m[3] == 2 && t.m[8] == 10);

    sc_mat2 r90 = {{0, 1, -1, 0}}; /* columns (0,1), (-1,0): a quarter turn counterclockwise */
    sc_vec2 y = sc_mat2_mul_vec(r90, sc_vec2_make(1, 0));
    assert_true(y.x == 0 && y.y == 1);

    /* mat4: translation lives in column 3, m[12..14]. */
    sc_mat4 tr = sc_mat4_identity();
    tr.m[12] = 5, tr.m[13] = 6, tr.m[14] = 7;
    sc_vec4 p = sc_mat4_mul_vec(tr, sc_vec4_make(1, 2, 3, 1));
    assert_true(p.x == 6 && p.y == 8 && p.z == 10 && p.w == 1);
    sc_vec4 d = sc_mat4_mul_vec(tr, sc_vec4_make(1, 2, 3, 0)); /* directions do not move */
    assert_true(d.x == 1 && d.y == 2 && d.z == 3 && d.w == 0);

    /* a·b applies b first: (translate · scale)·p = scale, then translate. */
    sc_dmat4 ts = sc_dmat4_mul(sc_dmat4_translate(1, 0, 0), sc_dmat4_scale(2, 2, 2));
    sc_dvec4 q = sc_dmat4_mul_vec(ts, (sc_dvec4){1, 1, 1, 1});
    assert_true(q.x == 3 && q.y == 2 && q.z == 2 && q.w == 1);
}

static void conversions_keep_the_upper_left_block(void **state)
{
    (void)state;
    sc_mat4 m;
    for (int k = 0; k < 16; k++)
        m.m[k] = (float)(k + 1);
    sc_mat3 u = sc_mat3_from_mat4(m);
    const float want3[9] = {1, 2, 3, 5, 6, 7, 9, 10, 11};
    for (int k = 0; k < 9; k++)
        assert_true(u.m[k] == want3[k]);
    sc_mat4 back = sc_mat4_from_mat3(u);
    const float want4[16] = {1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 0, 0, 0, 0, 1};
    for (int k = 0; k < 16; k++)
        assert_true(back.m[k] == want4[k]);
    sc_dmat4 dm = sc_dmat4_scale(0.1, 1.0 / 3.0, 1e300);
    sc_mat4 f = sc_mat4_from_dmat4(dm);
    assert_true(f.m[0] == 0.1f && f.m[5] == (float)(1.0 / 3.0) && f.m[10] == INFINITY &&
                f.m[15] == 1.0f && f.m[1] == 0.0f);
}

/* ---- products ------------------------------------------------------------------------------ */

static void identity_is_neutral_and_transpose_an_involution(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < 200; t++) {
        int n = (*api)->n;
        double a[16], id[16], o[16], tt[16], t2[16];
        random_matrix(*api, -10, 10, a);
        (*api)->identity(id);
        (*api)->mul(id, a, o);
        assert_memory_equal(o, a, sizeof(double) * n * n);
        (*api)->mul(a, id, o);
        assert_memory_equal(o, a, sizeof(double) * n * n);
        (*api)->transpose(a, tt);
        (*api)->transpose(tt, t2);
        assert_memory_equal(t2, a, sizeof(double) * n * n);
        for (int c = 0; c < n; c++)
            for (int r = 0; r < n; r++)
                assert_true(tt[r * n + c] == a[c * n + r]);
    }
}

/* Each entry of a·b (and of m·v) is a length-n dot product: within γ_n·(|a|·|b|). */
static void products_are_within_the_dot_product_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        double a[16], b[16], o[16], v[4], ov[4];
        long double ref[16], mag[16];
        random_matrix(*api, -4, 4, a);
        random_matrix(*api, -4, 4, b);
        (*api)->mul(a, b, o);
        matmul_ref(a, b, n, ref, mag);
        double g = gamma_n(n, (*api)->u) + REF_SLACK;
        for (int k = 0; k < n * n; k++)
            if (!(fabsl(o[k] - ref[k]) <= g * mag[k]))
                fail_msg("%dx%d mul entry %d off by %Lg > %Lg", n, n, k, fabsl(o[k] - ref[k]),
                         g * mag[k]);
        for (int k = 0; k < n; k++)
            v[k] = b[k]; /* column 0 of b: m·v is column 0 of m·b */
        (*api)->mul_vec(a, v, ov);
        for (int k = 0; k < n; k++)
            assert_true(fabsl(ov[k] - ref[k]) <= g * mag[k]);
    }
}

/* fl(fl(AB)C) = ABC + E with |E| <= (2γ_n + γ_n²)|A||B||C|, and the same for A(BC), so the two
 * groupings differ by at most twice that. */
static void multiplication_is_associative_within_rounding(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        double a[16], b[16], c[16], ab[16], bc[16], ab_c[16], a_bc[16], abs_a[16], abs_b[16],
            abs_c[16], abs_ab[16];
        long double tmp[16], mag1[16], mag2[16];
        random_matrix(*api, -3, 3, a);
        random_matrix(*api, -3, 3, b);
        random_matrix(*api, -3, 3, c);
        (*api)->mul(a, b, ab);
        (*api)->mul(ab, c, ab_c);
        (*api)->mul(b, c, bc);
        (*api)->mul(a, bc, a_bc);
        for (int k = 0; k < n * n; k++)
            abs_a[k] = fabs(a[k]), abs_b[k] = fabs(b[k]), abs_c[k] = fabs(c[k]);
        matmul_ref(abs_a, abs_b, n, tmp, mag1);
        for (int k = 0; k < n * n; k++)
            abs_ab[k] = (double)tmp[k];
        matmul_ref(abs_ab, abs_c, n, tmp, mag2); /* tmp = |A||B||C| */
        double g = gamma_n(n, (*api)->u);
        for (int k = 0; k < n * n; k++) {
            long double bound = 2 * (2 * g + g * g) * tmp[k] * (1 + 4 * REF_SLACK);
            if (!(fabsl((long double)ab_c[k] - a_bc[k]) <= bound))
                fail_msg("%dx%d (AB)C - A(BC) = %Lg > %Lg", n, n,
                         fabsl((long double)ab_c[k] - a_bc[k]), bound);
        }
    }
}

/* matrixCompMult: one rounded product per entry, so exactly the rounded double product. */
static void comp_mult_rounds_each_product_once(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < 500; t++) {
        int n = (*api)->n;
        double a[16], b[16], o[16];
        random_matrix(*api, -100, 100, a);
        random_matrix(*api, -100, 100, b);
        (*api)->comp_mult(a, b, o);
        for (int k = 0; k < n * n; k++)
            assert_true(o[k] == (*api)->round(a[k] * b[k]) || (*api)->u == U_DOUBLE);
        if ((*api)->u == U_DOUBLE)
            for (int k = 0; k < n * n; k++)
                assert_true(fabsl(o[k] - (long double)a[k] * b[k]) <=
                            U_DOUBLE * fabsl((long double)a[k] * b[k]));
    }
}

/* ---- determinant and inverse --------------------------------------------------------------- */

/* Every one of the n! Laplace products carries at most k = (n−1)(n+2)/2 roundings:
 * |det − exact| <= γ_k·per(|A|), exact by Leibniz's formula. */
static void determinant_is_within_the_laplace_bound(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        double a[16];
        random_matrix(*api, -2, 2, a);
        long double per, exact = det_ref(a, n, &per);
        double got = (*api)->determinant(a);
        long double bound = (gamma_n(laplace_roundings(n), (*api)->u) + REF_SLACK) * per;
        if (!(fabsl(got - exact) <= bound))
            fail_msg("%dx%d det off by %Lg > %Lg", n, n, fabsl(got - exact), bound);
    }
    sc_mat3 m = {{2, 0, 0, 0, 3, 0, 1, 1, 4}};
    assert_true(sc_mat3_determinant(m) == 24.0f);
}

/* inverse(r, c) = cof/det with cof = (−1)^(r+c)·det(minor(c, r)). With E_cof =
 * γ_k(n−1)·per(|minor|) and E_det = γ_k(n)·per(|A|) the Laplace bounds, |X̂ − X| <= (E_cof +
 * |X|·E_det)/(|det| − E_det) plus one rounding of the quotient. */
static double inverse_entry_bound(const double *a, int n, double u, int r, int c, long double det,
                                  long double per, long double *exact)
{
    double sub[9];
    long double per_minor = 1;
    minor_ref(a, n, c, r, sub);
    long double cof = n == 2 ? sub[0] : det_ref(sub, n - 1, &per_minor);
    if (n == 2)
        per_minor = fabsl(cof);
    if ((r + c) % 2)
        cof = -cof;
    *exact = cof / det;
    long double e_cof = (gamma_n(laplace_roundings(n - 1), u) + REF_SLACK) * per_minor;
    long double e_det = (gamma_n(laplace_roundings(n), u) + REF_SLACK) * per;
    long double x = fabsl(*exact), e = (e_cof + x * e_det) / (fabsl(det) - e_det);
    return (double)((e + u * (x + e)) * (1 + 4 * u));
}

static void inverse_is_within_its_bound_and_inverts(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        double a[16], x[16], err[16];
        random_matrix(*api, -1, 1, a);
        if (t % 2) /* half of them diagonally dominant: well conditioned */
            for (int k = 0; k < n; k++)
                a[k * n + k] = (*api)->round(a[k * n + k] + (a[k * n + k] < 0 ? -n : n));
        long double per, det = det_ref(a, n, &per);
        if (fabsl(det) <= 4 * gamma_n(laplace_roundings(n), (*api)->u) * per)
            continue; /* too close to singular for the bound to say anything */
        assert_int_equal((*api)->inverse(a, x), 0);
        for (int c = 0; c < n; c++)
            for (int r = 0; r < n; r++) {
                long double exact;
                err[c * n + r] = inverse_entry_bound(a, n, (*api)->u, r, c, det, per, &exact);
                if (!(fabsl(x[c * n + r] - exact) <= err[c * n + r]))
                    fail_msg("%dx%d inverse (%d,%d) off by %Lg > %g", n, n, r, c,
                             fabsl(x[c * n + r] - exact), err[c * n + r]);
            }
        /* X̂·A − I, in long double: |(X̂A − I)_rc| <= Σ_k |X̂ − X|_rk·|A_kc|. */
        for (int c = 0; c < n; c++)
            for (int r = 0; r < n; r++) {
                long double s = 0, bound = 0;
                for (int k = 0; k < n; k++) {
                    s += (long double)x[k * n + r] * a[c * n + k];
                    bound += (long double)err[k * n + r] * fabs(a[c * n + k]);
                }
                s -= r == c;
                assert_true(fabsl(s) <= bound * (1 + 4 * (*api)->u) + REF_SLACK * n);
                if (t % 2)
                    assert_true(fabsl(s) <= 64 * n * (*api)->u); /* well conditioned */
            }
    }
}

/* Exactly singular matrices: a column that is the exact sum of two others (integer significands
 * of 12 bits for float, 41 for double, and column scales 2^-12..2^-4: the sum is exact), a zero
 * column, a repeated column. Their computed determinants are often not 0 — a det == 0 test would
 * accept those — but always within the rule's bound, so every one is rejected and the output is
 * left untouched.
 */
static void singular_matrices_are_rejected(void **state)
{
    (void)state;
    FOR_EACH_API(api)
    {
        int n = (*api)->n, nonzero_det = 0;
        double span = (*api)->u == U_FLOAT ? 0x1p11 : 0x1p40;
        for (int t = 0; t < N_RANDOM; t++) {
            double a[16], x[16] = {42};
            for (int c = 0; c < n; c++) {
                int e = (int)(next_u64() % 9) - 12; /* any column scale: still singular */
                for (int r = 0; r < n; r++)
                    a[c * n + r] = ldexp(floor(uniform(-span, span)), e);
            }
            int dst = (int)(next_u64() % n), s1 = (dst + 1) % n, s2 = (dst + n - 1) % n;
            for (int r = 0; r < n; r++)
                a[dst * n + r] = t % 3 == 0   ? 0.0
                                 : t % 3 == 1 ? a[s1 * n + r]
                                              : a[s1 * n + r] + (n > 2 ? a[s2 * n + r] : 0.0);
            nonzero_det += (*api)->determinant(a) != 0.0;
            assert_int_equal((*api)->inverse(a, x), -1);
            assert_true(x[0] == 42);
        }
        if (n > 2)
            assert_true(nonzero_det > 0); /* rounding did produce nonzero determinants */
    }
    sc_mat3 nan_m = sc_mat3_identity(), inf_m = sc_mat3_identity(), out;
    nan_m.m[4] = NAN;
    inf_m.m[8] = INFINITY;
    assert_int_equal(sc_mat3_inverse(&nan_m, &out), -1);
    assert_int_equal(sc_mat3_inverse(&inf_m, &out), -1);
}

/* The rule is relative: tiny and huge but well-conditioned matrices are invertible. */
static void scaled_matrices_are_not_singular(void **state)
{
    (void)state;
    sc_dmat4 tiny = sc_dmat4_scale(1e-30, 2e-30, 3e-30), inv;
    assert_int_equal(sc_dmat4_inverse(&tiny, &inv), 0);
    assert_true(fabs(inv.m[0] - 1e30) <= 1e30 * 4 * U_DOUBLE && inv.m[15] == 1.0);
    sc_mat4 small = sc_mat4_from_dmat4(sc_dmat4_scale(1e-3, 1e-3, 1e-3)), finv;
    assert_int_equal(sc_mat4_inverse(&small, &finv), 0);
    assert_true(fabs(finv.m[5] - 1e3) <= 1e3 * 4 * U_FLOAT);
    sc_mat2 big = {{1e18f, 0, 0, 1e18f}}, binv;
    assert_int_equal(sc_mat2_inverse(&big, &binv), 0);
    assert_true(fabs(binv.m[0] - 1e-18) <= 1e-18 * 4 * U_FLOAT);
}

/* ---- the contract with shadecalc eval ------------------------------------------------------ */

static void float_matrices_match_eval_highp_bit_for_bit(void **state)
{
    (void)state;
    FOR_EACH_FLOAT_API(api)
    for (int t = 0; t < N_RANDOM; t++) {
        int n = (*api)->n;
        double a[16], b[16], o[16], p[16], v[4], ov[4], pv[4];
        random_matrix(*api, -3, 3, a);
        random_matrix(*api, -3, 3, b);
        (*api)->mul(a, b, o);
        sc_p_matmul(SC_HIGHP, a, b, n, p);
        assert_memory_equal(o, p, sizeof(double) * n * n);
        for (int k = 0; k < n; k++)
            v[k] = b[k];
        (*api)->mul_vec(a, v, ov);
        sc_p_mat_vec(SC_HIGHP, a, v, n, pv);
        assert_memory_equal(ov, pv, sizeof(double) * n);
        assert_true((*api)->determinant(a) == sc_p_determinant(SC_HIGHP, a, n));
        if ((*api)->inverse(a, o) == 0) {
            sc_p_inverse(SC_HIGHP, a, n, p);
            assert_memory_equal(o, p, sizeof(double) * n * n);
        }
    }
}

/* ---- transforms ---------------------------------------------------------------------------- */

static sc_dvec3 apply_point(sc_dmat4 m, sc_dvec3 p)
{
    sc_dvec4 q = sc_dmat4_mul_vec(m, (sc_dvec4){p.x, p.y, p.z, 1.0});
    return (sc_dvec3){q.x / q.w, q.y / q.w, q.z / q.w};
}

static sc_dvec3 apply_dir(sc_dmat4 m, sc_dvec3 p)
{
    sc_dvec4 q = sc_dmat4_mul_vec(m, (sc_dvec4){p.x, p.y, p.z, 0.0});
    return (sc_dvec3){q.x, q.y, q.z};
}

static double dist3(sc_dvec3 a, sc_dvec3 b) { return sc_dvec3_length(sc_dvec3_sub(a, b)); }

/* Quarter turns are exact and right-handed: z turns x into y, x turns y into z, y turns z into x.
 */
static void quarter_turns_are_exact_and_right_handed(void **state)
{
    (void)state;
    sc_dvec3 ex = {1, 0, 0}, ey = {0, 1, 0}, ez = {0, 0, 1};
    assert_true(dist3(apply_dir(sc_dmat4_rotate(90, 0, 0, 1), ex), ey) == 0.0);
    assert_true(dist3(apply_dir(sc_dmat4_rotate(90, 1, 0, 0), ey), ez) == 0.0);
    assert_true(dist3(apply_dir(sc_dmat4_rotate(90, 0, 2, 0), ez), ex) == 0.0);
    assert_true(dist3(apply_dir(sc_dmat4_rotate(-270, 0, 0, 5), ex), ey) == 0.0);
    assert_true(dist3(apply_dir(sc_dmat4_rotate(180, 0, 0, 1), ex), (sc_dvec3){-1, 0, 0}) == 0.0);
    assert_true(dist3(apply_dir(sc_dmat4_rotate(720, 1, 1, 1), ex), ex) == 0.0);
    sc_dmat4 id = sc_dmat4_identity(), zero_axis = sc_dmat4_rotate(30, 0, 0, 0);
    assert_memory_equal(zero_axis.m, id.m, sizeof id.m);
}

/* For a random unit axis a and angle θ: RᵀR = I and det R = 1 (orthonormal, proper), R·a = a,
 * and a vector v ⊥ a turns by θ counterclockwise about a: cos = v·Rv/|v|², sin = a·(v × Rv)/|v|²,
 * against libm's cos and sin of θ·π/180. Tolerance 32u (a few roundings per entry). */
static void rotations_are_orthonormal_and_turn_by_the_angle(void **state)
{
    (void)state;
    const double tol = 32 * U_DOUBLE, pi = 3.14159265358979323846;
    for (int t = 0; t < N_RANDOM; t++) {
        sc_dvec3 a = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        if (sc_dvec3_length(a) < 0.1)
            continue;
        double deg = uniform(-400, 400);
        sc_dmat4 r = sc_dmat4_rotate(deg, a.x, a.y, a.z);
        sc_dmat3 r3, rtr, id = sc_dmat3_identity();
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                r3.m[c * 3 + k] = r.m[c * 4 + k];
        rtr = sc_dmat3_mul(sc_dmat3_transpose(r3), r3);
        for (int k = 0; k < 9; k++)
            assert_true(fabs(rtr.m[k] - id.m[k]) <= tol);
        assert_true(fabs(sc_dmat3_determinant(r3) - 1.0) <= tol);
        assert_true(r.m[3] == 0 && r.m[7] == 0 && r.m[11] == 0 && r.m[12] == 0 && r.m[15] == 1);

        sc_dvec3 unit = sc_dvec3_normalize(a);
        assert_true(dist3(apply_dir(r, unit), unit) <= tol);
        sc_dvec3 v = sc_dvec3_cross(unit, (sc_dvec3){0.3, -0.7, 0.2});
        sc_dvec3 rv = apply_dir(r, v);
        double v2 = sc_dvec3_dot(v, v);
        double cos_got = sc_dvec3_dot(v, rv) / v2;
        double sin_got = sc_dvec3_dot(unit, sc_dvec3_cross(v, rv)) / v2;
        assert_true(fabs(cos_got - cos(deg * pi / 180)) <= tol + 1e-15 * fabs(deg));
        assert_true(fabs(sin_got - sin(deg * pi / 180)) <= tol + 1e-15 * fabs(deg));
    }
}

/* gluLookAt: the eye goes to the origin, the center onto the −z axis at its distance, up into
 * the y ≥ 0 half of the x = 0 plane; the rotation part is orthonormal. */
static void look_at_maps_eye_center_and_up(void **state)
{
    (void)state;
    const double tol = 64 * U_DOUBLE;
    for (int t = 0; t < N_RANDOM; t++) {
        sc_dvec3 eye = {uniform(-10, 10), uniform(-10, 10), uniform(-10, 10)};
        sc_dvec3 center = {uniform(-10, 10), uniform(-10, 10), uniform(-10, 10)};
        sc_dvec3 up = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        sc_dvec3 f = sc_dvec3_sub(center, eye);
        double dist = sc_dvec3_length(f);
        if (dist < 0.1 || sc_dvec3_length(sc_dvec3_cross(sc_dvec3_normalize(f), up)) < 0.05)
            continue;
        sc_dmat4 v;
        assert_int_equal(sc_dmat4_look_at(eye, center, up, &v), 0);
        sc_dvec3 e = apply_point(v, eye), c = apply_point(v, center), u = apply_dir(v, up);
        assert_true(sc_dvec3_length(e) <= tol * 20);
        assert_true(dist3(c, (sc_dvec3){0, 0, -dist}) <= tol * 40);
        assert_true(fabs(u.x) <= tol * sc_dvec3_length(up) && u.y > 0);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                sc_dvec3 ci = {v.m[i * 4], v.m[i * 4 + 1], v.m[i * 4 + 2]};
                sc_dvec3 cj = {v.m[j * 4], v.m[j * 4 + 1], v.m[j * 4 + 2]};
                assert_true(fabs(sc_dvec3_dot(ci, cj) - (i == j)) <= tol);
            }
    }
    sc_dmat4 out = sc_dmat4_identity(), keep = out;
    sc_dvec3 p = {1, 2, 3};
    assert_int_equal(sc_dmat4_look_at(p, p, (sc_dvec3){0, 1, 0}, &out), -1);
    assert_int_equal(sc_dmat4_look_at(p, (sc_dvec3){1, 5, 3}, (sc_dvec3){0, 2, 0}, &out), -1);
    assert_memory_equal(out.m, keep.m, sizeof out.m);
}

/* gluPerspective: the near plane goes to NDC z = −1, the far plane to +1, the top edge of the
 * near plane (y = near·tan(fovy/2)) to NDC y = 1 and the right edge to x = 1. */
static void perspective_maps_the_frustum_to_the_ndc_cube(void **state)
{
    (void)state;
    const double tol = 64 * U_DOUBLE, pi = 3.14159265358979323846;
    for (int t = 0; t < 1000; t++) {
        double fovy = uniform(10, 170), aspect = uniform(0.25, 4), zn = uniform(0.01, 10);
        double zf = zn * uniform(1.5, 1000);
        sc_dmat4 p;
        assert_int_equal(sc_dmat4_perspective(fovy, aspect, zn, zf, &p), 0);
        double top = zn * tan(fovy * pi / 360), right = top * aspect;
        sc_dvec3 near_corner = apply_point(p, (sc_dvec3){right, top, -zn});
        sc_dvec3 far_center = apply_point(p, (sc_dvec3){0, 0, -zf});
        assert_true(fabs(near_corner.x - 1) <= tol && fabs(near_corner.y - 1) <= tol);
        assert_true(fabs(near_corner.z + 1) <= tol * zf / zn);
        assert_true(fabs(far_center.z - 1) <= tol * zf / zn);
        assert_true(p.m[11] == -1.0 && p.m[15] == 0.0);
    }
    sc_dmat4 out = sc_dmat4_identity(), keep = out;
    assert_int_equal(sc_dmat4_perspective(0, 1, 1, 10, &out), -1);
    assert_int_equal(sc_dmat4_perspective(180, 1, 1, 10, &out), -1);
    assert_int_equal(sc_dmat4_perspective(60, 0, 1, 10, &out), -1);
    assert_int_equal(sc_dmat4_perspective(60, 1, 0, 10, &out), -1);
    assert_int_equal(sc_dmat4_perspective(60, 1, 10, 10, &out), -1);
    assert_int_equal(sc_dmat4_perspective(60, 1, 1, INFINITY, &out), -1);
    assert_int_equal(sc_dmat4_perspective(NAN, 1, 1, 10, &out), -1);
    assert_memory_equal(out.m, keep.m, sizeof out.m);
    /* 90°: f = cot 45° = 1 (cos/sin of the rounded π/4: within 2u). */
    assert_int_equal(sc_dmat4_perspective(90, 2, 1, 3, &out), 0);
    assert_true(fabs(out.m[0] - 0.5) <= U_DOUBLE && fabs(out.m[5] - 1.0) <= 2 * U_DOUBLE);
    assert_true(out.m[10] == -2.0 && out.m[14] == -3.0);
}

/* For M = T·R·S (non-uniform S), (M3⁻¹)ᵀ = (R·S)⁻ᵀ = R·S⁻¹ (R orthogonal). And the point of
 * it: a tangent t ⊥ n stays perpendicular, (M3·t)·(N·n) = t·n = 0. For a rotation with a
 * translation it is the rotation itself (docs/formulas.md §7). */
static void normal_matrix_is_the_inverse_transpose(void **state)
{
    (void)state;
    const double tol = 256 * U_DOUBLE;
    for (int t = 0; t < N_RANDOM; t++) {
        double sx = uniform(0.1, 10), sy = -uniform(0.1, 10), sz = uniform(0.1, 10);
        double deg = uniform(-180, 180), ax = uniform(-1, 1), ay = uniform(-1, 1),
               az = uniform(-1, 1);
        if (ax * ax + ay * ay + az * az < 0.01)
            continue;
        sc_dmat4 r = sc_dmat4_rotate(deg, ax, ay, az);
        sc_dmat4 m = sc_dmat4_mul(sc_dmat4_translate(uniform(-9, 9), 1, 2),
                                  sc_dmat4_mul(r, sc_dmat4_scale(sx, sy, sz)));
        sc_dmat3 nm;
        assert_int_equal(sc_dmat3_normal_matrix(&m, &nm), 0);
        const double inv_s[3] = {1 / sx, 1 / sy, 1 / sz};
        double max_inv = fmax(fabs(inv_s[0]), fmax(fabs(inv_s[1]), fabs(inv_s[2])));
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                if (!(fabs(nm.m[c * 3 + k] - r.m[c * 4 + k] * inv_s[c]) <= tol * max_inv * 100))
                    fail_msg("normal matrix (%d,%d): %g vs %g", k, c, nm.m[c * 3 + k],
                             r.m[c * 4 + k] * inv_s[c]);
        sc_dvec3 n = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        sc_dvec3 tan = sc_dvec3_cross(n, (sc_dvec3){0.5, 0.25, -1});
        sc_dvec3 mt = apply_dir(m, tan), nn = sc_dmat3_mul_vec(nm, n);
        double scale = sc_dvec3_length(mt) * sc_dvec3_length(nn);
        assert_true(fabs(sc_dvec3_dot(mt, nn)) <= tol * 100 * scale);
    }
    sc_dmat4 rt = sc_dmat4_mul(sc_dmat4_translate(3, 4, 5), sc_dmat4_rotate(33, 1, 2, 3));
    sc_dmat3 nr;
    assert_int_equal(sc_dmat3_normal_matrix(&rt, &nr), 0);
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++)
            assert_true(fabs(nr.m[c * 3 + k] - rt.m[c * 4 + k]) <= tol);
    sc_dmat4 flat = sc_dmat4_scale(1, 0, 1); /* projects onto a plane: no normal matrix */
    assert_int_equal(sc_dmat3_normal_matrix(&flat, &nr), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matrices_are_column_major_as_glsl),
        cmocka_unit_test(conversions_keep_the_upper_left_block),
        cmocka_unit_test(identity_is_neutral_and_transpose_an_involution),
        cmocka_unit_test(products_are_within_the_dot_product_bound),
        cmocka_unit_test(multiplication_is_associative_within_rounding),
        cmocka_unit_test(comp_mult_rounds_each_product_once),
        cmocka_unit_test(determinant_is_within_the_laplace_bound),
        cmocka_unit_test(inverse_is_within_its_bound_and_inverts),
        cmocka_unit_test(singular_matrices_are_rejected),
        cmocka_unit_test(scaled_matrices_are_not_singular),
        cmocka_unit_test(float_matrices_match_eval_highp_bit_for_bit),
        cmocka_unit_test(quarter_turns_are_exact_and_right_handed),
        cmocka_unit_test(rotations_are_orthonormal_and_turn_by_the_angle),
        cmocka_unit_test(look_at_maps_eye_center_and_up),
        cmocka_unit_test(perspective_maps_the_frustum_to_the_ndc_cube),
        cmocka_unit_test(normal_matrix_is_the_inverse_transpose),
    };
    return cmocka_run_group_tests_name("mat", tests, NULL, NULL);
}
