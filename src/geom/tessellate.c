/* Tessellation of a parametric surface into a grid of triangles with the exact points and
 * normals at the vertices (shadecalc/mesh.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "shadecalc/mesh.h"

enum { MAX_TRIANGLES = 1 << 26, SPEED_SAMPLES = 17 };

void sc_mesh_free(sc_mesh *m)
{
    free(m->pos);
    free(m->normal);
    free(m->uv);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

/* max ‖∂S/∂u‖ / max ‖∂S/∂v‖ over a 17 × 17 sample, within [1/64, 64] (1 if undefined). */
static double speed_ratio(const sc_surface *s)
{
    double su = 0.0, sv = 0.0;
    for (int j = 0; j < SPEED_SAMPLES; j++)
        for (int i = 0; i < SPEED_SAMPLES; i++) {
            sc_surface_point q;
            sc_surface_eval(s, i / (SPEED_SAMPLES - 1.0), j / (SPEED_SAMPLES - 1.0), &q);
            su = fmax(su, sc_dvec3_length(sc_dvec3_from(q.dpdu)));
            sv = fmax(sv, sc_dvec3_length(sc_dvec3_from(q.dpdv)));
        }
    double ratio = su / sv;
    return isfinite(ratio) && ratio > 0.0 ? fmin(fmax(ratio, 1.0 / 64.0), 64.0) : 1.0;
}

/* nu × nv quads, 2·nu·nv ≈ triangles, nu/nv ≈ the speed ratio; at least 3 around a seam. */
static void grid_size(const sc_surface *s, int triangles, int *nu, int *nv)
{
    double ratio = speed_ratio(s);
    *nv = (int)fmax(1.0, round(sqrt(triangles / (2.0 * ratio))));
    *nu = (int)fmax(1.0, round(triangles / (2.0 * *nv)));
    if (sc_surface_closed_u(s) && *nu < 3)
        *nu = 3;
    if (sc_surface_closed_v(s) && *nv < 3)
        *nv = 3;
}

typedef struct {
    int nu, nv;
    sc_mesh *m;
} grid;

static int vertex_index(const grid *g, int i, int j) { return j * (g->nu + 1) + i; }

static void copy_vertex(sc_mesh *m, int to, int from, int with_normal)
{
    memcpy(&m->pos[3 * to], &m->pos[3 * from], 3 * sizeof(float));
    if (with_normal)
        memcpy(&m->normal[3 * to], &m->normal[3 * from], 3 * sizeof(float));
}

/* The exact point, normal and (u,v) at every grid vertex; the largest coordinate in *size.
 * -1 with err at the first point that is not finite. */
static int fill_vertices(const sc_surface *s, const grid *g, double *size, char *err,
                         size_t errsize)
{
    *size = 0.0;
    for (int j = 0; j <= g->nv; j++)
        for (int i = 0; i <= g->nu; i++) {
            int k = vertex_index(g, i, j);
            double u = (double)i / g->nu, v = (double)j / g->nv;
            sc_surface_point q;
            sc_surface_eval(s, u, v, &q);
            if (!(isfinite(q.p[0]) && isfinite(q.p[1]) && isfinite(q.p[2]))) {
                snprintf(err, errsize, "tessellate: the surface is not finite at u=%g v=%g", u, v);
                return -1;
            }
            for (int c = 0; c < 3; c++) {
                g->m->pos[3 * k + c] = (float)q.p[c];
                g->m->normal[3 * k + c] = (float)q.n[c];
                *size = fmax(*size, fabs(q.p[c]));
            }
            g->m->uv[2 * k] = (float)u;
            g->m->uv[2 * k + 1] = (float)v;
        }
    return 0;
}

/* Closed surfaces: the last column (row) repeats the first's position and normal bitwise. */
static void join_seams(const sc_surface *s, const grid *g)
{
    for (int j = 0; j <= g->nv && sc_surface_closed_u(s); j++)
        copy_vertex(g->m, vertex_index(g, g->nu, j), vertex_index(g, 0, j), 1);
    for (int i = 0; i <= g->nu && sc_surface_closed_v(s); i++)
        copy_vertex(g->m, vertex_index(g, i, g->nv), vertex_index(g, i, 0), 1);
}

/* Whether the n vertices first, first + step, ... lie within tol of the first (a pole); if so
 * they get its position exactly. */
static int collapse_line(sc_mesh *m, int first, int step, int n, double tol)
{
    for (int k = 1; k < n; k++)
        for (int c = 0; c < 3; c++)
            if (!(fabs((double)m->pos[3 * (first + k * step) + c] - m->pos[3 * first + c]) <= tol))
                return 0;
    for (int k = 1; k < n; k++)
        copy_vertex(m, first + k * step, first, 0);
    return 1;
}

static void add_triangle(sc_mesh *m, int a, int b, int c)
{
    int *t = &m->tri[3 * m->n_triangles++];
    t[0] = a;
    t[1] = b;
    t[2] = c;
}

/* Two triangles per quad, CCW seen from outside (∂S/∂u × ∂S/∂v outward): (a, b, c) with
 * a = (i, j), b = (i+1, j), c = (i+1, j+1), and (a, c, d) with d = (i, j+1); a triangle with two
 * corners on a collapsed row or column has zero area and is left out. */
static void build_triangles(const grid *g, const char *row_gone, const char *col_gone)
{
    sc_mesh *m = g->m;
    m->n_triangles = 0;
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++) {
            int a = vertex_index(g, i, j), b = vertex_index(g, i + 1, j);
            int c = vertex_index(g, i + 1, j + 1), d = vertex_index(g, i, j + 1);
            if (!row_gone[j] && !col_gone[i + 1])
                add_triangle(m, a, b, c);
            if (!row_gone[j + 1] && !col_gone[i])
                add_triangle(m, a, c, d);
        }
}

static int connect(const grid *g, double size)
{
    double tol = 0x1p-40 * size;
    char *row_gone = calloc((size_t)g->nv + 1, 1), *col_gone = calloc((size_t)g->nu + 1, 1);
    if (row_gone == NULL || col_gone == NULL) {
        free(row_gone);
        free(col_gone);
        return -1;
    }
    for (int j = 0; j <= g->nv; j++)
        row_gone[j] = (char)collapse_line(g->m, vertex_index(g, 0, j), 1, g->nu + 1, tol);
    for (int i = 0; i <= g->nu; i++)
        col_gone[i] = (char)collapse_line(g->m, vertex_index(g, i, 0), g->nu + 1, g->nv + 1, tol);
    build_triangles(g, row_gone, col_gone);
    free(row_gone);
    free(col_gone);
    return 0;
}

static int allocate(sc_mesh *m, int n_vertices, int n_triangles)
{
    memset(m, 0, sizeof *m);
    m->n_vertices = n_vertices;
    m->pos = malloc(sizeof(float) * 3 * (size_t)n_vertices);
    m->normal = malloc(sizeof(float) * 3 * (size_t)n_vertices);
    m->uv = malloc(sizeof(float) * 2 * (size_t)n_vertices);
    m->tri = malloc(sizeof(int) * 3 * (size_t)n_triangles);
    if (m->pos && m->normal && m->uv && m->tri)
        return 0;
    sc_mesh_free(m);
    return -1;
}

int sc_surface_tessellate(const sc_surface *s, int triangles, sc_mesh *out, char *err,
                          size_t errsize)
{
    grid g = {0, 0, out};
    if (triangles < 2 || triangles > MAX_TRIANGLES) {
        snprintf(err, errsize, "tessellate: %d triangles: expected 2 .. %d", triangles,
                 MAX_TRIANGLES);
        return -1;
    }
    grid_size(s, triangles, &g.nu, &g.nv);
    if (allocate(out, (g.nu + 1) * (g.nv + 1), 2 * g.nu * g.nv) < 0) {
        snprintf(err, errsize, "tessellate: out of memory for %d triangles", triangles);
        return -1;
    }
    double size;
    int status = fill_vertices(s, &g, &size, err, errsize);
    if (status == 0) {
        join_seams(s, &g);
        status = connect(&g, size);
        if (status < 0)
            snprintf(err, errsize, "tessellate: out of memory");
        else if (out->n_triangles == 0) {
            snprintf(err, errsize, "tessellate: the surface has no area");
            status = -1;
        }
    }
    if (status < 0)
        sc_mesh_free(out);
    return status;
}
