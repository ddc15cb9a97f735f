/* The vec3 batch kernels and the tier operations of the shading, light and BRDF kernels, written
 * once against the vector helpers and included after src/simd/kernels_impl.h by each
 * instruction set's file (the shading kernel itself: src/simd/scene_impl.h).
 *
 * Tiers differ only in the few operations below (tier_rsqrt, tier_rcp, tier_sqrt, tier_pow):
 *   ACCURATE  sqrt and division rounded once; pow as the u1 kernel (double lanes)
 *   FAST12    rsqrt / rcp estimate with one Newton step; pow_bits12
 * (A tier of the bare estimate instructions and pow_bits8, bits8, was removed from the shading
 * kernel: its normalizations had to keep the Newton step, as (n·h)^m multiplies the relative
 * error of n·h by m and 3 · 2^-12 · 32 would be 2^-5.4, so for Blinn-Phong with an integer
 * exponent and directional lights it computed the bits of bits12, and for GGX it was 3-6%
 * faster at 3350 ULP against 53.)
 * The tier argument is a constant at every call, so each kernel compiles to straight-line code
 * with no branch on the tier.
 */

enum { ACCURATE, FAST12, REFINED }; /* REFINED: rsqrt_refined (normalize u3) */
enum { MAX_IN = 9, MAX_OUT = 3 };

/* ---- driver: k input arrays, m output arrays ---- */

/* A lane function loads its inputs in[j] + i and stores its outputs out[j] + i itself, with
 * constant j: straight-line code, no copies. params is args.params (the light kernels). */
typedef void (*lane_n_fn)(const float *const *in, float *const *out, size_t i, const void *params);

/* Vectors a lane may take per call (run_wide): the shading kernel's interleave two. */
enum { MAX_WIDTH = 2 };

/* Elements of a block that the driver runs through buffers: its outputs stay in L1 until they
 * are stored or streamed out. */
enum { BLOCK = 8 * VW };
_Static_assert(BLOCK % (MAX_WIDTH * VW) == 0, "a block is whole calls of every width");

/* Elements [start, start + count), `step` elements per call of f, the lane's
 * only call site (each inlined copy of a lane is kilobytes of code: one site halves the shading
 * kernel's compile time). Inputs are read in place when the calls cover exactly count elements,
 * else through copies padded with 1 (a harmless input for every kernel); outputs are stored in
 * place likewise, or computed into an L1 buffer and copied, or, for a whole block at an
 * aligned output (`stream`), streamed out with non-temporal stores. */
static SC_INLINE void run_block(const sc_batch_args *a, const float *const *ins, float *const *outs,
                                int k, int m, lane_n_fn f, size_t step, size_t start, size_t count,
                                int stream)
{ /* count <= BLOCK unless the calls cover it exactly and it is not streamed */
    float pad[MAX_IN][BLOCK], buf[MAX_OUT][BLOCK];
    const float *in[MAX_IN] = {0};
    float *out[MAX_OUT];
    size_t calls_end = (count + step - 1) / step * step; /* the elements the calls read */
    int exact = calls_end == count, buffered = stream || !exact;
    for (int j = 0; j < k; j++) {
        in[j] = ins[j] + start;
        if (!exact) {
            for (size_t e = 0; e < calls_end; e++)
                pad[j][e] = e < count ? in[j][e] : 1.0f;
            in[j] = pad[j];
        }
    }
    for (int j = 0; j < m; j++)
        out[j] = buffered ? buf[j] : outs[j] + start;
    for (size_t v = 0; v < calls_end; v += step)
        f(in, out, v, a->params);
    for (int j = 0; buffered && j < m; j++) {
        if (stream)
            for (size_t v = 0; v < BLOCK; v += VW)
                vf_stream(outs[j] + start + v, vf_loadu(buf[j] + v));
        else
            memcpy(outs[j] + start, buf[j], count * sizeof(float));
    }
}

/* The loop over a->n elements, `width` vectors per call of f. Streaming arrays: whole
 * aligned blocks are streamed out with non-temporal stores, which save the read of each output
 * line that an ordinary store costs (a fourth of shade's traffic); the first block is the peel
 * up to that alignment. */
static SC_INLINE void run_wide(const sc_batch_args *a, int k, int m, lane_n_fn f, int width)
{
    size_t i = 0, n = a->n, peel = 0, step = (size_t)width * VW;
    int stream = outputs_stream(a, m, &peel);
    /* local copies of the pointers: the compiler keeps them in registers, where through `a` it
     * reloaded them after every store (the stores might have changed them) */
    const float *ins[MAX_IN];
    float *outs[MAX_OUT];
    memcpy(ins, a->in, sizeof ins);
    memcpy(outs, a->out, sizeof outs);
    while (i < n) {
        size_t left = n - i, count;
        if (stream)
            count = i == 0 && peel ? peel : left < BLOCK ? left : BLOCK;
        else /* all whole steps in place at once, then the tail through buffers */
            count = left >= step ? left / step * step : left;
        run_block(a, ins, outs, k, m, f, step, i, count, stream && count == BLOCK);
        i += count;
    }
    if (stream)
        vf_stream_fence();
}

static SC_INLINE void run_n(const sc_batch_args *a, int k, int m, lane_n_fn f)
{
    run_wide(a, k, m, f, 1);
}

#define BATCH_N(name, k, m, lane)                                                                  \
    KERNEL(name);                                                                                  \
    KERNEL(name) { run_n(a, k, m, lane); }

/* ---- the operations tiers choose ---- */

static SC_INLINE vf rcp_newton(vf x) /* r (2 − x r) */
{
    vf r = vf_rcp_est(x);
    return vf_mul(r, vf_sub(vf_set1(2.0f), vf_mul(x, r)));
}

/* Whether a tier takes the square root and quotient rounded once. Portable C always does: it
 * has no estimate instruction (its vf_rsqrt_est is a bit-trick guess and two Newton steps, its
 * vf_rcp_est a division), and with -fno-math-errno its root is one vector instruction, so the
 * estimate and a Newton step cost more than the exact operations (Blinn-Phong, one light,
 * bits12: 4.84 ns per element against the accurate tier's 3.83). */
static SC_INLINE int exact_roots(int tier)
{
#ifdef SIMD_NO_ESTIMATES
    (void)tier;
    return 1;
#else
    return tier == ACCURATE;
#endif
}

static SC_INLINE vf tier_rsqrt(int tier, vf x)
{
    if (exact_roots(tier))
        return vf_div(vf_set1(1.0f), vf_sqrt(x));
    return tier == REFINED ? rsqrt_refined(x) : rsqrt_newton(x);
}

static SC_INLINE vf tier_rcp(int tier, vf x)
{
    return exact_roots(tier) ? vf_div(vf_set1(1.0f), x) : rcp_newton(x);
}

/* sqrt of x > 0 */
static SC_INLINE vf tier_sqrt(int tier, vf x)
{
    return exact_roots(tier) ? vf_sqrt(x) : vf_mul(x, tier_rsqrt(tier, x));
}

/* x^y for x in [2^-126, 1], y >= 0: the specular lobe and the spot falloff, where no special
 * case can occur, so the fast tier skips the selects of pow_bits12: 2^t, t = y log2 x <= 0,
 * with log2 and 2^f as in log2_fast and the exp2 bits tiers (same polynomials, same bounds).
 * Results below 2^-100 are flushed to 0: the lobe is then 30 decades under its peak, and the
 * subnormal products it would otherwise feed cost a microcode assist per lane on x86 (bits12
 * ran 2× slower than the former bits8 tier for that alone). */
static SC_INLINE vf lobe_pow_fast(vf x, vf y)
{
    vf m, e;
    log_split(x, &m, &e);
    vf u = vf_sub(m, vf_set1(1.0f));
    vf t = vf_mul(y, vf_fma(u, poly(u, log2_c8, 9), e));
    vf tc = vf_max(t, vf_set1(-125.0f));
    vi k = vi_round(tc);
    vf p = poly(vf_sub(tc, vi_to_vf(k)), exp2_c3, 4);
    vf r = vf_mul(p, vi_as_vf(vi_shl23(vi_add(k, vi_set1(127)))));
    return vf_select(vf_lt(t, vf_set1(-100.0f)), vf_set1(0.0f), r);
}

static SC_INLINE vf tier_pow(int tier, vf x, vf y)
{
    return tier == ACCURATE ? pow_d(x, y) : lobe_pow_fast(x, y);
}

#include "simd/spot_impl.h"

/* Integer lobe exponents up to these are raised by binary powering instead of tier_pow: the
 * error of the product of k roundings raised to powers is at most (2m − 1) 2^-24 relative
 * (2^-17 at 64 for the accurate tier's 2^-15, 2^-15 at 256 for the fast tiers). */
enum { POW_INT_MAX_ACCURATE = 64, POW_INT_MAX_FAST = 256 };

/* x^m, m >= 1 the same in every lane, by binary powering (vf_pow_uint, src/simd/spot_impl.h):
 * m = 32 five squarings. x below `cutoff` = 2^(−100/m) gives 0, as lobe_pow_fast
 * flushes below 2^-100, so that no power or product is subnormal (a microcode assist). */
static SC_INLINE vf pow_int(vf x, unsigned m, vf cutoff)
{
    return vf_pow_uint(vf_select(vf_lt(x, cutoff), vf_set1(0.0f), x), m);
}

/* ---- vec3 ---- */

typedef struct {
    vf x, y, z;
} v3;

/* components j, j+1, j+2 of the arrays, at element i */
static SC_INLINE v3 v3_load(const float *const *in, int j, size_t i)
{
    return (v3){vf_loadu(in[j] + i), vf_loadu(in[j + 1] + i), vf_loadu(in[j + 2] + i)};
}
static SC_INLINE void v3_store(v3 a, float *const *out, size_t i)
{
    vf_storeu(out[0] + i, a.x);
    vf_storeu(out[1] + i, a.y);
    vf_storeu(out[2] + i, a.z);
}
static SC_INLINE vf v3_dot(v3 a, v3 b)
{
    return vf_fma(a.x, b.x, vf_fma(a.y, b.y, vf_mul(a.z, b.z)));
}

/* a·b in the order C's a.x*b.x + a.y*b.y + a.z*b.z contracts to: x first */
static SC_INLINE vf v3_dot_x_first(v3 a, v3 b)
{
    return vf_fma(a.z, b.z, vf_fma(a.y, b.y, vf_mul(a.x, b.x)));
}
static SC_INLINE v3 v3_scale(v3 a, vf s)
{
    return (v3){vf_mul(a.x, s), vf_mul(a.y, s), vf_mul(a.z, s)};
}
static SC_INLINE v3 v3_add(v3 a, v3 b)
{
    return (v3){vf_add(a.x, b.x), vf_add(a.y, b.y), vf_add(a.z, b.z)};
}
static SC_INLINE v3 v3_sub(v3 a, v3 b)
{
    return (v3){vf_sub(a.x, b.x), vf_sub(a.y, b.y), vf_sub(a.z, b.z)};
}
static SC_INLINE v3 v3_set1(const float *c)
{
    return (v3){vf_set1(c[0]), vf_set1(c[1]), vf_set1(c[2])};
}

/* 1/|a| given dd = a·a finite, in a fast tier: the zero vector's is finite (dd is taken at
 * least 2^-149), so that a/|a| stays zero. */
static SC_INLINE vf inv_length_dd(int tier, vf dd)
{
    return tier_rsqrt(tier, vf_max(dd, vf_set1(0x1p-149f)));
}

/* a / |a| given dd = a·a finite. The zero vector stays zero. */
static SC_INLINE v3 v3_unit_dd(int tier, v3 a, vf dd)
{
    if (tier == ACCURATE) {
        vf len = vf_sqrt(vf_max(dd, vf_set1(0x1p-149f)));
        return (v3){vf_div(a.x, len), vf_div(a.y, len), vf_div(a.z, len)};
    }
    return v3_scale(a, inv_length_dd(tier, dd));
}

/* a, its lanes whose dd = a·a overflowed scaled by 2^-100 and dd recomputed there (rare: a
 * branch, not a cost on every vector). */
static SC_INLINE v3 v3_unoverflow(v3 a, vf *dd)
{
    vm big = vf_eq(*dd, vf_set1(INFINITY));
    if (vm_any(big)) {
        a = v3_scale(a, vf_select(big, vf_set1(0x1p-100f), vf_set1(1.0f)));
        *dd = v3_dot(a, a);
    }
    return a;
}

/* a / |a| given dd = a·a */
static SC_INLINE v3 v3_normalize_dd(int tier, v3 a, vf dd)
{
    a = v3_unoverflow(a, &dd);
    return v3_unit_dd(tier, a, dd);
}

static SC_INLINE v3 v3_normalize(int tier, v3 a) { return v3_normalize_dd(tier, a, v3_dot(a, a)); }

/* Half a vector of vec3s in double lanes: components j, j+1, j+2 of the arrays at element i,
 * the first (half 0) or second (half 1) VW/2 elements */
typedef struct {
    vd x, y, z;
} d3;

static SC_INLINE d3 d3_load(const float *const *in, int j, size_t i, int half)
{
    size_t e = i + (size_t)half * (VW / 2);
    return (d3){vd_load_floats(in[j] + e), vd_load_floats(in[j + 1] + e),
                vd_load_floats(in[j + 2] + e)};
}

/* a·b of floats in double: each product exact (24 + 24 bits), the two sums rounded to 53 bits,
 * so the float result is the exact dot product rounded once, but where the sum cancels to
 * below 2^-29 Σ|a_k b_k|. Without FMA a product and a sum round as the FMA does (the product
 * is exact): every instruction set gives the same bits. */
static SC_INLINE vd d3_dot(d3 a, d3 b)
{
    return vd_add(vd_add(vd_mul(a.x, b.x), vd_mul(a.y, b.y)), vd_mul(a.z, b.z));
}

static SC_INLINE void dot_lane(const float *const *in, float *const *out, size_t i, const void *p)
{
    (void)p;
    vd lo = d3_dot(d3_load(in, 0, i, 0), d3_load(in, 3, i, 0));
    vd hi = d3_dot(d3_load(in, 0, i, 1), d3_load(in, 3, i, 1));
    vf_storeu(out[0] + i, vf_from_vd(lo, hi));
}

/* reflect(I, N) = I − 2 (N·I) N (GLSL ES; N unit) in double: k = −2 N·I rounded to 53 bits,
 * I + k N with each product and sum rounded to 53 bits (no FMA: the same bits on every
 * instruction set), then once to float */
static SC_INLINE d3 d3_reflect(d3 i, d3 n)
{
    vd k = vd_mul(vd_set1(-2.0), d3_dot(n, i));
    return (d3){vd_add(i.x, vd_mul(k, n.x)), vd_add(i.y, vd_mul(k, n.y)),
                vd_add(i.z, vd_mul(k, n.z))};
}

/* the two halves of a vector of vec3s, each lane rounded once to float, stored at element i */
static SC_INLINE void d3_store(d3 lo, d3 hi, float *const *out, size_t i)
{
    v3_store((v3){vf_from_vd(lo.x, hi.x), vf_from_vd(lo.y, hi.y), vf_from_vd(lo.z, hi.z)}, out, i);
}

static SC_INLINE void reflect_lane(const float *const *in, float *const *out, size_t e,
                                   const void *p)
{
    (void)p;
    d3 lo = d3_reflect(d3_load(in, 0, e, 0), d3_load(in, 3, e, 0));
    d3 hi = d3_reflect(d3_load(in, 0, e, 1), d3_load(in, 3, e, 1));
    d3_store(lo, hi, out, e);
}

/* |a|: one square root, rounded once (the rsqrt tiers were slower and less accurate) */
static SC_INLINE void length_lane(const float *const *in, float *const *out, size_t i,
                                  const void *p)
{
    (void)p;
    v3 a = v3_load(in, 0, i);
    vf_storeu(out[0] + i, vf_sqrt(v3_dot_x_first(a, a)));
}

#define TIERED_LANE(name, body_fn, tier)                                                           \
    static SC_INLINE void name(const float *const *in, float *const *out, size_t i, const void *p) \
    {                                                                                              \
        (void)p;                                                                                   \
        body_fn(tier, in, out, i);                                                                 \
    }

static SC_INLINE void normalize_tier(int tier, const float *const *in, float *const *out, size_t i)
{
    v3_store(v3_normalize(tier, v3_load(in, 0, i)), out, i);
}

#ifdef SIMD_NO_ESTIMATES
/* a/|a| in double lanes: portable C has no estimate instruction, and 1/√(a·a) rounded twice,
 * then the product, measured 3.06 ULP against normalize u3's bound of 3 (SHADECALC_BATCH_SEED=53
 * of test_batch). a·a of floats errs by its two sums' 2^-53, the root, quotient and products by
 * 2^-53 each: the float result is within half an ULP plus 2^-27 ULP. The zero vector stays
 * zero (a·a at least 2^-1000); float squares cannot overflow a double. */
static SC_INLINE d3 d3_unit(d3 a)
{
    vd inv = vd_div(vd_set1(1.0), vd_sqrt(vd_max(d3_dot(a, a), vd_set1(0x1p-1000))));
    return (d3){vd_mul(a.x, inv), vd_mul(a.y, inv), vd_mul(a.z, inv)};
}

static SC_INLINE void normalize_lane(const float *const *in, float *const *out, size_t i,
                                     const void *p)
{
    (void)p;
    d3_store(d3_unit(d3_load(in, 0, i, 0)), d3_unit(d3_load(in, 0, i, 1)), out, i);
}
#else
TIERED_LANE(normalize_lane, normalize_tier, REFINED)
#endif
BATCH_N(dot_bits22, 6, 1, dot_lane)
BATCH_N(reflect_bits22, 6, 3, reflect_lane)
BATCH_N(normalize_u3, 3, 3, normalize_lane)
BATCH_N(length_u2, 3, 1, length_lane)

static const float inv_pi_f = 0.318309886183790671538f;
