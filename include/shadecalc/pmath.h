/*
 * shadecalc/pmath.h — the GLSL ES built-ins and arithmetic in a chosen precision (docs/formulas.md §9).
 *
 * Values travel as doubles that are already representable in the precision p. Each function
 * returns its result rounded to p:
 *   SC_DOUBLE   the reference: libm in binary64
 *   SC_HIGHP    the accurate binary32 built-ins of shadecalc/glsl.h
 *   SC_MEDIUMP  the binary32 built-in, rounded to binary16
 *   SC_LOWP     the binary32 built-in, rounded to 8-bit-fraction fixed point
 * So an expression written with these functions is evaluated exactly as a GLSL ES
 * implementation of that precision would round it, one operation at a time.
 *
 *   arithmetic     sc_p_add sc_p_sub sc_p_mul sc_p_div sc_p_neg
 *   one argument   sc_p_sin sc_p_cos sc_p_tan sc_p_asin sc_p_acos sc_p_atan sc_p_exp sc_p_log
 *                  sc_p_exp2 sc_p_log2 sc_p_sqrt sc_p_inversesqrt sc_p_sinh sc_p_cosh sc_p_tanh
 *                  sc_p_asinh sc_p_acosh sc_p_atanh
 *   two arguments  sc_p_pow sc_p_atan2
 *   common         sc_p_radians sc_p_degrees sc_p_abs sc_p_sign sc_p_floor sc_p_ceil sc_p_fract
 *                  sc_p_trunc sc_p_round sc_p_roundeven sc_p_modf sc_p_mod sc_p_min sc_p_max
 *                  sc_p_step sc_p_clamp sc_p_mix sc_p_smoothstep
 *   geometric      sc_p_dot sc_p_length sc_p_distance sc_p_normalize sc_p_cross sc_p_reflect
 *                  sc_p_refract sc_p_faceforward   (vectors as arrays of n doubles, n = 1..4)
 *
 * The geometric functions are their GLSL ES defining formulas (§8.5), each operation rounded:
 * dot = (((a0·b0 + a1·b1) + a2·b2) + a3·b3), length = sqrt(dot(a,a)), normalize = a / length(a)
 * (the zero vector gives 0/0 = NaN components: GLSL leaves it undefined), reflect =
 * I − 2·dot(N,I)·N, refract = the zero vector when k = 1 − η²(1 − dot(N,I)²) < 0.
 * Output arrays may alias the inputs.
 *
 *   matrices       sc_p_matmul sc_p_mat_vec sc_p_vec_mat sc_p_transpose sc_p_comp_mult
 *                  sc_p_outer sc_p_determinant sc_p_inverse
 * Matrices are n×n (n = 2..4), column-major as GLSL: element (row r, column c) is m[c·n + r].
 * Products sum left to right over k, each operation rounded; determinant is the cofactor
 * expansion along the first column, inverse the adjugate divided by the determinant.
 */
#ifndef SHADECALC_PMATH_H
#define SHADECALC_PMATH_H

#include "shadecalc/api.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

double sc_p_add(sc_prec p, double a, double b);
double sc_p_sub(sc_prec p, double a, double b);
double sc_p_mul(sc_prec p, double a, double b);
double sc_p_div(sc_prec p, double a, double b);
double sc_p_neg(sc_prec p, double a);

double sc_p_sin(sc_prec p, double x);
double sc_p_cos(sc_prec p, double x);
double sc_p_tan(sc_prec p, double x);
double sc_p_asin(sc_prec p, double x);
double sc_p_acos(sc_prec p, double x);
double sc_p_atan(sc_prec p, double x);
double sc_p_exp(sc_prec p, double x);
double sc_p_log(sc_prec p, double x);
double sc_p_exp2(sc_prec p, double x);
double sc_p_log2(sc_prec p, double x);
double sc_p_sqrt(sc_prec p, double x);
double sc_p_inversesqrt(sc_prec p, double x);
double sc_p_sinh(sc_prec p, double x);
double sc_p_cosh(sc_prec p, double x);
double sc_p_tanh(sc_prec p, double x);
double sc_p_asinh(sc_prec p, double x);
double sc_p_acosh(sc_prec p, double x);
double sc_p_atanh(sc_prec p, double x);
double sc_p_pow(sc_prec p, double x, double y);
double sc_p_atan2(sc_prec p, double y, double x);

double sc_p_radians(sc_prec p, double x);
double sc_p_degrees(sc_prec p, double x);
double sc_p_abs(sc_prec p, double x);
double sc_p_sign(sc_prec p, double x);
double sc_p_floor(sc_prec p, double x);
double sc_p_ceil(sc_prec p, double x);
double sc_p_fract(sc_prec p, double x);
double sc_p_trunc(sc_prec p, double x);
double sc_p_round(sc_prec p, double x); /* halves to even, as roundEven (shadecalc/glsl.h) */
double sc_p_roundeven(sc_prec p, double x);
/* GLSL modf: returns the fraction of x and writes its whole part to *whole, both in p. */
double sc_p_modf(sc_prec p, double x, double *whole);
double sc_p_mod(sc_prec p, double x, double y);
double sc_p_min(sc_prec p, double x, double y);
double sc_p_max(sc_prec p, double x, double y);
double sc_p_step(sc_prec p, double edge, double x);
double sc_p_clamp(sc_prec p, double x, double lo, double hi);
double sc_p_mix(sc_prec p, double x, double y, double a);
double sc_p_smoothstep(sc_prec p, double edge0, double edge1, double x);

double sc_p_dot(sc_prec p, const double *a, const double *b, int n);
double sc_p_length(sc_prec p, const double *a, int n);
double sc_p_distance(sc_prec p, const double *a, const double *b, int n);
void sc_p_normalize(sc_prec p, const double *a, int n, double *out);
void sc_p_cross(sc_prec p, const double *a, const double *b, double *out);
void sc_p_reflect(sc_prec p, const double *i, const double *nrm, int n, double *out);
void sc_p_refract(sc_prec p, const double *i, const double *nrm, double eta, int n, double *out);
void sc_p_faceforward(sc_prec p, const double *nrm, const double *i, const double *nref, int n,
                      double *out);

void sc_p_matmul(sc_prec p, const double *a, const double *b, int n, double *out);
void sc_p_mat_vec(sc_prec p, const double *m, const double *v, int n, double *out);
void sc_p_vec_mat(sc_prec p, const double *v, const double *m, int n, double *out);
void sc_p_transpose(const double *m, int n, double *out);
void sc_p_comp_mult(sc_prec p, const double *a, const double *b, int n, double *out);
/* outerProduct(c, r): column vector c times row vector r. */
void sc_p_outer(sc_prec p, const double *c, const double *r, int n, double *out);
double sc_p_determinant(sc_prec p, const double *m, int n);
/* Writes adjugate(m)/det(m) and returns det(m) (a zero determinant gives ±Inf/NaN entries:
 * GLSL leaves the inverse of a singular matrix undefined). */
double sc_p_inverse(sc_prec p, const double *m, int n, double *out);

SC_END_DECLS

#endif
