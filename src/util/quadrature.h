/* Gauss–Legendre quadrature rules, shared by the albedo check (src/brdf/check.c) and the area
 * light reference (src/light/area_reference.c). */
#ifndef SHADECALC_UTIL_QUADRATURE_H
#define SHADECALC_UTIL_QUADRATURE_H

/* The n nodes x and weights w of the n-point Gauss–Legendre rule on [−1, 1] (n >= 1), by
 * Newton's method on P_n (Numerical Recipes gauleg). */
void sc_gauss_legendre(int n, double *x, double *w);

#endif
