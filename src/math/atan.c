/* atan, atan2 in binary32 (GLSL ES atan(y_over_x), atan(y, x)), and their double kernels
 * sc_k_atan, sc_k_atan2 (also used by asin.c).
 *
 * Method: atan(t) for t in [0, 1] reduces once more, t > tan(π/12) giving
 * π/6 + atan((√3 t − 1)/(√3 + t)), to |u| <= tan(π/12) = 0.268, where the series
 * u − u³/3 + u⁵/5 − … to u^31 truncates below 2^-60; |t| > 1 uses π/2 − atan(1/t). All in
 * double. atan2 takes the ratio of the smaller to the larger magnitude (exact enough in double:
 * 2^-53) and places the angle in its quadrant. One rounding to binary32.
 * Special values: atan(±0) = ±0, atan(±Inf) = ±π/2; atan2 follows C99 Annex F, including
 * atan2(±0, +0) = ±0 and atan2(±0, −0) = ±π (GLSL ES leaves atan(0, 0) undefined: this is the
 * documented result), atan2(±Inf, ±Inf) = ±π/4 or ±3π/4; NaN in, NaN out.
 *
 * Binary64 error bound of the value rounded (u = 2^-53; Higham §5.1 for Horner's rule), the
 * bound make exhaustive relies on: atan |core − exact| <= 2^-47 |core|, atan2 <= 2^-46 |core|.
 *   atan_unit, t <= tan(π/12): z = t² carries u; Horner on 16 coefficients (each rounded, u):
 *   γ_30·1.025 + 1.05u absolute on a sum >= 0.977, z's error 0.03u, truncation 2^-65, the
 *   product u: 34u relative. t > tan(π/12): √3·t − 1 is within 3.5u absolute (constant and
 *   product; the subtraction rounds 4u|w| at most with the denominator and division), w within
 *   1.76u + 4u|w|, |w| <= 0.268; with π/6 (1.05u) and the final addition on a result >= π/12:
 *   13.6u absolute, 52u relative. A rounded argument (1/t, y/x) adds <= u.
 *   atan: |x| > 1 gives π/2 − atan_unit(1/|x|) >= π/4: (53u·0.786 + 1.57u)/0.785 + u = 56u.
 *   atan2: the ratio rounds (u); the steep case as atan (56u); x < 0 gives π − a >= π/2:
 *   (56u·1.571 + 3.14u)/1.571 + 2u = 60u < 2^-46. Special values are exact.
 *
 * Stated bound: <= 1 ULP against the double reference for every binary32 input (pairs for
 * atan2). make exhaustive, every binary32 input: atan correctly rounded with its table of one
 * hard case (atan_hard_cases); atan2 correctly rounded in 10^9 biased pairs with its table of one
 * hard pair (atan2_hard_cases). Measured against glibc rounded to binary32: atan correctly rounded (0.5 ULP) for all
 * 2^32 inputs; atan2 <= 0.5 + 10^-6 ULP on 10^8 random pairs (half of similar magnitude), one
 * of them not correctly rounded.
 */
#include <math.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

static const double pi = 3.14159265358979323846;
static const double sqrt3 = 1.73205080756887729353;
static const double tan_pi_12 = 0.26794919243112270647;

/* (−1)^j/(2j+1), j = 0..15: atan(u)/u = Σ (−1)^j u^(2j)/(2j+1) */
static const double atan_coef[16] = {1.0,      -1.0 / 3,  1.0 / 5,  -1.0 / 7,  1.0 / 9,  -1.0 / 11,
                                     1.0 / 13, -1.0 / 15, 1.0 / 17, -1.0 / 19, 1.0 / 21, -1.0 / 23,
                                     1.0 / 25, -1.0 / 27, 1.0 / 29, -1.0 / 31};

/* atan(t), 0 <= t <= 1 */
static double atan_unit(double t)
{
    double base = 0.0;
    if (t > tan_pi_12) {
        t = (sqrt3 * t - 1.0) / (sqrt3 + t);
        base = pi / 6.0;
    }
    return base + t * sc_k_horner(t * t, atan_coef, 16);
}

double sc_k_atan(double x)
{
    double t = fabs(x);
    double a = t <= 1.0 ? atan_unit(t) : pi / 2.0 - atan_unit(1.0 / t);
    return signbit(x) ? -a : a; /* atan(−0) = −0 */
}

double sc_k_atan2(double y, double x)
{
    if (x != x || y != y)
        return x + y;
    double ay = fabs(y), ax = fabs(x), a;
    if (ay == INFINITY && ax == INFINITY)
        a = pi / 4.0;
    else if (ay == 0.0 && ax == 0.0)
        a = 0.0;
    else if (ay <= ax) /* ratio in [0, 1]; 0 when x = ±Inf */
        a = atan_unit(ay / ax);
    else
        a = pi / 2.0 - atan_unit(ax / ay);
    if (signbit(x))
        a = pi - a; /* left half-plane, including x = −0 */
    return signbit(y) ? -a : a;
}

/* The hard case of atan (with its negative): make exhaustive found it over all 2^32 inputs (the
 * core rounds it to the wrong side); value from MPFR at 300 bits: the midpoint's double plus one
 * ULP (atan(0.0690520033) = 0.06894256547093391601248...). */
static const sc_k_hard_case atan_hard_cases[] = {{0x3d8d6b23, 0x1.1a63850000001p-4}};

double sc_k_atan_core(float x)
{
    double r = sc_k_atan((double)x);
    if (!sc_k_near_midpoint(r, 0x1p-46))
        return r;
    return copysign(sc_k_lookup_hard(atan_hard_cases, 1, fabsf(x), fabs(r)), r);
}

/* The hard case of atan2: make exhaustive found it in 10^9 biased pairs (the core rounds it to
 * the wrong side); value as for atan, atan2(y, x) = -3.141581177711487046264... */
static const sc_k_hard_pair atan2_hard_cases[] = {
    /* (y, x) = (-1.72213614e-15, -1.50065738e-10) */
    {0xa6f82f9c, 0xaf24ffc0, -0x1.921f550000001p+1},
};

double sc_k_atan2_core(float y, float x)
{
    double r = sc_k_atan2((double)y, (double)x);
    if (!sc_k_near_midpoint(r, 0x1p-46))
        return r;
    return sc_k_lookup_hard_pair(atan2_hard_cases, SC_K_TABLE_LEN(atan2_hard_cases), y, x, r);
}

float sc_atanf(float y_over_x) { return (float)sc_k_atan_core(y_over_x); }

float sc_atan2f(float y, float x) { return (float)sc_k_atan2_core(y, x); }
