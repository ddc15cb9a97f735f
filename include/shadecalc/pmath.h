/*
 * shadecalc/pmath.h — the GLSL ES built-ins and arithmetic in a chosen precision (SPEC §9).
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
 *                  sc_p_exp2 sc_p_log2 sc_p_sqrt sc_p_inversesqrt
 *   two arguments  sc_p_pow sc_p_atan2
 *   geometric      sc_p_dot sc_p_length sc_p_distance sc_p_normalize sc_p_cross sc_p_reflect
 *                  sc_p_refract sc_p_faceforward   (vectors as arrays of n doubles, n = 1..4)
 *
 * The geometric functions are their GLSL ES defining formulas (§8.5), each operation rounded:
 * dot = (((a0·b0 + a1·b1) + a2·b2) + a3·b3), length = sqrt(dot(a,a)), normalize = a / length(a)
 * (the zero vector gives 0/0 = NaN components: GLSL leaves it undefined), reflect =
 * I − 2·dot(N,I)·N, refract = the zero vector when k = 1 − η²(1 − dot(N,I)²) < 0.
 * Output arrays may alias the inputs.
 */
#ifndef SHADECALC_PMATH_H
#define SHADECALC_PMATH_H

#include "shadecalc/precision.h"

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
double sc_p_pow(sc_prec p, double x, double y);
double sc_p_atan2(sc_prec p, double y, double x);

double sc_p_dot(sc_prec p, const double *a, const double *b, int n);
double sc_p_length(sc_prec p, const double *a, int n);
double sc_p_distance(sc_prec p, const double *a, const double *b, int n);
void sc_p_normalize(sc_prec p, const double *a, int n, double *out);
void sc_p_cross(sc_prec p, const double *a, const double *b, double *out);
void sc_p_reflect(sc_prec p, const double *i, const double *nrm, int n, double *out);
void sc_p_refract(sc_prec p, const double *i, const double *nrm, double eta, int n, double *out);
void sc_p_faceforward(sc_prec p, const double *nrm, const double *i, const double *nref, int n,
                      double *out);

#endif
