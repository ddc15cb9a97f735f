/* Triangle normals and per-vertex normals by plain, area- or angle-weighted averaging of the
 * adjacent face normals (shadecalc/mesh.h, docs/formulas.md §7). All sums in double. */
#include <math.h>
#include <stdlib.h>

#include "geom/geom_internal.h"
#include "shadecalc/mesh.h"

static double max_abs(sc_dvec3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }

/* The binary exponent k of big (0 if big is 0 or not finite): v·2^-k brings big into [1, 2). */
static int unit_exponent(double big) { return big > 0.0 && isfinite(big) ? ilogb(big) : 0; }

/* v·2^-k, exact (ldexp per component: 2^-k alone overflows for a subnormal big). */
static sc_dvec3 times_pow2(sc_dvec3 v, int minus_k)
{
    return (sc_dvec3){ldexp(v.x, minus_k), ldexp(v.y, minus_k), ldexp(v.z, minus_k)};
}

sc_dvec3 sc_dvec3_unit_scaled(sc_dvec3 v) { return times_pow2(v, -unit_exponent(max_abs(v))); }

/* e1 × e2; 1 if the triangle is degenerate: the cross product is within its rounding error
 * 4ε‖e1‖‖e2‖ of zero, or not finite. */
static int edge_cross(sc_dvec3 e1, sc_dvec3 e2, sc_dvec3 *cross)
{
    *cross = sc_dvec3_cross(e1, e2);
    double len = sc_dvec3_length(*cross);
    return !(len > 4.0 * 0x1p-53 * sc_dvec3_length(e1) * sc_dvec3_length(e2)) || !isfinite(len);
}

/* (b − a) × (c − a) (docs/formulas.md §7) of a mesh's float positions: in double it neither overflows nor
 * underflows (|x| <= 3.4e38 and >= 1.4e-45), and its length is the area weight. */
static int face_cross(sc_dvec3 a, sc_dvec3 b, sc_dvec3 c, sc_dvec3 *cross)
{
    return edge_cross(sc_dvec3_sub(b, a), sc_dvec3_sub(c, a), cross);
}

/* A triangle of any doubles: the corners scaled by a common power of two (no overflow in the
 * differences), then each edge scaled to unit size (no overflow or underflow in the cross
 * product: the corners 1e308 or 1e-200 apart are not degenerate). */
void sc_triangle_normal(const double a[3], const double b[3], const double c[3], double n[3])
{
    sc_dvec3 pa = sc_dvec3_from(a), pb = sc_dvec3_from(b), pc = sc_dvec3_from(c);
    int k = unit_exponent(fmax(max_abs(pa), fmax(max_abs(pb), max_abs(pc))));
    pa = times_pow2(pa, -k);
    pb = times_pow2(pb, -k);
    pc = times_pow2(pc, -k);
    sc_dvec3 cross, unit = {0.0, 0.0, 0.0};
    if (!edge_cross(sc_dvec3_unit_scaled(sc_dvec3_sub(pb, pa)),
                    sc_dvec3_unit_scaled(sc_dvec3_sub(pc, pa)), &cross))
        unit = sc_dvec3_normalize(cross);
    n[0] = unit.x;
    n[1] = unit.y;
    n[2] = unit.z;
}

static sc_dvec3 position(const sc_mesh *m, int k)
{
    const float *p = &m->pos[3 * k];
    return (sc_dvec3){p[0], p[1], p[2]};
}

/* The angle at corner `at` between the edges to `p` and `q`: atan2(‖e1 × e2‖, e1·e2). */
static double corner_angle(sc_dvec3 at, sc_dvec3 p, sc_dvec3 q)
{
    sc_dvec3 e1 = sc_dvec3_sub(p, at), e2 = sc_dvec3_sub(q, at);
    return atan2(sc_dvec3_length(sc_dvec3_cross(e1, e2)), sc_dvec3_dot(e1, e2));
}

/* Adds triangle t's contribution to the sums of its three corners; 1 if it is degenerate. */
static int add_face(const sc_mesh *m, const int *t, sc_normal_weighting w, sc_dvec3 *sum)
{
    sc_dvec3 v[3] = {position(m, t[0]), position(m, t[1]), position(m, t[2])}, cross;
    if (face_cross(v[0], v[1], v[2], &cross))
        return 1;
    sc_dvec3 unit = sc_dvec3_normalize(cross);
    for (int k = 0; k < 3; k++) {
        sc_dvec3 add = unit;
        if (w == SC_NORMALS_AREA)
            add = cross;
        else if (w == SC_NORMALS_ANGLE)
            add = sc_dvec3_scale(unit, corner_angle(v[k], v[(k + 1) % 3], v[(k + 2) % 3]));
        sum[t[k]] = sc_dvec3_add(sum[t[k]], add);
    }
    return 0;
}

int sc_mesh_vertex_normals(sc_mesh *m, sc_normal_weighting w)
{
    sc_dvec3 *sum = calloc((size_t)m->n_vertices + 1, sizeof *sum);
    if (m->normal == NULL)
        m->normal = malloc(sizeof(float) * 3 * ((size_t)m->n_vertices + 1));
    if (sum == NULL || m->normal == NULL) {
        free(sum);
        return -1;
    }
    int degenerate = 0;
    for (int t = 0; t < m->n_triangles; t++)
        degenerate += add_face(m, &m->tri[3 * t], w, sum);
    for (int k = 0; k < m->n_vertices; k++) {
        double len = sc_dvec3_length(sum[k]);
        sc_dvec3 n = len > 0.0 && isfinite(len) ? sc_dvec3_scale(sum[k], 1.0 / len)
                                                : (sc_dvec3){0.0, 0.0, 1.0};
        m->normal[3 * k] = (float)n.x;
        m->normal[3 * k + 1] = (float)n.y;
        m->normal[3 * k + 2] = (float)n.z;
    }
    free(sum);
    return degenerate;
}
