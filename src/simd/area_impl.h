/* Area lights in the shading kernel (docs/formulas.md §5.3), written once against the vector
 * helpers and included after src/simd/scene_impl.h by each instruction set's file: the float
 * lanes of the double approximations of src/light/ — the representative point of Karis 2013
 * for spheres and tubes (area.c), linearly transformed cosines for disks and rects (ltc.c,
 * area_ltc.c) — with the same formulas, branches turned into masks, and the area_* kernels.
 *
 * The approximations' own operations have one tier: sqrt and division rounded once, atan and
 * acos to 2^-22 (trig_impl.h's bits22 polynomials). A fast one (rsqrt/rcp estimates with a
 * Newton step, the 2^-12 polynomials) was measured no faster (AVX2: sphere 20.4 against 18.5
 * ns/element, rect 65.2 against 62.0, in one run) and is not offered; the BRDF lobe at the
 * representative point is the plan's tier's (own_specular).
 *
 * Clipping to the horizon without branches: the polygons are convex (a rect, the disk's
 * 64-gon, and their images under M⁻¹), so each edge a→b clipped to z >= 0 is a segment or
 * nothing, and the clipped polygon is these segments plus one edge along the horizon from
 * where the boundary leaves z >= 0 to where it comes back. Each edge is clipped with masks and
 * blends (its end points replaced by the crossing), the exit and entry points kept by blends;
 * Lambert's edge sum is additive over edges, so no clipped polygon is ever assembled. The
 * second clip (of the LTC's carried polygon to its own horizon) takes the segments of the
 * first as they come. */

/* atan2(y, x) for y >= 0, in [0, π] (0 at the origin). */
static SC_INLINE vf area_angle(vf y, vf x)
{
    vf ax = vf_abs(x);
    return upper_half_angle(ax, y, x, vf_max(vf_max(ax, y), vf_set1(FLT_MIN)));
}

static SC_INLINE vf area_acos(vf x) { return acos_fast(x, acos_c9, 9); }

/* √x, 0 for x <= 0 */
static SC_INLINE vf area_length(vf x) { return vf_sqrt(vf_max(x, vf_set1(0.0f))); }

/* x / y for y > 0 (lanes where y = 0 give a finite number, to be selected away) */
static SC_INLINE vf area_ratio(vf x, vf y) { return vf_div(x, vf_max(y, vf_set1(FLT_MIN))); }

/* ---- representative point (light/area.c) ---- */

/* ∫ cos̄θ dω / 1 over a sphere of radius R at distance d > R seen at cos θ = ct from the
 * normal (Snyder 1996): π sin²σ cos θ wholly above the horizon, else the clipped form, with
 * x = √(1/sin²σ − 1) as √((d − R)(d + R))/R (no cancellation next to the sphere). */
static SC_INLINE vf sphere_irradiance(vf ct, vf d, vf R)
{
    vf zero = vf_set1(0.0f);
    vf sr = area_ratio(R, d), s2 = vf_mul(sr, sr);
    vf above = vf_keep(vf_lt(zero, ct), vf_mul(vf_mul(vf_set1(pi_f), s2), ct));
    vm clipped = vf_lt(vf_mul(ct, ct), s2);
    if (!vm_any(clipped))
        return above;
    vf st = area_length(sin2_of(ct));
    vf x = area_ratio(area_length(vf_mul(vf_sub(d, R), vf_add(d, R))), R);
    vf y = vf_clamp(vf_sub(zero, area_ratio(vf_mul(x, ct), st)), -1.0f, 1.0f);
    vf s = vf_mul(st, area_length(sin2_of(y)));
    vf e = vf_fma(vf_sub(vf_mul(ct, area_acos(y)), vf_mul(x, s)), s2, area_angle(s, x));
    return vf_select(clipped, vf_max(e, zero), above);
}

/* The lanes whose point is inside or on the sphere's ball or the tube's capsule (within R of
 * the segment p0–p1), where the whole sky above the horizon is the light (light/area.c's
 * inside_emitter). dc: the distance to the centre. */
static SC_INLINE vm inside_emitter(sc_light_kind kind, const sc_area_uniforms *a, vf dc, v3 p)
{
    vf R = vf_set1(a->radius);
    if (kind != SC_LIGHT_TUBE)
        return vf_le(dc, R);
    v3 l0 = v3_sub(v3_set1(a->p0), p), ld = v3_set1(a->axis);
    vf t = area_ratio(vf_sub(vf_set1(0.0f), v3_dot(l0, ld)), v3_dot(ld, ld));
    v3 q = v3_add(l0, v3_scale(ld, vf_clamp(t, 0.0f, 1.0f)));
    return vf_le(area_length(v3_dot(q, q)), R);
}

/* The irradiance of a sphere light, or a tube's (its cylinder as a line of width 2R, Karis
 * 2013, plus its ends as one ball at its centre), on a plane of unit normal w at the point,
 * over L_e; π in the lanes `inside` the emitter (inside_emitter: the line's form diverges on
 * the axis). c: centre − point, dc its length. */
static SC_INLINE vf area_irradiance(sc_light_kind kind, const sc_area_uniforms *a, v3 w, v3 c,
                                    vf dc, v3 p, vm inside)
{
    vf R = vf_set1(a->radius), zero = vf_set1(0.0f);
    vf e = sphere_irradiance(area_ratio(v3_dot(w, c), dc), dc, R);
    if (kind == SC_LIGHT_TUBE) { /* (w·L0/|L0| + w·L1/|L1|) / (|L0||L1| + L0·L1) */
        v3 l0 = v3_sub(v3_set1(a->p0), p), l1 = v3_add(l0, v3_set1(a->axis));
        vf a0 = area_length(v3_dot(l0, l0)), a1 = area_length(v3_dot(l1, l1));
        vf ab = vf_mul(a0, a1), dd = v3_dot(l0, l1);
        /* ab + L0·L1 = |L0 × L1|² / (ab − L0·L1) where L0·L1 < 0 (no cancellation) */
        vf den = vf_select(vf_lt(dd, zero), area_ratio(cross2(l0, l1), vf_sub(ab, dd)),
                           vf_add(ab, dd));
        vf num = vf_add(area_ratio(v3_dot(w, l0), a0), area_ratio(v3_dot(w, l1), a1));
        vf line = vf_keep(vf_lt(zero, den), area_ratio(num, den));
        e = vf_add(e, vf_max(zero, vf_mul(vf_set1(a->line), line)));
    }
    return vf_select(inside, vf_set1(pi_f), e);
}

/* The point of the tube's axis (the sphere's centre) closest to the ray along r, relative
 * to the point: t = −(L0·Ld⊥)/|r × Ld|², Ld⊥ = Ld − (r·Ld) r, clamped to [0, 1]; ½ for a ray
 * along the axis. L0·Ld⊥ = (L0 × r)·(Ld × r) for unit r (Ld⊥ = r × (Ld × r)): a ray nearly
 * along the axis made Ld − (r·Ld) r cancel, and t, d and the energy normalisation err by 2^-12
 * relative (GGX α 0.3, 4e-3 of the tube's specular part, r 0.8° off a 4-long axis). */
static SC_INLINE v3 closest_centre(sc_light_kind kind, const sc_area_uniforms *a, v3 r, v3 c, v3 p)
{
    if (kind != SC_LIGHT_TUBE)
        return c;
    v3 l0 = v3_sub(v3_set1(a->p0), p), ld = v3_set1(a->axis);
    v3 w = v3_cross(ld, r);
    vf den = v3_dot(w, w);
    vf t = area_ratio(vf_sub(vf_set1(0.0f), v3_dot(v3_cross(l0, r), w)), den);
    t = vf_select(vf_lt(vf_set1(0.0f), den), vf_clamp(t, 0.0f, 1.0f), vf_set1(0.5f));
    return v3_add(l0, v3_scale(ld, t));
}

/* Karis's energy normalisation of GGX: α/α' across (R) times α/α' along the emitter,
 * α' = min(1, α + w/(2d)); α² at d = 0. 1 for the other lobes. */
static SC_INLINE vf energy_normalisation(sc_lobe lobe, const shade_vecs *sv,
                                         const sc_area_uniforms *a, vf d)
{
    if (lobe != SC_LOBE_GGX)
        return vf_set1(1.0f);
    vf alpha = vf_set1(sv->s->alpha), inv_2d = area_ratio(vf_set1(0.5f), d);
    vf across = vf_min(vf_set1(1.0f), vf_fma(vf_set1(a->radius), inv_2d, alpha));
    vf along = vf_min(vf_set1(1.0f), vf_fma(vf_set1(a->half_along), inv_2d, alpha));
    vf w = area_ratio(sv->a2, vf_mul(across, along));
    return vf_select(vf_lt(vf_set1(0.0f), d), w, sv->a2);
}

/* L_e ⊙ (c_diff/π E(n) + c_spec f_s(l_s) N E(l_s) cos̄θ_s), 0 where n·v <= 0. The colours
 * L_e ⊙ c_diff/π and L_e ⊙ c_spec ⊙ the lobe's constant factor are lv's, made once per call
 * (light_vecs_of), not per vector. */
static SC_INLINE v3 representative_term(int tier, sc_lobe lobe, const shade_vecs *sv,
                                        sc_light_kind kind, const sc_light_uniforms *lt,
                                        const light_vecs *lv, v3 n, v3 v, vf nv, v3 p)
{
    const sc_area_uniforms *a = &lt->area;
    vf zero = vf_set1(0.0f);
    v3 c = v3_sub(v3_set1(a->centre), p);
    vf dc = area_length(v3_dot(c, c));
    vm inside = inside_emitter(kind, a, dc, p);
    vf e_diffuse = area_irradiance(kind, a, n, c, dc, p, inside);
    v3 out = v3_scale(lv->diff, e_diffuse);
    if (lobe != SC_LOBE_NONE) {
        v3 r = v3_sub(v3_scale(n, vf_mul(vf_set1(2.0f), nv)), v);
        v3 L = closest_centre(kind, a, r, c, p);
        vf d = area_length(v3_dot(L, L));
        v3 C = v3_sub(v3_scale(r, v3_dot(L, r)), L);
        vf cl = area_length(v3_dot(C, C));
        vf toward = vf_min(vf_set1(1.0f), area_ratio(vf_set1(a->radius), cl));
        v3 P = v3_add(L, v3_scale(C, vf_keep(vf_lt(zero, cl), toward)));
        vf pp = v3_dot(P, P);
        vm at_r = vm_or(inside, vf_eq(pp, zero)); /* inside: l_s = r */
        v3 ls = v3_select(at_r, r, v3_normalize_dd(tier, P, pp));
        vf cos_s = v3_dot(n, ls);
        vm lit = vf_lt(zero, cos_s);
        vf sp = vf_keep(lit, own_specular(tier, lobe, sv, n, v, ls, cos_s, nv, v3_dot(v, ls)));
        vf w = vf_mul(vf_mul(sp, energy_normalisation(lobe, sv, a, d)),
                      vf_mul(area_irradiance(kind, a, ls, c, dc, p, inside), vf_max(cos_s, zero)));
        out = v3_fma_scalar(w, lv->spec, out);
    }
    return v3_select(vf_lt(zero, nv), out, (v3){zero, zero, zero});
}

/* ---- LTC (light/ltc.c) ---- */

/* θ ẑ·ĉ of edge a→b, c = a × b, θ the angle between a and b (atan2(|c|, a·b): short and
 * near-parallel edges keep their precision); 0 for parallel ends. a and b need not be unit. */
static SC_INLINE vf edge_term(v3 a, v3 b)
{
    v3 c = v3_cross(a, b);
    vf s = area_length(v3_dot(c, c));
    vf theta = area_angle(s, v3_dot(a, b));
    return vf_keep(vf_lt(vf_set1(0.0f), s), vf_mul(c.z, area_ratio(theta, s)));
}

/* Lambert's edge sum of a convex polygon clipped to z >= 0, accumulated edge by edge, with
 * where its boundary leaves (exit) and re-enters (entry) the half-space. */
typedef struct {
    vf sum;
    v3 exit, entry;
    vm crossed;
} clip_sum;

/* Adds edge a→b (where `valid`) clipped to z >= 0 to cs; *a2, *b2 its clipped ends. Returns
 * where the clipped edge is a segment. Sutherland–Hodgman's rules: an end with z >= 0 is
 * kept, a strict sign change crosses at t = a_z/(a_z − b_z). `on_y_axis`: the edge's z is a
 * multiple of its x, so that it crosses z = 0 where x = 0 too, which is then set exactly (the
 * interpolated x, rounded, would turn the crossing's direction when it lies near the origin). */
static SC_INLINE vm clip_edge(v3 a, v3 b, vm valid, vm on_y_axis, clip_sum *cs, v3 *a2, v3 *b2)
{
    vf zero = vf_set1(0.0f);
    vm a_out = vf_lt(a.z, zero), b_out = vf_lt(b.z, zero);
    vf den = vf_sub(a.z, b.z);
    vf t = vf_div(a.z, vf_select(vf_eq(den, zero), vf_set1(1.0f), den));
    vf cross_x = vf_select(on_y_axis, zero, vf_fma(t, vf_sub(b.x, a.x), a.x));
    v3 x = {cross_x, vf_fma(t, vf_sub(b.y, a.y), a.y), zero};
    *a2 = v3_select(a_out, x, a);
    *b2 = v3_select(b_out, x, b);
    vm leaves = vm_and(valid, vm_and(vf_le(zero, a.z), b_out));
    vm enters = vm_and(valid, vm_and(a_out, vf_le(zero, b.z)));
    cs->exit = v3_select(leaves, x, cs->exit);
    cs->entry = v3_select(enters, x, cs->entry);
    cs->crossed = vm_or(cs->crossed, leaves);
    return vm_and(valid, vm_or(vf_le(zero, a.z), vf_le(zero, b.z)));
}

/* M⁻¹ w for M⁻¹ = [[m00, 0, m02], [0, m11, 0], [m20, 0, 1]] */
static SC_INLINE v3 ltc_carry(const vf m[SC_LTC_ROW], v3 w)
{
    return (v3){vf_fma(m[0], w.x, vf_mul(m[1], w.z)), vf_mul(m[2], w.y), vf_fma(m[3], w.x, w.z)};
}

/* The LTC table at cos θ_v (clamped to [0, 1]), per lane: the plan's rows (already at the
 * scene's α) interpolated at y = √(1 − cos θ_v)·31 as light/ltc.c's bilinear() does. A lookup
 * per lane, in plain C for every instruction set: twelve AVX2 gathers instead measured the
 * same (area_rect, AVX2, n 4096, min of 9 repeats in four alternating runs: 53.2 51.0 55.6
 * 61.6 ns/element gathered, 54.4 56.7 56.3 51.0 per lane): the eleven edge terms of the two
 * clipped sums dominate. */
static SC_INLINE void ltc_lookup(const sc_shade_uniforms *s, vf cos_v, vf m[SC_LTC_ROW])
{
    vf y = vf_mul(vf_sqrt(vf_sub(vf_set1(1.0f), vf_clamp(cos_v, 0.0f, 1.0f))),
                  vf_set1((float)(SC_LTC_ROWS - 1)));
    float ys[VW], out[SC_LTC_ROW][VW];
    vf_storeu(ys, y);
    for (int l = 0; l < VW; l++) {
        int j = (int)ys[l] > SC_LTC_ROWS - 2 ? SC_LTC_ROWS - 2 : (int)ys[l];
        float fy = ys[l] - (float)j;
        const float *lo = s->ltc_rows[j], *hi = s->ltc_rows[j + 1];
        for (int k = 0; k < SC_LTC_ROW; k++)
            out[k][l] = lo[k] + fy * (hi[k] - lo[k]);
    }
    for (int k = 0; k < SC_LTC_ROW; k++)
        m[k] = vf_loadu(out[k]);
}

/* The share of the LTC above the horizon (ltc.c's mass_above_horizon): ½(1 ± m00/|(m00,
 * m20)|), the sign of M⁻¹'s xz determinant. */
static SC_INLINE vf ltc_mass(const vf m[SC_LTC_ROW])
{
    vf det = vf_sub(m[0], vf_mul(m[1], m[3]));
    vf len = area_length(vf_fma(m[0], m[0], vf_mul(m[3], m[3])));
    vf c = area_ratio(m[0], len);
    c = vf_select(vf_lt(det, vf_set1(0.0f)), vf_sub(vf_set1(0.0f), c), c);
    vm nonzero = vm_or(vf_lt(det, vf_set1(0.0f)), vf_lt(vf_set1(0.0f), det));
    return vf_keep(vm_and(vf_lt(vf_set1(0.0f), len), nonzero),
                   vf_mul(vf_set1(0.5f), vf_add(vf_set1(1.0f), c)));
}

/* The view frame (ltc.c's view_frame): z = n, x = v's direction in the tangent plane (the
 * frame's tangent where v is along n: its axis chosen on the unit n, which may differ from
 * brdf.c's at the seam; no matter, as with v along n the lobes are symmetric about n),
 * y = z × x. */
static SC_INLINE void view_frame(int tier, v3 n, v3 v, vf nv, v3 axes[3])
{
    v3 x = v3_sub(v, v3_scale(n, nv));
    vf xx = v3_dot(x, x);
    axes[0] = v3_select(vf_lt(xx, vf_set1(0x1p-40f)), tangent_of(tier, n, tangent_axis_x(n)),
                        v3_normalize_dd(tier, x, xx));
    axes[1] = v3_cross(n, axes[0]);
    axes[2] = n;
}

static SC_INLINE v3 to_frame(const v3 axes[3], v3 w)
{
    return (v3){v3_dot(w, axes[0]), v3_dot(w, axes[1]), v3_dot(w, axes[2])};
}

/* Both edge sums of a convex polygon (view frame): the cosine's over it clipped to the
 * horizon (into *cosine), and the cosine's over its image under M⁻¹ clipped to the carried
 * horizon (into *lobe). The polygon's vertex k is q + ring[0][k] e1 + ring[1][k] e2. */
static SC_INLINE void ltc_sums(const float *ring, int sides, v3 q, v3 e1, v3 e2,
                               const vf m[SC_LTC_ROW], vf *cosine, vf *lobe)
{
    vf zero = vf_set1(0.0f);
    v3 origin = {zero, zero, zero}, a2, b2, c2, d2;
    clip_sum first = {zero, origin, origin, vf_lt(vf_set1(1.0f), zero)}, second = first;
    vm all = vf_le(zero, vf_set1(1.0f)), none = vf_lt(vf_set1(1.0f), zero);
    v3 v0 = v3_add(q, v3_add(v3_scale(e1, vf_set1(ring[0])), v3_scale(e2, vf_set1(ring[sides])))),
       a = v0;
    for (int k = 1; k <= sides; k++) {
        v3 b = k == sides ? v0
                          : v3_add(q, v3_add(v3_scale(e1, vf_set1(ring[k])),
                                             v3_scale(e2, vf_set1(ring[sides + k]))));
        vm seg = clip_edge(a, b, all, none, &first, &a2, &b2);
        first.sum = vf_add(first.sum, vf_keep(seg, edge_term(a2, b2)));
        vm seg2 = clip_edge(ltc_carry(m, a2), ltc_carry(m, b2), seg, none, &second, &c2, &d2);
        second.sum = vf_add(second.sum, vf_keep(seg2, edge_term(c2, d2)));
        a = b;
    }
    /* the horizon edge of the first clip, through the second: on it z = 0, so its image under
     * M⁻¹ has x = m00 x and z = m20 x, which vanish together */
    first.sum = vf_add(first.sum, vf_keep(first.crossed, edge_term(first.exit, first.entry)));
    vm seg2 = clip_edge(ltc_carry(m, first.exit), ltc_carry(m, first.entry), first.crossed, all,
                        &second, &c2, &d2);
    second.sum = vf_add(second.sum, vf_keep(seg2, edge_term(c2, d2)));
    second.sum = vf_add(second.sum, vf_keep(second.crossed, edge_term(second.exit, second.entry)));
    *cosine = vf_min(vf_mul(vf_set1(0.5f), vf_abs(first.sum)), vf_set1(pi_f));
    *lobe = vf_min(vf_mul(vf_set1(0.5f / pi_f), vf_abs(second.sum)), vf_set1(1.0f));
}

/* L_e ⊙ (c_diff/π ∫cos̄ + (c_spec F0 A + c_spec (1 − F0) B) · lobe share / mass) over a rect or
 * disk (area_ltc.c): 0 behind a one-sided emitter and in its plane; the specular part only
 * where n·v > 0. */
static SC_INLINE v3 ltc_term(int tier, const sc_shade_uniforms *s, sc_light_kind kind,
                             const sc_light_uniforms *lt, v3 n, v3 v, vf nv, v3 p)
{
    const sc_area_uniforms *a = &lt->area;
    vf zero = vf_set1(0.0f);
    v3 q = v3_sub(v3_set1(a->centre), p);
    vf h = vf_sub(zero, v3_dot(q, v3_set1(a->normal))); /* (p − centre)·normal */
    vm seen = vf_lt(zero, h);
    if (a->two_sided)
        seen = vm_or(seen, vf_lt(h, zero));
    if (!vm_any(seen))
        return (v3){zero, zero, zero};
    v3 axes[3];
    view_frame(tier, n, v, nv, axes);
    vf m[SC_LTC_ROW], cosine, lobe;
    ltc_lookup(s, nv, m);
    if (kind == SC_LIGHT_RECT)
        ltc_sums(&sc_area_ring_rect[0][0], 4, to_frame(axes, q), to_frame(axes, v3_set1(a->e1)),
                 to_frame(axes, v3_set1(a->e2)), m, &cosine, &lobe);
    else
        ltc_sums(&sc_area_ring_disk[0][0], 64, to_frame(axes, q), to_frame(axes, v3_set1(a->e1)),
                 to_frame(axes, v3_set1(a->e2)), m, &cosine, &lobe);
    vf mass = ltc_mass(m);
    vm spec_on = vm_and(vf_lt(zero, nv), vf_lt(vf_set1(1e-6f), mass));
    vf share = vf_keep(spec_on, area_ratio(lobe, mass));
    v3 sa = v3_set1(s->ltc_sa), sb = v3_set1(s->ltc_sb), e = v3_set1(lt->color),
       kd = v3_set1(s->diff_pi);
    v3 spec = {vf_fma(sa.x, m[4], vf_mul(sb.x, m[5])), vf_fma(sa.y, m[4], vf_mul(sb.y, m[5])),
               vf_fma(sa.z, m[4], vf_mul(sb.z, m[5]))};
    v3 out = {vf_fma(kd.x, cosine, vf_mul(spec.x, share)),
              vf_fma(kd.y, cosine, vf_mul(spec.y, share)),
              vf_fma(kd.z, cosine, vf_mul(spec.z, share))};
    return (v3){vf_keep(seen, vf_mul(e.x, out.x)), vf_keep(seen, vf_mul(e.y, out.y)),
                vf_keep(seen, vf_mul(e.z, out.z))};
}

static SC_INLINE v3 area_term(int tier, sc_lobe lobe, const shade_vecs *c, sc_light_kind kind,
                              const sc_light_uniforms *lt, const light_vecs *lv, v3 n, v3 v, vf nv,
                              const float *const *in, size_t i, v3 acc)
{
    v3 p = v3_load(in, 6, i);
    v3 l = kind == SC_LIGHT_SPHERE || kind == SC_LIGHT_TUBE
               ? representative_term(tier, lobe, c, kind, lt, lv, n, v, nv, p)
               : ltc_term(tier, c->s, kind, lt, n, v, nv, p);
    return v3_add(acc, l);
}

/* ---- the area_* kernels: one area light (and the ambient term) of a scene (params: an
 * sc_scene) whose uniforms each call computes; NaN outputs for a scene the kernels do not
 * cover, or of another light ---- */

#define AREA_LANE(name, tier, lobe, kind)                                                          \
    static SC_INLINE void name(const float *const *in, float *const *out, size_t i, const void *u) \
    {                                                                                              \
        shade_tier(tier, lobe, (light_shape){kind, SC_ATTEN_NONE}, 1, in, out, i, u);              \
    }

static SC_INLINE void area_kernel(const sc_batch_args *a, sc_light_kind kind,
                                  const lane_n_fn lanes[4])
{
    sc_shade_uniforms u;
    char why[8];
    if (sc_uniforms_shade(a->params, &u, why, sizeof why) != 0 || u.n_lights != 1 ||
        u.lights[0].kind != kind) {
        for (int j = 0; j < 3; j++)
            for (size_t i = 0; i < a->n; i++)
                a->out[j][i] = NAN;
        return;
    }
    shade_vecs c;
    shade_vecs_make(&u, &c);
    run_uniforms(a, 9, 3, lanes[u.lobe], &c, 1);
}

/* Representative point: a lane per lobe of the kernel (lambert, blinn-phong, GGX). */
#define AREA_RP_KERNEL(name, tier, kind)                                                           \
    AREA_LANE(name##_none, tier, SC_LOBE_NONE, kind)                                               \
    AREA_LANE(name##_blinn, tier, SC_LOBE_BLINN, kind)                                             \
    AREA_LANE(name##_ggx, tier, SC_LOBE_GGX, kind)                                                 \
    KERNEL(name);                                                                                  \
    KERNEL(name)                                                                                   \
    {                                                                                              \
        static const lane_n_fn lanes[4] = {name##_none, name##_blinn, name##_ggx, name##_none};    \
        area_kernel(a, kind, lanes);                                                               \
    }
/* LTC: one lane (the lobe is the table's) */
#define AREA_LTC_KERNEL(name, tier, kind)                                                          \
    AREA_LANE(name##_lane, tier, SC_LOBE_NONE, kind)                                               \
    KERNEL(name);                                                                                  \
    KERNEL(name)                                                                                   \
    {                                                                                              \
        static const lane_n_fn lanes[4] = {name##_lane, name##_lane, name##_lane, name##_lane};    \
        area_kernel(a, kind, lanes);                                                               \
    }
AREA_RP_KERNEL(area_sphere_accurate, ACCURATE, SC_LIGHT_SPHERE)
AREA_RP_KERNEL(area_tube_accurate, ACCURATE, SC_LIGHT_TUBE)
AREA_LTC_KERNEL(area_disk_accurate, ACCURATE, SC_LIGHT_DISK)
AREA_LTC_KERNEL(area_rect_accurate, ACCURATE, SC_LIGHT_RECT)
