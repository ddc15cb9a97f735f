/* The shading kernel (docs/formulas.md §6): L = c_amb ⊙ L_A + Σ_k f(l_k, v) ⊙ E_k cos θ_i,
 * written once against the vector helpers and included after src/simd/light_impl.h (whose
 * attenuation functions and BRDF models it evaluates) by each instruction set's file. It reads
 * the uniforms of a plan (src/simd/uniforms.h): what a scene names is all it computes — a
 * directional light costs no distance, falloff or spot factor, a point light no spot factor, a
 * lambert scene no specular lobe. */

/* The kernel's own lobes for one light (n, v, l unit): normalized or plain Blinn-Phong
 * k (n·h)^m, and GGX with Smith height-correlated masking and Schlick's Fresnel (grey F0).
 * nt is the tier of the normalizations. */
static SC_INLINE vf own_specular(int tier, int nt, sc_lobe lobe, const sc_shade_uniforms *s, v3 n,
                                 v3 v, v3 l, vf nl, vf nv)
{
    v3 h = v3_add(l, v);
    vf inv_h = tier_rsqrt(nt, vf_max(v3_dot(h, h), vf_set1(FLT_MIN))); /* l = −v: h = 0 */
    /* n·h floored at 2^-40, not at 0: its square (GGX) must not underflow (a microcode assist) */
    vf nh = vf_max(vf_mul(v3_dot(n, h), inv_h), vf_set1(0x1p-40f));
    if (lobe == SC_LOBE_BLINN) { /* RTR3 §7.6 */
        unsigned m = tier == ACCURATE && s->lobe_m > POW_INT_MAX_ACCURATE ? 0u : s->lobe_m;
        vf lobe_v = m ? pow_int(nh, m, vf_set1(s->lobe_cutoff)) : tier_pow(tier, nh, vf_set1(s->m));
        return vf_mul(vf_set1(s->lobe_k), lobe_v);
    }
    /* GGX D = α² / (π (n·h² (α² − 1) + 1)²); V = G2/(4 n·l n·v) for Smith height-correlated
     * = 1 / (2 (n·l √(n·v² (1 − α²) + α²) + n·v √(n·l² (1 − α²) + α²))) (Heitz 2014 eq. 99);
     * F = F0 + (1 − F0)(1 − v·h)^5 (Schlick 1994). */
    vf a2 = vf_set1(s->alpha * s->alpha), one_a2 = vf_set1(1.0f - s->alpha * s->alpha);
    vf d = vf_fma(vf_mul(nh, nh), vf_sub(a2, vf_set1(1.0f)), vf_set1(1.0f));
    vf D = vf_mul(vf_mul(a2, vf_set1(inv_pi_f)), tier_rcp(tier, vf_mul(d, d)));
    vf gv = vf_mul(nl, tier_sqrt(tier, vf_fma(vf_mul(nv, nv), one_a2, a2)));
    vf gl = vf_mul(nv, tier_sqrt(tier, vf_fma(vf_mul(nl, nl), one_a2, a2)));
    vf V = tier_rcp(tier, vf_mul(vf_set1(2.0f), vf_add(gv, gl)));
    vf vh = vf_max(vf_mul(v3_dot(v, h), inv_h), vf_set1(0.0f));
    vf c = vf_sub(vf_set1(1.0f), vh); /* below 2^-24, c^5 (< 2^-120) would turn subnormal */
    c = vf_select(vf_lt(c, vf_set1(0x1p-24f)), vf_set1(0.0f), c);
    vf c2 = vf_mul(c, c);
    vf F = vf_fma(vf_set1(1.0f - s->f0), vf_mul(vf_mul(c2, c2), c), vf_set1(s->f0));
    return vf_mul(vf_mul(D, V), F);
}

/* Any BRDF model of the BRDF kernel (src/simd/light_impl.h), chosen by the uniforms. */
static SC_INLINE brdf_weights any_model(int tier, const brdf_uniforms *u, const brdf_geometry *g)
{
    switch (u->model) {
    case SC_BRDF_PHONG: return model_phong(tier, u, g);
    case SC_BRDF_BLINN_PHONG: return model_blinn_phong(tier, u, g);
    case SC_BRDF_WARD: return model_ward(tier, u, g);
    case SC_BRDF_OREN_NAYAR: return model_oren_nayar(tier, u, g);
    case SC_BRDF_COOK_TORRANCE: return model_cook_torrance(tier, u, g);
    default: return model_lambert(tier, u, g);
    }
}

/* The kind and falloff of a light: the light's own (the generic loop), or constants (the
 * straight-line variants, where they fold away). */
typedef struct {
    sc_light_kind kind;
    sc_atten_kind atten;
} light_shape;

/* f_d(r) from r² for a point or spot light (light.h): inverse-square 1/max(r², 10^-4) without
 * the root; the other functions of r as the attenuation kernels compute them. */
static SC_INLINE vf falloff_of(int tier, light_shape shape, const sc_light_uniforms *lt, vf r2)
{
    if (shape.atten == SC_ATTEN_INVERSE_SQUARE)
        return tier_rcp(tier, vf_min(vf_max(r2, vf_set1(1e-4f)), vf_set1(FLT_MAX)));
    vf r = vf_sqrt(r2);
    switch (shape.atten) {
    case SC_ATTEN_CLQ: return atten_clq(tier, r, &lt->atten_u);
    case SC_ATTEN_WINDOW: return atten_window(tier, r, &lt->atten_u);
    case SC_ATTEN_PIXAR: return atten_pixar(tier, r, &lt->atten_u);
    case SC_ATTEN_WINDOWED: return atten_windowed(tier, r, &lt->atten_u);
    default: return vf_set1(1.0f);
    }
}

/* Direction to a light and its irradiance factor: 1 (directional), or f_d times the spot
 * factor; at the light itself (r = 0) l = n, as light.h has it. */
static SC_INLINE v3 light_dir(int tier, int nt, light_shape shape, const sc_light_uniforms *lt,
                              v3 n, const float *const *in, size_t i, vf *falloff)
{
    if (shape.kind == SC_LIGHT_DIRECTIONAL) {
        *falloff = vf_set1(1.0f);
        return v3_set1(lt->dir);
    }
    v3 d = v3_sub(v3_set1(lt->pos), v3_load(in, 6, i));
    vf r2 = v3_dot(d, d);
    *falloff = falloff_of(tier, shape, lt, r2);
    v3 l = v3_normalize_dd(nt, d, r2);
    vm at_light = vf_eq(r2, vf_set1(0.0f));
    l = (v3){vf_select(at_light, n.x, l.x), vf_select(at_light, n.y, l.y),
             vf_select(at_light, n.z, l.z)};
    if (shape.kind == SC_LIGHT_SPOT) {
        vf cos_s = vf_sub(vf_set1(0.0f), v3_dot(l, v3_set1(lt->dir)));
        *falloff = vf_mul(*falloff, spot_factor(tier, lt->spot, cos_s, &lt->spot_u));
    }
    return l;
}

static SC_INLINE v3 v3_select(vm m, v3 a, v3 b)
{
    return (v3){vf_select(m, a.x, b.x), vf_select(m, a.y, b.y), vf_select(m, a.z, b.z)};
}

/* acc + an area light's term (src/simd/area_impl.h, included after this file) */
static SC_INLINE v3 area_term(int tier, sc_lobe lobe, const sc_shade_uniforms *s,
                              sc_light_kind kind, const sc_light_uniforms *lt, v3 n, v3 v, vf nv,
                              const float *const *in, size_t i, v3 acc);

/* acc + f(l, v) ⊙ E cos θ_i for one light; lobe is a constant at each call. Unlit lanes drop
 * f: it may be ∞ or NaN there. */
static SC_INLINE v3 light_term(int tier, sc_lobe lobe, const sc_shade_uniforms *s,
                               light_shape shape, const sc_light_uniforms *lt, v3 n, v3 v, vf nv,
                               const float *const *in, size_t i, v3 acc)
{
    if (shape.kind >= SC_LIGHT_SPHERE)
        return area_term(tier, lobe, s, shape.kind, lt, n, v, nv, in, i, acc);
    int nt = tier == FAST8 ? FAST12 : tier;
    vf falloff, zero = vf_set1(0.0f);
    v3 l = light_dir(tier, nt, shape, lt, n, in, i, &falloff);
    vf nl = v3_dot(n, l);
    vm lit = vm_and(vf_lt(zero, nl), vf_lt(zero, nv));
    vf w = vf_select(lit, vf_mul(nl, falloff), zero); /* cos θ_i · falloff */
    v3 f = v3_set1(s->diff_pi);
    if (lobe == SC_LOBE_MODEL) {
        brdf_geometry g = brdf_geometry_make(nt, &s->brdf, n, l, v);
        f = v3_select(lit, brdf_colour(&s->brdf, any_model(tier, &s->brdf, &g)),
                      (v3){zero, zero, zero});
    } else if (lobe != SC_LOBE_NONE) {
        vf sp = vf_select(lit, own_specular(tier, nt, lobe, s, n, v, l, nl, nv), zero);
        v3 ks = v3_set1(s->spec);
        f = (v3){vf_fma(ks.x, sp, f.x), vf_fma(ks.y, sp, f.y), vf_fma(ks.z, sp, f.z)};
    }
    v3 e = v3_scale(v3_set1(lt->color), w);
    return (v3){vf_fma(f.x, e.x, acc.x), vf_fma(f.y, e.y, acc.y), vf_fma(f.z, e.z, acc.z)};
}

/* The shading equation for one vector of elements: count < 0, the generic loop over all the
 * scene's lights, each of its own kind; count 1..SC_SHADE_FIXED_MAX, straight-line code for
 * that many lights of one shape (the plan's variant): no loop, no branch on a light's kind,
 * the lights' terms independent for the out-of-order core to overlap. */
static SC_INLINE void shade_tier(int tier, sc_lobe lobe, light_shape shape, int count,
                                 const float *const *in, float *const *out, size_t i,
                                 const sc_shade_uniforms *s)
{
    int nt = tier == FAST8 ? FAST12 : tier;
    v3 n = v3_normalize(nt, v3_load(in, 0, i)), v = v3_normalize(nt, v3_load(in, 3, i));
    vf nv = v3_dot(n, v);
    v3 acc = v3_set1(s->amb_term);
    if (count < 0)
        for (int k = 0; k < s->n_lights; k++) {
            const sc_light_uniforms *lt = &s->lights[k];
            acc = light_term(tier, lobe, s, (light_shape){lt->kind, lt->atten}, lt, n, v, nv, in, i,
                             acc);
        }
    for (int k = 0; k < count; k++) /* a constant count: unrolled */
        acc = light_term(tier, lobe, s, shape, &s->lights[k], n, v, nv, in, i, acc);
    v3_store(acc, out, i);
}

/* A lane of the generic loop, and one of a fixed shape: count lights of shape index `si`
 * (src/simd/uniforms.h: 0 directional, 1 point with inverse-square falloff). */
#define SHADE_LANE(name, tier, lobe)                                                               \
    static SC_INLINE void name(const float *const *in, float *const *out, size_t i, const void *u) \
    {                                                                                              \
        shade_tier(tier, lobe, (light_shape){SC_LIGHT_DIRECTIONAL, SC_ATTEN_NONE}, -1, in, out, i, \
                   u);                                                                             \
    }
#define SHADE_FIXED_LANE(name, tier, lobe, si, count)                                              \
    static SC_INLINE void name##_##si##_##count(const float *const *in, float *const *out,         \
                                                size_t i, const void *u)                           \
    {                                                                                              \
        static const light_shape shapes[] = {{SC_LIGHT_DIRECTIONAL, SC_ATTEN_NONE},                \
                                             {SC_LIGHT_POINT, SC_ATTEN_INVERSE_SQUARE}};           \
        shade_tier(tier, lobe, shapes[si], count, in, out, i, u);                                  \
    }
#define SHADE_FIXED_LANES(name, tier, lobe)                                                        \
    SHADE_LANE(name, tier, lobe)                                                                   \
    SHADE_FIXED_LANE(name, tier, lobe, 0, 1)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 0, 2)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 0, 3)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 0, 4)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 1, 1)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 1, 2)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 1, 3)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 1, 4)
#define SHADE_VARIANTS(name)                                                                       \
    {                                                                                              \
        name, name##_0_1, name##_0_2, name##_0_3, name##_0_4, name##_1_1, name##_1_2, name##_1_3,  \
            name##_1_4                                                                             \
    }
/* One loop per lobe and variant, chosen once per call from what the plan resolved (its lobe
 * and its variant); params is a plan. */
#define SHADE_KERNEL(name, tier)                                                                   \
    SHADE_FIXED_LANES(name##_none, tier, SC_LOBE_NONE)                                             \
    SHADE_FIXED_LANES(name##_blinn, tier, SC_LOBE_BLINN)                                           \
    SHADE_FIXED_LANES(name##_ggx, tier, SC_LOBE_GGX)                                               \
    SHADE_LANE(name##_model, tier, SC_LOBE_MODEL)                                                  \
    void K(name)(const sc_batch_args *a);                                                          \
    void K(name)(const sc_batch_args *a)                                                           \
    {                                                                                              \
        static const lane_n_fn lanes[][SC_SHADE_VARIANTS] = {SHADE_VARIANTS(name##_none),          \
                                                             SHADE_VARIANTS(name##_blinn),         \
                                                             SHADE_VARIANTS(name##_ggx),           \
                                                             {name##_model}};                      \
        const sc_shade_uniforms *u = sc_batch_plan_uniforms(a->params);                            \
        run_uniforms(a, 9, 3, lanes[u->lobe][u->variant], u);                                      \
    }
SHADE_KERNEL(shade_accurate, ACCURATE)
SHADE_KERNEL(shade_bits12, FAST12)
SHADE_KERNEL(shade_bits8, FAST8)
