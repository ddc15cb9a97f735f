/*
 * shadecalc/mesh.h — triangle meshes: tessellated surfaces, face and vertex normals, OBJ files
 * (docs/formulas.md §7).
 *
 *   sc_mesh                  positions, optional normals and (u,v), triangles (CCW outside)
 *   sc_mesh_free
 *   sc_surface_tessellate    a grid of about N triangles with the exact points and normals
 *   sc_normal_weighting      SC_NORMALS_PLAIN | SC_NORMALS_AREA | SC_NORMALS_ANGLE
 *   sc_mesh_vertex_normals   per-vertex normals from the adjacent faces; degenerate count
 *   sc_triangle_normal       unit (P2 − P1) × (P3 − P1), or 0 for a degenerate triangle
 *   sc_obj_read              Wavefront OBJ (v, vn, f) -> mesh; errors name the line
 *   sc_obj_write             mesh -> OBJ, atomically (shadecalc/file.h)
 *
 * Tessellation: an nu × nv grid of quads over [0,1]², two triangles each, nu/nv the ratio of
 * the longest u and v parameter speeds (max ‖∂S/∂u‖ / max ‖∂S/∂v‖ on a 17 × 17 sample; 2 for
 * a sphere, as in the lecture's 1024 = 2·32·16 and 6320 = 2·79·40), 2·nu·nv ≈ N. Every vertex
 * is sc_surface_eval's exact point and normal, in float. Seams of closed surfaces copy the
 * position and normal of the first row/column (bitwise equal; (u,v) stay 1 there). A row or
 * column that collapses to one point (a pole) gets one position and loses the triangles
 * that would have zero area, so a sphere of 2·nu·nv has 2·nu·(nv − 1) triangles.
 *
 * Vertex normals (docs/formulas.md §7: the normalized sum of the adjacent face normals): PLAIN sums the
 * unit face normals (the lecture's (n12 + n23 + n34 + n41)/‖…‖), AREA the unnormalized
 * (P2 − P1) × (P3 − P1) (twice the area times the unit normal), ANGLE the unit normals times
 * the face's angle at the vertex (Thürmer & Wüthrich 1998). A triangle is degenerate when
 * ‖(P2 − P1) × (P3 − P1)‖ <= 4ε‖P2 − P1‖‖P3 − P1‖ in double (ε = 2⁻⁵³), i.e. zero up to the
 * cross product's rounding; it contributes nothing. A vertex with no contribution (or whose sum
 * cancels) gets (0, 0, 1).
 *
 * OBJ: `v x y z [w]`, `vn x y z`, `f` with `i`, `i/t`, `i//n`, `i/t/n` corners (1-based or
 * negative = relative, referring to elements defined earlier), polygons split into fans;
 * `vt`, `vp`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, comments and blank lines are
 * ignored. A vertex used with two different normals is split in two. If only some faces give
 * normals, normals are dropped (NULL). Malformed lines (a bad or non-finite number, an index
 * out of range, a face of fewer than 3 corners, any other statement) and files without faces
 * fail with "PATH:LINE: reason". Written files have
 * v, vn (if normals), vt (if uv) and `f a/b/c` lines, numbers with 9 significant digits (floats
 * round-trip exactly).
 *
 * Functions returning int give 0 (or a count) on success and −1 with a message in err.
 */
#ifndef SHADECALC_MESH_H
#define SHADECALC_MESH_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/surface.h"

SC_BEGIN_DECLS

typedef struct {
    int n_vertices, n_triangles;
    float *pos;    /* 3 per vertex */
    float *normal; /* 3 per vertex, or NULL */
    float *uv;     /* 2 per vertex (surface parameters), or NULL (OBJ meshes) */
    int *tri;      /* 3 vertex indices per triangle, counter-clockwise seen from outside */
} sc_mesh;

/* Frees the arrays and zeroes *m (a zeroed mesh is a valid argument). */
void sc_mesh_free(sc_mesh *m);

/* A grid of about `triangles` triangles (2 .. 2^26) over [0,1]², vertices at the exact surface
 * points with the exact normals and their (u,v). 0, or -1 with err. */
int sc_surface_tessellate(const sc_surface *s, int triangles, sc_mesh *out, char *err,
                          size_t errsize);

typedef enum { SC_NORMALS_PLAIN, SC_NORMALS_AREA, SC_NORMALS_ANGLE } sc_normal_weighting;

/* Per-vertex normals by averaging adjacent face normals (allocating m->normal if NULL);
 * returns the count of degenerate (zero-area) triangles, which contribute nothing, or -1 if
 * out of memory. */
int sc_mesh_vertex_normals(sc_mesh *m, sc_normal_weighting w);

/* n = (b − a) × (c − a) normalized; (0, 0, 0) if the triangle is degenerate (above). */
void sc_triangle_normal(const double a[3], const double b[3], const double c[3], double n[3]);

/* Reads a Wavefront OBJ file ("-": standard input). 0; -1 with err when the content is
 * malformed (err names FILE:LINE); -2 with err when the file cannot be opened or read, or
 * memory runs out. */
int sc_obj_read(const char *path, sc_mesh *out, char *err, size_t errsize);
int sc_obj_write(const char *path, const sc_mesh *m, char *err, size_t errsize); /* atomic */

SC_END_DECLS

#endif
