/* Phong (1975) and Blinn-Phong (1977) BRDFs and their normalizations (docs/formulas.md §6.2–§6.3). */
#include "brdf/brdf_internal.h"

static void add_diffuse(sc_prec p, const sc_brdf *b, sc_brdf_terms *out)
{
    sc_scale3(p, b->diff, Q(1.0 / SC_PI), out->diffuse);
}

/* r = 2(n·l)n − l; cos α_r = max(r·v, 0). */
static double cos_alpha_r(sc_prec p, const brdf_geometry *g)
{
    double r[3];
    double two_cos = Q(2.0 * g->cos_i);
    for (int c = 0; c < 3; c++)
        r[c] = sc_p_sub(p, Q(two_cos * g->frame->n[c]), g->l[c]);
    double c = sc_p_dot(p, r, g->v, 3);
    return c > 0.0 ? c : 0.0;
}

void sc_brdf_phong(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out)
{
    add_diffuse(p, b, out);
    double lobe = sc_lobe_pow(p, cos_alpha_r(p, g), b->m), scale;
    if (lobe == 0.0)
        return; /* an underflowed lobe never meets an overflowed normalization (0·∞) */
    switch (b->form) {
    case SC_PHONG_ORIGINAL: /* the 1/cos θ_i that makes it non-reciprocal */
        scale = Q(lobe / Q(SC_PI * sc_cos_floor(g, g->cos_i)));
        break;
    case SC_PHONG_MODIFIED: scale = Q(lobe / SC_PI); break;
    default: scale = Q(Q(Q(b->m + 2.0) / Q(2.0 * SC_PI)) * lobe); break;
    }
    sc_scale3(p, b->spec, scale, out->specular);
}

void sc_brdf_blinn_phong(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out)
{
    add_diffuse(p, b, out);
    double lobe = sc_lobe_pow(p, g->cos_h, b->m);
    if (lobe == 0.0)
        return;
    double scale = b->form == SC_BLINN_PLAIN ? lobe : Q(Q(Q(b->m + 8.0) / Q(8.0 * SC_PI)) * lobe);
    sc_scale3(p, b->spec, scale, out->specular);
}
