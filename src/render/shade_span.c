/* Shading a span of pixels with sc_shade (render/shade_span.h). */
#include "render/shade_span.h"

#include <math.h>

static void shade_one(const sc_scene *scene, sc_prec prec, const double eye[3],
                      const render_shade_input *in, float rgb[3])
{
    sc_shade_point at;
    double v[3], len2 = 0.0;
    for (int c = 0; c < 3; c++) {
        at.pos[c] = in->pos[c];
        v[c] = eye[c] - in->pos[c];
        len2 += v[c] * v[c];
    }
    double len = sqrt(len2);
    for (int c = 0; c < 3; c++)
        at.v[c] = len > 0.0 ? v[c] / len : in->normal[c];
    sc_shade_result r = {.per_light = NULL};
    if (sc_frame_make(in->normal, NULL, &at.frame) < 0) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return;
    }
    sc_shade(prec, scene, &at, &r);
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)r.L[c];
}

void render_shade_span(const sc_scene *scene, sc_prec prec, const double eye[3], int n,
                       const render_shade_input *in, float *rgb)
{
    for (int i = 0; i < n; i++)
        shade_one(scene, prec, eye, &in[i], rgb + 3 * i);
}
