/* The shading kernel (docs/formulas.md §6): L = c_amb ⊙ L_A + Σ_k f(l_k, v) ⊙ E_k cos θ_i,
 * written once against the vector helpers and included after src/simd/light_impl.h (whose
 * attenuation functions and BRDF models it evaluates) by each instruction set's file. It reads
 * the uniforms of a plan (src/simd/uniforms.h): what a scene names is all it computes — a
 * directional light costs no distance, falloff or spot factor, a point light no spot factor, a
 * lambert scene no specular lobe. */

/* The uniforms of one light as vectors: its direction or position, its colour E_L (the BRDF
 * models), and E_L ⊙ c_diff/π and E_L ⊙ c_spec (the kernel's own lobes). */
typedef struct {
    v3 dir, pos, color, diff, spec;
} light_vecs;

static SC_INLINE v3 v3_mul(v3 a, v3 b)
{
    return (v3){vf_mul(a.x, b.x), vf_mul(a.y, b.y), vf_mul(a.z, b.z)};
}

/* s a + b, an FMA per component */
static SC_INLINE v3 v3_fma_scalar(vf s, v3 a, v3 b)
{
    return (v3){vf_fma(s, a.x, b.x), vf_fma(s, a.y, b.y), vf_fma(s, a.z, b.z)};
}

/* The constant factor own_specular leaves out: k of Blinn-Phong, α²/(2π) of GGX. */
static SC_INLINE float lobe_factor(sc_lobe lobe, const sc_shade_uniforms *s)
{
    return lobe == SC_LOBE_GGX ? s->alpha * s->alpha * (0.5f * inv_pi_f) : s->lobe_k;
}

/* spec carries the lobe's constant factor (lobe_factor). */
static SC_INLINE light_vecs light_vecs_of(const sc_shade_uniforms *s, const sc_light_uniforms *lt)
{
    float k = lobe_factor(s->lobe, s);
    float spec[3] = {s->spec[0] * k, s->spec[1] * k, s->spec[2] * k};
    v3 color = v3_set1(lt->color);
    return (light_vecs){v3_set1(lt->dir), v3_set1(lt->pos), color,
                        v3_mul(color, v3_set1(s->diff_pi)), v3_mul(color, v3_set1(spec))};
}

/* A plan's uniforms as vectors, broadcast once per call into the kernel's own frame, where the
 * output stores cannot alias them: the loop keeps them in registers (or reads them from the
 * stack as operands) instead of broadcasting each one for every vector. `lights`: every light's
 * (n_lights of them), for the straight-line variants and the generic loop alike; only the
 * vector from a point or spot light to the shading point is per element. */
typedef struct {
    const sc_shade_uniforms *s;
    v3 amb;
    vf m, cutoff;                    /* blinn-phong */
    vf nh_floor, nh2_floor;          /* max(2^-40, cutoff) and its square */
    vf a2, a2m1, one_a2, f0, one_f0; /* ggx: α², α² − 1, 1 − α², F0, 1 − F0 */
    light_vecs lights[SC_BATCH_MAX_LIGHTS];
} shade_vecs;

/* Not inlined into the loops: c is then memory the output stores might alias, which the loops
 * read as operands where they use it. Inlined, its vectors were the loop's own values, spilled
 * and copied between stack slots every iteration when two vectors' work took the registers. */
SC_NOINLINE static void shade_vecs_make(const sc_shade_uniforms *s, shade_vecs *c)
{
    float a2 = s->alpha * s->alpha;
    c->s = s;
    c->amb = v3_set1(s->amb_term);
    c->m = vf_set1(s->m), c->cutoff = vf_set1(s->lobe_cutoff);
    float nh_floor = s->lobe_cutoff > 0x1p-40f ? s->lobe_cutoff : 0x1p-40f;
    c->nh_floor = vf_set1(nh_floor), c->nh2_floor = vf_set1(nh_floor * nh_floor);
    c->a2 = vf_set1(a2), c->a2m1 = vf_set1(a2 - 1.0f), c->one_a2 = vf_set1(1.0f - a2);
    c->f0 = vf_set1(s->f0), c->one_f0 = vf_set1(1.0f - s->f0);
    for (int k = 0; k < s->n_lights; k++)
        c->lights[k] = light_vecs_of(s, &s->lights[k]);
}

/* n·h for h = l + v (unnormalized). At grazing, next to the mirror direction, h is short (2 n·v)
 * and n·l + n·v, two dot products each off by ~2^-24 absolutely, is off by ~2^-24/n·v
 * relatively, uncorrelated with |h|: n·h/|h| then errs by ~2^-18 at n·v = 2^-6, which the lobe
 * at its peak multiplies (Blinn-Phong by m, GGX's D, whose denominator cancels to α², by
 * ~4/α²): up to 8.8 times the accurate bound at α = 0.1. n·(l + v) is off by ~2^-24 |h|, as
 * |h| is: the accurate tier pays its two FMAs; the fast tiers' bounds hold with the sum. */
static SC_INLINE vf n_dot_h(int tier, v3 n, v3 h, vf nl, vf nv)
{
    return tier == ACCURATE ? v3_dot(n, h) : vf_add(nl, nv);
}

/* The shading point: n and v unit and n·v, and in the fast tiers also n and v as loaded (lanes
 * whose squares overflowed scaled by 2^-100) with their inverse lengths, so that n·v, and a
 * directional light's n·l and v·l, are a dot product of the loaded vectors and one product:
 * computed beside the normalization, not after it (its latency is most of a vector's). */
typedef struct {
    v3 n, v, n0, v0;
    vf nv, inv_n, inv_v;
} surface;

static SC_INLINE surface surface_at(int tier, const float *const *in, size_t i)
{
    v3 n = v3_load(in, 0, i), v = v3_load(in, 3, i);
    vf nn = v3_dot(n, n), vv = v3_dot(v, v);
    if (vm_any(vf_eq(vf_max(nn, vv), vf_set1(INFINITY)))) /* one test for the rare lanes of both */
        n = v3_unoverflow(n, &nn), v = v3_unoverflow(v, &vv);
    surface s = {.n0 = n, .v0 = v};
    if (tier == ACCURATE) {
        s.n = v3_unit_dd(tier, n, nn), s.v = v3_unit_dd(tier, v, vv);
        s.nv = v3_dot(s.n, s.v);
        return s;
    }
    s.inv_n = inv_length_dd(tier, nn), s.inv_v = inv_length_dd(tier, vv);
    s.n = v3_scale(n, s.inv_n), s.v = v3_scale(v, s.inv_v);
    s.nv = vf_mul(v3_dot(n, v), vf_mul(s.inv_n, s.inv_v));
    return s;
}

/* Schlick's 1 − v·h, v·h = √((1 + v·l)/2) = |h|/2 for unit l and v. The accurate tier takes it
 * from v·l; the fast tiers from |h|², where v·l costs five operations (a dot product, its
 * scale, the FMA and the max), and as accurate: v, of length 1 + δ after its Newton step,
 * makes |h|² err by about δ relative, where the dot product's roundings are 2^-24. 1 − √(|h|²)/2
 * is one FMA after the root: the same bits as 1 − √(|h|²/4) (a scaling by 1/4 commutes with
 * the root), an operation fewer. */
static SC_INLINE vf one_minus_v_dot_h(int tier, vf hh, vf vl)
{
    if (tier != ACCURATE)
        return vf_fma(vf_sqrt(hh), vf_set1(-0.5f), vf_set1(1.0f));
    vf vh2 = vf_max(vf_fma(vl, vf_set1(0.5f), vf_set1(0.5f)), vf_set1(0.0f));
    return vf_sub(vf_set1(1.0f), vf_sqrt(vh2));
}

/* The kernel's own lobes for one light (n, v, l unit; nl = n·l, nv = n·v, vl = v·l) without their
 * constant factor (light_vecs_of): normalized or plain Blinn-Phong (n·h)^m, and GGX with Smith
 * height-correlated masking and Schlick's Fresnel (grey F0). */
static SC_INLINE vf own_specular(int tier, sc_lobe lobe, const shade_vecs *c, v3 n, v3 v, v3 l,
                                 vf nl, vf nv, vf vl)
{
    v3 h = v3_add(l, v);
    vf hh = v3_dot(h, h);
    if (lobe == SC_LOBE_BLINN) { /* RTR3 §7.6 */
        /* n·h = n·(l + v)/|h| (n_dot_h), floored at 2^-40; l = −v: h = 0 */
        vf hh_min = vf_max(hh, vf_set1(FLT_MIN));
        const sc_shade_uniforms *s = c->s;
        unsigned m = tier == ACCURATE && s->lobe_m > POW_INT_MAX_ACCURATE ? 0u : s->lobe_m;
        /* The fast tiers raise n·h floored at the cutoff too, one max for both floors: below
         * it x^m is about 2^-100 where pow_int gives 0, which their bounds' absolute term
         * holds many times over, and no power is subnormal. An even m raises (n·h)² =
         * (n·(l + v))²/|h|² to m/2: one division (the divider is idle here; a reciprocal and
         * its Newton step took three issue slots of the multiply pipes, and measured 7% slower),
         * where n·h from 1/|h| takes a reciprocal square root and its Newton step, and the power
         * a squaring more. */
        if (m && tier != ACCURATE && m % 2 == 0) {
            vf sum = n_dot_h(tier, n, h, nl, nv);
            vf nh2 = vf_div(vf_mul(sum, sum), hh_min);
            return vf_pow_uint(vf_max(nh2, c->nh2_floor), m / 2);
        }
        vf nh = vf_mul(n_dot_h(tier, n, h, nl, nv), tier_rsqrt(tier, hh_min));
        if (m && tier != ACCURATE)
            return vf_pow_uint(vf_max(nh, c->nh_floor), m);
        nh = vf_max(nh, vf_set1(0x1p-40f));
        return m ? pow_int(nh, m, c->cutoff) : tier_pow(tier, nh, c->m);
    }
    /* GGX D = α² / (π d²), d = n·h² (α² − 1) + 1; V = G2/(4 n·l n·v) for Smith height-correlated
     * = 1 / (2 (g_v + g_l)), g_v = n·l √(n·v² (1 − α²) + α²), g_l = n·v √(n·l² (1 − α²) + α²)
     * (Heitz 2014 eq. 99): D V = α²/(2π) / (d² (g_v + g_l)). With n·h² = (n·(l + v))²/|h|²,
     * d |h|² = (n·(l + v))² (α² − 1) + |h|² needs no root of |h|², and D V = α²/(2π) |h|⁴ /
     * ((d |h|²)² (g_v + g_l)), one division. The roots are square-root instructions in every
     * tier: one operation each, rounded once, where x rsqrt(x) needs six with its Newton step, or
     * two without (the former bits8 tier's, which measured no faster: the multiplies, not the
     * divider, bound the loop). For the same reason the quotient is a division in every tier,
     * not a reciprocal estimate and its Newton step, which took three issue slots of the
     * multiply pipes (GGX 1d AVX2 bits12 5% faster).
     * F = F0 + (1 − F0) b^5, b = 1 − v·h (Schlick 1994), v·h = (1 + v·l)/|h| = √((1 + v·l)/2)
     * for unit l and v, |h|² = 2 (1 + v·l): apart from |h|, F's factor needs no h at all. b is 0
     * or at least 2^-24 in magnitude (1 − v·h, exact for v·h >= 1/2; the fast tiers' v·h may
     * exceed 1 by their δ), so b^5 is no subnormal. */
    vf sum = n_dot_h(tier, n, h, nl, nv); /* n·h |h| */
    vf dh = vf_fma(vf_mul(sum, sum), c->a2m1, hh);
    vf gv = vf_mul(nl, vf_sqrt(vf_fma(vf_mul(nv, nv), c->one_a2, c->a2)));
    vf gl = vf_mul(nv, vf_sqrt(vf_fma(vf_mul(nl, nl), c->one_a2, c->a2)));
    vf dv = vf_div(vf_mul(hh, hh), vf_mul(vf_mul(dh, dh), vf_add(gv, gl)));
    vf b = one_minus_v_dot_h(tier, hh, vl);
    vf b2 = vf_mul(b, b);
    return vf_mul(dv, vf_fma(c->one_f0, vf_mul(vf_mul(b2, b2), b), c->f0));
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

/* d/|d| and, in *falloff, the inverse-square 1/max(r², 10^-4) of r² = d·d in a fast tier: the
 * square of 1/|d|, which the unit vector takes anyway, where 1/r² would take a reciprocal and
 * its Newton step. 1/|d| errs by about 2^-22 after its Newton step (rsqrt_newton), its square
 * twice that, far inside the tier's bound. The rare lanes whose r² overflowed (the estimate's
 * Newton step gives NaN there) take a falloff of 0, below 2^-128 in truth, and d normalized
 * again (v3_normalize_dd). */
static SC_INLINE v3 unit_and_inverse_square(int tier, v3 d, vf r2, vf *falloff)
{
    vf inv = inv_length_dd(tier, r2);
    *falloff = vf_min(vf_mul(inv, inv), vf_set1(1e4f));
    vm big = vf_eq(r2, vf_set1(INFINITY));
    if (!vm_any(big))
        return v3_scale(d, inv);
    *falloff = vf_select(big, vf_set1(0.0f), *falloff);
    return v3_normalize_dd(tier, d, r2);
}

static SC_INLINE v3 v3_select(vm m, v3 a, v3 b)
{
    return (v3){vf_select(m, a.x, b.x), vf_select(m, a.y, b.y), vf_select(m, a.z, b.z)};
}

/* Direction to a light and its irradiance factor: 1 (directional), or f_d times the spot
 * factor; at the light itself (r = 0) l = n, as light.h has it. */
static SC_INLINE v3 light_dir(int tier, light_shape shape, const sc_light_uniforms *lt,
                              const light_vecs *lv, v3 n, const float *const *in, size_t i,
                              vf *falloff)
{
    if (shape.kind == SC_LIGHT_DIRECTIONAL) {
        *falloff = vf_set1(1.0f);
        return lv->dir;
    }
    v3 d = v3_sub(lv->pos, v3_load(in, 6, i));
    vf r2 = v3_dot(d, d);
    v3 l;
    if (tier != ACCURATE && shape.atten == SC_ATTEN_INVERSE_SQUARE)
        l = unit_and_inverse_square(tier, d, r2, falloff);
    else {
        *falloff = falloff_of(tier, shape, lt, r2);
        l = v3_normalize_dd(tier, d, r2);
    }
    vm at_light = vf_eq(r2, vf_set1(0.0f)); /* rare: a branch, not three blends a vector */
    if (vm_any(at_light))
        l = v3_select(at_light, n, l);
    if (shape.kind == SC_LIGHT_SPOT) {
        vf cos_s = vf_sub(vf_set1(0.0f), v3_dot(l, lv->dir));
        *falloff = vf_mul(*falloff, spot_factor(tier, lt->spot, cos_s, &lt->spot_u));
    }
    return l;
}

/* acc + an area light's term (src/simd/area_impl.h, included after this file) */
static SC_INLINE v3 area_term(int tier, sc_lobe lobe, const shade_vecs *c, sc_light_kind kind,
                              const sc_light_uniforms *lt, const light_vecs *lv, v3 n, v3 v, vf nv,
                              const float *const *in, size_t i, v3 acc);

/* n·l and v·l: a directional light's from the loaded vectors in the fast tiers (surface) */
static SC_INLINE void light_cosines(int tier, light_shape shape, const surface *sf, v3 l, vf *nl,
                                    vf *vl)
{
    if (tier != ACCURATE && shape.kind == SC_LIGHT_DIRECTIONAL) {
        *nl = vf_mul(v3_dot(sf->n0, l), sf->inv_n);
        *vl = vf_mul(v3_dot(sf->v0, l), sf->inv_v);
        return;
    }
    *nl = v3_dot(sf->n, l);
    *vl = v3_dot(sf->v, l);
}

/* acc + E cos θ_i ⊙ f(l, v) for one light; lobe is a constant at each call. Unlit lanes drop
 * f: it may be ∞ or NaN there. */
static SC_INLINE v3 light_term(int tier, sc_lobe lobe, const shade_vecs *c, light_shape shape,
                               const sc_light_uniforms *lt, const light_vecs *lv, const surface *sf,
                               const float *const *in, size_t i, v3 acc)
{
    v3 n = sf->n, v = sf->v;
    vf nv = sf->nv;
    if (shape.kind >= SC_LIGHT_SPHERE)
        return area_term(tier, lobe, c, shape.kind, lt, lv, n, v, nv, in, i, acc);
    vf falloff, zero = vf_set1(0.0f);
    v3 l = light_dir(tier, shape, lt, lv, n, in, i, &falloff);
    vf nl, vl;
    light_cosines(tier, shape, sf, l, &nl, &vl);
    /* lit: both cosines positive (where either is NaN the min is n·l) */
    vm lit = vf_lt(zero, vf_min(nv, nl));
    vf w = vf_keep(lit, vf_mul(nl, falloff)); /* cos θ_i · falloff */
    if (lobe == SC_LOBE_MODEL) {
        const sc_brdf_uniforms *bu = &c->s->brdf;
        brdf_geometry g = brdf_geometry_make(tier, bu, v3_load(in, 0, i), n, l, v);
        v3 f = v3_select(lit, brdf_colour(bu, any_model(tier, bu, &g)), (v3){zero, zero, zero});
        v3 e = v3_scale(lv->color, w);
        return (v3){vf_fma(f.x, e.x, acc.x), vf_fma(f.y, e.y, acc.y), vf_fma(f.z, e.z, acc.z)};
    }
    if (lobe == SC_LOBE_NONE) /* w (E ⊙ c_diff/π) */
        return v3_fma_scalar(w, lv->diff, acc);
    vf fs = vf_keep(lit, own_specular(tier, lobe, c, n, v, l, nl, nv, vl));
    /* w (E ⊙ c_diff/π + f_s E ⊙ c_spec): six FMAs, a product fewer than the form below, for a
     * lobe at most about 1 */
    if (lobe == SC_LOBE_BLINN)
        return v3_fma_scalar(w, v3_fma_scalar(fs, lv->spec, lv->diff), acc);
    /* w E ⊙ c_diff/π + (w f_s) E ⊙ c_spec: GGX's V grows as 1/(n·l + n·v) at grazing, where
     * f_s E ⊙ c_spec alone may exceed FLT_MAX, and w f_s = n·l f_s, n·l/(g_v + g_l) <= 1/α,
     * does not */
    return v3_fma_scalar(vf_mul(w, fs), lv->spec, v3_fma_scalar(w, lv->diff, acc));
}

/* The shading equation for one vector of elements: count < 0, the generic loop over all the
 * scene's lights, each of its own kind; count 1..SC_SHADE_FIXED_MAX, straight-line code for
 * that many lights of one shape (the plan's variant): no loop, no branch on a light's kind,
 * the lights' terms independent for the out-of-order core to overlap. */
static SC_INLINE void shade_tier(int tier, sc_lobe lobe, light_shape shape, int count,
                                 const float *const *in, float *const *out, size_t i,
                                 const shade_vecs *c)
{
    const sc_shade_uniforms *s = c->s;
    surface sf = surface_at(tier, in, i);
    v3 acc = c->amb;
    if (count < 0)
        for (int k = 0; k < s->n_lights; k++) {
            const sc_light_uniforms *lt = &s->lights[k];
            acc = light_term(tier, lobe, c, (light_shape){lt->kind, lt->atten}, lt, &c->lights[k],
                             &sf, in, i, acc);
        }
    for (int k = 0; k < count; k++) /* a constant count: unrolled */
        acc = light_term(tier, lobe, c, shape, &s->lights[k], &c->lights[k], &sf, in, i, acc);
    v3_store(acc, out, i);
}

/* shade_tier's straight-line variants on two vectors, i and i + VW, the second's statements
 * written after the first's, step by step: independent work for the out-of-order core beside
 * each vector's chain of about 90 cycles, which one vector alone leaves it short of (GGX and
 * Blinn-Phong ran 7-15% faster). Separate variables, not arrays of two: gcc kept the arrays
 * in memory. */
static SC_INLINE void shade_pair(int tier, sc_lobe lobe, light_shape shape, int count,
                                 const float *const *in, float *const *out, size_t i,
                                 const shade_vecs *c)
{
    const sc_shade_uniforms *s = c->s;
    size_t j = i + VW;
    surface sa = surface_at(tier, in, i), sb = surface_at(tier, in, j);
    v3 acc_a = c->amb, acc_b = c->amb;
    for (int k = 0; k < count; k++) { /* a constant count: unrolled */
        const sc_light_uniforms *lt = &s->lights[k];
        acc_a = light_term(tier, lobe, c, shape, lt, &c->lights[k], &sa, in, i, acc_a);
        acc_b = light_term(tier, lobe, c, shape, lt, &c->lights[k], &sb, in, j, acc_b);
    }
    v3_store(acc_a, out, i);
    v3_store(acc_b, out, j);
}

/* The loop of one lane, the lane inlined into it; width: the vectors it takes (shade_pair 2). */
static SC_INLINE void shade_run(const sc_batch_args *a, lane_n_fn lane, int width)
{
    const sc_shade_uniforms *s = sc_batch_plan_uniforms(a->params);
    shade_vecs c;
    shade_vecs_make(s, &c);
    run_uniforms(a, 9, 3, lane, &c, width);
}

/* The fixed shapes of src/simd/uniforms.h's variants, by index. */
static const light_shape fixed_shapes[SC_SHAPES] = {
    [SC_SHAPE_DIRECTIONAL] = {SC_LIGHT_DIRECTIONAL, SC_ATTEN_NONE},
    [SC_SHAPE_POINT] = {SC_LIGHT_POINT, SC_ATTEN_INVERSE_SQUARE},
    [SC_SHAPE_SPOT] = {SC_LIGHT_SPOT, SC_ATTEN_INVERSE_SQUARE}};

/* Vectors a step of the fixed shape si: spot lights one (shade_tier), the others two
 * (shade_pair). Spot pairs ran 1-3% faster than one vector a step (bench shade, blinn-phong 1s)
 * and took the shading kernels 23% longer to compile: the spot factor's cone kinds and powers
 * are much code to inline twice per light. */
static SC_INLINE int fixed_width(int si) { return si == SC_SHAPE_SPOT ? 1 : 2; }

static SC_INLINE void shade_fixed(int tier, sc_lobe lobe, int si, int count, const float *const *in,
                                  float *const *out, size_t i, const shade_vecs *c)
{
    if (fixed_width(si) == 1)
        shade_tier(tier, lobe, fixed_shapes[si], count, in, out, i, c);
    else
        shade_pair(tier, lobe, fixed_shapes[si], count, in, out, i, c);
}

/* A loop of the generic lane, and one of a fixed shape: count lights of shape index `si`, a
 * number (the functions' names are pasted from it): 0, 1, 2 are SC_SHAPE_DIRECTIONAL, _POINT
 * and _SPOT. */
#define SHADE_LANE(name, tier, lobe)                                                               \
    static SC_INLINE void name##_lane(const float *const *in, float *const *out, size_t i,         \
                                      const void *c)                                               \
    {                                                                                              \
        shade_tier(tier, lobe, (light_shape){SC_LIGHT_DIRECTIONAL, SC_ATTEN_NONE}, -1, in, out, i, \
                   c);                                                                             \
    }                                                                                              \
    static void name(const sc_batch_args *a) { shade_run(a, name##_lane, 1); }
#define SHADE_FIXED_LANE(name, tier, lobe, si, count)                                              \
    static SC_INLINE void name##_##si##_##count##_lane(const float *const *in, float *const *out,  \
                                                       size_t i, const void *c)                    \
    {                                                                                              \
        shade_fixed(tier, lobe, si, count, in, out, i, c);                                         \
    }                                                                                              \
    static void name##_##si##_##count(const sc_batch_args *a)                                      \
    {                                                                                              \
        shade_run(a, name##_##si##_##count##_lane, fixed_width(si));                               \
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
    SHADE_FIXED_LANE(name, tier, lobe, 1, 4)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 2, 1)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 2, 2)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 2, 3)                                                       \
    SHADE_FIXED_LANE(name, tier, lobe, 2, 4)
#define SHADE_VARIANTS(name)                                                                       \
    {                                                                                              \
        name, name##_0_1, name##_0_2, name##_0_3, name##_0_4, name##_1_1, name##_1_2, name##_1_3,  \
            name##_1_4, name##_2_1, name##_2_2, name##_2_3, name##_2_4                             \
    }
/* One loop per lobe and variant, chosen once per call from what the plan resolved (its lobe
 * and its variant); params is a plan. */
#define SHADE_KERNEL(name, tier)                                                                   \
    SHADE_FIXED_LANES(name##_none, tier, SC_LOBE_NONE)                                             \
    SHADE_FIXED_LANES(name##_blinn, tier, SC_LOBE_BLINN)                                           \
    SHADE_FIXED_LANES(name##_ggx, tier, SC_LOBE_GGX)                                               \
    SHADE_LANE(name##_model, tier, SC_LOBE_MODEL)                                                  \
    KERNEL(name);                                                                                  \
    KERNEL(name)                                                                                   \
    {                                                                                              \
        static const sc_batch_fn loops[][SC_SHADE_VARIANTS] = {SHADE_VARIANTS(name##_none),        \
                                                               SHADE_VARIANTS(name##_blinn),       \
                                                               SHADE_VARIANTS(name##_ggx),         \
                                                               {name##_model}};                    \
        const sc_shade_uniforms *u = sc_batch_plan_uniforms(a->params);                            \
        loops[u->lobe][u->variant](a);                                                             \
    }
/* one tier per file (src/simd/kernel_group.h) */
#if SC_KERNEL_GROUP == SC_GROUP_SHADE_ACCURATE
SHADE_KERNEL(shade_accurate, ACCURATE)
#elif SC_KERNEL_GROUP == SC_GROUP_SHADE_BITS12
SHADE_KERNEL(shade_bits12, FAST12)
#endif
