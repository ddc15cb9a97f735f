/* Square matrices, column-major (shadecalc/mat.h): the n×n kernels are written once and
 * instantiated for float and double by SC_MAT_KERNELS; the typed API wraps them per type
 * (SC_MAT_API). Orders of evaluation are those of shadecalc/pmath.h. The transform builders
 * follow the OpenGL 2.1 reference pages (glTranslate, glScale, glRotate) and GLU 1.3
 * (gluLookAt, gluPerspective). */
#include <float.h>
#include <math.h>

#include "shadecalc/mat.h"

#define U_FLOAT 0x1p-24
#define U_DOUBLE 0x1p-53

/* Roundings on the way to one product of the Laplace expansion: n − 1 products and
 * (n − 1) + (n − 2) + ... + 1 additions (shadecalc/mat.h, "Singular"). */
static int laplace_roundings(int n) { return (n - 1) * (n + 2) / 2; }

/* The computed determinant det of the column-major n×n matrix whose column 1-norms are
 * col_norm[] is indistinguishable from zero when |det| <= γ_k·Π col_norm; it is unusable when
 * not finite or below the smallest normal number (underflow is outside the error model). */
static int is_singular(double det, const double *col_norm, int n, double u, double min_normal)
{
    double k = laplace_roundings(n), bound = k * u / (1.0 - k * u);
    for (int c = 0; c < n; c++)
        bound *= col_norm[c];
    return !isfinite(det) || !(fabs(det) >= min_normal) || !(fabs(det) > bound);
}

#define SC_MAT_KERNELS(S, SUF, U, MIN_NORMAL)                                                      \
    static void identity_##SUF(int n, S *out)                                                      \
    {                                                                                              \
        for (int k = 0; k < n * n; k++)                                                            \
            out[k] = k % (n + 1) == 0 ? (S)1 : (S)0;                                               \
    }                                                                                              \
    static void transpose_##SUF(const S *m, int n, S *out)                                         \
    {                                                                                              \
        for (int c = 0; c < n; c++)                                                                \
            for (int r = 0; r < n; r++)                                                            \
                out[r * n + c] = m[c * n + r];                                                     \
    }                                                                                              \
    static void comp_mult_##SUF(const S *a, const S *b, int n, S *out)                             \
    {                                                                                              \
        for (int k = 0; k < n * n; k++)                                                            \
            out[k] = a[k] * b[k];                                                                  \
    }                                                                                              \
    /* The (n−1)×(n−1) matrix left when row skip_r and column skip_c are removed. */          \
    static void minor_##SUF(const S *m, int n, int skip_r, int skip_c, S *out)                     \
    {                                                                                              \
        int k = 0;                                                                                 \
        for (int c = 0; c < n; c++)                                                                \
            for (int r = 0; r < n; r++)                                                            \
                if (r != skip_r && c != skip_c)                                                    \
                    out[k++] = m[c * n + r];                                                       \
    }                                                                                              \
    /* Laplace along the first column: Σ_r (−1)^r·m[r][0]·det(minor(r, 0)), left to right. */ \
    static S determinant_##SUF(const S *m, int n)                                                  \
    {                                                                                              \
        if (n == 1)                                                                                \
            return m[0];                                                                           \
        S sum = 0, sub[9];                                                                         \
        for (int r = 0; r < n; r++) {                                                              \
            minor_##SUF(m, n, r, 0, sub);                                                          \
            S term = m[r] * determinant_##SUF(sub, n - 1);                                         \
            sum = r == 0 ? term : r % 2 ? sum - term : sum + term;                                 \
        }                                                                                          \
        return sum;                                                                                \
    }                                                                                              \
    /* inverse = adjugate / det, adjugate(r, c) = (−1)^(r+c)·det(minor(c, r)). */               \
    static int inverse_##SUF(const S *m, int n, S *out)                                            \
    {                                                                                              \
        S det = determinant_##SUF(m, n), sub[9];                                                   \
        double col_norm[4] = {0, 0, 0, 0};                                                         \
        for (int k = 0; k < n * n; k++)                                                            \
            col_norm[k / n] += fabs((double)m[k]);                                                 \
        if (is_singular(det, col_norm, n, U, MIN_NORMAL))                                          \
            return -1;                                                                             \
        for (int c = 0; c < n; c++)                                                                \
            for (int r = 0; r < n; r++) {                                                          \
                minor_##SUF(m, n, c, r, sub);                                                      \
                S cof = determinant_##SUF(sub, n - 1);                                             \
                out[c * n + r] = ((r + c) % 2 ? -cof : cof) / det;                                 \
            }                                                                                      \
        return 0;                                                                                  \
    }                                                                                              \
    /* The upper-left 3×3 of a 4×4. */                                                           \
    static void upper_left_##SUF(const S *m4, S *m3)                                               \
    {                                                                                              \
        for (int c = 0; c < 3; c++)                                                                \
            for (int r = 0; r < 3; r++)                                                            \
                m3[c * 3 + r] = m4[c * 4 + r];                                                     \
    }

SC_MAT_KERNELS(float, f, U_FLOAT, FLT_MIN)
SC_MAT_KERNELS(double, d, U_DOUBLE, DBL_MIN)

#define SC_MAT_COLUMN_(c, k) col[k]
#define SC_MAT_STORE_(c, k) out[k] = prod.c

/* The typed API of matrix type T (n×n of S) with column vector V of components EACH
 * (mul_vec is inline in shadecalc/mat.h). */
#define SC_MAT_API(T, V, S, N, SUF, EACH)                                                          \
    T T##_identity(void)                                                                           \
    {                                                                                              \
        T r;                                                                                       \
        identity_##SUF(N, r.m);                                                                    \
        return r;                                                                                  \
    }                                                                                              \
    /* Column c of a·b is a·(column c of b). */                                                  \
    T T##_mul(T a, T b)                                                                            \
    {                                                                                              \
        T r;                                                                                       \
        for (int c = 0; c < N; c++) {                                                              \
            const S *col = b.m + c * N;                                                            \
            S *out = r.m + c * N;                                                                  \
            V prod = T##_mul_vec(a, (V){EACH(SC_MAT_COLUMN_)});                                    \
            EACH(SC_MAT_STORE_);                                                                   \
        }                                                                                          \
        return r;                                                                                  \
    }                                                                                              \
    T T##_transpose(T m)                                                                           \
    {                                                                                              \
        T r;                                                                                       \
        transpose_##SUF(m.m, N, r.m);                                                              \
        return r;                                                                                  \
    }                                                                                              \
    S T##_determinant(T m) { return determinant_##SUF(m.m, N); }                                   \
    int T##_inverse(const T *m, T *out)                                                            \
    {                                                                                              \
        T r;                                                                                       \
        if (inverse_##SUF(m->m, N, r.m) != 0)                                                      \
            return -1;                                                                             \
        *out = r;                                                                                  \
        return 0;                                                                                  \
    }                                                                                              \
    T T##_comp_mult(T a, T b)                                                                      \
    {                                                                                              \
        T r;                                                                                       \
        comp_mult_##SUF(a.m, b.m, N, r.m);                                                         \
        return r;                                                                                  \
    }

SC_MAT_API(sc_mat2, sc_vec2, float, 2, f, SC_EACH2)
SC_MAT_API(sc_mat3, sc_vec3, float, 3, f, SC_EACH3)
SC_MAT_API(sc_mat4, sc_vec4, float, 4, f, SC_EACH4)
SC_MAT_API(sc_dmat3, sc_dvec3, double, 3, d, SC_EACH3)
SC_MAT_API(sc_dmat4, sc_dvec4, double, 4, d, SC_EACH4)

/* ---- conversions ---------------------------------------------------------------------------- */

sc_mat3 sc_mat3_from_mat4(sc_mat4 m)
{
    sc_mat3 r;
    upper_left_f(m.m, r.m);
    return r;
}

sc_mat4 sc_mat4_from_mat3(sc_mat3 m)
{
    sc_mat4 r = sc_mat4_identity();
    for (int c = 0; c < 3; c++)
        for (int row = 0; row < 3; row++)
            r.m[c * 4 + row] = m.m[c * 3 + row];
    return r;
}

sc_mat4 sc_mat4_from_dmat4(sc_dmat4 m)
{
    sc_mat4 r;
    for (int k = 0; k < 16; k++)
        r.m[k] = (float)m.m[k];
    return r;
}

/* ---- transforms ----------------------------------------------------------------------------- */

sc_dmat4 sc_dmat4_translate(double x, double y, double z)
{
    sc_dmat4 r = sc_dmat4_identity();
    r.m[12] = x;
    r.m[13] = y;
    r.m[14] = z;
    return r;
}

sc_dmat4 sc_dmat4_scale(double x, double y, double z)
{
    sc_dmat4 r = sc_dmat4_identity();
    r.m[0] = x;
    r.m[5] = y;
    r.m[10] = z;
    return r;
}

/* sin and cos of deg degrees, exact at multiples of 90°: deg is reduced exactly to
 * t + 90·q with |t| <= 45 (fmod is exact, and so is r − 90·q by Sterbenz's lemma since
 * 90q/2 <= r <= 2·90q), and the quarter turns q are applied by symmetry. */
static void sincos_degrees(double deg, double *s, double *c)
{
    if (!isfinite(deg)) {
        *s = *c = NAN;
        return;
    }
    static const double rad_per_deg = 3.14159265358979323846 / 180.0;
    double r = fmod(deg, 360.0), q = nearbyint(r / 90.0), t = (r - 90.0 * q) * rad_per_deg;
    double st = sin(t), ct = cos(t);
    switch (((int)q % 4 + 4) % 4) {
    case 0: *s = st, *c = ct; break;
    case 1: *s = ct, *c = -st; break;
    case 2: *s = -st, *c = -ct; break;
    default: *s = -ct, *c = st; break;
    }
}

/* R = cos θ·I + (1 − cos θ)·a·aᵀ + sin θ·[a]×, a the unit axis (Rodrigues; glRotate). Column j is
 * cos θ·e_j + (1 − cos θ)·a_j·a + sin θ·(a × e_j). */
sc_dmat4 sc_dmat4_rotate(double deg, double ax, double ay, double az)
{
    sc_dmat4 r = sc_dmat4_identity();
    double len = sqrt(ax * ax + ay * ay + az * az);
    if (!(len > 0.0) || !isfinite(len))
        return r;
    sc_dvec3 a = {ax / len, ay / len, az / len};
    double s, c;
    sincos_degrees(deg, &s, &c);
    for (int j = 0; j < 3; j++) {
        sc_dvec3 e = {j == 0, j == 1, j == 2};
        double a_j = sc_dvec3_dot(a, e);
        sc_dvec3 col = sc_dvec3_add(
            sc_dvec3_add(sc_dvec3_scale(e, c), sc_dvec3_scale(a, (1.0 - c) * a_j)),
            sc_dvec3_scale(sc_dvec3_cross(a, e), s));
        r.m[j * 4 + 0] = col.x;
        r.m[j * 4 + 1] = col.y;
        r.m[j * 4 + 2] = col.z;
    }
    return r;
}

/* gluLookAt: f = normalize(center − eye), s = normalize(f × up), u = s × f; the rows of the
 * rotation are s, u, −f, followed by the translation by −eye. */
int sc_dmat4_look_at(sc_dvec3 eye, sc_dvec3 center, sc_dvec3 up, sc_dmat4 *out)
{
    sc_dvec3 f = sc_dvec3_sub(center, eye);
    double flen = sc_dvec3_length(f);
    if (!(flen > 0.0) || !isfinite(flen))
        return -1;
    f = sc_dvec3_scale(f, 1.0 / flen);
    sc_dvec3 side = sc_dvec3_cross(f, up);
    double slen = sc_dvec3_length(side);
    if (!(slen > 4.0 * U_DOUBLE * sc_dvec3_length(up)) || !isfinite(slen))
        return -1;
    side = sc_dvec3_scale(side, 1.0 / slen);
    sc_dvec3 u = sc_dvec3_cross(side, f);
    const sc_dvec3 rows[3] = {side, u, sc_dvec3_scale(f, -1.0)};
    sc_dmat4 r = sc_dmat4_identity();
    for (int i = 0; i < 3; i++) {
        r.m[0 + i] = rows[i].x;
        r.m[4 + i] = rows[i].y;
        r.m[8 + i] = rows[i].z;
        r.m[12 + i] = -sc_dvec3_dot(rows[i], eye);
    }
    *out = r;
    return 0;
}

/* gluPerspective: f = cot(fovy/2); diag(f/aspect, f, (far+near)/(near−far), 0) with
 * m[3][2] = 2·far·near/(near−far) and m[2][3] = −1 (clip w = −z_eye). */
int sc_dmat4_perspective(double fovy_deg, double aspect, double znear, double zfar, sc_dmat4 *out)
{
    if (!(fovy_deg > 0.0 && fovy_deg < 180.0 && aspect > 0.0 && isfinite(aspect) && znear > 0.0 &&
          znear < zfar && isfinite(zfar)))
        return -1;
    double s, c;
    sincos_degrees(fovy_deg / 2.0, &s, &c);
    double f = c / s;
    sc_dmat4 r = {{0}};
    r.m[0] = f / aspect;
    r.m[5] = f;
    r.m[10] = (zfar + znear) / (znear - zfar);
    r.m[11] = -1.0;
    r.m[14] = 2.0 * zfar * znear / (znear - zfar);
    *out = r;
    return 0;
}

/* docs/formulas.md §7: R = (M3⁻¹)ᵀ, M3 the upper-left 3×3 of M. */
int sc_dmat3_normal_matrix(const sc_dmat4 *m, sc_dmat3 *out)
{
    sc_dmat3 m3, inv;
    upper_left_d(m->m, m3.m);
    if (sc_dmat3_inverse(&m3, &inv) != 0)
        return -1;
    *out = sc_dmat3_transpose(inv);
    return 0;
}
