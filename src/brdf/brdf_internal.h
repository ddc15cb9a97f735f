/* Shared by the BRDF models (shadecalc/brdf.h): the geometry of one (l, v) pair, computed once
 * in the precision, and each model's evaluator. */
#ifndef SHADECALC_BRDF_INTERNAL_H
#define SHADECALC_BRDF_INTERNAL_H

#include "shadecalc/brdf.h"
#include "shadecalc/pmath.h"

#define Q(x) sc_round(p, (x))

#define SC_PI 3.14159265358979323846
/* Divisions by cos θ_i, cos θ_o use at least this (brdf.h: guards). */
#define SC_COS_FLOOR 1e-6
/* Smallest roughness α (pbrt-v4 clamps α >= 1e-4). */
#define SC_ALPHA_FLOOR 1e-4

typedef struct {
    const sc_frame *frame;
    const double *l, *v;
    double cos_i, cos_o; /* n·l, n·v (both > 0 when a model is called) */
    double h[3];         /* half vector; n when l = −v */
    double cos_h;        /* n·h */
    double cos_floor;    /* the divisions by cos θ_i, cos θ_o take at least this (sc_cos_floor) */
} brdf_geometry;

void sc_brdf_phong(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out);
void sc_brdf_blinn_phong(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out);
void sc_brdf_ward(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out);
void sc_brdf_oren_nayar(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out);
void sc_brdf_cook_torrance(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out);

/* x^y for the cosine lobes: pow(0, 0) = 1, a non-positive base gives 0 for y > 0. */
double sc_lobe_pow(sc_prec p, double x, double y);
/* out = scale · colour, rounded; 0 where either is 0 (sc_mul_reach). */
void sc_scale3(sc_prec p, const double colour[3], double scale, double out[3]);
/* max(α, SC_ALPHA_FLOOR) rounded to p, and never 0: the precision's smallest step where the
 * floor itself rounds to 0 (lowp). */
double sc_alpha_floor(sc_prec p, double alpha);
/* max(x, g->cos_floor): SC_COS_FLOOR, or 0 (x itself) for sc_brdf_eval_many_unguarded */
double sc_cos_floor(const brdf_geometry *g, double x);
/* sc_brdf_eval_many of the models as written, without SC_COS_FLOOR: the albedo integrates them
 * (check.c), since the floor would cut a band 10⁻⁶ rad wide off the horizon (f cos θ_o stays
 * finite there in double: cos θ_o > 0 at every quadrature node). BRDF files are unchanged. */
int sc_brdf_eval_many_unguarded(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                                sc_brdf_terms *out);

#endif
