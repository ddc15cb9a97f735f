/* Cook–Torrance microfacet specular (docs/formulas.md §6.6): D·F·G / (4 cos θ_i cos θ_o) in the
 * normalization of Walter et al. 2007; the form printed by Cook and Torrance (1982),
 * F·D_CT·G/(π cos θ_i cos θ_o) with D_CT = π·D_Beckmann, is 4× that. */
#include <math.h>

#include "brdf/brdf_internal.h"
#include "shadecalc/light.h"

typedef struct {
    double ax, ay;
} roughness;

/* α²tan²θ of direction w, anisotropic: ((w·t)² α_x² + (w·b)² α_y²)/(w·n)² (Heitz 2014). */
static double alpha2_tan2(sc_prec p, const sc_frame *f, const double w[3], roughness a)
{
    double wt = Q(sc_p_dot(p, w, f->t, 3) * a.ax), wb = Q(sc_p_dot(p, w, f->b, 3) * a.ay);
    double wn = sc_p_dot(p, w, f->n, 3);
    double num = Q(Q(wt * wt) + Q(wb * wb));
    return num == 0.0 ? 0.0 : Q(num / Q(wn * wn)); /* never 0/0 where both underflow */
}

/* The slope terms (h·t/α_x)² + (h·b/α_y)², which are tan²θ_h·(…)·cos²θ_h without the
 * cancellation of 1 − (n·h)² near the highlight (docs/formulas.md §6.6 pitfalls). */
static double slope2(sc_prec p, const sc_frame *f, const double h[3], roughness a)
{
    double ht = Q(sc_p_dot(p, h, f->t, 3) / a.ax), hb = Q(sc_p_dot(p, h, f->b, 3) / a.ay);
    return Q(Q(ht * ht) + Q(hb * hb));
}

static double ndf(sc_prec p, const sc_brdf *b, const brdf_geometry *g, roughness a)
{
    double ch = g->cos_h, ch2 = Q(ch * ch), s2 = slope2(p, g->frame, g->h, a);
    double pa = Q(Q(SC_PI * a.ax) * a.ay);
    if (ch <= 0.0 || isinf(pa))
        return 0.0; /* π α_x α_y beyond the precision: the limit α → ∞, 0 (not inf·0) */
    if (b->D == SC_D_BECKMANN) { /* exp(−s²/cos²θ_h) / (π α_x α_y cos⁴θ_h) */
        double e = s2 == 0.0 ? 1.0 : sc_p_exp(p, Q(-Q(s2 / ch2)));
        return e == 0.0 ? 0.0 : Q(e / Q(pa * Q(ch2 * ch2)));
    }
    double d = Q(s2 + ch2); /* GGX: 1 / (π α_x α_y (s² + cos²θ_h)²) */
    return Q(1.0 / Q(pa * Q(d * d)));
}

/* Smith Λ(w): GGX (−1 + √(1 + α²tan²θ))/2; Beckmann (erf(a) − 1)/2 + e^(−a²)/(2a√π) with
 * a = 1/(α tan θ), 0 along the normal. */
static double smith_lambda(sc_prec p, const sc_brdf *b, const sc_frame *f, const double w[3],
                           roughness a)
{
    double at2 = alpha2_tan2(p, f, w, a);
    if (b->D == SC_D_GGX)
        return Q(Q(-1.0 + sc_p_sqrt(p, Q(1.0 + at2))) / 2.0);
    if (at2 == 0.0)
        return 0.0;
    double x = Q(1.0 / sc_p_sqrt(p, at2));
    double tail = Q(sc_p_exp(p, Q(-Q(x * x))) / Q(Q(2.0 * x) * sqrt(SC_PI)));
    return Q(Q(Q(erf(x)) - 1.0) / 2.0 + tail);
}

static double masking(sc_prec p, const sc_brdf *b, const brdf_geometry *g, roughness a)
{
    if (b->G == SC_G_VCAVITY) { /* min(1, 2 n·h min(n·v, n·l) / v·h), v·h not floored */
        double vh = sc_p_dot(p, g->v, g->h, 3);
        double m = Q(Q(2.0 * g->cos_h) * (g->cos_o < g->cos_i ? g->cos_o : g->cos_i));
        return m >= vh ? 1.0 : Q(m / vh); /* m >= 0, so v·h > 0 in the division */
    }
    double ll = smith_lambda(p, b, g->frame, g->l, a), lv = smith_lambda(p, b, g->frame, g->v, a);
    if (b->G == SC_G_SMITH_CORRELATED)
        return Q(1.0 / Q(Q(1.0 + ll) + lv));
    return Q(Q(1.0 / Q(1.0 + ll)) * Q(1.0 / Q(1.0 + lv)));
}

/* Exact unpolarized dielectric Fresnel (pbrt FrDielectric), 1 on total internal reflection —
 * also where η² underflows to 0 (0/0 at normal incidence), the limit η → 0 for every angle. */
static double fresnel_exact(sc_prec p, double eta, double c)
{
    double sin2_t = Q(Q(1.0 - Q(c * c)) / Q(eta * eta));
    if (!(sin2_t < 1.0))
        return 1.0;
    double cos_t = sc_p_sqrt(p, Q(1.0 - sin2_t));
    double ec = Q(eta * c), et = Q(eta * cos_t);
    double r_par = Q(Q(ec - cos_t) / Q(ec + cos_t));
    double r_perp = Q(Q(c - et) / Q(c + et));
    return Q(Q(Q(r_par * r_par) + Q(r_perp * r_perp)) / 2.0);
}

static void fresnel(sc_prec p, const sc_brdf *b, const brdf_geometry *g, double F[3])
{
    double c = sc_p_dot(p, g->v, g->h, 3);
    c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
    double exact = b->F == SC_F_EXACT ? fresnel_exact(p, Q(b->ior), c) : 1.0;
    double m = Q(1.0 - c), m2 = Q(m * m), m5 = Q(Q(m2 * m2) * m);
    for (int k = 0; k < 3; k++) /* Schlick 1994: F0 + (1 − F0)(1 − cos θ)^5 */
        F[k] = b->F == SC_F_SCHLICK ? Q(Q(b->f0[k]) + Q(Q(1.0 - Q(b->f0[k])) * m5)) : exact;
}

void sc_brdf_cook_torrance(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out)
{
    sc_scale3(p, b->diff, Q(1.0 / SC_PI), out->diffuse);
    roughness a = {sc_alpha_floor(p, b->ax), sc_alpha_floor(p, b->ay)};
    out->D = ndf(p, b, g, a);
    out->G = masking(p, b, g, a);
    fresnel(p, b, g, out->F);
    /* D = inf where cos⁴θ_h underflows meets G = 0 at grazing angles: 0, not NaN */
    double dg = sc_mul_reach(p, out->D, out->G);
    if (dg == 0.0)
        return; /* D or G vanished: no 0/0 where the cosines' product underflows */
    dg = Q(dg / Q(Q(4.0 * sc_cos_floor(g, g->cos_i)) * sc_cos_floor(g, g->cos_o)));
    if (b->form == SC_CT_1982)
        dg = Q(4.0 * dg);
    for (int k = 0; k < 3; k++)
        out->specular[k] = sc_mul_reach(p, sc_mul_reach(p, dg, out->F[k]), Q(b->spec[k]));
}
