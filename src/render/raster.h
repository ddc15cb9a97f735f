/*
 * render/raster.h — the triangle rasterizer behind sc_render (private to src/render and its
 * tests).
 *
 *   raster_vertex        a vertex in clip space (x, y, w; w = view depth) with its barycentric
 *                        coordinates in the source triangle (clipping makes new vertices)
 *   raster_clip          Sutherland–Hodgman against the near plane and a guard band
 *   raster_tri           a set-up screen triangle: fixed-point vertices, edge biases, 1/w
 *   raster_setup         clip space -> fixed-point screen triangle (0 if nothing to draw)
 *   raster_cover         call a function for each pixel of a rectangle the triangle covers
 *   raster_barycentric   the perspective-correct barycentrics of a pixel in the source triangle
 *
 * Screen: pixel (x, y) has its centre at (x + 0.5, y + 0.5), y = 0 the top row. Vertices are
 * snapped to 1/2^RASTER_SUBPIXEL_BITS pixel; edge functions are exact 64-bit integers.
 * Fill rule (top-left, as Direct3D 10 and OpenGL implementations): a pixel centre exactly on an
 * edge belongs to the triangle for which that edge is a top or left edge. With the vertices
 * ordered so that the area is positive, an edge a→b is claimed when b.y < a.y, or b.y = a.y
 * and b.x > a.x; the edge b→a of the neighbour is then not, so a shared edge's pixels are
 * drawn exactly once and a closed mesh leaves no gap (watertight).
 * Interpolation: screen-space barycentrics λ_i are affine in the pixel; attributes divided by
 * w are too, so the perspective-correct weight is b_i = (λ_i/w_i) / Σ_j λ_j/w_j (Heckbert and
 * Moreton 1991).
 */
#ifndef SHADECALC_RENDER_RASTER_H
#define SHADECALC_RENDER_RASTER_H

#include <stdint.h>

enum { RASTER_SUBPIXEL_BITS = 8, RASTER_CLIP_MAX = 9 };

typedef struct {
    double x, y, w; /* clip space: x/w, y/w in [-1, 1] on screen; w > 0 in front of the eye */
    double bc[3];   /* barycentric coordinates in the source triangle */
} raster_vertex;

typedef struct {
    int64_t x[3], y[3]; /* fixed-point screen coordinates */
    int64_t area;       /* twice the area in fixed-point units squared, > 0 */
    int bias[3];        /* 0 for a top or left edge, -1 otherwise (edge i is opposite vertex i) */
    double inv_w[3];
    double bc[3][3];    /* vertex i's barycentrics in the source triangle */
    int x0, y0, x1, y1; /* the pixel bounding box, inclusive, inside the screen */
    int source;         /* index of the source triangle */
} raster_tri;

/* Clips the triangle against w >= near and |x|, |y| <= guard·w. Writes the polygon (at most
 * RASTER_CLIP_MAX vertices) to out and returns its vertex count, 0 if nothing is left.
 * A new vertex is computed from the inside end of the cut edge, so the triangles that share an
 * edge cut it at the same point. Non-finite coordinates give 0. */
int raster_clip(const raster_vertex in[3], double near, double guard,
                raster_vertex out[RASTER_CLIP_MAX]);

/* The guard band for a width × height screen: clip-space |x|/w, |y|/w up to this value keep
 * every fixed-point coordinate and edge function product inside 64 bits. */
double raster_guard_band(int width, int height);

/* Sets up a clipped triangle for a width × height screen; returns 1, or 0 when it has no area
 * or misses the screen. */
int raster_setup(const raster_vertex v[3], int width, int height, int source, raster_tri *out);

/* Calls fn(ctx, x, y, lambda) for each pixel of the rectangle [x0, x1] × [y0, y1] (inclusive)
 * that t covers, row by row; lambda is the screen-space barycentric triple. */
typedef void raster_fragment_fn(void *ctx, int x, int y, const double lambda[3]);
void raster_cover(const raster_tri *t, int x0, int y0, int x1, int y1, raster_fragment_fn *fn,
                  void *ctx);

/* The screen-space barycentrics of pixel (x, y)'s centre (not necessarily covered). */
void raster_lambda(const raster_tri *t, int x, int y, double lambda[3]);

/* The perspective-correct barycentrics in the source triangle for screen barycentrics lambda,
 * and 1/w there (Heckbert–Moreton). */
double raster_barycentric(const raster_tri *t, const double lambda[3], double b[3]);

#endif
