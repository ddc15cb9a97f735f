/*
 * shadecalc/check.h — are the models physical? Directional albedo and reciprocity
 * (docs/formulas.md §6, §6.9).
 *
 *   sc_albedo              a(θ_i) = ∫ f(l, v) cos θ_o dω_v by quadrature, with an error estimate
 *   sc_reciprocity_error   max |f(l, v) − f(v, l)| / max(|f(l, v)|, |f(v, l)|) over a grid of pairs
 *
 * The quadrature is over (θ_o, φ_o) in composite Gauss–Legendre panels refined geometrically
 * toward the mirror direction (θ_i, π): breakpoints θ_i ± π·2^-k and π ± π·2^-k for k = 1..K,
 * where K >= 12 makes the narrowest panel at most an eighth of the specular lobe's width
 * (√(2/m) for Phong, 2√(2/m) for Blinn-Phong, 2α for Ward and Cook–Torrance); breakpoints also
 * at φ = π/2, 3π/2 (the kinks of Oren–Nayar's max terms). The integrand is the model as written
 * (docs/formulas.md §6): the floor 10⁻⁶ of shade's divisions by cos θ_o (brdf.h) is left out,
 * since it would cut a band 10⁻⁶ rad wide off the horizon (6.3·10⁻⁸ of Ward–Dür's albedo at
 * θ_i = 60°, α = 0.2). The estimate is the quadrature at `order` nodes per panel; the error
 * estimate is its difference from the same at half the order, plus a bound of the rounding of
 * the sums. l lies in the t–n plane (φ_i = 0). Evaluated in double.
 *
 * A lobe narrower than 10⁻⁶ rad (Phong m > 2·10¹², Blinn-Phong m > 8·10¹²) is not resolved:
 * cos θ near 1 is known to 2⁻⁵³, so cos^m θ evaluated in double is a staircase with steps
 * above 0.1 % there. sc_albedo then returns -1 and an infinite error estimate.
 */
#ifndef SHADECALC_CHECK_H
#define SHADECALC_CHECK_H

#include "shadecalc/api.h"
#include "shadecalc/brdf.h"

SC_BEGIN_DECLS

typedef struct {
    double albedo[3]; /* per colour channel */
    double error[3];  /* |a − a at half resolution| + rounding */
} sc_albedo_result;

/* theta_i in degrees; order = Gauss–Legendre nodes per panel (2..32; 0 = default 16).
 * 0, or -1 if the lobe is too narrow to resolve (the error estimate is then +inf; also out of
 * memory, with a NaN albedo). */
int sc_albedo(const sc_brdf *b, double theta_i_deg, int order, sc_albedo_result *out);

/* The worst relative reciprocity error over θ in {0, 10, …, 80, 89}° × φ in {0, 45, …, 315}°
 * for both directions; *worst_l, *worst_v (may be NULL) get the pair (unit vectors). */
double sc_reciprocity_error(const sc_brdf *b, double worst_l[3], double worst_v[3]);

SC_END_DECLS

#endif
