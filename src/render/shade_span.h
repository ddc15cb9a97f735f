/* render/shade_span.h — shading a span of pixels (private to src/render).
 *
 * The seam for the SIMD batch shading kernels: the rasterizer gathers the points of one span
 * (a row of a tile, or a block of vertices for Gouraud), this function turns them into colours.
 * Today it calls sc_shade per point in the requested precision; a vectorized kernel that
 * takes the same inputs can replace its body. */
#ifndef SHADECALC_RENDER_SHADE_SPAN_H
#define SHADECALC_RENDER_SHADE_SPAN_H

#include "shadecalc/shade.h"

typedef struct {
    double pos[3];    /* world-space point */
    double normal[3]; /* unit normal, facing the side being shaded */
} render_shade_input;

/* rgb[3 i .. 3 i + 2] = L_o at in[i], seen from eye (v = normalize(eye − pos); v = n when the
 * point is the eye). */
void render_shade_span(const sc_scene *scene, sc_prec prec, const double eye[3], int n,
                       const render_shade_input *in, float *rgb);

#endif
