/*
 * shadecalc/check.h — are the models physical? Directional albedo and reciprocity (SPEC §6,
 * reference §5, §12).
 *
 *   sc_albedo              a(θ_i) = ∫ f(l, v) cos θ_o dω_v by quadrature, with an error estimate
 *   sc_reciprocity_error   max |f(l, v) − f(v, l)| / max(|f(l, v)|, |f(v, l)|) over a grid of pairs
 *
 * The quadrature is centred on the mirror direction r of l (where the specular lobes peak):
 * polar angle ψ about r in geometric panels [0, π·2^-12], [π·2^-12, π·2^-11], …, [π/2, π], each
 * with Gauss–Legendre nodes, and azimuth χ about r by the trapezoid rule (exact for the periodic
 * integrand's low harmonics). Directions below the horizon contribute 0 (f = 0 there). The
 * estimate is the quadrature at `order` nodes per panel and 2·order azimuths; the error estimate
 * is its difference from the same at half the resolution. l lies in the t–n plane (φ_i = 0).
 * Evaluated in double.
 */
#ifndef SHADECALC_CHECK_H
#define SHADECALC_CHECK_H

#include "shadecalc/api.h"
#include "shadecalc/brdf.h"

SC_BEGIN_DECLS

typedef struct {
    double albedo[3]; /* per colour channel */
    double error[3];  /* |a − a at half resolution| */
} sc_albedo_result;

/* theta_i in degrees; order = Gauss–Legendre nodes per panel (2..32; 0 = default 16). */
void sc_albedo(const sc_brdf *b, double theta_i_deg, int order, sc_albedo_result *out);

/* The worst relative reciprocity error over θ in {0, 10, …, 80, 89}° × φ in {0, 45, …, 315}°
 * for both directions; *worst_l, *worst_v (may be NULL) get the pair (unit vectors). */
double sc_reciprocity_error(const sc_brdf *b, double worst_l[3], double worst_v[3]);

SC_END_DECLS

#endif
