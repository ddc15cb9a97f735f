/*
 * shadecalc/surface.h — parametric surfaces S(u,v) and their exact normals (docs/formulas.md §7).
 *
 *   sc_surface               an opaque surface: sphere, torus, plane, cylinder or user S(u,v)
 *   sc_surface_parse         "sphere r=1" ... -> surface; NULL with err on a bad spec
 *   sc_surface_free
 *   sc_surface_point         p, ∂S/∂u, ∂S/∂v, the unit normal n and a degenerate flag
 *   sc_surface_eval          the point, its derivatives and normal at (u, v)
 *   sc_surface_closed_u/_v   whether S(0,v) = S(1,v) (resp. S(u,0) = S(u,1)): a seam
 *
 * Parameters u, v ∈ [0,1] (values outside extend the formulas). With φ = 2πu:
 *   sphere r=R           θ = πv, S = R(sin θ cos φ, sin θ sin φ, −cos θ): poles at v = 0 (south,
 *                        −z) and v = 1 (north, +z); closed in u.
 *   torus R=A r=B        ψ = 2πv, S = ((A + B cos ψ) cos φ, (A + B cos ψ) sin φ, B sin ψ),
 *                        0 < B < A (a ring torus); closed in u and v.
 *   plane size=L         S = (L(u − ½), L(v − ½), 0), n = +z (default L = 2).
 *   cylinder r=R h=H     S = (R cos φ, R sin φ, H(v − ½)), open ends; closed in u.
 *   user x=E y=E z=E     three expressions in u and v in the eval language (shadecalc/expr.h);
 *                        each key starts a word, its expression runs to the next key. Closed
 *                        in u (v) when S(0,v) = S(1,v) (S(u,0) = S(u,1)) at 9 sample points
 *                        within 1e-9 of the surface's size.
 * Defaults: sphere r=1, torus R=1 r=0.3, cylinder r=1 h=2. Built-in sizes must be finite, > 0.
 *
 * Derivatives are exact: closed forms for the built-ins, forward-mode automatic differentiation
 * (dual numbers, sc_expr_eval_dual) through the expression for user surfaces — no differencing.
 * All in double precision.
 *
 * The normal is n = ∂S/∂u × ∂S/∂v / ‖…‖, outward for the built-ins. Where the cross product
 * vanishes — zero, not finite, or below its rounding error 8ε‖∂S/∂u‖‖∂S/∂v‖ (a pole, a cone's
 * apex) — degenerate = 1 and n is the normal at (u, v) moved toward the centre (½, ½) of the
 * parameter square by a step δ = 2⁻³⁰ (then 2⁻²⁰, 2⁻¹⁰ if still degenerate): the limit
 * approached from inside the domain, to O(δ) (the sphere's poles: (0, 0, ∓1) within 4·10⁻⁹).
 * If every step is degenerate too (a surface that is a curve or a point), n = (0, 0, 1).
 * n is never NaN; p and the derivatives are NaN only where the user's expressions are.
 */
#ifndef SHADECALC_SURFACE_H
#define SHADECALC_SURFACE_H

#include <stddef.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef struct sc_surface sc_surface;

/* Parses a surface spec (above). NULL with a message naming the offending word in err. */
sc_surface *sc_surface_parse(const char *spec, char *err, size_t errsize);
void sc_surface_free(sc_surface *s);

typedef struct {
    double p[3], dpdu[3], dpdv[3];
    double n[3];    /* unit normal dpdu × dpdv / ‖…‖, or the fallback above; never NaN */
    int degenerate; /* 1 where the cross product vanished and the fallback was used */
} sc_surface_point;

void sc_surface_eval(const sc_surface *s, double u, double v, sc_surface_point *out);

/* Whether the surface is closed in u and/or v (for seams when tessellating). */
int sc_surface_closed_u(const sc_surface *s);
int sc_surface_closed_v(const sc_surface *s);

SC_END_DECLS

#endif
