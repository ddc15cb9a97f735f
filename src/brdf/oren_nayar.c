/* Oren–Nayar (1994) rough diffuse reflection, qualitative and full models (docs/formulas.md §6.5).
 * σ is the slope-angle standard deviation in radians, α = max(θ_i, θ_o), β = min(θ_i, θ_o),
 * Δφ the azimuth difference (cos Δφ = 0 where a direction is along n, so the Δφ terms
 * vanish there instead of becoming 0/0). The full model's direct term is clamped at 0, where
 * the approximation breaks down at extreme grazing angles. */
#include <math.h>

#include "brdf/brdf_internal.h"
#include "shadecalc/light.h"

/* cos Δφ from the projections of l and v onto the tangent plane. */
static double cos_delta_phi(sc_prec p, const brdf_geometry *g)
{
    double lp[3], vp[3];
    for (int c = 0; c < 3; c++) {
        lp[c] = sc_p_sub(p, g->l[c], Q(g->cos_i * g->frame->n[c]));
        vp[c] = sc_p_sub(p, g->v[c], Q(g->cos_o * g->frame->n[c]));
    }
    double ll = sc_p_dot(p, lp, lp, 3), vv = sc_p_dot(p, vp, vp, 3);
    if (!(ll > 1e-24 && vv > 1e-24))
        return 0.0;
    double c = Q(sc_p_dot(p, lp, vp, 3) / sc_p_sqrt(p, Q(ll * vv)));
    return c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c;
}

/* θ = acos(c) for c in (0, 1], never above π/2: highp rounds acos of a tiny cosine to
 * binary32(π/2) = 1.57079637 > π/2, whose tangent is −2.3e7 (f turned negative, −6.6e6, at
 * cos θ = 3e-19); it takes the precision's value just below π/2 instead. */
static double clamped_acos(sc_prec p, double c)
{
    double a = sc_p_acos(p, c > 1.0 ? 1.0 : c);
    return a > SC_PI / 2.0 ? Q(a - sc_prec_ulp(p, a)) : a;
}

/* σ²/(σ² + k), 1 where σ² overflows the precision (inf/inf). */
static double sigma_ratio(sc_prec p, double s2, double k)
{
    return isinf(s2) ? 1.0 : Q(s2 / Q(s2 + k));
}

/* f/ρ·π of the qualitative model: A + B max(0, cos Δφ) sin α tan β. */
static double qualitative(sc_prec p, double s2, double cdp, double alpha, double beta)
{
    double A = Q(1.0 - Q(0.5 * sigma_ratio(p, s2, 0.33)));
    double B = Q(0.45 * sigma_ratio(p, s2, 0.09));
    double term = cdp > 0.0 ? Q(Q(cdp * sc_p_sin(p, alpha)) * sc_p_tan(p, beta)) : 0.0;
    return Q(A + Q(B * term));
}

/* f1/ρ·π of the full model: C1 + cos Δφ C2 tan β + (1 − |cos Δφ|) C3 tan((α+β)/2). */
static double full_direct(sc_prec p, double s2, double cdp, double alpha, double beta)
{
    double C1 = Q(1.0 - Q(0.5 * sigma_ratio(p, s2, 0.33)));
    double k = Q(0.45 * sigma_ratio(p, s2, 0.09));
    double two_beta_pi = Q(Q(2.0 * beta) / SC_PI);
    double sin_a = sc_p_sin(p, alpha);
    double C2 = cdp >= 0.0 ? Q(k * sin_a)
                           : Q(k * Q(sin_a - Q(Q(two_beta_pi * two_beta_pi) * two_beta_pi)));
    double ab = Q(Q(Q(4.0 * alpha) * beta) / Q(SC_PI * SC_PI));
    double C3 = Q(Q(0.125 * sigma_ratio(p, s2, 0.09)) * Q(ab * ab));
    double t2 = Q(Q(cdp * C2) * sc_p_tan(p, beta));
    double t3 = Q(Q(Q(1.0 - fabs(cdp)) * C3) * sc_p_tan(p, Q(Q(alpha + beta) / 2.0)));
    double f1 = Q(Q(C1 + t2) + t3);
    /* With cos Δφ < 0, both directions near grazing and a large σ, tan β outgrows the vanishing
     * C2 and the bracket turns negative (e.g. −0.16 at θ = 89.9999°, σ = 1): clamped to 0. */
    return f1 > 0.0 ? f1 : 0.0;
}

void sc_brdf_oren_nayar(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out)
{
    double s2 = Q(Q(b->sigma) * Q(b->sigma));
    double ti = clamped_acos(p, g->cos_i), to = clamped_acos(p, g->cos_o);
    double alpha = ti > to ? ti : to, beta = ti > to ? to : ti;
    double cdp = cos_delta_phi(p, g);
    double inv_pi = Q(1.0 / SC_PI);
    if (b->form != SC_OREN_FULL) {
        sc_scale3(p, b->diff, Q(inv_pi * qualitative(p, s2, cdp, alpha, beta)), out->diffuse);
        return;
    }
    sc_scale3(p, b->diff, Q(inv_pi * full_direct(p, s2, cdp, alpha, beta)), out->diffuse);
    /* f2 = 0.17 ρ²/π · σ²/(σ²+0.13) · [1 − cos Δφ (2β/π)²], the interreflection term */
    double two_beta_pi = Q(Q(2.0 * beta) / SC_PI);
    double f2 = Q(Q(Q(0.17 * inv_pi) * sigma_ratio(p, s2, 0.13)) *
                  Q(1.0 - Q(cdp * Q(two_beta_pi * two_beta_pi))));
    f2 = f2 > 0.0 ? f2 : 0.0; /* 2β/π rounded above 1 (mediump, lowp) must not make it negative */
    for (int c = 0; c < 3; c++)
        out->diffuse[c] = Q(out->diffuse[c] +
                            sc_mul_reach(p, Q(Q(b->diff[c]) * Q(b->diff[c])), f2));
}
