/* render/shade_span.h — shading a span of pixels (private to src/render).
 *
 * The seam for the SIMD batch shading kernels: the rasterizer gathers the points of one span
 * (a row of a tile, or a block of vertices for Gouraud), this function turns them into colours.
 * In highp, scenes the batch shading kernel computes (sc_batch_plan_compile of batch.h) go
 * through a plan of it, on the instruction set SHADECALC_ISA, --isa or CPUID chose; everything
 * else through sc_shade per point. */
#ifndef SHADECALC_RENDER_SHADE_SPAN_H
#define SHADECALC_RENDER_SHADE_SPAN_H

#include "shadecalc/batch.h"
#include "shadecalc/shade.h"

typedef struct {
    double pos[3];    /* world-space point */
    double normal[3]; /* unit normal, facing the side being shaded */
} render_shade_input;

/* How a render shades: the scene and precision, and the plan of the batch shading kernel when
 * it computes the scene — compiled once per render, shared by the threads. */
typedef struct {
    const sc_scene *scene;
    sc_prec prec;
    sc_batch_plan *plan; /* NULL: sc_shade per point */
} render_shader;

/* 1 with a plan of the kernel's tier (NULL: accurate) in highp; 0 with the reason in why when
 * the points go through sc_shade (another precision, a scene the kernel does not compute, out
 * of memory). */
int render_shader_init(render_shader *sh, const sc_scene *scene, sc_prec prec, const char *tier,
                       char *why, size_t size);
void render_shader_free(render_shader *sh);

/* rgb[3 i .. 3 i + 2] = L_o at in[i], seen from eye (v = normalize(eye − pos); v = n when the
 * point is the eye). */
void render_shade_span(const render_shader *sh, const double eye[3], int n,
                       const render_shade_input *in, float *rgb);

#endif
