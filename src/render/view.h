/* render/view.h — the camera as the rasterizer uses it (private to src/render). */
#ifndef SHADECALC_RENDER_VIEW_H
#define SHADECALC_RENDER_VIEW_H

#include "render/raster.h"
#include "shadecalc/render.h"

typedef struct {
    double eye[3];
    double right[3], up[3], forward[3]; /* orthonormal, right-handed: right × up = −forward */
    double scale_x, scale_y;            /* cot(fov/2)/aspect, cot(fov/2) */
    double near;                        /* |at − eye| / 1000 */
} render_view;

/* The view of a valid camera on a width × height screen. */
void render_view_make(const sc_camera *c, int width, int height, render_view *out);

/* Clip-space position of a world point (x, y, w; w the depth along forward). */
void render_view_project(const render_view *v, const double p[3], raster_vertex *out);

#endif
