/*
 * shadecalc/area.h — area lights: L_o of a sphere, tube, disk or rect emitter of uniform
 * radiance L_e at a surface point (docs/formulas.md §5).
 *
 *   sc_area_eval             ∫ f(l, v) L_e cos̄θ_i dω over the emitter, by a method:
 *                            reference             Gauss–Legendre panels in solid-angle
 *                                                  coordinates, any BRDF, with an error estimate
 *                            representative-point  Karis 2013 (sphere, tube)
 *                            point                 a point light at the centre, I = L_e · extent
 *                            ltc                   linearly transformed cosines (disk, rect;
 *                                                  lambert and GGX cook-torrance)
 *   sc_area_method_applies   whether a method evaluates a light kind with a BRDF, as a message
 *   sc_area_extent           the stand-in's I / L_e: πR² (sphere, disk), 2Rℓ + πR² (tube),
 *                            ‖edge1 × edge2‖ (rect)
 *
 * Evaluated in double whatever the precision of the caller; no occlusion. Documented results
 * (never NaN): a zero-size emitter (radius 0) gives 0; an emitter wholly below the tangent plane,
 * or a one-sided disk or rect seen from behind, gives 0; a point in the plane of a disk or rect
 * gives 0 (it is seen edge-on); a point inside or on a sphere or tube sees L_e in every direction
 * above its horizon, L_o = L_e ⊙ ∫_H f cos θ_i dω.
 */
#ifndef SHADECALC_AREA_H
#define SHADECALC_AREA_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

SC_BEGIN_DECLS

typedef struct {
    double L[3];      /* the light's share of L_o (no ambient term) */
    double error[3];  /* reference: |Q(2N) − Q(N)|, the estimate of |L − exact|; else 0 */
    double l[3];      /* the direction used: to the centre (point, reference), or the
                       * specular representative point */
    double r;         /* distance from the point to the centre */
    int nodes;        /* reference: Gauss–Legendre nodes per panel and dimension of Q(2N) */
    long evaluations; /* reference: BRDF evaluations, both rules; else 1 or 2 */
    int converged;    /* reference: the error estimate meets tol (always 1 with samples=N) */
} sc_area_result;

/* L_o of area light `light` (sc_light_is_area) with BRDF b at point pos (frame: its normal),
 * v the unit direction to the viewer, by `method` (which must apply: sc_area_method_applies;
 * where it does not, out->L is 0 and -1 is returned). */
int sc_area_eval(const sc_light *light, sc_area_method method, const sc_brdf *b,
                 const sc_frame *frame, const double pos[3], const double v[3],
                 sc_area_result *out);

/* 0 if `method` evaluates light kind `kind` with BRDF b (NULL: any BRDF the method may take),
 * else -1 with a message naming the method and what it takes ("method=representative-point:
 * sphere and tube lights only"). */
int sc_area_method_applies(sc_light_kind kind, sc_area_method method, const sc_brdf *b, char *msg,
                           size_t size);

/* The point light that the method `point` puts in place of an area light: at its centre (a
 * tube's: the midpoint of p0–p1), I = L_e · sc_area_extent, inverse-square falloff. */
void sc_area_stand_in(const sc_light *light, sc_light *point);

/* The name of a method ("representative-point"), or NULL past the last. */
const char *sc_area_method_name(sc_area_method method);

double sc_area_extent(const sc_light *light);

SC_END_DECLS

#endif
