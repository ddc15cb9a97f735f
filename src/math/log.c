/* log2 and log in binary32 (GLSL ES log2, log).
 *
 * Method: x = m·2^e with m in [√½, √2) from the bits of the double; with s = (m−1)/(m+1),
 * |s| <= 0.1716, log(m) = 2 atanh(s) = 2(s + s³/3 + s⁵/5 + …) to s^23 (truncation below
 * 2^-60), in double; log2 x = e + log(m)/ln 2 and log x = e ln 2 + log(m). One rounding to
 * binary32. Float subnormals are normal doubles, so they need no scaling.
 * Special values (C99 Annex F): log(±0) = −Inf, log(x < 0) = NaN, log(+Inf) = +Inf, NaN → NaN.
 *
 * Binary64 error bound of the value rounded (u = 2^-53; Higham §5.1 for Horner's rule), the
 * bound make exhaustive relies on: |core − exact| <= 2^-48 |core| for log2 and log.
 *   log_reduced: m − 1 exact (Sterbenz), m + 1 and the division round: s carries 2u + u²;
 *   z = s² <= 0.0295 carries 5u; Horner on 12 coefficients (each rounded, u): γ_22·1.011 + 1.01u,
 *   and z's error moves the sum by <= 0.05u, on a sum >= 1; truncation 2^-65; the product 2s·Q
 *   rounds once: log m within 26.2u relative, |log m| <= 0.347.
 *   log2: times inv_ln2 (constant and product, 2u): log2 m within 28.2u, |log2 m| <= 1/2. For
 *   e = 0 that is the result; otherwise |e + log2 m| >= 1/2, so the absolute 14.1u plus the
 *   final rounding is <= 29.2u relative.
 *   log: e·ln2 carries 2u + u² relative; for e ≠ 0, |e ln2 + log m| >= |e| ln2 / 2, so
 *   4.02u + 26.2u + u (final addition) = 31.2u relative.
 * Special values are exact (no rounding error).
 *
 * Stated bound: <= 1 ULP against the double reference for every positive binary32. make
 * exhaustive, every binary32 input: log2 correctly rounded; log correctly rounded with its table
 * of three hard cases (log_hard_cases).
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

static const double ln2 = 0.6931471805599453094;
static const double inv_ln2 = 1.4426950408889634074;

/* 1/(2k+1) for k = 0..11: atanh(s)/s = Σ s^(2k)/(2k+1) */
static const double inv_odd[12] = {1.0,      1.0 / 3,  1.0 / 5,  1.0 / 7,  1.0 / 9,  1.0 / 11,
                                   1.0 / 13, 1.0 / 15, 1.0 / 17, 1.0 / 19, 1.0 / 21, 1.0 / 23};

double sc_k_atanh_series(double s) { return s * sc_k_horner(s * s, inv_odd, 12); }

/* Natural log of m in [√½, √2). */
static double log_reduced(double m) { return 2.0 * sc_k_atanh_series((m - 1.0) / (m + 1.0)); }

/* Splits positive normal x into m in [√½, √2) and the exponent e. */
static double split(double x, int *e)
{
    uint64_t u = sc_bits_of(x);
    int ex = (int)((u >> 52) & 0x7ff) - 1023;
    double m = sc_double_of((u & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL); /* [1, 2) */
    int big = m > 1.4142135623730951;
    *e = ex + big;
    return big ? m * 0.5 : m;
}

double sc_k_log(double x)
{
    int e;
    double m = split(x, &e);
    return (double)e * ln2 + log_reduced(m);
}

double sc_k_log2(double x)
{
    int e;
    double m = split(x, &e);
    return (double)e + log_reduced(m) * inv_ln2;
}

/* Special values of both logs: NaN for x < 0 or NaN, −Inf at ±0, +Inf at +Inf; 0 otherwise. */
static int log_special(float x, double *out)
{
    if (x > 0.0f && x < INFINITY)
        return 0;
    *out = x == 0.0f ? -INFINITY : x > 0.0f ? (double)x : NAN;
    return 1;
}

double sc_k_log2_core(float x)
{
    double special;
    if (log_special(x, &special))
        return special;
    return sc_k_log2((double)x);
}

/* The hard cases of log: make exhaustive found these three over all 2^32 inputs (the core
 * rounds them to the wrong side); values from MPFR at 300 bits: the midpoint's double plus one
 * ULP. */
static const sc_k_hard_case log_hard_cases[] = {
    {0x4c5d65a5, 0x1.1e06950000001p+4}, /* log(58037908) = 17.87660694122314468798... */
    {0x65d890d3, 0x1.a9a3f10000001p+5}, /* log(1.2783784e23) = 53.20504951477050802794... */
    {0x6f31a8ec, 0x1.08b5110000001p+6}, /* log(5.4983061e28) = 66.17682266235352211194... */
};

double sc_k_log_core(float x)
{
    double special;
    if (log_special(x, &special))
        return special;
    double r = sc_k_log((double)x);
    return SC_K_SETTLE(log_hard_cases, x, r, 0x1p-47);
}

float sc_log2f(float x) { return (float)sc_k_log2_core(x); }
float sc_logf(float x) { return (float)sc_k_log_core(x); }
