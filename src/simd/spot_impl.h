/* The spot functions of docs/formulas.md §4 (light.c), written once against the vector helpers: the
 * spot_* batch kernels of src/simd/light_impl.h and the shading kernel of src/simd/shade_impl.h
 * (which includes this file after its tier operations) both evaluate them. Each function reads
 * its uniforms, fixed once per call, from a func_uniforms:
 *   spot_setup_opengl, spot_setup_penumbra   from sc_batch_spot_params (angles in degrees)
 *   spot_uniforms_of_light                   from an sc_batch_light (cosines)
 * The cone's cosines from degrees are rounded toward the inside of each test, so that
 * cos θ_s >= cos θ_p and cos θ_s <= cos θ_u decide as in double. */

/* pow by tier; the u1 one hands NaN, infinities, zeros and 1 to the built-in */
static SC_INLINE vf light_pow(int tier, vf x, vf y)
{
    if (tier != ACCURATE)
        return tier == FAST12 ? pow_bits12(x, y) : pow_bits8(x, y);
#ifdef SIMD_HAS_DOUBLE
    return pow_u1(x, y);
#else
    return sc_powf(x, y);
#endif
}

static SC_INLINE vf vf_clamp(vf x, float lo, float hi)
{
    return vf_min(vf_max(x, vf_set1(lo)), vf_set1(hi));
}

enum { MAX_UNIFORMS = 6 };
typedef struct {
    float k[MAX_UNIFORMS]; /* named by each function's setup */
} func_uniforms;

static const double deg = 3.14159265358979323846 / 180.0;

static float float_at_least(double x) /* the least float >= x */
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static float float_at_most(double x)
{
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

/* k: cos θ_u (at least), exponent, 1 for no cone */
static inline void spot_setup_opengl(const void *params, func_uniforms *u)
{
    const sc_batch_spot_params *p = params;
    *u = (func_uniforms){
        {float_at_least(cos(p->cutoff * deg)), p->exponent, p->cutoff == 180.0f ? 1.0f : 0.0f}};
}

/* k: cos θ_p (at least), cos θ_u (at most) as hi + lo, 1/(cos θ_p − cos θ_u), exponent: the
 * ramp (cos θ_s − cos θ_u)/(cos θ_p − cos θ_u) keeps its relative accuracy near the edge */
static inline void spot_setup_penumbra(const void *params, func_uniforms *u)
{
    const sc_batch_spot_params *p = params;
    double cp = cos(p->inner * deg), cu = cos(p->outer * deg);
    float cu_hi = float_at_most(cu);
    *u = (func_uniforms){{float_at_least(cp), cu_hi, (float)(cu - cu_hi),
                          cp > cu ? (float)(1.0 / (cp - cu)) : 0.0f, p->exponent}};
}

/* x^e for x <= 1 with pow(0, 0) = 1 and 0 for x <= 0 (the cosine lobes, light.c lobe_pow);
 * the lanes x <= 0 and x = 1 (the ramp's clamp inside the inner cone) take the base 1/2, which
 * the u1 pow does not hand to the scalar built-in as it would 0 and 1, and get 0 and 1. */
static SC_INLINE vf lobe_pow(int tier, vf x, float e)
{
    if (e == 0.0f)
        return vf_set1(1.0f);
    vm pos = vf_lt(vf_set1(0.0f), x), one = vf_eq(x, vf_set1(1.0f));
    vf base = vf_select(vm_and(pos, vf_lt(x, vf_set1(1.0f))), x, vf_set1(0.5f));
    vf p = vf_select(one, vf_set1(1.0f), light_pow(tier, base, vf_set1(e)));
    return vf_select(pos, p, vf_set1(0.0f));
}

static SC_INLINE vf spot_opengl(int tier, vf c, const func_uniforms *u)
{
    if (u->k[2] != 0.0f)
        return vf_set1(1.0f);
    return vf_select(vf_le(vf_set1(u->k[0]), c), lobe_pow(tier, c, u->k[1]), vf_set1(0.0f));
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

/* The uniforms of a spot light of the shading kernel (batch.h: cosines of the half-angles). */
static inline void spot_uniforms_of_light(const sc_batch_light *lt, func_uniforms *u)
{
    if (lt->spot == SC_BATCH_SPOT_OPENGL) {
        *u = (func_uniforms){{lt->cos_outer, lt->exponent, lt->cos_outer <= -1.0f ? 1.0f : 0.0f}};
        return;
    }
    double cp = lt->cos_inner, cu = lt->cos_outer;
    *u = (func_uniforms){{lt->cos_inner, lt->cos_outer, 0.0f,
                          cp > cu ? (float)(1.0 / (cp - cu)) : 0.0f, lt->exponent}};
}

static SC_INLINE vf spot_factor(int tier, sc_batch_spot kind, vf cos_s, const func_uniforms *u)
{
    switch (kind) {
    case SC_BATCH_SPOT_DIRECTX: return spot_directx(tier, cos_s, u);
    case SC_BATCH_SPOT_SMOOTHSTEP: return spot_smoothstep(tier, cos_s, u);
    default: return spot_opengl(tier, cos_s, u);
    }
}
