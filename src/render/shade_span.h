/* render/shade_span.h — shading a span of pixels (private to src/render).
 *
 * The seam for the SIMD batch shading kernels: the rasterizer gathers the points of one span
 * (a row of a tile, or a block of vertices for Gouraud), this function turns them into colours.
 * In highp, scenes the batch shading kernel computes (lambert, normalized blinn-phong, GGX
 * cook-torrance; directional lights, inverse-square point and spot lights) go through it, on the instruction
 * set SHADECALC_ISA or CPUID chose; everything else through sc_shade per point. */
#ifndef SHADECALC_RENDER_SHADE_SPAN_H
#define SHADECALC_RENDER_SHADE_SPAN_H

#include "shadecalc/batch.h"
#include "shadecalc/shade.h"

typedef struct {
    double pos[3];    /* world-space point */
    double normal[3]; /* unit normal, facing the side being shaded */
} render_shade_input;

/* 1 and the kernel's uniforms if the batch shading kernel computes this scene's SPEC §6
 * equation (the per-light ambient terms c_amb ⊙ L_A,k join the global one); 0 otherwise. */
int render_batch_scene(const sc_scene *s, sc_batch_scene *out);

/* How a render shades: the scene and precision, and whether (and with what uniforms) the batch
 * kernel does it — decided once per render, not per span. */
typedef struct {
    const sc_scene *scene;
    sc_prec prec;
    int batch; /* 1: through the kernel, with bs */
    sc_batch_scene bs;
} render_shader;

void render_shader_init(render_shader *sh, const sc_scene *scene, sc_prec prec);

/* rgb[3 i .. 3 i + 2] = L_o at in[i], seen from eye (v = normalize(eye − pos); v = n when the
 * point is the eye). */
void render_shade_span(const render_shader *sh, const double eye[3], int n,
                       const render_shade_input *in, float *rgb);

#endif
