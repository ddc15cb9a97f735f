/* Shared by the area light methods (shadecalc/area.h): the integrand f(l, v) L_e cos̄θ_i and
 * small vector helpers. */
#ifndef SHADECALC_AREA_INTERNAL_H
#define SHADECALC_AREA_INTERNAL_H

#include "shadecalc/area.h"

#define AREA_PI 3.14159265358979323846

/* What the integrand needs: the BRDF at the point, and L_e. */
typedef struct {
    const sc_brdf *b;
    const sc_frame *frame;
    const double *v;
    double Le[3];
    long evaluations;
} area_integrand;

/* acc += weight · f(l, v) ⊙ L_e · max(n·l, 0) for a unit l. */
void area_add(area_integrand *g, const double l[3], double weight, double acc[3]);

/* The converging reference (area_reference.c): fills L, error, nodes, evaluations, converged. */
void area_reference(const sc_light *light, area_integrand *g, const double pos[3],
                    sc_area_result *out);

/* method=ltc (area_ltc.c): fills L. */
void area_ltc(const sc_light *light, area_integrand *g, const double pos[3], sc_area_result *out);

/* The centre of the emitter (a tube's: the midpoint of p0–p1). */
void area_centre(const sc_light *light, double out[3]);

double area_dot(const double a[3], const double b[3]);
/* ‖a‖, and a/‖a‖ into unit (unit untouched when a = 0). */
double area_unit(const double a[3], double unit[3]);
void area_cross(const double a[3], const double b[3], double out[3]);
/* A unit vector perpendicular to unit w. */
void area_perpendicular(const double w[3], double out[3]);

#endif
