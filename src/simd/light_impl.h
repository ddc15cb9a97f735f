/* The attenuation, spot and BRDF batch kernels, written once against the vector helpers and
 * included after src/simd/shade_impl.h by each instruction set's file.
 *
 * Tiers (the enum of shade_impl.h): ACCURATE has sqrt and division rounded once and the u1
 * pow/exp (double lanes); FAST12 the rsqrt/rcp estimates with
 * one Newton step and pow/exp_bits12. Every kernel computes the float uniforms of its double
 * parameters (sc_atten, sc_spot, sc_brdf) once per call (src/simd/uniforms.h) and hands them to
 * the lanes as args.params.
 * The attenuation and spot functions are rational functions and one pow/exp: their fast tiers
 * keep the division (a fraction of a nanosecond) and change only pow and exp.
 */
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

/* ---- exp by tier (pow: light_pow of src/simd/spot_impl.h); the u1 one hands NaN and
 * infinities to the built-in ---- */

static SC_INLINE vf light_exp(int tier, vf x)
{
    return tier == ACCURATE ? exp_u1(x) : exp_bits12(x);
}

/* e^−x for x >= 0 (the Gaussian lobes of Ward and Beckmann, Beckmann's Λ), 0 beyond x = 87,
 * where e^−x < 1.7e-38 (FLT_MIN is 1.2e-38): an absolute error far inside every bound's
 * absolute term, as the factor beside it (Beckmann's 1/cos⁴θ_h = (1 + α² x)² at x =
 * tan²θ_h/α²) grows far slower than e^−x falls. Every tier's exp hands the lanes below about
 * −87.3 to the scalar built-in, and grazing half vectors reach them on ordinary inputs: a third
 * of the lanes at α = 0.3, where the Beckmann shading kernel took 23 ns per element against
 * GGX's 1.3. NaN stays NaN (the min keeps it: src/simd/<isa>/vec.h). */
static SC_INLINE vf exp_minus(int tier, vf x)
{
    vf ceiling = vf_set1(87.0f);
    return vf_keep(vf_nlt(ceiling, x), light_exp(tier, vf_sub(vf_set1(0.0f), vf_min(ceiling, x))));
}

/* ---- one input, one output: attenuation of r and spot of cos θ_s ---- */

typedef vf (*func_fn)(int tier, vf x, const func_uniforms *u);

static SC_INLINE void func_lane(int tier, func_fn f, const float *const *in, float *const *out,
                                size_t i, const void *u)
{
    vf_storeu(out[0] + i, f(tier, load_once(in[0] + i), u));
}

static SC_INLINE void run_uniforms(const sc_batch_args *a, int k, int m, lane_n_fn lane,
                                   const void *uniforms, int width)
{
    sc_batch_args b = *a;
    b.params = uniforms;
    run_wide(&b, k, m, lane, width);
}

/* setup: sc_uniforms_atten or sc_uniforms_spot, for the function's kind */
#define FUNC_KERNEL(name, tier, f, setup, kind)                                                    \
    static SC_INLINE void name##_lane(const float *const *in, float *const *out, size_t i,         \
                                      const void *u)                                               \
    {                                                                                              \
        func_lane(tier, f, in, out, i, u);                                                         \
    }                                                                                              \
    KERNEL(name);                                                                                  \
    KERNEL(name)                                                                                   \
    {                                                                                              \
        func_uniforms u;                                                                           \
        setup(a->params, kind, &u);                                                                \
        run_uniforms(a, 1, 1, name##_lane, &u, 1);                                                 \
    }

/* -- attenuation (docs/formulas.md §3; light.c): denominators at least 1e-4, so r = 0 is finite -- */

static SC_INLINE vf inverse_square(vf r)
{
    return vf_div(vf_set1(1.0f), vf_max(vf_mul(r, r), vf_set1(1e-4f)));
}

#if defined(SIMD_FINE_ESTIMATES) && defined(SIMD_HAS_FMA)
/* 1/max(r², 1e-4) from AVX-512's 2^-14 reciprocal estimate y of m = max(hi, 1e-4), where
 * hi + lo = r² exactly (lo = r r − hi by an FMA; 0 where m is the floor): the residual
 * t = 1 − m y − lo y, and y (1 + t), rounded once by the last FMA, is 1/(m + lo) within t² <=
 * 2^-27 relative before that rounding. The quotient of the rounded r² (inverse_square) erred by
 * up to 1.40 ULP, as did clang's -ffast-math estimate and Newton step, which was faster: this
 * is 0.51 ULP, the division's 0.043 ns per element becoming 0.056 (Zen 4, bench --n 4096). */
static SC_INLINE vf inverse_square_refined(vf r)
{
    vf hi = vf_mul(r, r), m = vf_max(hi, vf_set1(1e-4f));
    vf lo = vf_select(vf_lt(hi, vf_set1(1e-4f)), vf_set1(0.0f), vf_fms(r, r, hi));
    vf y = vf_rcp_est(m);
    vf t = vf_fnma(lo, y, vf_fnma(m, y, vf_set1(1.0f)));
    return vf_fma(y, t, y);
}
#else
static SC_INLINE vf inverse_square_refined(vf r) { return inverse_square(r); }
#endif

static SC_INLINE vf atten_none(int tier, vf r, const func_uniforms *u)
{
    (void)tier, (void)r, (void)u;
    return vf_set1(1.0f);
}

static SC_INLINE vf atten_invsq(int tier, vf r, const func_uniforms *u)
{
    (void)tier, (void)u;
    return inverse_square_refined(r);
}

static SC_INLINE vf atten_clq(int tier, vf r, const func_uniforms *u)
{
    (void)tier;
    vf d = vf_add(vf_fma(vf_set1(u->k[1]), r, vf_set1(u->k[0])),
                  vf_mul(vf_set1(u->k[2]), vf_mul(r, r)));
    return vf_div(vf_set1(1.0f), vf_max(d, vf_set1(1e-4f)));
}

/* The ramp (r_end − r)/w for r > r_start (r_start >= 0, light.c), with r taken at most r_end
 * (vf_min keeps a NaN r), so that r >= r_end, the step w = 0 (setup: 1/w = 0) and r = ∞ give
 * 0 with no compare or select. In the ramp's lanes r_end − r lies between w 2^-24 (an ULP of
 * r_end >= w; 2^-149 for a subnormal w) and w (1 + 2^-23).
 * With an FMA, the exact difference divided without a division: r_end − r rounded, then
 * divided, erred by 1 ULP, where -ffast-math's reciprocal multiply was as accurate on the
 * bench's inputs and faster (AVX2, Zen 4: 0.088 against 0.098 ns per element). Here all is
 * scaled by s, the power of 2 that takes w s into [1, 2): R = r_end s and r s are exact but
 * for products negligible beside R >= w s >= 1, so hi + lo = R − r s exactly (Fast2Sum,
 * R >= r s: Dekker 1971). q = hi (w s)^-1 is within 1.5 ULP of hi/(w s), one FMA forms its
 * remainder hi − q w s exactly (Markstein 1990; Muller et al., Handbook of Floating-Point
 * Arithmetic, §4.7), and q + (hi − q w s + lo) (w s)^-1, rounded once by the second FMA,
 * misses (hi + lo)/(w s) by about 2^-21 ULP before that rounding: within 0.5 + 2^-21 ULP.
 * Without an FMA, the rounded difference divided once (1 ULP). */
static SC_INLINE vf window_ramp(vf r, const func_uniforms *u)
{
    r = vf_min(vf_set1(u->k[1]), r);
#ifdef SIMD_HAS_FMA
    vf big = vf_set1(u->k[1] * u->k[4]), rs = vf_mul(r, vf_set1(u->k[4]));
    vf hi = vf_sub(big, rs), lo = vf_sub(vf_sub(big, hi), rs);
    vf inv = vf_set1(u->k[3]), q = vf_mul(hi, inv);
    vf rem = vf_add(vf_fma(q, vf_set1(-u->k[2]), hi), lo);
    return vf_fma(rem, inv, q);
#else
    return vf_div(vf_sub(vf_set1(u->k[1]), r), vf_set1(u->k[5]));
#endif
}

/* 1 for r <= r_start, 0 for r >= r_end (so r_start = r_end is a step), else the ramp */
static SC_INLINE vf atten_window(int tier, vf r, const func_uniforms *u)
{
    (void)tier;
    return vf_select(vf_le(r, vf_set1(u->k[0])), vf_set1(1.0f), window_ramp(r, u));
}

/* Barzel 1997: f_c (r/r_c)^(−s_e) beyond r_c; f_max exp(k0 (r/r_c)^(−k1)) inside (−k1 > 0,
 * so r = 0 gives f_max); f_c = f_max is the flat limit f_max. Each side is computed only where
 * a lane needs it (the lights' falloff is mostly beyond r_c), and by the same formula whatever
 * the other lanes, so that a result does not depend on its neighbours. The other side's lanes,
 * whose values a side drops, take r = r_c/2 inside and 2 r_c beyond (a base of 1/2): inside
 * the domain of every tier's pow and exp, away from its special cases, where r/r_c far beyond
 * 1 inside (0 and NaN beyond; 1 exactly, had r been clamped to r_c) sent them to the scalar
 * built-ins (a vector of AVX-512 with both kinds of lane, at the bench's r in [0, 1000], cost
 * 0.74 ns per element against 0.18 with all lanes beyond). */

/* r/r_c, the base of the tiers' pow (negative r: 0) */
static SC_INLINE vf pixar_base(vf r, const func_uniforms *u)
{
    return vf_max(vf_div(r, vf_set1(u->k[1])), vf_set1(0.0f));
}

/* f_c (r_c/q)^m in double: q, r_c and f_c exact; the quotient's rounding raised to the m-th
 * power, at most 2 log2 m products and the last one: (m + 2 log2 m + 1) 2^-53 relative, 2^-19
 * of a float ULP for m up to 1024, before the one rounding to float */
static SC_INLINE vd pixar_far_d(vd q, vd r_c, vd f_c, unsigned m)
{
    return vd_mul(f_c, vd_pow_uint(vd_div(r_c, q), m));
}

/* The lanes beyond r_c. An integer s_e (the usual inverse square: 2) is raised by binary
 * powering, as the spot exponents are (src/simd/spot_impl.h): faster than the tiers' pow; in
 * the accurate tier in double, within 0.5 ULP (pixar_far_d), in the fast tiers in float
 * (pow_uint_tier) of the quotient rounded to float, 3m 2^-24 relative in all (2^-12.4
 * at m = 1024). Other exponents take the tier's pow of r/r_c. r > r_c in every lane
 * (atten_pixar). */
static SC_INLINE vf pixar_far(int tier, vf r, const func_uniforms *u)
{
    unsigned m = lobe_uint(u->k[2]);
    if (!m)
        return vf_mul(vf_set1(u->k[0]), light_pow(tier, pixar_base(r, u), vf_set1(-u->k[2])));
    if (tier != ACCURATE)
        return vf_mul(vf_set1(u->k[0]), pow_uint_tier(tier, vf_div(vf_set1(u->k[1]), r), m));
    vd r_c = vd_set1(u->k[1]), f_c = vd_set1(u->k[0]);
    return vf_from_vd(pixar_far_d(vd_from_lo(r), r_c, f_c, m),
                      pixar_far_d(vd_from_hi(r), r_c, f_c, m));
}

/* The lanes at or inside r_c (and NaN) */
static SC_INLINE vf pixar_near(int tier, vf r, const func_uniforms *u)
{
    vf f_max = vf_set1(u->k[3]);
    if (u->k[4] == 0.0f)
        return f_max;
    vf t = light_pow(tier, pixar_base(r, u), vf_set1(u->k[5]));
    return vf_mul(f_max, light_exp(tier, vf_mul(vf_set1(u->k[4]), t)));
}

static SC_INLINE vf atten_pixar(int tier, vf r, const func_uniforms *u)
{
    float r_c = u->k[1];
    vm outside = vf_lt(vf_set1(r_c), r), near = vf_nlt(vf_set1(r_c), r); /* near: NaN too */
    vf far_value = vm_any(outside) ? pixar_far(tier, vf_select(outside, r, vf_set1(2.0f * r_c)), u)
                                   : vf_set1(0.0f);
    vf near_value = vm_any(near) ? pixar_near(tier, vf_select(outside, vf_set1(0.5f * r_c), r), u)
                                 : vf_set1(0.0f);
    return vf_select(outside, far_value, near_value);
}

/* Karis 2013: saturate(1 − (r/r_max)^4)² / max(r², 1e-4), with 1 − (r/r_max)^4 as
 * (r_max − r)(r_max + r)(r_max² + r²)/r_max^4: no cancellation as r -> r_max */
static SC_INLINE vf atten_windowed(int tier, vf r, const func_uniforms *u)
{
    (void)tier;
    vf rm = vf_set1(u->k[0]);
    vf d = vf_mul(vf_sub(rm, r), vf_add(rm, r));
    vf w = vf_mul(vf_mul(d, vf_fma(r, r, vf_set1(u->k[1]))), vf_set1(u->k[2]));
    w = vf_clamp(w, 0.0f, 1.0f);
    return vf_mul(vf_mul(w, w), inverse_square(r));
}

/* f(r) = 1 reads no input: a fill, four vectors a step (through run_wide's calls of two
 * vectors Zen 4 stored at 0.76 cycle per vector, where clang's unrolled fill reached 0.5), from
 * the first element aligned to a whole vector on: at the bench's arrays, 48 bytes into a cache
 * line, half of AVX2's stores and all of AVX-512's split a line, and the fill ran at clang's
 * speed, 0.031 ns per element on AVX2 (aligned 0.018). Large arrays get non-temporal stores,
 * as the one-input drivers have them. */
static SC_INLINE void fill_steps(float *out, size_t *i, size_t n, vf v, void (*store)(float *, vf))
{
    for (; *i + 4 * VW <= n; *i += 4 * VW) {
        float *p = out + *i;
        store(p, v), store(p + VW, v), store(p + 2 * VW, v), store(p + 3 * VW, v);
    }
    for (; *i + VW <= n; *i += VW)
        store(out + *i, v);
}

KERNEL(atten_none_u1);
KERNEL(atten_none_u1)
{
    float *out = a->out[0];
    size_t i = aligning_peel(out, a->n);
    vf one = vf_set1(1.0f);
    int stream = outputs_stream(a, 1, &i); /* the same peel where it streams */
    for (size_t k = 0; k < i; k++)
        out[k] = 1.0f;
    if (stream) {
        fill_steps(out, &i, a->n, one, vf_stream);
        vf_stream_fence();
    } else
        fill_steps(out, &i, a->n, one, vf_storeu);
    for (; i < a->n; i++)
        out[i] = 1.0f;
}
FUNC_KERNEL(atten_invsq_u2, ACCURATE, atten_invsq, sc_uniforms_atten, SC_ATTEN_INVERSE_SQUARE)
FUNC_KERNEL(atten_clq_u3, ACCURATE, atten_clq, sc_uniforms_atten, SC_ATTEN_CLQ)
FUNC_KERNEL(atten_window_u2, ACCURATE, atten_window, sc_uniforms_atten, SC_ATTEN_WINDOW)
FUNC_KERNEL(atten_pixar_u4, ACCURATE, atten_pixar, sc_uniforms_atten, SC_ATTEN_PIXAR)
FUNC_KERNEL(atten_pixar_bits12, FAST12, atten_pixar, sc_uniforms_atten, SC_ATTEN_PIXAR)
FUNC_KERNEL(atten_windowed_u12, ACCURATE, atten_windowed, sc_uniforms_atten, SC_ATTEN_WINDOWED)

/* -- spot (docs/formulas.md §4): the functions and their setup are in src/simd/spot_impl.h, shared with
 * the shading kernel -- */

FUNC_KERNEL(spot_opengl_u1, ACCURATE, spot_opengl, sc_uniforms_spot, SC_SPOT_OPENGL)
FUNC_KERNEL(spot_opengl_bits12, FAST12, spot_opengl, sc_uniforms_spot, SC_SPOT_OPENGL)
FUNC_KERNEL(spot_directx_u16, ACCURATE, spot_directx, sc_uniforms_spot, SC_SPOT_DIRECTX)
FUNC_KERNEL(spot_directx_bits12, FAST12, spot_directx, sc_uniforms_spot, SC_SPOT_DIRECTX)
FUNC_KERNEL(spot_smoothstep_u8, ACCURATE, spot_smoothstep, sc_uniforms_spot, SC_SPOT_SMOOTHSTEP)

/* ---- BRDFs (docs/formulas.md §6, brdf.h): in l, v, n; out f as r, g, b ----
 *
 * With n, l, v normalized and the unnormalized half vector h_u = l + v, the isotropic models
 * need only n·l, n·v, h_u·h_u, n·h_u and |n × h_u|² (= (h_u·h_u) sin²θ_h, without the
 * cancellation of 1 − cos²θ_h at the highlight). Anisotropic Ward and Cook–Torrance need the
 * tangent frame (t, b) too: the one sc_frame_make builds from n alone. A model returns weights
 * w_j with f_c = Σ_j w_j col_j[c] for colour vectors fixed per call (sc_uniforms_brdf). */

static const float pi_f = 3.14159265358979323846f;

typedef sc_brdf_uniforms brdf_uniforms;

typedef struct {
    v3 n, l, v;
    vf nl, nv, hh, hn, s2; /* n·l, n·v, h_u·h_u, n·h_u, |n × h_u|² */
    /* anisotropic only: sl = (h_u·t/α_x)² + (h_u·b/α_y)², and for w = l, v: p_w = (w·t α_x)² +
     * (w·b α_y)² (α²tan²θ_w cos²θ_w, Heitz 2014) */
    vf sl, pl, pv;
} brdf_geometry;

typedef struct {
    vf w[3];
} brdf_weights;

static SC_INLINE v3 v3_cross(v3 a, v3 b)
{
    return (v3){vf_sub(vf_mul(a.y, b.z), vf_mul(a.z, b.y)),
                vf_sub(vf_mul(a.z, b.x), vf_mul(a.x, b.z)),
                vf_sub(vf_mul(a.x, b.y), vf_mul(a.y, b.x))};
}

static SC_INLINE vf cross2(v3 a, v3 b) /* |a × b|² */
{
    v3 c = v3_cross(a, b);
    return v3_dot(c, c);
}

/* sc_frame_make's axis for the tangent, decided on n as given (any length): e_x, or e_y where
 * |n_x| >= 2 max(|n_y|, |n_z|). Comparisons and a doubling are exact, so the lanes choose as
 * brdf.c does in double for the same input (on n normalized in float they could not: two
 * components a float apart may round to one). The mask is e_x's. */
static SC_INLINE vm tangent_axis_x(v3 n)
{
    vf m = vf_max(vf_abs(n.y), vf_abs(n.z));
    return vf_lt(vf_abs(n.x), vf_add(m, m));
}

/* sc_frame_make's tangent for a unit n: e_x where use_x (tangent_axis_x), else e_y, made
 * orthogonal to n */
static SC_INLINE v3 tangent_of(int tier, v3 n, vm use_x)
{
    vf tn = vf_select(use_x, n.x, n.y), one = vf_set1(1.0f), zero = vf_set1(0.0f);
    v3 t = {vf_sub(vf_keep(use_x, one), vf_mul(tn, n.x)),
            vf_sub(vf_select(use_x, zero, one), vf_mul(tn, n.y)), vf_mul(vf_sub(zero, tn), n.z)};
    return v3_normalize(tier, t);
}

/* (1 − c)(1 + c) = sin²θ, accurate near c = 1 */
static SC_INLINE vf sin2_of(vf c)
{
    return vf_mul(vf_sub(vf_set1(1.0f), c), vf_add(vf_set1(1.0f), c));
}

/* sl and p_w of brdf_geometry. With (w·t)² + (w·b)² = sin²θ_w for unit w, and (h_u·t)² +
 * (h_u·b)² = |n × h_u|², each is written as the isotropic form of one α plus a positive
 * multiple of one axis' square, so that no term cancels:
 *   sl  = s2 / α_hi² + (1/α_lo² − 1/α_hi²) (h_u·e_lo)²
 *   p_w = α_lo² sin²θ_w + (α_hi² − α_lo²) (w·e_hi)²
 * where e_lo is the axis of the smaller α (t for α_x), e_hi the other. */
static SC_INLINE void aniso_geometry(int tier, const brdf_uniforms *u, vm use_x, brdf_geometry *g)
{
    v3 t = tangent_of(tier, g->n, use_x), b = v3_cross(g->n, t);
    int x_lo = u->ax <= u->ay;
    v3 e_lo = x_lo ? t : b, e_hi = x_lo ? b : t;
    float lo = x_lo ? u->ax : u->ay, hi = x_lo ? u->ay : u->ax;
    float lo2 = lo * lo, hi2 = hi * hi;
    vf h_lo = v3_dot(v3_add(g->l, g->v), e_lo), l_hi = v3_dot(g->l, e_hi);
    vf v_hi = v3_dot(g->v, e_hi);
    g->sl = vf_fma(vf_set1(1.0f / lo2 - 1.0f / hi2), vf_mul(h_lo, h_lo),
                   vf_mul(g->s2, vf_set1(1.0f / hi2)));
    vf d = vf_set1(hi2 - lo2), lo2v = vf_set1(lo2);
    g->pl = vf_fma(d, vf_mul(l_hi, l_hi), vf_mul(lo2v, sin2_of(g->nl)));
    g->pv = vf_fma(d, vf_mul(v_hi, v_hi), vf_mul(lo2v, sin2_of(g->nv)));
}

/* The geometry of unit n, l, v; tier that of the tangent's normalization; n_given the normal
 * before its normalization (the tangent's axis). */
static SC_INLINE brdf_geometry brdf_geometry_make(int tier, const brdf_uniforms *u, v3 n_given,
                                                  v3 n, v3 l, v3 v)
{
    brdf_geometry g;
    g.n = n, g.l = l, g.v = v;
    g.nl = v3_dot(n, l);
    g.nv = v3_dot(n, v);
    v3 hu = v3_add(l, v);
    g.hh = v3_dot(hu, hu);
    g.hn = vf_add(g.nl, g.nv);
    g.s2 = cross2(n, hu);
    g.sl = g.pl = g.pv = vf_set1(0.0f);
    if (u->aniso)
        aniso_geometry(tier, u, tangent_axis_x(n_given), &g);
    return g;
}

static SC_INLINE brdf_geometry brdf_geometry_of(int tier, const brdf_uniforms *u,
                                                const float *const *in, size_t i)
{
    v3 n = v3_load(in, 6, i);
    return brdf_geometry_make(tier, u, n, v3_normalize(tier, n),
                              v3_normalize(tier, v3_load(in, 0, i)),
                              v3_normalize(tier, v3_load(in, 3, i)));
}

static SC_INLINE brdf_weights weights(vf w0, vf w1, vf w2) { return (brdf_weights){{w0, w1, w2}}; }

static SC_INLINE vf inv_pi_v(void) { return vf_set1(inv_pi_f); }

/* cos θ_i, floored as brdf.c's divisions (inactive in the stated domain) */
static SC_INLINE vf cos_floor(vf c) { return vf_max(c, vf_set1(1e-6f)); }

static SC_INLINE brdf_weights model_lambert(int tier, const brdf_uniforms *u,
                                            const brdf_geometry *g)
{
    (void)tier, (void)u, (void)g;
    return weights(inv_pi_v(), vf_set1(0.0f), vf_set1(0.0f));
}

/* c^m for a cosine c <= 1: pow(0, 0) = 1, else 0 for a non-positive base. An integer m (the
 * uniforms' lobe_m) by binary powering: in double in the accurate tier (pow_uint_u1), in float
 * in the fast tiers with powers below 2^-100 flushed to 0 (pow_int, as the shading kernel's
 * own lobes); another m by the tier's pow of c floored at FLT_MIN (tier_pow). No lane goes to
 * the scalar built-in, where pow(0, m) and powers that underflow did: every unlit or
 * back-facing lane (Phong, m = 20, shaded at 20 ns per element on AVX2 and AVX-512 alike). */
static SC_INLINE vf cos_lobe(int tier, const brdf_uniforms *u, vf c, float m)
{
    if (m == 0.0f)
        return vf_set1(1.0f);
    vf c0 = vf_max(c, vf_set1(0.0f));
    if (u->lobe_m && tier == ACCURATE)
        return pow_uint_u1(c0, u->lobe_m);
    if (u->lobe_m)
        return pow_int(c0, u->lobe_m, vf_set1(u->lobe_cutoff));
    return vf_keep(vf_lt(vf_set1(0.0f), c),
                   tier_pow(tier, vf_max(c, vf_set1(FLT_MIN)), vf_set1(m)));
}

/* Phong: cos α_r = r·v with r = 2(n·l)n − l, as 1 − |r − v|²/2 (accurate at the peak, where
 * m multiplies its error); k0 = the normalization 1/π, (m+2)/(2π); original divides by
 * π cos θ_i (Phong 1975, Lewis 1994, Lafortune 1994). */
static SC_INLINE brdf_weights model_phong(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    v3 rv = v3_sub(v3_scale(g->n, vf_add(g->nl, g->nl)), v3_add(g->l, g->v));
    vf c = vf_fma(vf_set1(-0.5f), v3_dot(rv, rv), vf_set1(1.0f));
    vf lobe = vf_mul(cos_lobe(tier, u, c, u->m), vf_set1(u->k[0]));
    if (u->form == SC_PHONG_ORIGINAL)
        lobe = vf_mul(lobe, tier_rcp(tier, cos_floor(g->nl)));
    return weights(inv_pi_v(), lobe, vf_set1(0.0f));
}

/* Blinn-Phong: (n·h)^m = (1 − |n × h_u|²/(h_u·h_u))^(m/2) times k0 = (m+8)/(8π) (normalized,
 * RTR3 §7.6) or 1 (plain); cos²θ_h from sin²θ_h stays accurate at the peak. */
static SC_INLINE brdf_weights model_blinn_phong(int tier, const brdf_uniforms *u,
                                                const brdf_geometry *g)
{
    vf sin2 = vf_mul(g->s2, tier_rcp(tier, vf_max(g->hh, vf_set1(FLT_MIN))));
    vf lobe = cos_lobe(tier, u, vf_sub(vf_set1(1.0f), sin2), 0.5f * u->m);
    return weights(inv_pi_v(), vf_mul(lobe, vf_set1(u->k[0])), vf_set1(0.0f));
}

/* tan²θ_h / α² = |n × h_u|² / (α² (n·h_u)²): the exponent of Ward and Beckmann; anisotropic
 * [(h_u·t/α_x)² + (h_u·b/α_y)²] / (n·h_u)² */
static SC_INLINE vf slope_exponent(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    vf hn2 = vf_mul(g->hn, g->hn);
    if (u->aniso)
        return vf_mul(g->sl, tier_rcp(tier, hn2));
    return vf_mul(g->s2, tier_rcp(tier, vf_mul(vf_set1(u->a2), hn2)));
}

/* Ward (docs/formulas.md §6.4): E = exp(−slope_exponent) over 4π α_x α_y √(cos θ_i cos θ_o)
 * (1992), 4π α_x α_y cos θ_i cos θ_o (duer) or π α_x α_y (h_u·n)^4/(h_u·h_u) (gmd); k0 =
 * 1/(4π α_x α_y) or 1/(π α_x α_y). */
static SC_INLINE brdf_weights model_ward(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    vf e = exp_minus(tier, slope_exponent(tier, u, g));
    vf ci = cos_floor(g->nl), co = cos_floor(g->nv), den;
    if (u->form == SC_WARD_DUER) {
        den = vf_mul(ci, co);
    } else if (u->form == SC_WARD_GMD) {
        vf hn2 = vf_mul(g->hn, g->hn);
        den = cos_floor(vf_mul(vf_mul(hn2, hn2), tier_rcp(tier, g->hh)));
    } else {
        den = tier_sqrt(tier, vf_mul(ci, co));
    }
    return weights(inv_pi_v(), vf_mul(vf_mul(e, vf_set1(u->k[0])), tier_rcp(tier, den)),
                   vf_set1(0.0f));
}

/* asin x for 0 <= x <= 1/2: x + x R(x²), musl asinf's rational R (error < 1 ULP in float) */
static SC_INLINE vf asin_half(int tier, vf x)
{
    vf z = vf_mul(x, x);
    vf p = vf_mul(z, vf_fma(z, vf_fma(z, vf_set1(-8.6563630030e-03f), vf_set1(-4.2743422091e-02f)),
                            vf_set1(1.6666586697e-01f)));
    vf q = vf_fma(z, vf_set1(-7.0662963390e-01f), vf_set1(1.0f));
    return vf_fma(x, vf_mul(p, tier_rcp(tier, q)), x);
}

/* θ in [0, π/2] from cos θ = c >= 0 and sin θ = s: π/2 − asin c for c < 1/2, else
 * 2 asin(sin(θ/2)) with sin(θ/2) = s/√(2 + 2c) (no cancellation near θ = 0) */
static SC_INLINE vf angle_of(int tier, vf c, vf s)
{
    vm low = vf_lt(c, vf_set1(0.5f));
    vf half = vf_mul(s, tier_rsqrt(tier, vf_fma(vf_set1(2.0f), c, vf_set1(2.0f))));
    vf a = asin_half(tier, vf_select(low, c, half));
    return vf_select(low, vf_sub(vf_set1(1.57079632679489662f), a), vf_add(a, a));
}

/* Oren–Nayar (docs/formulas.md §6.5): α = max(θ_i, θ_o), β = min; cos Δφ = (n × l)·(n × v) /
 * (|n × l| |n × v|), 0 where either is below 1e-12; tan((α+β)/2) = (sin α + sin β)/(cos α +
 * cos β). k0 = A (= C1), k1 = B, k2 = 0.125 σ²/(σ²+0.09), k3 = 0.17/π σ²/(σ²+0.13). */
static SC_INLINE brdf_weights model_oren_nayar(int tier, const brdf_uniforms *u,
                                               const brdf_geometry *g)
{
    v3 nxl = v3_cross(g->n, g->l), nxv = v3_cross(g->n, g->v);
    vf ll = v3_dot(nxl, nxl), vv = v3_dot(nxv, nxv);
    vm tangent = vm_and(vf_lt(vf_set1(1e-24f), ll), vf_lt(vf_set1(1e-24f), vv));
    vf inv = vf_mul(tier_rsqrt(tier, vf_max(ll, vf_set1(1e-24f))),
                    tier_rsqrt(tier, vf_max(vv, vf_set1(1e-24f))));
    vf cdp = vf_keep(tangent, vf_clamp(vf_mul(v3_dot(nxl, nxv), inv), -1.0f, 1.0f));
    vf sin_a = tier_sqrt(tier, vf_max(vf_max(ll, vv), vf_set1(FLT_MIN)));
    vf sin_b = tier_sqrt(tier, vf_max(vf_min(ll, vv), vf_set1(FLT_MIN)));
    vf cos_a = vf_min(g->nl, g->nv), cos_b = vf_max(g->nl, g->nv);
    vf tan_b = vf_mul(sin_b, tier_rcp(tier, cos_b));
    vf A = vf_set1(u->k[0]), B = vf_set1(u->k[1]);
    if (u->form != SC_OREN_FULL) /* A + B max(0, cos Δφ) sin α tan β */
        return weights(
            vf_mul(vf_fma(B, vf_mul(vf_max(cdp, vf_set1(0.0f)), vf_mul(sin_a, tan_b)), A),
                   inv_pi_v()),
            vf_set1(0.0f), vf_set1(0.0f));
    vf alpha = angle_of(tier, cos_a, sin_a), beta = angle_of(tier, cos_b, sin_b);
    vf tb = vf_mul(beta, vf_set1(2.0f / pi_f)), tb2 = vf_mul(tb, tb); /* 2β/π */
    vf sin_term = vf_select(vf_lt(cdp, vf_set1(0.0f)), vf_sub(sin_a, vf_mul(tb2, tb)), sin_a);
    vf c2 = vf_mul(B, sin_term);
    vf ab = vf_mul(vf_mul(alpha, beta), vf_set1(4.0f / (pi_f * pi_f)));
    vf c3 = vf_mul(vf_set1(u->k[2]), vf_mul(ab, ab));
    vf tan_half = vf_mul(vf_add(sin_a, sin_b), tier_rcp(tier, vf_add(cos_a, cos_b)));
    vf abs_cdp = vf_max(cdp, vf_sub(vf_set1(0.0f), cdp));
    vf f1 = vf_fma(vf_mul(cdp, c2), tan_b, A);
    f1 = vf_fma(vf_mul(vf_sub(vf_set1(1.0f), abs_cdp), c3), tan_half, f1);
    vf f2 = vf_mul(vf_set1(u->k[3]), vf_sub(vf_set1(1.0f), vf_mul(cdp, tb2)));
    return weights(vf_mul(vf_max(f1, vf_set1(0.0f)), inv_pi_v()), vf_set1(0.0f), f2);
}

/* Beckmann Smith Λ(w) = (erfc(a) − e^(−a²)/(a√π))·(−1/2), a = cos θ/(α sin θ), with
 * erfc(a) = t P(t) e^(−a²), t = 1/(1 + p a), P of degree 4 (Abramowitz and Stegun 7.1.26,
 * absolute error < 1.5e-7): Λ = e^(−a²) (1/(a√π) − t P(t)) / 2, one exponential (the
 * Numerical Recipes erfcc, relative error < 1.2e-7, took a second, of a degree-9 polynomial).
 * Λ is wanted only in G = 1/(1 + Λ_l + Λ_v) (or the product of 1 + Λ), so its absolute error
 * counts against 1 + Λ: |ΔΛ|/(1 + Λ) < 2^-23.7 for a in (0, 3] by steps of 10^-5 against
 * libm's erfc in double, and beyond a = 3 Λ is below 10^-5 and ΔΛ below e^(−a²)/10^6. */
static const float erfc_as[5] = {1.061405429f, -1.453152027f, 1.421413741f, -0.284496736f,
                                 0.254829592f};

/* c = cos θ; p = (w·t α_x)² + (w·b α_y)² when anisotropic (α sin θ = √p) */
static SC_INLINE vf beckmann_lambda(int tier, const brdf_uniforms *u, vf c, vf p)
{
    /* c > 0 in nearly every lit lane; a lane's c < 0 would take t beyond [0, 1] and its exp to
     * the scalar built-in. Floored at FLT_MIN, not 0: a lane lit by the fast tiers' n·l of the
     * loaded vectors may have c <= 0 here at grazing, and c = 0 made 1/a (rcp_newton of 0) NaN.
     * NaN stays NaN (the max keeps it). */
    c = vf_max(vf_set1(FLT_MIN), c);
    vf as;
    if (u->aniso)
        as = tier_sqrt(tier, vf_max(p, vf_set1(FLT_MIN)));
    else
        as = vf_mul(
            vf_set1(u->k[0]), /* k0 = α */
            tier_sqrt(tier, vf_max(vf_mul(vf_sub(vf_set1(1.0f), c), vf_add(vf_set1(1.0f), c)),
                                   vf_set1(FLT_MIN))));
    vf a = vf_mul(c, tier_rcp(tier, as));
    vf t = tier_rcp(tier, vf_fma(vf_set1(0.3275911f), a, vf_set1(1.0f)));
    vf erfc_scaled = vf_mul(t, poly(t, erfc_as, 5)); /* erfc(a) e^(a²) */
    vf tail = tier_rcp(tier, vf_mul(a, vf_set1(1.7724538509055160273f)));
    vf e = exp_minus(tier, vf_mul(a, a));
    return vf_mul(vf_mul(vf_set1(0.5f), e), vf_sub(tail, erfc_scaled));
}

/* D with h unit: GGX α² (h_u·h_u)² / (π (|n×h_u|² + α² (n·h_u)²)²), anisotropic
 * (h_u·h_u)² / (π α_x α_y (sl + (n·h_u)²)²); Beckmann exp(−slope_exponent) (h_u·h_u)² /
 * (π α_x α_y (n·h_u)^4) */
static SC_INLINE vf ndf(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    vf hh2 = vf_mul(g->hh, g->hh), hn2 = vf_mul(g->hn, g->hn);
    if (u->D == SC_D_GGX && u->aniso) {
        vf d = vf_add(g->sl, hn2);
        return vf_mul(vf_mul(vf_set1(inv_pi_f / u->a2), hh2), tier_rcp(tier, vf_mul(d, d)));
    }
    if (u->D == SC_D_GGX) {
        vf d = vf_fma(vf_set1(u->a2), hn2, g->s2);
        return vf_mul(vf_mul(vf_set1(u->a2 * inv_pi_f), hh2), tier_rcp(tier, vf_mul(d, d)));
    }
    vf e = exp_minus(tier, slope_exponent(tier, u, g));
    return vf_mul(vf_mul(e, hh2), tier_rcp(tier, vf_mul(vf_set1(pi_f * u->a2), vf_mul(hn2, hn2))));
}

/* V = G / (4 cos θ_i cos θ_o). GGX Smith with q = √(cos² (1 − α²) + α²) = cos θ √(1 + α²tan²θ)
 * (anisotropic √(cos² + p)):
 * separable 1/((n·l + q_l)(n·v + q_v)), height-correlated 1/(2 (q_l n·v + q_v n·l)) (Heitz
 * 2014 eq. 99); v-cavity min(1, 4 (n·h_u) min(n·l, n·v) / (h_u·h_u)) / (4 n·l n·v). */
static SC_INLINE vf visibility(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    vf four_cc = vf_mul(vf_set1(4.0f), vf_mul(cos_floor(g->nl), cos_floor(g->nv)));
    if (u->G == SC_G_VCAVITY) {
        vf k = vf_mul(vf_mul(vf_set1(4.0f), g->hn), tier_rcp(tier, g->hh));
        vf G = vf_min(vf_set1(1.0f), vf_mul(k, vf_min(g->nl, g->nv)));
        return vf_mul(G, tier_rcp(tier, four_cc));
    }
    if (u->D == SC_D_BECKMANN) {
        vf ll = beckmann_lambda(tier, u, g->nl, g->pl), lv = beckmann_lambda(tier, u, g->nv, g->pv);
        vf den;
        if (u->G == SC_G_SMITH_CORRELATED)
            den = vf_add(vf_add(vf_set1(1.0f), ll), lv);
        else
            den = vf_mul(vf_add(vf_set1(1.0f), ll), vf_add(vf_set1(1.0f), lv));
        return tier_rcp(tier, vf_mul(den, four_cc));
    }
    vf one_a2 = vf_set1(1.0f - u->a2), a2 = vf_set1(u->a2), ql, qv;
    if (u->aniso) {
        ql = tier_sqrt(tier, vf_fma(g->nl, g->nl, g->pl));
        qv = tier_sqrt(tier, vf_fma(g->nv, g->nv, g->pv));
    } else {
        ql = tier_sqrt(tier, vf_fma(vf_mul(g->nl, g->nl), one_a2, a2));
        qv = tier_sqrt(tier, vf_fma(vf_mul(g->nv, g->nv), one_a2, a2));
    }
    if (u->G == SC_G_SMITH_CORRELATED)
        return tier_rcp(tier, vf_mul(vf_set1(2.0f), vf_fma(ql, g->nv, vf_mul(qv, g->nl))));
    return tier_rcp(tier, vf_mul(vf_add(g->nl, ql), vf_add(g->nv, qv)));
}

/* Exact dielectric Fresnel (pbrt FrDielectric) at cos θ = c, η = k1; 1 on total internal
 * reflection. */
static SC_INLINE vf fresnel_exact(int tier, const brdf_uniforms *u, vf c)
{
    vf eta = vf_set1(u->k[1]);
    vf sin2_t = vf_mul(vf_mul(vf_sub(vf_set1(1.0f), c), vf_add(vf_set1(1.0f), c)),
                       vf_set1(u->k[2]));
    vf cos_t = tier_sqrt(tier, vf_max(vf_sub(vf_set1(1.0f), sin2_t), vf_set1(FLT_MIN)));
    vf ec = vf_mul(eta, c), et = vf_mul(eta, cos_t);
    vf r_par = vf_mul(vf_sub(ec, cos_t), tier_rcp(tier, vf_add(ec, cos_t)));
    vf r_perp = vf_mul(vf_sub(c, et), tier_rcp(tier, vf_add(c, et)));
    vf F = vf_mul(vf_set1(0.5f), vf_fma(r_par, r_par, vf_mul(r_perp, r_perp)));
    return vf_select(vf_le(vf_set1(1.0f), sin2_t), vf_set1(1.0f), F);
}

/* Cook–Torrance (docs/formulas.md §6.6): S = D V (× 4 for the 1982 form, k3); Schlick F =
 * F0 + (1 − F0)(1 − v·h)^5 splits as S·(c_spec F0) + S (1 − v·h)^5·(c_spec (1 − F0)); with
 * v·h = |h_u|/2 for unit l, v. */
static SC_INLINE brdf_weights model_cook_torrance(int tier, const brdf_uniforms *u,
                                                  const brdf_geometry *g)
{
    vf S = vf_mul(vf_mul(ndf(tier, u, g), visibility(tier, u, g)), vf_set1(u->k[3]));
    vf vh = vf_clamp(vf_mul(vf_set1(0.5f), tier_sqrt(tier, vf_max(g->hh, vf_set1(FLT_MIN)))), 0.0f,
                     1.0f);
    if (u->F == SC_F_SCHLICK) {
        vf c = vf_sub(vf_set1(1.0f), vh), c2 = vf_mul(c, c);
        return weights(inv_pi_v(), S, vf_mul(S, vf_mul(vf_mul(c2, c2), c)));
    }
    if (u->F == SC_F_EXACT)
        S = vf_mul(S, fresnel_exact(tier, u, vh));
    return weights(inv_pi_v(), S, vf_set1(0.0f));
}

typedef brdf_weights (*brdf_model_fn)(int tier, const brdf_uniforms *u, const brdf_geometry *g);

/* f_c = Σ_j w_j col_j[c] */
static SC_INLINE v3 brdf_colour(const brdf_uniforms *u, brdf_weights w)
{
    vf f[3];
    for (int c = 0; c < 3; c++) {
        f[c] = vf_mul(w.w[0], vf_set1(u->col[0][c]));
        f[c] = vf_fma(w.w[1], vf_set1(u->col[1][c]), f[c]);
        f[c] = vf_fma(w.w[2], vf_set1(u->col[2][c]), f[c]);
    }
    return (v3){f[0], f[1], f[2]};
}

/* f where n·l > 0 and n·v > 0, else 0; the model's terms are dropped in unlit lanes, where
 * they may be ∞ or NaN. */
static SC_INLINE void brdf_lane(int tier, brdf_model_fn model, const float *const *in,
                                float *const *out, size_t i, const brdf_uniforms *u)
{
    brdf_geometry g = brdf_geometry_of(tier, u, in, i);
    vm lit = vm_and(vf_lt(vf_set1(0.0f), g.nl), vf_lt(vf_set1(0.0f), g.nv));
    v3 f = brdf_colour(u, model(tier, u, &g));
    v3_store((v3){vf_keep(lit, f.x), vf_keep(lit, f.y), vf_keep(lit, f.z)}, out, i);
}

#define BRDF_LANE(model, tier)                                                                     \
    static SC_INLINE void brdf_##model##_##tier(const float *const *in, float *const *out,         \
                                                size_t i, const void *u)                           \
    {                                                                                              \
        brdf_lane(tier, model_##model, in, out, i, u);                                             \
    }                                                                                              \
    static void brdf_##model##_##tier##_loop(const sc_batch_args *a, const brdf_uniforms *u)       \
    {                                                                                              \
        brdf_uniforms local = *u; /* not aliased by the output stores: kept in registers */        \
        run_uniforms(a, 9, 3, brdf_##model##_##tier, &local, 1);                                   \
    }
/* One loop per model, chosen once per call (the sc_brdf's kind), the lane inlined into it, so
 * that each is straight-line. */
#define BRDF_KERNEL(name, tier)                                                                    \
    BRDF_LANE(lambert, tier)                                                                       \
    BRDF_LANE(phong, tier)                                                                         \
    BRDF_LANE(blinn_phong, tier)                                                                   \
    BRDF_LANE(ward, tier)                                                                          \
    BRDF_LANE(oren_nayar, tier)                                                                    \
    BRDF_LANE(cook_torrance, tier)                                                                 \
    KERNEL(name);                                                                                  \
    KERNEL(name)                                                                                   \
    {                                                                                              \
        static void (*const loops[])(const sc_batch_args *, const brdf_uniforms *) = {             \
            brdf_lambert_##tier##_loop,     brdf_phong_##tier##_loop,                              \
            brdf_blinn_phong_##tier##_loop, brdf_ward_##tier##_loop,                               \
            brdf_oren_nayar_##tier##_loop,  brdf_cook_torrance_##tier##_loop};                     \
        brdf_uniforms u;                                                                           \
        sc_uniforms_brdf(a->params, &u);                                                           \
        loops[u.model](a, &u);                                                                     \
    }
BRDF_KERNEL(brdf_bits16, ACCURATE)
BRDF_KERNEL(brdf_bits12, FAST12)
