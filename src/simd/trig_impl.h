/* The sin, cos, acos, atan2 batch kernels, written once against the vector helpers and included
 * after src/simd/kernels_impl.h by each instruction set's file.
 *
 * u1: the algorithms of src/math/sincos.c, atan.c and asin.c in double lanes (same constants,
 * same polynomials, same order of operations, so that without FMA the bits are those of sc_sinf
 * etc.), rounded once; lanes with rare inputs go to the scalar built-in: sin/cos beyond the
 * Cody–Waite range or not finite, atan2 of (0, 0), (±Inf, ±Inf) or NaN, and the inputs of the
 * sin and acos hard-case tables.
 * Float tiers: Cody–Waite reduction by multiples of π/2 in two float parts, and polynomials
 * fitted on the reduced interval (mpmath chebyfit; the fit error is in each comment). */

#include "math/kernel.h"

/* ---- float tiers ---- */

/* sin r / r as a polynomial in s = r², s in [0, (π/2 + 0.001)²]: 3 terms (fit error 8.8e-5);
 * 5 terms (4.3e-9), whose constant term 1 − 4.3e-9 is 1 in float: (sin r / r − 1)/s by the
 * other four, sin_p4. */
static const float sin_c3[3] = {0.00762579659446825f, -0.16601839683017208f, 0.9999111957241367f};
static const float sin_p4[4] = {2.604920700948167e-06f, -0.00019808936593914233f,
                                0.008333049100952087f, -0.1666665790378068f};

/* π/2 = pio2_hi + pio2_lo + 1.7e-13: pio2_hi has 11 significant bits, so m·pio2_hi is exact
 * for |m| < 2^13, and x − m·pio2_hi is exact where it matters (Sterbenz). */
static const float pio2_hi = 0x1.922p+0f, pio2_lo = -0x1.2aeef4p-18f;
static const float trig_inv_pi = 0x1.45f306p-2f; /* 1/π */
/* 1.5·2^23: for |v| < 2^22, v + round_shifter is rounded to the integer rint(v), which sits in
 * the low bits of the float's mantissa (so its lowest bit is the parity of rint(v)). */
static const float round_shifter = 0x1.8p23f;
/* The fast range |x| <= 1000: |m| <= 637, r = x − m·π/2 to about 2^-33 absolute. Its test is
 * |x| < the next float above 1000, whose negation also holds for NaN. */
static const float fast_trig_above = 0x1.f40002p+9f;

/* sin r, |r| <= π/2 + 0.001, of the bits22 tier: r + r³ p(r²), the exact r added by the last
 * FMA, so the result carries its one rounding plus p's small relative share (on the bench's
 * sample: max 1.41 ULP, 1.70 as r·q(r²) with two roundings of full weight; glibc's vector sinf
 * 1.42), in as many operations. */
static inline vf sin_r_bits22(vf r)
{
    vf t = vf_mul(r, r);
    return vf_fma(vf_mul(r, t), poly(t, sin_p4, 4), r);
}

/* sin r of the bits12 tier: r q(r²) */
static inline vf sin_r_bits12(vf r) { return vf_mul(r, poly(vf_mul(r, r), sin_c3, 3)); }

/* (−1)^k sin(x − m·π/2), |x| <= 1000, for the integer m nearest the reduction and k
 * the integer in the low bits of k_bits: r = x − m·π/2 in |r| <= π/2 (plus the rounding of m),
 * sin r by sin_r, and the sign flipped by adding k's lowest bit at the sign bit. */
static SC_INLINE vf sin_of_reduced(vf x, vf mf, vi k_bits, vf (*sin_r)(vf))
{
    vf r = vf_fma(mf, vf_set1(-pio2_hi), x);
    r = vf_fma(mf, vf_set1(-pio2_lo), r);
    return vi_as_vf(vi_add(vf_as_vi(sin_r(r)), vi_shl31(k_bits)));
}

/* |x| > 1000 or NaN: the lanes the scalar built-in replaces (the fast lanes compute
 * garbage there, without undefined behaviour: float operations only). */
static inline vm outside_trig(vf x) { return vf_nlt(vf_abs(x), vf_set1(fast_trig_above)); }

/* sin x = (−1)^k sin(x − kπ), k = rint(x/π) by round_shifter: m = 2k */
static SC_INLINE vf sin_fast(vf x, vf (*sin_r)(vf))
{
    vf shifted = vf_fma(x, vf_set1(trig_inv_pi), vf_set1(round_shifter));
    vf kf = vf_sub(shifted, vf_set1(round_shifter));
    vf r = sin_of_reduced(x, vf_add(kf, kf), vf_as_vi(shifted), sin_r);
    return fixup1(outside_trig(x), x, r, sc_sinf);
}

/* cos x = sin(x + π/2) = (−1)^k sin(x − (k − ½)π), k = rint(x/π + ½): m = 2k − 1 */
static SC_INLINE vf cos_fast(vf x, vf (*sin_r)(vf))
{
    vf shifted = vf_add(vf_fma(x, vf_set1(trig_inv_pi), vf_set1(0.5f)), vf_set1(round_shifter));
    vf kf = vf_sub(shifted, vf_set1(round_shifter));
    vf mf = vf_fma(kf, vf_set1(2.0f), vf_set1(-1.0f));
    return fixup1(outside_trig(x), x, sin_of_reduced(x, mf, vf_as_vi(shifted), sin_r), sc_cosf);
}

static inline vf sin_bits22(vf x) { return sin_fast(x, sin_r_bits22); }
static inline vf sin_bits12(vf x) { return sin_fast(x, sin_r_bits12); }
static inline vf cos_bits22(vf x) { return cos_fast(x, sin_r_bits22); }
static inline vf cos_bits12(vf x) { return cos_fast(x, sin_r_bits12); }
BATCH1(sin_bits22, sin_bits22)
BATCH1(sin_bits12, sin_bits12)
BATCH1(cos_bits22, cos_bits22)
BATCH1(cos_bits12, cos_bits12)

/* π = pi_hi + pi_lo, π/2 and π/4 likewise, to about 2^-48 */
static const float pi_hi = 0x1.921fb6p+1f, pi_lo = -0x1.777a5cp-24f;
static const float half_pi_hi = 0x1.921fb6p+0f, half_pi_lo = -0x1.777a5cp-25f;
static const float quarter_pi_hi = 0x1.921fb6p-1f, quarter_pi_lo = -0x1.777a5cp-26f;

/* c_hi + c_lo − a, with the small part first (a >= 0 up to c) */
static inline vf minus_from(vf a, float c_hi, float c_lo)
{
    return vf_add(vf_sub(vf_set1(c_lo), a), vf_set1(c_hi));
}

/* acos t / √(1 − t), t in [0, 1] (limit √2 at 1): 4 terms (fit error 7.8e-5 absolute, on
 * values >= √2), 9 terms (4.1e-9). */
static const float acos_c4[4] = {-0.018192852640625243f, 0.07344754367998303f,
                                 -0.21180357102370512f, 1.5707106950252874f};
static const float acos_c9[9] = {
    0.0006845318166245465f, -0.003974577703820064f, 0.011028380666317037f,
    -0.02072766525325272f,  0.03257117017408731f,   -0.05059357388390752f,
    0.08903013693965323f,   -0.2146011607316858f,   1.570796322643815f};

/* acos |x| = √(1 − |x|)·p(|x|) (the form of Abramowitz & Stegun 4.4.45, refitted), and
 * acos x = π − acos |x| for x < 0. |x| > 1 and NaN give NaN through the square root. */
static inline vf acos_fast(vf x, const float *c, int n)
{
    vf t = vf_abs(x);
    vf v = vf_mul(vf_sqrt(vf_sub(vf_set1(1.0f), t)), poly(t, c, n));
    return vf_select(vf_lt(x, vf_set1(0.0f)), minus_from(v, pi_hi, pi_lo), v);
}

static inline vf acos_bits22(vf x) { return acos_fast(x, acos_c9, 9); }
static inline vf acos_bits12(vf x) { return acos_fast(x, acos_c4, 4); }
BATCH1(acos_bits22, acos_bits22)
BATCH1(acos_bits12, acos_bits12)

/* atan u / u as a polynomial in s = u², s in [0, 1/4]: 6 terms (fit error 5.0e-9; there is no
 * bits12 tier: with 3 terms, 5.1e-5, it was barely faster than bits22, and gcc -O3 -mavx2
 * -ffast-math's libmvec atan2f beat it on speed and accuracy). The reduction keeps
 * |u| <= tan(π/8); the interval reaches |u| = 1/2, where a threshold test rounded in the
 * subnormals (n = 1, d = 2 units) can leave u. */
static const float atan_c6[6] = {-0.050662412913701174f, 0.10115525048521459f,
                                 -0.14164254995259587f,  0.1999310497045346f,
                                 -0.33333187824070487f,  0.9999999949625897f};
static const float cot_pi_8_f = 2.414213562373095f; /* 1/tan(π/8) */

/* The sign bit of y on a >= 0 (the integer add sets bit 31, which is clear in a). */
static inline vf with_sign_of(vf a, vf y)
{
    return vi_as_vf(vi_add(vf_as_vi(a), vi_and(vf_as_vi(y), vf_as_vi(vf_set1(-0.0f)))));
}

/* atan(n/d) for 0 <= n <= d: above tan(π/8), π/4 + atan((n − d)/(n + d)), which cancels
 * down to 0.39 (hence π/4 in two parts); then atan u = u·q(u²). One division. */
static inline vf atan_ratio(vf n, vf d)
{
    vm big = vf_lt(d, vf_mul(n, vf_set1(cot_pi_8_f)));
    vf u = vf_div(vf_select(big, vf_sub(n, d), n), vf_select(big, vf_add(n, d), d));
    vf base_hi = vf_keep(big, vf_set1(quarter_pi_hi));
    vf base_lo = vf_keep(big, vf_set1(quarter_pi_lo));
    return vf_add(vf_fma(u, poly(vf_mul(u, u), atan_c6, 6), base_lo), base_hi);
}

/* The angle of (x, y) for |x| = ax, y >= 0 of magnitude ay, in [0, π]: atan of the smaller
 * over the larger, d = max(ax, ay) (or a floor of it), placed in its quadrant. */
static inline vf upper_half_angle(vf ax, vf ay, vf x, vf d)
{
    vf a = atan_ratio(vf_min(ax, ay), d);
    a = vf_select(vf_lt(ax, ay), minus_from(a, half_pi_hi, half_pi_lo), a);
    return vf_select(vf_lt(x, vf_set1(0.0f)), minus_from(a, pi_hi, pi_lo), a);
}

/* atan2(y, x) from the angle of (|x|, |y|) in [0, π/2], placed in its quadrant. Lanes with
 * NaN, (0, 0), or a magnitude beyond 2^126 (where n + d could overflow; the infinities) go to
 * the scalar built-in. */
static inline vf atan2_bits22(vf y, vf x)
{
    vf ax = vf_abs(x), ay = vf_abs(y), d = vf_max(ax, ay);
    vf a = upper_half_angle(ax, ay, x, d);
    vm special = vm_or(vm_or(vf_isnan(x), vf_isnan(y)), vf_eq(d, vf_set1(0.0f)));
    special = vm_or(special, vf_lt(vf_set1(0x1p126f), d));
    return fixup2(special, y, x, with_sign_of(a, y), sc_atan2f);
}

BATCH2(atan2_bits22, atan2_bits22)

/* ---- double lanes: the u1 tier ---- */

static const double two_over_pi_d = 0x1.45f306dc9c883p-1;
static const double pio2_1 = 0x1.921fb544p+0;       /* π/2, first 33 bits */
static const double pio2_2 = 0x1.0b4611a6p-34;      /* next 33 bits */
static const double pio2_3 = 0x1.3198a2e037073p-69; /* π/2 − pio2_1 − pio2_2, to 2^-122 */
/* the smallest float >= 2^19·π/2, the Cody–Waite limit of sincos.c (|k| < 2^20) */
static const float cody_waite_limit_f = 0x1.921fb6p+19f;

/* sin(r)/r = Σ (−1)^j r^(2j)/(2j+1)!, j = 0..7, and cos(r) = Σ (−1)^j r^(2j)/(2j)!, j = 0..8:
 * the Taylor series of sincos.c, truncated below 2^-55 on |r| <= π/4. */
static const double sin_taylor[8] = {
    1.0,          -1.0 / 6,        1.0 / 120,          -1.0 / 5040,
    1.0 / 362880, -1.0 / 39916800, 1.0 / 6227020800.0, -1.0 / 1307674368000.0};
static const double cos_taylor[9] = {1.0,
                                     -1.0 / 2,
                                     1.0 / 24,
                                     -1.0 / 720,
                                     1.0 / 40320,
                                     -1.0 / 3628800,
                                     1.0 / 479001600,
                                     -1.0 / 87178291200.0,
                                     1.0 / 20922789888000.0};

static inline vdm quadrant_bit(vl q, long long bit)
{
    return vl_eq(vl_and(q, vl_set1(bit)), vl_set1(bit));
}

/* sin(x + shift·π/2) for |x| < 2^19·π/2 (sincos.c): k = rint(x·2/π) by the 1.5·2^52 shifter,
 * whose low bits hold k mod 4; r = x − k·π/2 with three parts; the quadrant selects ±sin r,
 * ±cos r. */
static inline vd sin_shifted_d(vd x, long long shift)
{
    const double shifter = 0x1.8p52;
    vd shifted = vd_add(vd_mul(x, vd_set1(two_over_pi_d)), vd_set1(shifter));
    vd k = vd_sub(shifted, vd_set1(shifter));
    vl quadrant = vl_add(vd_as_vl(shifted), vl_set1(shift));
    vd r = vd_sub(vd_sub(vd_sub(x, vd_mul(k, vd_set1(pio2_1))), vd_mul(k, vd_set1(pio2_2))),
                  vd_mul(k, vd_set1(pio2_3)));
    vd r2 = vd_mul(r, r);
    vd v = vd_select(quadrant_bit(quadrant, 1), vd_horner(r2, cos_taylor, 9),
                     vd_mul(r, vd_horner(r2, sin_taylor, 8)));
    return vd_select(quadrant_bit(quadrant, 2), vd_mul(v, vd_set1(-1.0)), v);
}

static inline vd sin_d(vd x) { return sin_shifted_d(x, 0); }
static inline vd cos_d(vd x) { return sin_shifted_d(x, 1); }

static inline vm outside_cody_waite(vf x)
{
    return vm_or(vf_isnan(x), vf_le(vf_set1(cody_waite_limit_f), vf_abs(x)));
}

/* x's lanes equal to an input of a hard-case table (src/math/kernel.h): the double lanes compute
 * what the scalar core computes before it consults the table, so those lanes go to the core. */
static inline vm hard_case_lanes(vf x, const sc_k_hard_case *table, int n)
{
    vm lanes = vi_eq(vf_as_vi(x), vi_set1((int)table[0].bits));
    for (int i = 1; i < n; i++)
        lanes = vm_or(lanes, vi_eq(vf_as_vi(x), vi_set1((int)table[i].bits)));
    return lanes;
}

#define HARD_CASE_LANES(x, table) hard_case_lanes((x), (table), SC_K_TABLE_LEN(table))

static inline vf sin_u1(vf x)
{
    vm scalar = vm_or(outside_cody_waite(x), HARD_CASE_LANES(x, sc_k_sin_hard_cases));
    return fixup1(scalar, x, on_doubles(x, sin_d), sc_sinf);
}
static inline vf cos_u1(vf x)
{
    return fixup1(outside_cody_waite(x), x, on_doubles(x, cos_d), sc_cosf);
}

static const double pi_d = 3.14159265358979323846;
static const double sqrt3_d = 1.73205080756887729353;
static const double tan_pi_12_d = 0.26794919243112270647;

/* (−1)^j/(2j+1), j = 0..15: atan(u)/u = Σ (−1)^j u^(2j)/(2j+1) (atan.c) */
static const double atan_series[16] = {
    1.0,      -1.0 / 3,  1.0 / 5,  -1.0 / 7,  1.0 / 9,  -1.0 / 11, 1.0 / 13, -1.0 / 15,
    1.0 / 17, -1.0 / 19, 1.0 / 21, -1.0 / 23, 1.0 / 25, -1.0 / 27, 1.0 / 29, -1.0 / 31};

/* atan t for 0 <= t <= 1: above tan(π/12), π/6 + atan((√3 t − 1)/(√3 + t)) (atan.c) */
static inline vd atan_unit_d(vd t)
{
    vdm big = vd_lt(vd_set1(tan_pi_12_d), t);
    vd shifted = vd_div(vd_sub(vd_mul(vd_set1(sqrt3_d), t), vd_set1(1.0)),
                        vd_add(vd_set1(sqrt3_d), t));
    vd u = vd_select(big, shifted, t);
    vd base = vd_select(big, vd_set1(pi_d / 6.0), vd_set1(0.0));
    return vd_fma(u, vd_horner(vd_mul(u, u), atan_series, 16), base);
}

static inline vd abs_d(vd x)
{
    return vl_as_vd(vl_and(vd_as_vl(x), vl_set1(0x7fffffffffffffffLL)));
}

/* |atan2(y, x)| in [0, π] (sc_k_atan2 without its special cases): the ratio of the smaller to
 * the larger magnitude, then the quadrant. x < 0 stands for signbit(x): they differ at x = −0,
 * where the angle is π/2 and π − π/2 = π/2 exactly. */
static inline vd angle_d(vd y, vd x)
{
    vd ay = abs_d(y), ax = abs_d(x);
    vdm steep = vd_lt(ax, ay);
    vd a = atan_unit_d(vd_div(vd_select(steep, ax, ay), vd_select(steep, ay, ax)));
    a = vd_select(steep, vd_sub(vd_set1(pi_d / 2.0), a), a);
    return vd_select(vd_lt(x, vd_set1(0.0)), vd_sub(vd_set1(pi_d), a), a);
}

static inline vd atan2_d(vd y, vd x)
{
    vl sign = vl_and(vd_as_vl(y), vd_as_vl(vd_set1(-0.0)));
    return vl_as_vd(vl_or(vd_as_vl(angle_d(y, x)), sign));
}

/* acos x = atan2(√((1 − x)(1 + x)), x) (asin.c); NaN for |x| > 1 through the square root */
static inline vd acos_d(vd x)
{
    vd one = vd_set1(1.0);
    return angle_d(vd_sqrt(vd_mul(vd_sub(one, x), vd_add(one, x))), x);
}

static inline vf atan2_u1(vf y, vf x)
{
    vm zeros = vm_and(vf_eq(x, vf_set1(0.0f)), vf_eq(y, vf_set1(0.0f)));
    vm infinities = vm_and(vf_eq(vf_abs(x), vf_set1(INFINITY)),
                           vf_eq(vf_abs(y), vf_set1(INFINITY)));
    vm special = vm_or(vm_or(vf_isnan(x), vf_isnan(y)), vm_or(zeros, infinities));
    return fixup2(special, y, x, on_doubles2(y, x, atan2_d), sc_atan2f);
}

static inline vf acos_u1(vf x)
{
    return fixup1(HARD_CASE_LANES(x, sc_k_acos_hard_cases), x, on_doubles(x, acos_d), sc_acosf);
}

BATCH1(sin_u1, sin_u1)
BATCH1(cos_u1, cos_u1)
BATCH1(acos_u1, acos_u1)
BATCH2(atan2_u1, atan2_u1)
