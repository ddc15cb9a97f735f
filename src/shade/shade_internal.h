/* Shared by the shading models (shadecalc/shade.h). */
#ifndef SHADECALC_SHADE_INTERNAL_H
#define SHADECALC_SHADE_INTERNAL_H

#include "shadecalc/pmath.h"
#include "shadecalc/shade.h"

/* out = a ⊙ b and acc += x, each component rounded to p; a zero factor gives 0 even against an
 * infinite one (sc_mul_reach). */
void sc_mul3(sc_prec p, const double a[3], const double b[3], double out[3]);
void sc_add3(sc_prec p, double acc[3], const double x[3]);

void sc_shade_ads(sc_prec p, const sc_scene *s, const sc_shade_point *at, sc_shade_result *out);
/* opengl and direct3d9 */
void sc_shade_fixed_function(sc_prec p, const sc_scene *s, const sc_shade_point *at,
                             sc_shade_result *out);

#endif
