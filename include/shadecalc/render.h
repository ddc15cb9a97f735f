/*
 * shadecalc/render.h — a software rasterizer: meshes of parametric surfaces drawn with flat,
 * Gouraud, Phong or exact per-pixel shading, and the error of each against the exact (docs/formulas.md §8).
 *
 *   sc_camera, sc_camera_fit       perspective camera (eye, at, up, vertical field of view);
 *                                  a camera that frames a mesh
 *   sc_camera_validate             eye ≠ at, up not along the view, 0 < fov < 180
 *   sc_shading                     flat | gouraud | phong | exact
 *   sc_shading_parse, sc_shading_name
 *   sc_framebuffer                 RGBA, view depth and shading normal per pixel
 *   sc_framebuffer_init, _free     every plane; _init_planes: RGBA and the planes asked for
 *   sc_render_image                a framebuffer as an image (R G B A [Z] [N.X N.Y N.Z]);
 *                                  _take: the same, taking the RGBA array when that is all
 *   sc_render                      rasterize and shade a mesh, tiles spread over threads
 *   sc_render_compare              RMSE and maximum error of an image against a reference
 *
 * Pipeline: every triangle goes to clip space, is clipped against the near plane (w ≥ near =
 * |at − eye|/1000) and a guard band, snapped to 1/256 pixel, and drawn with the top-left fill
 * rule (watertight: a closed mesh covers each pixel it hides exactly once) and a z-buffer on
 * 1/w (nearest wins; on a tie the triangle listed first). Each pixel keeps the triangle and the
 * perspective-correct barycentrics of its centre, then is shaded once:
 *   flat     one colour per face: sc_shade at the centroid with the face's geometric normal
 *   gouraud  sc_shade at each vertex with its normal; colours interpolated (perspective-correct)
 *   phong    position and normal interpolated, the normal renormalized, sc_shade per pixel
 *   exact    (u, v) interpolated, then the surface's own point and normal (sc_surface_eval)
 *            per pixel: the reference
 * Both sides are drawn: a triangle seen from behind (its counter-clockwise side away from the
 * eye) is shaded with its normals reversed. v is the unit vector from the shaded point to the
 * eye. Shading uses no tangent: anisotropic BRDFs get an arbitrary tangent.
 */
#ifndef SHADECALC_RENDER_H
#define SHADECALC_RENDER_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/image.h"
#include "shadecalc/mesh.h"
#include "shadecalc/shade.h"
#include "shadecalc/surface.h"

SC_BEGIN_DECLS

/* At most this many pixels (e.g. 8192 × 4096) and this many per side. */
#define SC_RENDER_MAX_PIXELS ((long)1 << 25)
enum { SC_RENDER_MAX_SIDE = 16384 };

typedef struct {
    double eye[3], at[3], up[3];
    double fov; /* vertical field of view, degrees */
} sc_camera;

/* Sets at to the centre of m's bounding sphere and eye along `direction` (need not be unit)
 * from it, far enough that the sphere fits the view with a 5% margin on a width × height
 * screen. up and fov are kept. */
void sc_camera_fit(sc_camera *c, const sc_mesh *m, const double direction[3], int width,
                   int height);

/* 0, or -1 with a message ("--eye 0,0,0 equals --at"). */
int sc_camera_validate(const sc_camera *c, char *err, size_t errsize);

typedef enum { SC_SHADING_FLAT, SC_SHADING_GOURAUD, SC_SHADING_PHONG, SC_SHADING_EXACT } sc_shading;

/* "flat|gouraud|phong|exact"; 0, or -1 for another name. */
int sc_shading_parse(const char *name, sc_shading *out);
const char *sc_shading_name(sc_shading s);

typedef struct {
    int width, height;
    float *rgba;   /* 4 per pixel, row 0 the top; A = 1 where a triangle covers, else all 0 */
    float *depth;  /* view-space depth (along the view axis), +Inf where nothing is drawn;
                      NULL when not asked for */
    float *normal; /* 3 per pixel: the unit normal the pixel was shaded with, 0 where empty;
                      NULL when not asked for */
} sc_framebuffer;

/* The planes besides RGBA. A render writes only those the framebuffer has: a plane nobody
 * reads would cost its memory's first touch (a 2048x2048 render's depth and normals are
 * 64 MiB that the kernel zeroes page by page). */
enum { SC_FRAMEBUFFER_DEPTH = 1, SC_FRAMEBUFFER_NORMAL = 2, SC_FRAMEBUFFER_ALL = 3 };

/* Zeroed RGBA plus the planes in the mask `planes`; sc_framebuffer_init: every plane. The
 * arrays belong to the library, as an sc_image's data (image.h): released by
 * sc_framebuffer_free (or taken by sc_render_image_take) only.
 * 0, or -1 (size outside 1..SC_RENDER_MAX_SIDE or above SC_RENDER_MAX_PIXELS, planes outside
 * SC_FRAMEBUFFER_ALL, no memory). */
int sc_framebuffer_init_planes(sc_framebuffer *fb, int width, int height, int planes);
int sc_framebuffer_init(sc_framebuffer *fb, int width, int height);
void sc_framebuffer_free(sc_framebuffer *fb);

/* The framebuffer as an image with channels R, G, B, A, then Z (the depth) if depth, then N.X,
 * N.Y, N.Z (the normal) if normals. 0, or -1 (out of memory, or a plane asked for that fb
 * lacks). sc_render_image_take gives the same image, but when it has only R, G, B and A it
 * takes fb's RGBA array instead of copying it (fb->rgba is then NULL). */
int sc_render_image(const sc_framebuffer *fb, int depth, int normals, sc_image *out);
int sc_render_image_take(sc_framebuffer *fb, int depth, int normals, sc_image *out);

/* Called after each tile (from the worker threads, one at a time). */
typedef void sc_render_progress_fn(void *ctx, int tiles_done, int tiles_total);

typedef struct {
    const sc_mesh *mesh;       /* normals needed for gouraud and phong, uv for exact */
    const sc_surface *surface; /* exact: the surface the mesh's uv refer to */
    const sc_scene *scene;
    sc_prec prec;     /* the precision sc_shade computes in */
    const char *tier; /* highp: the batch shading kernel's tier (batch.h: accurate,
                                  bits12); NULL: accurate */
    sc_shading shading;
    sc_camera camera;
    int threads;                     /* 0: one per online core */
    sc_render_progress_fn *progress; /* or NULL */
    void *progress_ctx;
} sc_render_params;

/* Draws into fb (initialized; cleared here, tile by tile: after a failure its pixels are
 * unspecified), into the planes it has. 0, or -1 with err (invalid camera, a mesh without the
 * normals or uv the shading needs, exact without a surface, fb without RGBA, out of memory). */
int sc_render(const sc_render_params *p, sc_framebuffer *fb, char *err, size_t errsize);

typedef struct {
    double rmse;      /* sqrt of the mean over pixels and R, G, B of the squared difference */
    double max_error; /* the largest |difference| of one channel */
    long pixels;      /* the pixels compared: those ref covers (A > 0) */
} sc_render_error;

/* img against ref over the pixels ref covers (an uncovered pixel of img counts as its RGB, 0).
 * map (width × height floats, or NULL) receives each pixel's largest channel difference, 0
 * where ref is empty. The sizes must match. */
void sc_render_compare(const sc_framebuffer *img, const sc_framebuffer *ref, float *map,
                       sc_render_error *out);

SC_END_DECLS

#endif
