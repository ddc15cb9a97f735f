/* Shared by the files of src/geom: the surface representation and small helpers. */
#ifndef SHADECALC_GEOM_INTERNAL_H
#define SHADECALC_GEOM_INTERNAL_H

#include "shadecalc/expr.h"
#include "shadecalc/surface.h"
#include "shadecalc/vec.h"

typedef enum {
    SURFACE_SPHERE,
    SURFACE_TORUS,
    SURFACE_PLANE,
    SURFACE_CYLINDER,
    SURFACE_USER
} surface_kind;

struct sc_surface {
    surface_kind kind;
    double a, b;     /* sphere r; torus R, r; plane size; cylinder r, h */
    sc_expr *xyz[3]; /* user: x(u,v), y(u,v), z(u,v) */
    int closed_u, closed_v;
};

/* Sets closed_u/closed_v of a user surface by sampling (surface.h). */
void sc_surface_detect_closed(sc_surface *s);

static inline sc_dvec3 sc_dvec3_from(const double *a) { return (sc_dvec3){a[0], a[1], a[2]}; }

/* v·2^-k, k the binary exponent of its largest |component| (exact): the largest component in
 * [1, 2), so that a cross product or a squared length of such vectors neither overflows nor
 * underflows. v itself if it is zero or not finite. */
sc_dvec3 sc_dvec3_unit_scaled(sc_dvec3 v);

#endif
