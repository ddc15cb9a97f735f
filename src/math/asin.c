/* asin, acos in binary32 (GLSL ES asin, acos).
 *
 * Method: asin x = atan2(x, √((1−x)(1+x))) and acos x = atan2(√((1−x)(1+x)), x), in double
 * with the shared atan2 kernel (atan.c) and the libm double square root (correctly rounded
 * IEEE sqrt, one instruction). For |x| >= 1/2, 1 − x and 1 + x are exact in double and so is
 * their product (at most 49 bits); below, the cosine is near 1 and its relative rounding
 * (2^-52) moves the angle by less than that. One rounding to binary32.
 * Special values: asin(±0) = ±0, asin(±1) = ±π/2, acos(1) = +0, acos(−1) = π;
 * |x| > 1 (GLSL ES: undefined) and NaN give NaN.
 *
 * Binary64 error bound of the value rounded, the bound make exhaustive relies on (u = 2^-53):
 * |core − exact| <= 2^-46 |core| for both. The cosine c carries u (|x| >= 1/2: one sqrt
 * rounding) or 2.5u (below: two differences, a product, then the square root halves it);
 * atan2(x, c(1 + δ)) moves by |δ|·|x|c, at most 2.5u relative to |asin x| >= |x| and to
 * acos x >= |x|c (near 1) or >= π/2; then the atan2 kernel's 60u (atan.c): 63u < 2^-46.
 *
 * Stated bound: <= 1 ULP against the double reference for every binary32 input. make
 * exhaustive, every binary32 input against this bound and MPFR: asin correctly rounded; acos
 * correctly rounded with its table of two hard cases (acos_hard_cases, consulted only when the
 * core lands within its bound of a midpoint).
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

/* cos(asin x) = √((1 − x)(1 + x)); NaN for |x| > 1. */
static double cosine_of_asin(double x) { return sqrt((1.0 - x) * (1.0 + x)); }

double sc_k_asin_core(float x)
{
    double xd = (double)x;
    return sc_k_atan2(xd, cosine_of_asin(xd));
}

/* The hard cases of acos: make exhaustive found these two over all 2^32 inputs (the core rounds
 * them the wrong way); values from MPFR at 300 bits: the midpoint's double plus one ULP. */
const sc_k_hard_case sc_k_acos_hard_cases[2] = {
    {0x328885a3, 0x1.921fb50000001p+0}, /* acos(1.58932547e-8) = 1.57079631090164190694 */
    {0x39826222, 0x1.920f690000001p+0}, /* acos(0.000248686469) = 1.57054764032363892599 */
};

double sc_k_acos_core(float x)
{
    double xd = (double)x;
    double r = sc_k_atan2(cosine_of_asin(xd), xd);
    return SC_K_SETTLE(sc_k_acos_hard_cases, x, r, 0x1p-46);
}

float sc_asinf(float x) { return (float)sc_k_asin_core(x); }

float sc_acosf(float x) { return (float)sc_k_acos_core(x); }
