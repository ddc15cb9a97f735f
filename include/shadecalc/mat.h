/*
 * shadecalc/mat.h — small square matrices, column-major as in GLSL, and the transforms of the
 * renderer and the normal matrix (docs/formulas.md §7).
 *
 *   types     sc_mat2 {float m[4]}  sc_mat3 {float m[9]}  sc_mat4 {float m[16]}
 *             sc_dmat3 {double m[9]}  sc_dmat4 {double m[16]}
 *             element (row r, column c) of an n×n matrix is m[c·n + r], so m[c·n .. c·n+n−1] is
 *             column c, as GLSL's mat3(col0, col1, col2).
 *
 * For T = mat2, mat3, mat4, dmat3, dmat4 with V its vector (vec2, vec3, vec4, dvec3, dvec4)
 * and S its scalar:
 *   T   sc_T_identity(void)
 *   T   sc_T_mul(T a, T b)               a·b (GLSL a * b)
 *   V   sc_T_mul_vec(T m, V v)           m·v (GLSL m * v): component r = dot(row r, v)
 *   T   sc_T_transpose(T m)
 *   S   sc_T_determinant(T m)
 *   int sc_T_inverse(const T *m, T *out) 0, or −1 (out untouched) if m is singular (below)
 *   T   sc_T_comp_mult(T a, T b)         matrixCompMult: a[c][r]·b[c][r]
 * Conversions:
 *   sc_mat3 sc_mat3_from_mat4(sc_mat4 m)     the upper-left 3×3
 *   sc_mat4 sc_mat4_from_mat3(sc_mat3 m)     m in the upper left, then 0 0 0 1 (GLSL mat4(mat3))
 *   sc_mat4 sc_mat4_from_dmat4(sc_dmat4 m)   each entry rounded to float
 * Transforms, in double (OpenGL conventions: right-handed, angles in degrees):
 *   sc_dmat4 sc_dmat4_translate(x, y, z)     glTranslate
 *   sc_dmat4 sc_dmat4_scale(x, y, z)         glScale
 *   sc_dmat4 sc_dmat4_rotate(deg, ax, ay, az) glRotate: counterclockwise by deg about the axis
 *            (ax, ay, az) (normalized here) seen from its tip; a zero or non-finite axis gives
 *            the identity, as Mesa's glRotate. Multiples of 90° are exact (cos 90° = 0).
 *   int sc_dmat4_look_at(eye, center, up, sc_dmat4 *out)   gluLookAt; −1 if eye = center or up
 *            is parallel to the view direction (|f × up| within its rounding error, 4u·|up|)
 *   int sc_dmat4_perspective(fovy_deg, aspect, znear, zfar, sc_dmat4 *out)   gluPerspective;
 *            −1 unless 0 < fovy < 180, aspect > 0, 0 < znear < zfar, all finite
 *   int sc_dmat3_normal_matrix(const sc_dmat4 *m, sc_dmat3 *out)   transpose(inverse(upper-left
 *            3×3 of m)) (docs/formulas.md §7); −1 if that 3×3 is singular
 *
 * Arithmetic (the order of shadecalc/pmath.h, so float results equal `shadecalc eval` highp):
 * products sum over k left to right, each operation rounded to S; the determinant is the
 * Laplace expansion along the first column, det = Σ_r (−1)^r·m[r][0]·det(minor(r, 0)); the
 * inverse is adjugate / det.
 * Singular: det is not finite, or subnormal (underflow voids the error bound; the adjugate
 * would lose precision), or |det| <= γ_k·Π_c ‖column c‖₁ with γ_k = k·u/(1 − k·u),
 * k = (n − 1)(n + 2)/2 roundings (2, 5, 9 for n = 2, 3, 4) and u = 2^-24 (float) or 2^-53
 * (double). Each of the n! products of the Laplace expansion passes through at most k
 * roundings, so the computed determinant of an exactly singular matrix is at most γ_k·per(|A|)
 * <= γ_k·Π‖column‖₁ in magnitude: a determinant within that bound cannot be told from zero.
 * The rule is invariant under scaling any column (diag(1e-30, ...) is not singular).
 *
 * Passing: matrices and vectors by value; the functions that can reject their input take
 * pointers and return 0 or −1. sc_T_mul_vec is static inline here; the rest is in src/mat.c.
 */
#ifndef SHADECALC_MAT_H
#define SHADECALC_MAT_H

#include "shadecalc/api.h"
#include "shadecalc/vec.h"

SC_BEGIN_DECLS

typedef struct {
    float m[4];
} sc_mat2;
typedef struct {
    float m[9];
} sc_mat3;
typedef struct {
    float m[16];
} sc_mat4;
typedef struct {
    double m[9];
} sc_dmat3;
typedef struct {
    double m[16];
} sc_dmat4;

/* m·v: component r is row r of m times v, summed left to right (((m[r][0]·v.x + m[r][1]·v.y)
 * + m[r][2]·v.z) + m[r][3]·v.w). Inline: the renderer's hot path. */
// clang-format off
#define SC_MAT_ROW2_(c, r) (m.m[r] * v.x + m.m[2 + r] * v.y)
#define SC_MAT_ROW3_(c, r) ((m.m[r] * v.x + m.m[3 + r] * v.y) + m.m[6 + r] * v.z)
#define SC_MAT_ROW4_(c, r) (((m.m[r] * v.x + m.m[4 + r] * v.y) + m.m[8 + r] * v.z) + m.m[12 + r] * v.w)
// clang-format on
#define SC_MAT_DEFINE_MUL_VEC(T, V, EACH, ROW)                                                     \
    static inline V T##_mul_vec(T m, V v) { return SC_LITERAL_(V){EACH(ROW)}; }
SC_MAT_DEFINE_MUL_VEC(sc_mat2, sc_vec2, SC_EACH2, SC_MAT_ROW2_)
SC_MAT_DEFINE_MUL_VEC(sc_mat3, sc_vec3, SC_EACH3, SC_MAT_ROW3_)
SC_MAT_DEFINE_MUL_VEC(sc_mat4, sc_vec4, SC_EACH4, SC_MAT_ROW4_)
SC_MAT_DEFINE_MUL_VEC(sc_dmat3, sc_dvec3, SC_EACH3, SC_MAT_ROW3_)
SC_MAT_DEFINE_MUL_VEC(sc_dmat4, sc_dvec4, SC_EACH4, SC_MAT_ROW4_)

sc_mat2 sc_mat2_identity(void);
sc_mat2 sc_mat2_mul(sc_mat2 a, sc_mat2 b);
sc_mat2 sc_mat2_transpose(sc_mat2 m);
float sc_mat2_determinant(sc_mat2 m);
int sc_mat2_inverse(const sc_mat2 *m, sc_mat2 *out);
sc_mat2 sc_mat2_comp_mult(sc_mat2 a, sc_mat2 b);

sc_mat3 sc_mat3_identity(void);
sc_mat3 sc_mat3_mul(sc_mat3 a, sc_mat3 b);
sc_mat3 sc_mat3_transpose(sc_mat3 m);
float sc_mat3_determinant(sc_mat3 m);
int sc_mat3_inverse(const sc_mat3 *m, sc_mat3 *out);
sc_mat3 sc_mat3_comp_mult(sc_mat3 a, sc_mat3 b);

sc_mat4 sc_mat4_identity(void);
sc_mat4 sc_mat4_mul(sc_mat4 a, sc_mat4 b);
sc_mat4 sc_mat4_transpose(sc_mat4 m);
float sc_mat4_determinant(sc_mat4 m);
int sc_mat4_inverse(const sc_mat4 *m, sc_mat4 *out);
sc_mat4 sc_mat4_comp_mult(sc_mat4 a, sc_mat4 b);

sc_dmat3 sc_dmat3_identity(void);
sc_dmat3 sc_dmat3_mul(sc_dmat3 a, sc_dmat3 b);
sc_dmat3 sc_dmat3_transpose(sc_dmat3 m);
double sc_dmat3_determinant(sc_dmat3 m);
int sc_dmat3_inverse(const sc_dmat3 *m, sc_dmat3 *out);
sc_dmat3 sc_dmat3_comp_mult(sc_dmat3 a, sc_dmat3 b);

sc_dmat4 sc_dmat4_identity(void);
sc_dmat4 sc_dmat4_mul(sc_dmat4 a, sc_dmat4 b);
sc_dmat4 sc_dmat4_transpose(sc_dmat4 m);
double sc_dmat4_determinant(sc_dmat4 m);
int sc_dmat4_inverse(const sc_dmat4 *m, sc_dmat4 *out);
sc_dmat4 sc_dmat4_comp_mult(sc_dmat4 a, sc_dmat4 b);

sc_mat3 sc_mat3_from_mat4(sc_mat4 m);
sc_mat4 sc_mat4_from_mat3(sc_mat3 m);
sc_mat4 sc_mat4_from_dmat4(sc_dmat4 m);

sc_dmat4 sc_dmat4_translate(double x, double y, double z);
sc_dmat4 sc_dmat4_scale(double x, double y, double z);
sc_dmat4 sc_dmat4_rotate(double deg, double ax, double ay, double az);
int sc_dmat4_look_at(sc_dvec3 eye, sc_dvec3 center, sc_dvec3 up, sc_dmat4 *out);
int sc_dmat4_perspective(double fovy_deg, double aspect, double znear, double zfar, sc_dmat4 *out);
int sc_dmat3_normal_matrix(const sc_dmat4 *m, sc_dmat3 *out);

SC_END_DECLS

#endif
