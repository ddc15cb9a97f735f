/* method=ltc (shadecalc/area.h, docs/formulas.md §5.3): a disk or rect by linearly transformed
 * cosines (Heitz, Dupuy, Hill, Neubelt 2016), through light/ltc.h:
 *   L_o = L_e ⊙ (c_diff/π · ∫ cos̄θ_i dω + c_spec ⊙ ∫ f_GGX cos̄θ_i dω),
 * the first integral exact (the emitter clipped to the horizon), the second by the LTC fit. */
#include <math.h>
#include <string.h>

#include "light/area_internal.h"
#include "light/ltc.h"

/* The sidedness is decided here, as for the reference: nothing reaches a point behind a
 * one-sided emitter or in its plane; otherwise the emitter is handed over as two-sided, so
 * that the result does not depend on the order of its corners. */
static int faces_point(const sc_light *light, const double pos[3])
{
    double nl[3], x[3];
    if (light->kind == SC_LIGHT_RECT)
        area_cross(light->area.edge1, light->area.edge2, nl);
    else
        memcpy(nl, light->area.normal, sizeof nl);
    for (int c = 0; c < 3; c++)
        x[c] = pos[c] - light->pos[c];
    double h = area_dot(x, nl);
    return h > 0.0 || (h < 0.0 && light->area.two_sided);
}

static int ltc_of(const sc_light *light, const area_integrand *g, const double pos[3], double alpha,
                  const double f0[3], sc_ltc_result *r)
{
    double centre[3];
    for (int c = 0; c < 3; c++)
        centre[c] = light->pos[c] - pos[c];
    if (light->kind == SC_LIGHT_DISK)
        return sc_ltc_disk(g->frame, g->v, alpha, f0, centre, light->area.normal,
                           light->area.radius, 1, r);
    static const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    double corners[4][3];
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++)
            corners[i][c] = centre[c] + 0.5 * (signs[i][0] * light->area.edge1[c] +
                                               signs[i][1] * light->area.edge2[c]);
    return sc_ltc_polygon(g->frame, g->v, alpha, f0, (const double(*)[3])corners, 4, 1, r);
}

void area_ltc(const sc_light *light, area_integrand *g, const double pos[3], sc_area_result *out)
{
    const sc_brdf *b = g->b;
    int specular = b->kind == SC_BRDF_COOK_TORRANCE;
    double f0[3] = {1.0, 1.0, 1.0}; /* F=none: F = 1 */
    if (specular && b->F == SC_F_SCHLICK)
        memcpy(f0, b->f0, sizeof f0);
    sc_ltc_result r;
    memset(&r, 0, sizeof r);
    out->evaluations = 1;
    if (!(light->kind == SC_LIGHT_RECT || light->area.radius > 0.0) || !faces_point(light, pos) ||
        ltc_of(light, g, pos, specular ? b->ax : 1.0, f0, &r) < 0)
        return; /* 0: documented results (docs/formulas.md §5.1), or degenerate inputs */
    for (int c = 0; c < 3; c++)
        out->L[c] = g->Le[c] *
                    (b->diff[c] / AREA_PI * r.cosine + (specular ? b->spec[c] * r.spec[c] : 0.0));
}
