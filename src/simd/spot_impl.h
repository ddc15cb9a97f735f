/* The spot functions of docs/formulas.md §4 (light.c), written once against the vector helpers: the
 * spot_* batch kernels of src/simd/light_impl.h and the shading kernel of src/simd/scene_impl.h
 * both evaluate them. Each function reads its uniforms, fixed once per call or per plan, from
 * the sc_func_uniforms that sc_uniforms_spot (src/simd/uniforms.h) computes from an sc_spot. */
#include "simd/uniforms.h"

/* pow by tier; the u1 one hands NaN, infinities, zeros and 1 to the built-in */
static SC_INLINE vf light_pow(int tier, vf x, vf y)
{
    return tier == ACCURATE ? pow_u1(x, y) : pow_bits12(x, y);
}

static SC_INLINE vf vf_clamp(vf x, float lo, float hi)
{
    return vf_min(vf_max(x, vf_set1(lo)), vf_set1(hi));
}

typedef sc_func_uniforms func_uniforms;

/* x^m, m >= 1 the same in every lane, by binary powering (Knuth TAOCP 4.6.3): the squarings
 * up to m's lowest set bit, then a squaring and at most one product per further bit; in float
 * lanes or in double ones. */
#define POW_UINT(name, type, mul)                                                                  \
    static SC_INLINE type name(type x, unsigned m)                                                 \
    {                                                                                              \
        for (; !(m & 1u); m >>= 1)                                                                 \
            x = mul(x, x);                                                                         \
        type r = x;                                                                                \
        for (m >>= 1; m; m >>= 1) {                                                                \
            x = mul(x, x);                                                                         \
            if (m & 1u)                                                                            \
                r = mul(r, x);                                                                     \
        }                                                                                          \
        return r;                                                                                  \
    }
POW_UINT(vf_pow_uint, vf, vf_mul)
POW_UINT(vd_pow_uint, vd, vd_mul)

/* Integer exponents up to this are raised by pow_uint_u1. */
enum { LOBE_UINT_MAX = 1024 };

/* x^m for x in [0, 1], m in 1..LOBE_UINT_MAX: the powers in double, whose at most 2 log2 m
 * products err by 2^-53 relative each (2^-49 in all), rounded once to float: within the u1
 * tiers' ULP, no special case, no subnormal float on the way. */
static SC_INLINE vf pow_uint_u1(vf x, unsigned m)
{
    return vf_from_vd(vd_pow_uint(vd_from_lo(x), m), vd_pow_uint(vd_from_hi(x), m));
}

/* x^m for x in [0, 1], m in 1..LOBE_UINT_MAX, by tier. The accurate tier's is pow_uint_u1. The
 * fast tiers raise x in float lanes: each of at most 2 log2 m products rounds by 2^-24 and a
 * squaring doubles the relative error before it, (2m − 1) 2^-24 relative in all (2^-13 at
 * m = 1024); the lanes whose power falls below 2^-125 (x > 0), where a float product may be
 * subnormal (a microcode assist, and bits lost), are raised again in double: a branch on rare
 * lanes, not a cost on every vector. */
static SC_INLINE vf pow_uint_tier(int tier, vf x, unsigned m)
{
    if (tier == ACCURATE)
        return pow_uint_u1(x, m);
    vf p = vf_pow_uint(x, m);
    vm tiny = vm_and(vf_lt(p, vf_set1(0x1p-125f)), vf_lt(vf_set1(0.0f), x));
    return vm_any(tiny) ? vf_select(tiny, pow_uint_u1(x, m), p) : p;
}

/* e as an integer exponent of pow_uint_tier, or 0 */
static SC_INLINE unsigned lobe_uint(float e)
{
    return e >= 1.0f && e <= (float)LOBE_UINT_MAX && e == (float)(unsigned)e ? (unsigned)e : 0u;
}

/* x^e for x <= 1 with pow(0, 0) = 1 and 0 for x <= 0 (the cosine lobes, light.c lobe_pow);
 * the lanes x <= 0 and x = 1 (the ramp's clamp inside the inner cone) take the base 1/2, which
 * the u1 pow does not hand to the scalar built-in as it would 0 and 1, and get 0 and 1. An
 * integer e (the usual spot exponents) is raised by binary powering (pow_uint_tier): faster
 * than the tiers' pow, and within their bounds. */
static SC_INLINE vf lobe_pow(int tier, vf x, float e)
{
    if (e == 0.0f)
        return vf_set1(1.0f);
    unsigned m = lobe_uint(e);
    if (m) /* 0^m = 0 and 1^m = 1 exactly: no select (x <= 0 and NaN: max gives 0) */
        return pow_uint_tier(tier, vf_max(x, vf_set1(0.0f)), m);
    vm pos = vf_lt(vf_set1(0.0f), x), one = vf_eq(x, vf_set1(1.0f));
    vf base = vf_select(vm_and(pos, vf_lt(x, vf_set1(1.0f))), x, vf_set1(0.5f));
    vf p = vf_select(one, vf_set1(1.0f), light_pow(tier, base, vf_set1(e)));
    return vf_keep(pos, p);
}

static SC_INLINE vf spot_opengl(int tier, vf c, const func_uniforms *u)
{
    if (u->k[2] != 0.0f)
        return vf_set1(1.0f);
    vm inside = vf_le(vf_set1(u->k[0]), c);
    if (!vm_any(inside)) /* no lane in the cone: no power to raise */
        return vf_set1(0.0f);
    return vf_keep(inside, lobe_pow(tier, c, u->k[1]));
}

/* 1 inside the inner cone, 0 outside the outer one, else shape(ramp) */
static SC_INLINE vf penumbra(vf c, const func_uniforms *u, vf shaped)
{
    vf f = vf_select(vf_le(c, vf_set1(u->k[1])), vf_set1(0.0f), shaped);
    return vf_select(vf_le(vf_set1(u->k[0]), c), vf_set1(1.0f), f);
}

static SC_INLINE vf ramp(vf c, const func_uniforms *u)
{
    vf t = vf_sub(vf_sub(c, vf_set1(u->k[1])), vf_set1(u->k[2]));
    return vf_clamp(vf_mul(t, vf_set1(u->k[3])), 0.0f, 1.0f);
}

static SC_INLINE vf spot_directx(int tier, vf c, const func_uniforms *u)
{
    return penumbra(c, u, lobe_pow(tier, ramp(c, u), u->k[4]));
}

/* pbrt-v4: smoothstep t²(3 − 2t) */
static SC_INLINE vf spot_smoothstep(int tier, vf c, const func_uniforms *u)
{
    (void)tier;
    vf t = ramp(c, u);
    return penumbra(c, u, vf_mul(vf_mul(t, t), vf_fma(vf_set1(-2.0f), t, vf_set1(3.0f))));
}

static SC_INLINE vf spot_factor(int tier, sc_spot_kind kind, vf cos_s, const func_uniforms *u)
{
    switch (kind) {
    case SC_SPOT_DIRECTX: return spot_directx(tier, cos_s, u);
    case SC_SPOT_SMOOTHSTEP: return spot_smoothstep(tier, cos_s, u);
    default: return spot_opengl(tier, cos_s, u);
    }
}
