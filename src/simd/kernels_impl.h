/* The batch kernels, written once against the vector helpers (vf, vm, vi; vd, vl) and included,
 * through src/simd/kernel_group.h, by the files of each instruction set's folder
 * (src/simd/scalar/, sse41/, avx2/, avx512/). Every kernel is
 * `void sc_batch_<kernel>_<tier>_<isa>(const sc_batch_args *)`.
 *
 * Tiers (shadecalc/batch.h): u1 kernels evaluate the algorithm of the scalar highp built-ins
 * (src/math/) in double lanes and round once (exp2 and exp where the FMA is one instruction:
 * float lanes, within 1 ULP, no slower than SLEEF's 1-ULP functions), handing the lanes with
 * special inputs (zeros, infinities, NaN, out-of-range arguments) to the scalar built-in, so
 * their results are those of sc_*f up to the FMA contractions of the instruction set; the
 * faster tiers work in float lanes with polynomials fitted on the reduced interval (Chebyshev
 * interpolation, mpmath chebyfit; the fit error is in each comment) and flush results below
 * 2^-125 to zero, as GLSL ES highp allows.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "shadecalc/batch.h"
#include "shadecalc/glsl.h"

/* Drivers and lanes are inlined into each kernel, so that the lane function passed by pointer
 * becomes straight-line code in the loop. `make coverage` defines SC_NO_ALWAYS_INLINE: one body
 * per helper, so that a branch counts as taken when any kernel takes it (inlined copies would
 * each count the branches on their compile-time tier as never taken). */
#if defined(__GNUC__) && !defined(SC_NO_ALWAYS_INLINE)
#define SC_INLINE inline __attribute__((always_inline))
#else
#define SC_INLINE inline
#endif
/* The rare paths kept out of the loops they would otherwise crowd (registers, constants). */
#if defined(__GNUC__)
#define SC_NOINLINE __attribute__((noinline))
#else
#define SC_NOINLINE
#endif

#define SC_CAT2(a, b) a##_##b
#define SC_CAT(a, b) SC_CAT2(a, b)
#define K(name) SC_CAT(sc_batch_##name, ISA_SUFFIX)
/* A kernel's declarator. SC_KERNEL_SCOPE (src/simd/kernel_group.h) is empty in the file that
 * defines the kernel, `static inline` in those that include its header only for the helpers:
 * there the kernel is never called, so neither compiler generates its code. */
#define KERNEL(name) SC_KERNEL_SCOPE void K(name)(const sc_batch_args *a)

/* ---- drivers: whole vectors, then the tail through a padded buffer ---- */

typedef vf (*lane1_fn)(vf);
typedef vf (*lane2_fn)(vf, vf);

/* An input vector loaded once, into a register. gcc folds a load into each instruction that
 * reads it, so a lane that reads its input twice (rsqrt_newton: the estimate, then x y) loaded
 * it twice. From an array not aligned to 64 bytes every AVX-512 load splits a cache line (an
 * AVX2 one every other), and on Zen 4 inversesqrt u4 (AVX-512) took 0.051 ns per element with
 * the folded loads against 0.033 with one (input at 48 mod 64 bytes, as malloc gave the bench;
 * atten_window 0.094 against 0.065). With fewer lanes the register copy measured no faster
 * (AVX2 inversesqrt u4 0.068 ns both ways) and cost some kernels (SSE4.1 atten_clq 0.27 ns
 * with it, 0.22 without): only AVX-512 takes it. The empty asm statement says v changed, so
 * the compiler can no longer re-read it from memory. */
static SC_INLINE vf load_once(const float *p)
{
    vf v = vf_loadu(p);
#if defined(__GNUC__) && VW >= 16
    __asm__("" : "+v"(v));
#endif
    return v;
}

/* The first count < VW elements at p, padded with 1 (a harmless input for every kernel), and
 * the first count lanes of x stored at p: the tails of the drivers. */
static SC_INLINE vf load_partial(const float *p, size_t count)
{
    float b[VW];
    for (size_t k = 0; k < (size_t)VW; k++)
        b[k] = k < count ? p[k] : 1.0f;
    return vf_loadu(b);
}

static SC_INLINE void store_partial(float *p, vf x, size_t count)
{
    float b[VW];
    vf_storeu(b, x);
    for (size_t k = 0; k < count; k++)
        p[k] = b[k];
}

/* Elements [start, start + count) of a one-input kernel, count < VW (the tail, or the elements
 * before the first aligned output vector). */
static SC_INLINE void partial1(const float *x, float *out, size_t start, size_t count, lane1_fn f)
{
    store_partial(out + start, f(load_partial(x + start, count)), count);
}

/* Arrays past this many elements stream their output with non-temporal stores: it leaves the
 * caches to the inputs and saves the read of each output line before it is written. */
enum { STREAM_MIN = 1 << 21 };

/* Elements of p before its first element aligned to a whole vector, at most n (0 where p is
 * not aligned to a float) */
static SC_INLINE size_t aligning_peel(const float *p, size_t n)
{
    size_t bytes = VW * sizeof(float), misalign = (uintptr_t)p % bytes;
    size_t peel = misalign % sizeof(float) ? 0 : (bytes - misalign) % bytes / sizeof(float);
    return peel < n ? peel : n;
}

/* 1 if the outputs are large enough to stream (STREAM_MIN) and share one alignment, whose first
 * `peel` elements come before an aligned vector. */
static SC_INLINE int outputs_stream(const sc_batch_args *a, int m, size_t *peel)
{
    size_t bytes = VW * sizeof(float), misalign = (uintptr_t)a->out[0] % bytes;
    if (a->n < STREAM_MIN || misalign % sizeof(float) != 0)
        return 0;
    for (int j = 1; j < m; j++)
        if ((uintptr_t)a->out[j] % bytes != misalign)
            return 0;
    *peel = aligning_peel(a->out[0], a->n);
    return 1;
}

static SC_INLINE void run1(const sc_batch_args *a, lane1_fn f)
{
    const float *x = a->in[0];
    float *out = a->out[0];
    size_t i = 0, n = a->n, peel;
    if (outputs_stream(a, 1, &peel)) {
        partial1(x, out, 0, peel, f);
        for (i = peel; i + 2 * VW <= n; i += 2 * VW) {
            vf a = f(load_once(x + i)), b = f(load_once(x + i + VW));
            vf_stream(out + i, a);
            vf_stream(out + i + VW, b);
        }
        for (; i + VW <= n; i += VW)
            vf_stream(out + i, f(load_once(x + i)));
        vf_stream_fence();
    } else {
        for (; i + 2 * VW <= n; i += 2 * VW) {
            vf a = f(load_once(x + i)), b = f(load_once(x + i + VW));
            vf_storeu(out + i, a);
            vf_storeu(out + i + VW, b);
        }
        for (; i + VW <= n; i += VW)
            vf_storeu(out + i, f(load_once(x + i)));
    }
    if (i < n)
        partial1(x, out, i, n - i, f);
}

static SC_INLINE void run2(const sc_batch_args *a, lane2_fn f)
{
    const float *x = a->in[0], *y = a->in[1];
    float *out = a->out[0];
    size_t i = 0;
    for (; i + 2 * VW <= a->n; i += 2 * VW) {
        vf r0 = f(load_once(x + i), load_once(y + i));
        vf r1 = f(load_once(x + i + VW), load_once(y + i + VW));
        vf_storeu(out + i, r0);
        vf_storeu(out + i + VW, r1);
    }
    for (; i + VW <= a->n; i += VW)
        vf_storeu(out + i, f(load_once(x + i), load_once(y + i)));
    if (i < a->n)
        store_partial(out + i, f(load_partial(x + i, a->n - i), load_partial(y + i, a->n - i)),
                      a->n - i);
}

#define BATCH1(name, lane)                                                                         \
    KERNEL(name);                                                                                  \
    KERNEL(name) { run1(a, lane); }
#define BATCH2(name, lane)                                                                         \
    KERNEL(name);                                                                                  \
    KERNEL(name) { run2(a, lane); }

/* Lanes where `special` holds get the scalar built-in's result (rare inputs only). */
static inline vf fixup1(vm special, vf x, vf r, float (*f)(float))
{
    if (!vm_any(special))
        return r;
    float bx[VW], br[VW];
    vf_storeu(bx, x);
    vf_storeu(br, r);
    for (int k = 0; k < VW; k++)
        if (vm_lane(special, k))
            br[k] = f(bx[k]);
    return vf_loadu(br);
}

static SC_NOINLINE vf fixup2_lanes(vm special, vf x, vf y, vf r, float (*f)(float, float))
{
    float bx[VW], by[VW], br[VW];
    vf_storeu(bx, x);
    vf_storeu(by, y);
    vf_storeu(br, r);
    for (int k = 0; k < VW; k++)
        if (vm_lane(special, k))
            br[k] = f(bx[k], by[k]);
    return vf_loadu(br);
}

/* fixup1 for two-argument kernels, whose loops inline the lane: the test inline, the scalar
 * calls out of line. */
static SC_INLINE vf fixup2(vm special, vf x, vf y, vf r, float (*f)(float, float))
{
    return vm_any(special) ? fixup2_lanes(special, x, y, r, f) : r;
}

/* Polynomial loops are unrolled into straight-line FMAs with their constants in registers:
 * gcc -O2 left them as loops that broadcast a coefficient per step (exp u1 2.60 to
 * 1.44 ns, exp2 u4 0.91 to 0.48 ns in one bench run each). */
#if defined(__GNUC__)
#define SC_UNROLL _Pragma("GCC unroll 16")
#else
#define SC_UNROLL
#endif

/* c[0] x^(n−1) + … + c[n−1] (chebyfit order), by Horner's rule. */
static SC_INLINE vf poly(vf x, const float *c, int n)
{
    vf r = vf_set1(c[0]);
    SC_UNROLL
    for (int i = 1; i < n; i++)
        r = vf_fma(r, x, vf_set1(c[i]));
    return r;
}

/* ---- float tiers: exp2, log2, pow, exp, log, inversesqrt ---- */

/* 2^f on [−1/2, 1/2]: degree 2 (fit error 1.9e-3), 3 (8.1e-5), 5 (7.9e-8). */
static const float exp2_c2[3] = {0.242035330190541f, 0.7036011773937813f, 1.0f};
static const float exp2_c3[4] = {0.055838282946219855f, 0.24263947854625853f, 0.6931367338836215f,
                                 0.9999245569508708f};
static const float exp2_c5[6] = {0.0013390863364671234f, 0.009676031918322054f,
                                 0.05550357114219078f,   0.2402210748530834f,
                                 0.6931471880262288f,    1.0000000754548972f};

/* 2^f rounded once to float (f: float lanes, or the double lanes of exp_reduced_d) times 2^k
 * by an integer add to the exponent field: exact while the result is a normal float and
 * 2^f >= 1 when k = −126, which the callers' ranges ensure. */
static inline vf scale_by_2k(vf p, vi k) { return vi_as_vf(vi_add(vf_as_vi(p), vi_shl23(k))); }

/* 2^x = 2^k · 2^f, k = rint(x), f = x − k exact, 2^f in [2^-1/2, 2^1/2] by two_to_f. Lanes
 * outside −126 < x < 128 (subnormal or infinite results) and NaN go to the scalar built-in, so
 * that the scaling is an integer add to the exponent: no clamp, flush or NaN selects per
 * vector (the u4 and bits tiers did those, and ran no faster than u1). */
static SC_INLINE vf exp2_by_parts(vf x, vf (*two_to_f)(vf))
{
    vm special = vf_nlt(vf_abs(vf_sub(x, vf_set1(1.0f))), vf_set1(127.0f));
    vf xc = vf_select(special, vf_set1(0.0f), x);
    vi k = vi_round(xc);
    vf p = two_to_f(vf_sub(xc, vi_to_vf(k)));
    return fixup1(special, x, scale_by_2k(p, k), sc_exp2f);
}

/* log2(1+t)/t on [√½ − 1, √2 − 1]: degree 3 (fit error 6.0e-4), 4 (8.9e-5), 8 (5.0e-8). */
static const float log2_c3[4] = {-0.32262359078704306f, 0.5101832372272362f, -0.7246998473568208f,
                                 1.4423070538781517f};
static const float log2_c4[5] = {0.25028784696095874f, -0.38967522379177433f, 0.48573784244262974f,
                                 -0.7206292158599162f, 1.442640464283215f};
static const float log2_c8[9] = {0.1231096846719146f,  -0.20586188051276055f, 0.21607822552243777f,
                                 -0.2391698814010418f, 0.28790326092450147f,  -0.36069326813533614f,
                                 0.48091075345941253f, -0.7213474682495624f,  1.4426950035679822f};

/* x = m · 2^e with m in [√½, √2), for positive normal x, by integer arithmetic on the float
 * bits (musl logf's offset trick): both m and e exact in float. */
static inline void log_split(vf x, vf *m, vf *e)
{
    vi ix = vi_sub(vf_as_vi(x), vi_set1(0x3f3504f3));
    *e = vi_to_vf(vi_sra23(ix));
    *m = vi_as_vf(vi_add(vi_and(ix, vi_set1(0x007fffff)), vi_set1(0x3f3504f3)));
}

/* x not a positive normal float, or +Inf */
static inline vm not_positive_finite(vf x)
{
    return vm_or(vf_lt(x, vf_set1(FLT_MIN)), vm_or(vf_eq(x, vf_set1(INFINITY)), vf_isnan(x)));
}

/* The lanes of log2 x for x not a positive normal float: subnormal inputs count as 0 (−Inf),
 * x < 0 is NaN, +Inf and NaN are themselves. Out of line: one test guards it. */
static SC_NOINLINE vf log2_specials(vf x, vf r)
{
    r = vf_select(vf_lt(x, vf_set1(FLT_MIN)), vf_set1(-INFINITY), r);
    r = vf_select(vf_lt(x, vf_set1(0.0f)), vf_set1(NAN), r);
    r = vf_select(vf_eq(x, vf_set1(INFINITY)), x, r);
    return vf_select(vf_isnan(x), x, r);
}

/* r, or log2_specials where a lane of x is not a positive normal float. */
static inline vf log2_fixup(vf x, vf r)
{
    return vm_any(not_positive_finite(x)) ? log2_specials(x, r) : r;
}

/* log2 x = e + t·q(t), t = m − 1 (log_split); special inputs as log2_specials. */
static inline vf log2_fast(vf x, const float *c, int n)
{
    vf m, e;
    log_split(x, &m, &e);
    vf t = vf_sub(m, vf_set1(1.0f));
    return log2_fixup(x, vf_fma(t, poly(t, c, n), e));
}

/* log2_c8's constant term minus its float value: log2_u4 adds it to the product t·(t·p(t)). */
static const float log2_c8_lo = (float)(1.4426950035679822 - (double)1.4426950035679822f);

/* log2_fast with log2_c8, its last step split: e + (c·t + t·(t·p(t) + c_lo)), c = the constant
 * term in float, p = the other terms. The rounding of q(t) to float, amplified by up to 1/ln2
 * where t·q(t) ≈ 1/2, does not enter the sum: exhaustively over [1/4, 4), 1.36 ulp instead of
 * 2.10 ulp with the FMA (2.27 instead of 2.15 ulp without: SSE4.1, scalar). */
static inline vf log2_u4(vf x)
{
    vf m, e;
    log_split(x, &m, &e);
    vf t = vf_sub(m, vf_set1(1.0f));
    vf tail = vf_fma(poly(t, log2_c8, 8), t, vf_set1(log2_c8_lo));
    vf s = vf_fma(t, vf_set1(log2_c8[8]), vf_mul(t, tail));
    return log2_fixup(x, vf_add(e, s));
}

static inline vf exp2_c3_of(vf f) { return poly(f, exp2_c3, 4); }
static inline vf exp2_c2_of(vf f) { return poly(f, exp2_c2, 3); }
static inline vf exp2_bits12(vf x) { return exp2_by_parts(x, exp2_c3_of); }
static inline vf exp2_bits8(vf x) { return exp2_by_parts(x, exp2_c2_of); }
static inline vf log2_bits12(vf x) { return log2_fast(x, log2_c4, 5); }
static inline vf log2_bits8(vf x) { return log2_fast(x, log2_c3, 4); }
BATCH1(exp2_bits12, exp2_bits12)
BATCH1(exp2_bits8, exp2_bits8)
BATCH1(log2_u4, log2_u4)
BATCH1(log2_bits12, log2_bits12)
BATCH1(log2_bits8, log2_bits8)

/* e^r on [−ln2/2, ln2/2] (widened by 10^-4): degree 5 (fit error 1.0e-7) */
static const float exp_c5[6] = {0.008369169200809018f, 0.041917652374735236f, 0.1666650507381473f,
                                0.4999886807080089f,   1.0000000107902474f,   1.0000000755857619f};
/* ln 2 = ln2_hi + ln2_lo (Cody and Waite): ln2_hi has 9 significant bits, so k·ln2_hi is exact
 * for |k| < 2^15 and x − k·ln2_hi is exact, with or without FMA. */
static const float ln2_hi = 0.693359375f, ln2_lo = -2.12194440e-4f;

/* exp x = 2^(x log2 e): the product's rounding (|x| <= 88: 2^-17.5 absolute) limits these to
 * the bits tiers. log x = log2 x · ln 2. */
static const float log2e_f = 1.44269504088896340736f, ln2_f = 0.693147180559945309417f;
static inline vf exp_bits12(vf x) { return exp2_bits12(vf_mul(x, vf_set1(log2e_f))); }
static inline vf exp_bits8(vf x) { return exp2_bits8(vf_mul(x, vf_set1(log2e_f))); }
static inline vf log_u4(vf x) { return vf_mul(log2_u4(x), vf_set1(ln2_f)); }
static inline vf log_bits12(vf x) { return vf_mul(log2_bits12(x), vf_set1(ln2_f)); }
static inline vf log_bits8(vf x) { return vf_mul(log2_bits8(x), vf_set1(ln2_f)); }
BATCH1(exp_bits12, exp_bits12)
BATCH1(exp_bits8, exp_bits8)
BATCH1(log_u4, log_u4)
BATCH1(log_bits12, log_bits12)
BATCH1(log_bits8, log_bits8)

/* pow = 2^(y log2 x): the logarithm one tier finer than the exponential, since y log2 x
 * multiplies its error (domain: |y log2 x| <= 20, the useful range of a specular lobe). */
static inline vf pow_bits12(vf x, vf y) { return exp2_bits12(vf_mul(y, log2_u4(x))); }
static inline vf pow_bits8(vf x, vf y) { return exp2_bits8(vf_mul(y, log2_bits12(x))); }
BATCH2(pow_bits12, pow_bits12)
BATCH2(pow_bits8, pow_bits8)

/* inversesqrt: the estimate instruction (relative error <= 1.5·2^-12), and one Newton step
 * y (3 − x y²)/2, as (−y/2)((x y) y − 3): four operations, one of them an FMA, and no
 * intermediate below x y >= √x (−x/2 is subnormal for x < 2^-125, which cost SSE4.1 1.02 times
 * its 4-ULP bound at x = 1.008·2^-126; elsewhere the bits of y (3/2 + (−x/2) y · y)). */
static inline vf rsqrt_newton(vf x)
{
    vf y = vf_rsqrt_est(x);
    return vf_mul(vf_mul(y, vf_set1(-0.5f)), vf_fma(vf_mul(x, y), y, vf_set1(-3.0f)));
}
/* 1/√x to about one ULP, for normal x: the estimate y, its residual d = x y² − 1 (an FMA), and
 * the Newton–Raphson step to second order, y − y d (1/2 − 3/8 d): the first-order step alone
 * leaves 3/8 d² (up to 2^-22.4 relative with rsqrtps's 1.5·2^-12). */
static inline vf rsqrt_refined(vf x)
{
    vf y = vf_rsqrt_est(x);
    vf d = vf_fma(vf_mul(x, y), y, vf_set1(-1.0f));
    vf c = vf_fma(d, vf_set1(0.375f), vf_set1(-0.5f));
    return vf_fma(vf_mul(y, d), c, y);
}
/* inversesqrt u4 where the FMA rounds once: the estimate's residual d = x y² − 1 and the
 * Newton step in residual form, y − (y/2) d, whose last FMA adds the small correction to y and
 * rounds once. The first-order step leaves 3/8 d²: negligible after AVX-512's 2^-14 estimate
 * (d <= 2^-13: 2^-27.4 relative), which takes it at the cost of rsqrt_newton (what -ffast-math
 * makes of 1/sqrtf); after rsqrtps's 1.5·2^-12 it is up to 2^-22.2, so AVX2 takes the
 * second-order step, one FMA more. Every float of [1, 4): AVX-512 1.96 -> 1.04 ULP, AVX2
 * 2.39 -> 1.00. Without the FMA the residual costs two operations more and rounds twice:
 * SSE4.1 and portable C keep rsqrt_newton. */
static inline vf rsqrt_u4(vf x)
{
#if defined(SIMD_HAS_FMA) && defined(SIMD_FINE_ESTIMATES)
    vf y = vf_rsqrt_est(x);
    vf d = vf_fma(vf_mul(x, y), y, vf_set1(-1.0f));
    return vf_fma(vf_mul(y, vf_set1(-0.5f)), d, y);
#elif defined(SIMD_HAS_FMA)
    return rsqrt_refined(x);
#else
    return rsqrt_newton(x);
#endif
}
static inline vf sqrt_u1(vf x) { return vf_sqrt(x); }
BATCH1(inversesqrt_u4, rsqrt_u4)
BATCH1(inversesqrt_bits11, vf_rsqrt_est)
BATCH1(sqrt_u1, sqrt_u1)

/* ---- double lanes: the u1 tier ---- */

/* A double kernel on the low and high halves of a float vector, rounded back to float. */
static inline vf on_doubles(vf x, vd (*f)(vd))
{
    return vf_from_vd(f(vd_from_lo(x)), f(vd_from_hi(x)));
}

static SC_INLINE vd vd_horner(vd x, const double *c, int n) /* c[0] + c[1] x + … */
{
    vd r = vd_set1(c[n - 1]);
    SC_UNROLL
    for (int i = n - 2; i >= 0; i--)
        r = vd_fma(r, x, vd_set1(c[i]));
    return r;
}

/* 2^f on [−1/2, 1/2]: degree 8, relative fit error 1.1e-12 = 2^-39.8 (mpmath chebyfit), so
 * that the one rounding to float is wrong only within 2^-15 ULP of a midpoint; c[0] + c[1] f
 * + … */
static const double exp2_d8[9] = {1.0,
                                  0.69314718054593345493,
                                  0.2402265069581298821,
                                  0.055504109412059329931,
                                  0.0096181291594025581885,
                                  0.0013333450568000645685,
                                  0.00015403455852453839442,
                                  0.000015310079402249297437,
                                  1.3255224878668816975e-6};

static inline vd exp2_reduced_d(vd f) { return vd_horner(f, exp2_d8, 9); }

/* 2^f on [−1/2, 1/2], degree 7: relative fit error 5.5e-11 = 2^-34.1 (mpmath chebyfit, the
 * coefficients rounded to double), pow's: at most 2^-10 ULP of the float result before its
 * rounding (pow u1 measured 0.50069 ULP at most on 2^24 random pairs, 0.50004 with exp2_d8,
 * and 6% slower) */
static const double exp2_d7[8] = {
    0.9999999999595618,   0.6931471805568324,    0.24022651213498092,    0.055504109063258665,
    0.009618025613318034, 0.0013333478473685416, 0.00015469729214118296, 1.5303700711365693e-05};

/* 2^x in double: 2^k · 2^(x − k), k = rint(x), |x| clamped to 1000 (pow's exponential). k by
 * a shifter: x + 1.5·2^52 rounds x to an integer, ties to even, and its low bits are k; the
 * shift by 52 leaves k·2^52 (the shifter's bits above shift out), and adding it to the bits of
 * 2^(x − k) in [0.7, 1.5) multiplies by 2^k exactly (exponents −1001 to 1000 stay normal),
 * with an integer add instead of a floating-point multiply. */
static SC_INLINE vd exp2_d(vd x)
{
    const double shifter = 0x1.8p52;
    x = vd_min(vd_max(x, vd_set1(-1000.0)), vd_set1(1000.0));
    vd shifted = vd_add(x, vd_set1(shifter));
    vd k = vd_sub(shifted, vd_set1(shifter));
    vl k_exponent = vl_shl52(vd_as_vl(shifted));
    return vl_as_vd(vl_add(vd_as_vl(vd_horner(vd_sub(x, k), exp2_d7, 8)), k_exponent));
}

/* 2^f by exp2_c5 (fit error 7.9e-8): the u4 tier */
static inline vf exp2_c5_of(vf f) { return poly(f, exp2_c5, 6); }
static inline vf exp2_u4(vf x) { return exp2_by_parts(x, exp2_c5_of); }
BATCH1(exp2_u4, exp2_u4)

/* e^x = 2^k e^r, k = rint(x log2 e), r = x − k ln 2 by Cody and Waite's two-part constant
 * (ln2_hi: k·ln2_hi and its FMA exact), e^r by e_to_r. k can be one off where x log2 e rounds
 * across a half-integer: the fits' widened interval covers that r. Lanes outside
 * −87.3 < x < 88.7 and NaN go to the scalar built-in; k = 128 only with r < 0, so 2^k·e^r
 * stays finite. */
static SC_INLINE vf exp_by_parts(vf x, vf (*e_to_r)(vf))
{
    vm special = vf_nlt(vf_abs(vf_sub(x, vf_set1(0.7f))), vf_set1(88.0f));
    vf xc = vf_select(special, vf_set1(0.0f), x);
    vi k = vi_round(vf_mul(xc, vf_set1(log2e_f)));
    vf kf = vi_to_vf(k);
    vf r = vf_fma(kf, vf_set1(-ln2_lo), vf_fma(kf, vf_set1(-ln2_hi), xc));
    return fixup1(special, x, scale_by_2k(e_to_r(r), k), sc_expf);
}

/* e^r by exp_c5 (fit error 1.0e-7): the u4 tier */
static inline vf exp_c5_of(vf r) { return poly(r, exp_c5, 6); }
static inline vf exp_u4(vf x) { return exp_by_parts(x, exp_c5_of); }
BATCH1(exp_u4, exp_u4)

/* s = (m − 1)/(m + 1) for m in [√½, √2), |s| <= 0.1716: log m = 2 atanh(s) = s P(s²), P(t) =
 * Σ 2 t^k/(2k + 1). The Taylor series needs 6 terms for 2^-34 relative and 7 for 2^-39.5; the
 * polynomials below, fitted to P (or P/ln 2) on t in [0, 0.0295] (mpmath chebyfit, s² <=
 * 0.029437), reach 2^-37.7 with 5 terms and 2^-45 with 6 (relative, measured on 4001 points
 * with the coefficients rounded to double): pow's, whose error y log2 x multiplies, and the
 * log and log2 u1 tiers'. c[0] + c[1] t + … */
#define SC_LN2 0.6931471805599453094
static const double log2_fit6[6] = {2.8853900817778495,  0.96179669411429003, 0.57707794201789842,
                                    0.41220929390060301, 0.31990375397287574, 0.28293105400823265};
static const double log2_fit5[5] = {2.8853900817901179, 0.96179667327363916, 0.57708360228932221,
                                    0.41167146505900692, 0.3407567042788236};
static const double log_fit5[5] = {2.0000000000084501, 0.66666665235155786, 0.40000387187422048,
                                   0.28534891532263268, 0.23619454882776561};

static SC_INLINE vd atanh_arg(vd m)
{
    return vd_div(vd_sub(m, vd_set1(1.0)), vd_add(m, vd_set1(1.0)));
}

/* log m on one half, s P(s²) with log_fit5 */
static inline vd log_m_d(vd m)
{
    vd s = atanh_arg(m);
    return vd_mul(s, vd_horner(vd_mul(s, s), log_fit5, 5));
}

/* log2 x = e + s P(s²)/ln 2 on one half (m, e from log_split), P/ln 2 the n coefficients c
 * (log2_fit5 or log2_fit6) and e added by the last FMA, two operations fewer than
 * log m / ln 2 + e. */
static inline vd log2_parts_d(vd m, vd e, const double *c, int n)
{
    vd s = atanh_arg(m);
    return vd_fma(s, vd_horner(vd_mul(s, s), c, n), e);
}

static inline vd log2_me_d(vd m, vd e) { return log2_parts_d(m, e, log2_fit5, 5); }
static inline vd log_me_d(vd m, vd e) { return vd_fma(e, vd_set1(SC_LN2), log_m_d(m)); }

/* A two-argument double kernel on the low and high halves, rounded back to float. */
static inline vf on_doubles2(vf a, vf b, vd (*f)(vd, vd))
{
    return vf_from_vd(f(vd_from_lo(a), vd_from_lo(b)), f(vd_from_hi(a), vd_from_hi(b)));
}

static inline vd rsqrt_d(vd x) { return vd_div(vd_set1(1.0), vd_sqrt(x)); }

#ifdef SIMD_HAS_FMA
/* ---- exp2 and exp u1 in float lanes, where the FMA is a single rounding ---- */

/* (2^f − 1)/f on [−1/2, 1/2], degree 6: relative fit error 1.7e-10 (mpmath chebyfit) */
static const float exp2_q6[7] = {0.000015297323760701074f,  0.00015461444698569129f,
                                 0.0013333502386162770741f, 0.0096180566785246380754f,
                                 0.055504108839096183929f,  0.24022650922288758071f,
                                 0.69314718055994530942f};
/* (e^r − 1)/r on [−ln2/2, ln2/2] widened by 10^-4, degree 6: relative fit error 2.4e-10 */
static const float exp_q6[7] = {0.00019899307482115443987f,
                                0.0013941138623396756287f,
                                0.008333298443479888647f,
                                0.041666352534085763919f,
                                0.16666666719088228652f,
                                0.50000000471994520251f,
                                1.0f};

/* 2^f = 1 + f q(f) (exp2_by_parts): the last step is one FMA, so the result carries its one
 * rounding plus q's few float ULPs scaled by |f q| / 2^f <= 0.6 (measured over every 101st
 * binary32: 0.78 ULP at most; make exhaustive checks all). */
static inline vf exp2_q6_of(vf f) { return vf_fma(f, poly(f, exp2_q6, 7), vf_set1(1.0f)); }
static inline vf exp2_u1(vf x) { return exp2_by_parts(x, exp2_q6_of); }

/* e^r = 1 + r q(r) (exp_by_parts), the last step one FMA (measured over every 101st binary32:
 * 0.85 ULP at most). */
static inline vf exp_q6_of(vf r) { return vf_fma(r, poly(r, exp_q6, 7), vf_set1(1.0f)); }
static inline vf exp_u1(vf x) { return exp_by_parts(x, exp_q6_of); }
#else
/* ---- exp2 and exp u1 in double lanes, without an FMA instruction ---- */

/* 2^f in double lanes (exp2_by_parts) */
static inline vf exp2_d_of(vf f) { return on_doubles(f, exp2_reduced_d); }
static inline vf exp2_u1(vf x) { return exp2_by_parts(x, exp2_d_of); }

/* f = x log2 e − k in double (one rounding: the FMA with −k), |f| <= 1/2 + 2^-17 */
static inline vd exp_reduced_d(vd x, vd minus_k)
{
    return exp2_reduced_d(vd_fma(x, vd_set1(1.4426950408889634074), minus_k));
}

/* e^x = 2^k · 2^(x log2 e − k), k = rint(x log2 e) in float (off by one at worst, which the
 * fit's interval absorbs). Lanes outside −87.3 < x < 88.7 and NaN go to the scalar built-in. */
static inline vf exp_u1(vf x)
{
    vm special = vf_nlt(vf_abs(vf_sub(x, vf_set1(0.7f))), vf_set1(88.0f));
    vf xc = vf_select(special, vf_set1(0.0f), x);
    vi k = vi_round(vf_mul(xc, vf_set1(log2e_f)));
    vf p = on_doubles2(xc, vi_to_vf(vi_sub(vi_set1(0), k)), exp_reduced_d);
    return fixup1(special, x, scale_by_2k(p, k), sc_expf);
}
#endif

static inline vf log2_u1(vf x)
{
    vf m, e;
    log_split(x, &m, &e);
    return fixup1(not_positive_finite(x), x, on_doubles2(m, e, log2_me_d), sc_log2f);
}
static inline vf log_u1(vf x)
{
    vf m, e;
    log_split(x, &m, &e);
    return fixup1(not_positive_finite(x), x, on_doubles2(m, e, log_me_d), sc_logf);
}
static inline vf inversesqrt_u1(vf x) { return on_doubles(x, rsqrt_d); }

/* 2^(y log2 x) on one half, x = m 2^e (log_split); the special cases of src/math/pow.c
 * (x <= 0, x = 1, infinities, NaN, y = 0) go to the scalar built-in. */
static SC_INLINE vd pow_half(vd m, vd e, vd y)
{
    return exp2_d(vd_mul(y, log2_parts_d(m, e, log2_fit6, 6)));
}

/* x^y for positive normal x, in double lanes, rounded once */
static SC_INLINE vf pow_d(vf x, vf y)
{
    vf m, e;
    log_split(x, &m, &e);
    return vf_from_vd(pow_half(vd_from_lo(m), vd_from_lo(e), vd_from_lo(y)),
                      pow_half(vd_from_hi(m), vd_from_hi(e), vd_from_hi(y)));
}

/* The lanes of pow's special cases: x not a positive normal float (at most the largest
 * subnormal, +Inf or NaN), y zero, infinite or NaN, or x = 1. Each test is one comparison that
 * is also true for NaN (!(a < b)): nine operations per vector where separate NaN tests took
 * fifteen. */
static SC_INLINE vm pow_special(vf x, vf y)
{
    const vf inf = vf_set1(INFINITY);
    vf abs_y = vf_abs(y);
    vm x_bad = vm_or(vf_nlt(vf_set1(0x1.fffffcp-127f), x), vf_nlt(x, inf));
    vm y_bad = vm_or(vf_nlt(vf_set1(0.0f), abs_y), vf_nlt(abs_y, inf));
    return vm_or(vm_or(x_bad, y_bad), vf_eq(x, vf_set1(1.0f)));
}

static SC_INLINE vf pow_u1(vf x, vf y)
{
    return fixup2(pow_special(x, y), x, y, pow_d(x, y), sc_powf);
}

BATCH1(exp2_u1, exp2_u1)
BATCH1(exp_u1, exp_u1)
BATCH1(log2_u1, log2_u1)
BATCH1(log_u1, log_u1)
BATCH2(pow_u1, pow_u1)
BATCH1(inversesqrt_u1, inversesqrt_u1)
