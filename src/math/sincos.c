/* sin, cos, tan in binary32 (GLSL ES sin, cos, tan), for every binary32 input.
 *
 * Method: r = x − k·π/2 with k = rint(x·2/π), then sin r and cos r on |r| <= π/4 (plus the
 * rounding slack of k) by their Taylor series to degree 15 and 16 (truncation below 2^-55
 * relative), in double; the quadrant k mod 4 selects ±sin r or ±cos r, and tan = sin r/cos r or
 * −cos r/sin r. One rounding to binary32.
 * Reduction, |x| < 2^19·π/2 (about 8.2e5): Cody–Waite with π/2 = p1 + p2 + p3, p1 and p2 of
 * 33 bits, so k·p1 and k·p2 are exact for |k| < 2^20 and x − k·p1 is exact (Sterbenz); the
 * absolute error of r is below 2^-100.
 * Reduction, larger x (Payne–Hanek): x = m·2^e with m < 2^24, and x·2/π mod 4 needs only the
 * bits of 2/π from weight 2^(1−e) on; 192 of them, times m in 32-bit limbs, give the fraction
 * exactly to 2^-168, from which k mod 4 and r are read. 320 bits of 2/π cover e <= 104.
 * Special values: sin(±0) = ±0, tan(±0) = ±0, cos(±0) = 1; ±Inf and NaN give NaN.
 *
 * Binary64 error bound of the value rounded (u = 2^-53; Higham §5.1 for Horner's rule), the
 * bound make exhaustive relies on: sin, cos |core − exact| <= 2^-47 |core| + a, tan
 * |core − exact| <= 2^-46 |core| + a (1 + core²), with a = 0 for |x| < 0.78 (k = 0, r = x
 * exactly) and a = 2^-99 otherwise.
 *   r: Cody–Waite, x − k·p1 and k·p2 exact; k·p3 and the middle subtraction round (2^-101
 *   each, |k p3| < 2^-48), the last subtraction u|r|, π/2 − p1 − p2 − p3 <= 2^-122 times k:
 *   |δr| <= 2^-52|r| + 2^-99.7. Payne–Hanek: t exact to 2^-144, its conversion and the product
 *   by π/2 4u|r|.
 *   sin_poly: z = r² <= 0.62 carries u; Horner on 8 coefficients: γ_14·sinh r/r + 1.1u on a
 *   sum >= 0.9, z's error 0.11u, the product u: 19.5u. cos_poly: γ_16·cosh r + 1.9u on a sum
 *   >= 0.70, z's error 0.44u: 33u. With δr (|cos| <= 1; 2^-52|r| <= 2.2u|sin r|): sin, cos
 *   within 35u|core| + 2^-99.7.
 *   tan: s/c adds 56u relative; δr moves tan r by δr(1 + core²): 2^-52|r|(1 + core²) <= 4u|core|
 *   and 2^-99.7(1 + core²): 61u|core| + 2^-99.7(1 + core²).
 *
 * Stated bound: <= 1 ULP against the double reference for every finite binary32 x (GLSL ES
 * asks nothing; the accuracy test checks |x| <= 1e4). make exhaustive, every binary32 input
 * against this bound and MPFR: sin and cos correctly rounded with their tables of two and four
 * hard cases (sin_hard_cases, cos_hard_cases, consulted only when the core lands within its
 * bound of a midpoint).
 */
#include <stdint.h>
#include <string.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"

static const double two_over_pi = 0x1.45f306dc9c883p-1;
static const double pio2 = 0x1.921fb54442d18p+0;
static const double pio2_1 = 0x1.921fb544p+0;       /* π/2, first 33 bits */
static const double pio2_2 = 0x1.0b4611a6p-34;      /* next 33 bits */
static const double pio2_3 = 0x1.3198a2e037073p-69; /* π/2 − pio2_1 − pio2_2, to 2^-122 */
static const double cody_waite_limit = 0x1p19 * 0x1.921fb54442d18p+0; /* |k| < 2^20 */

/* Bits of 2/π in 32-bit words, most significant first, after one zero word standing for the
 * integer part and the (zero) bits of weight 2^0 .. 2^31: word 1 holds weights 2^-1 .. 2^-32. */
static const uint32_t two_over_pi_bits[11] = {0,          0xa2f9836e, 0x4e441529, 0xfc2757d1,
                                              0xf534ddc0, 0xdb629599, 0x3c439041, 0xfe5163ab,
                                              0xdebbc561, 0xb7246e3a, 0x424dd2e0};

/* sin(r)/r = Σ (−1)^j r^(2j)/(2j+1)!, j = 0..7 */
static const double sin_coef[8] = {
    1.0,          -1.0 / 6,        1.0 / 120,          -1.0 / 5040,
    1.0 / 362880, -1.0 / 39916800, 1.0 / 6227020800.0, -1.0 / 1307674368000.0};
/* cos(r) = Σ (−1)^j r^(2j)/(2j)!, j = 0..8 */
static const double cos_coef[9] = {1.0,
                                   -1.0 / 2,
                                   1.0 / 24,
                                   -1.0 / 720,
                                   1.0 / 40320,
                                   -1.0 / 3628800,
                                   1.0 / 479001600,
                                   -1.0 / 87178291200.0,
                                   1.0 / 20922789888000.0};

typedef struct {
    double r;     /* x − k·π/2, |r| <= π/4 (slightly more when x·2/π rounds across a half) */
    int quadrant; /* k mod 4 */
} reduced;

/* The 32 bits of 2/π of weights 2^-i .. 2^-(i+31), for i >= -31 (zeros before the point). */
static uint32_t two_over_pi_word(int i)
{
    int p = i + 31; /* bit offset into two_over_pi_bits */
    int j = p / 32, shift = p % 32;
    uint64_t pair = (uint64_t)two_over_pi_bits[j] << 32 | two_over_pi_bits[j + 1];
    return (uint32_t)(pair >> (32 - shift));
}

/* Payne–Hanek for finite |x| >= cody_waite_limit, x = m·2^e: x·2/π ≡ 4·frac(m·F) (mod 4),
 * F = 0.b(e−1) b(e) … the bits of 2/π from weight 2^(1−e) (bits of larger weight add
 * multiples of 4). m·F is formed in six 32-bit limbs; its fraction gives k mod 4 and t = the
 * signed distance to the nearest k in units of π/2. */
static reduced reduce_large(float x)
{
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    uint64_t m = (bits & 0x7fffffu) | 0x800000u;
    int e = (int)((bits >> 23) & 0xff) - 150;

    uint32_t limb[6];
    uint64_t carry = 0;
    for (int j = 5; j >= 0; j--) {
        uint64_t acc = m * two_over_pi_word(e - 1 + 32 * j) + carry;
        limb[j] = (uint32_t)acc;
        carry = acc >> 32;
    }
    uint64_t a = (uint64_t)limb[0] << 32 | limb[1], b = (uint64_t)limb[2] << 32 | limb[3];
    uint64_t c = (uint64_t)limb[4] << 32 | limb[5];

    int quadrant = (int)(a >> 62);
    uint64_t hi = a << 2 | b >> 62, lo = b << 2 | c >> 62; /* t = 0.hi lo, in [0, 1) */
    double sign = 1.0;
    if (hi >> 63) { /* t >= 1/2: the nearest k is the next one, t − 1 = −(2^128 − hi lo)/2^128 */
        quadrant += 1;
        sign = -1.0;
        lo = ~lo + 1;
        hi = ~hi + (lo == 0);
    }
    double t = sign * ((double)hi * 0x1p-64 + (double)lo * 0x1p-128);

    reduced out = {t * pio2, quadrant & 3};
    if (x < 0.0f) {
        out.r = -out.r;
        out.quadrant = -quadrant & 3;
    }
    return out;
}

static reduced reduce(float x)
{
    double xd = (double)x;
    if (!(xd > -cody_waite_limit && xd < cody_waite_limit)) {
        if (x - x != 0.0f) /* ±Inf, NaN */
            return (reduced){x - x, 0};
        return reduce_large(x);
    }
    double k = sc_k_rint(xd * two_over_pi);
    double r = ((xd - k * pio2_1) - k * pio2_2) - k * pio2_3;
    return (reduced){r, (int)((int64_t)k & 3)};
}

static double sin_poly(double r) { return r * sc_k_horner(r * r, sin_coef, 8); }
static double cos_poly(double r) { return sc_k_horner(r * r, cos_coef, 9); }

/* sin(x) = sin r, cos r, −sin r, −cos r in quadrants 0..3; cos(x) = sin(x + π/2). */
static double sin_quadrant(double r, int quadrant)
{
    double v = quadrant & 1 ? cos_poly(r) : sin_poly(r);
    return quadrant & 2 ? -v : v;
}

/* The relative form of the bound 2^-47 |core| + 2^-99 (core = 0 only where it is exact). */
static double sincos_eps(double core)
{
    return core != 0.0 ? 0x1p-47 + 0x1p-99 / (core < 0 ? -core : core) : 0.0;
}

/* The hard cases of sin: make exhaustive found these two over all 2^32 inputs (the core rounds
 * them the wrong way); values from MPFR at 300 bits: the midpoint's double one ULP toward the
 * exact value. */
const sc_k_hard_case sc_k_sin_hard_cases[2] = {
    {0x46199998, -0x1.63f4bafffffffp-2}, /* sin(9830.39844) = -0.34761326014995572995 */
    {0xc6199998, 0x1.63f4bafffffffp-2},  /* sin(-9830.39844) */
};

double sc_k_sin_core(float x)
{
    reduced q = reduce(x);
    double r = sin_quadrant(q.r, q.quadrant);
    return SC_K_SETTLE(sc_k_sin_hard_cases, x, r, sincos_eps(r));
}

/* The hard cases of cos (even: both signs of x), found and valued as sin's. */
static const sc_k_hard_case cos_hard_cases[] = {
    {0x5f18b878, 0x1.fe2976fffffffp-1}, /* cos(1.10046776e19) = 0.99641010165214536707 */
    {0xdf18b878, 0x1.fe2976fffffffp-1},
    {0x6115cb11, 0x1.f0285d0000001p-1}, /* cos(1.72699834e20) = 0.96905794739723207014 */
    {0xe115cb11, 0x1.f0285d0000001p-1},
};

double sc_k_cos_core(float x)
{
    reduced q = reduce(x);
    double r = sin_quadrant(q.r, (q.quadrant + 1) & 3);
    return SC_K_SETTLE(cos_hard_cases, x, r, sincos_eps(r));
}

/* tan(x) = tan r in even quadrants, −cot r in odd ones. */
double sc_k_tan_core(float x)
{
    reduced q = reduce(x);
    double s = sin_poly(q.r), c = cos_poly(q.r);
    return q.quadrant & 1 ? -c / s : s / c;
}

float sc_sinf(float x) { return (float)sc_k_sin_core(x); }

float sc_cosf(float x) { return (float)sc_k_cos_core(x); }

float sc_tanf(float x) { return (float)sc_k_tan_core(x); }
