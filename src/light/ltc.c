/* Linearly transformed cosines over polygons and disks (light/ltc.h; docs/ltc.md).
 *
 * The polygon is carried into the view frame (z = n, v in the xz plane), normalised vertex by
 * vertex, and clipped to the horizon z >= 0. Its clamped-cosine integral is Lambert's edge sum
 * (Lambert 1760; Arvo 1995) ½ |Σ_i θ_i ẑ·(p_i × p_(i+1))/|p_i × p_(i+1)||, θ_i the angle
 * between p_i and p_(i+1), taken with atan2 so that short and near-parallel edges keep their
 * precision. The GGX lobe is the cosine carried by a fitted matrix M: the same polygon, carried
 * by M⁻¹ and clipped again, has the cosine integral of the lobe (Heitz et al. 2016). */
#include "light/ltc.h"

#include <math.h>
#include <string.h>

#include "shadecalc/pmath.h"

static const double pi = 3.14159265358979323846;

/* Room for a polygon clipped by a plane: each vertex and at most one crossing after it, so
 * twice as many vertices once clipped, four times as many clipped twice. */
#define CLIPPED_ONCE (2 * SC_LTC_MAX_VERTS)
#define CLIPPED_TWICE (4 * SC_LTC_MAX_VERTS)

/* Helpers take vec3 * without const: C11 does not convert double (*)[3] to const double (*)[3]. */
typedef double vec3[3];

static double dot3(const double a[3], const double b[3]) { return sc_p_dot(SC_DOUBLE, a, b, 3); }

static void cross3(const double a[3], const double b[3], double out[3])
{
    sc_p_cross(SC_DOUBLE, a, b, out);
}

/* Normalises in place (sc_p_normalize gives NaN for 0); returns the length before. */
static double normalize3(double a[3])
{
    double len = sc_p_length(SC_DOUBLE, a, 3);
    if (len > 0.0)
        sc_p_normalize(SC_DOUBLE, a, 3, a);
    return len;
}

/* ---- the clamped cosine over a polygon ---- */

/* Sutherland–Hodgman against the plane z = 0, keeping z >= 0. Returns the vertex count. */
static int clip_to_horizon(vec3 *in, int count, vec3 *out)
{
    int m = 0;
    for (int i = 0; i < count; i++) {
        const double *a = in[i], *b = in[(i + 1) % count];
        if (a[2] >= 0.0)
            memcpy(out[m++], a, sizeof(vec3));
        if ((a[2] > 0.0 && b[2] < 0.0) || (a[2] < 0.0 && b[2] > 0.0)) {
            double t = a[2] / (a[2] - b[2]);
            for (int c = 0; c < 2; c++)
                out[m][c] = a[c] + t * (b[c] - a[c]);
            out[m++][2] = 0.0;
        }
    }
    return m;
}

/* Σ_i θ_i ẑ·(p_i × p_(i+1))/|p_i × p_(i+1)|: 2π times the signed cosine form factor. An edge whose
 * ends are parallel (a point) or opposite (through the origin, only on the emitter's plane)
 * adds nothing. */
static double edge_sum(vec3 *poly, int count)
{
    double sum = 0.0;
    for (int i = 0; i < count; i++) {
        const double *a = poly[i], *b = poly[(i + 1) % count];
        double c[3];
        cross3(a, b, c);
        double s = sqrt(dot3(c, c));
        if (s > 0.0)
            sum += atan2(s, dot3(a, b)) * (c[2] / s);
    }
    return sum;
}

/* ∫ max(cos θ, 0) dω / π over a polygon of at most CLIPPED_ONCE vertices (view frame), clipped
 * here: in [0, 1]. */
static double cosine_form_factor(vec3 *poly, int count)
{
    vec3 clipped[CLIPPED_TWICE];
    int m = clip_to_horizon(poly, count, clipped);
    if (m < 3)
        return 0.0;
    double f = fabs(edge_sum(clipped, m)) / (2.0 * pi);
    return f < 1.0 ? f : 1.0;
}

/* ---- the fitted lobe ---- */

void sc_ltc_brdf(double alpha, const double *f0, sc_brdf *out)
{
    sc_brdf_init(out, SC_BRDF_COOK_TORRANCE);
    out->form = SC_CT_WALTER;
    out->D = SC_D_GGX;
    out->G = SC_G_SMITH_CORRELATED;
    out->F = f0 ? SC_F_SCHLICK : SC_F_NONE;
    out->ax = out->ay = alpha;
    for (int k = 0; k < 3; k++) {
        out->diff[k] = 0.0;
        out->spec[k] = 1.0;
        out->f0[k] = f0 ? f0[k] : 0.0;
    }
}

/* The table's inverse matrices, magnitudes and Fresnel parts at fractional indices. */
static void bilinear(double x, double y, double out[SC_LTC_FIELDS])
{
    int i = (int)x, j = (int)y;
    i = i > SC_LTC_SIZE - 2 ? SC_LTC_SIZE - 2 : i;
    j = j > SC_LTC_SIZE - 2 ? SC_LTC_SIZE - 2 : j;
    double fx = x - i, fy = y - j;
    for (int k = 0; k < SC_LTC_FIELDS; k++) {
        double lo = sc_ltc_table[j][i][k] +
                    fx * (sc_ltc_table[j][i + 1][k] - sc_ltc_table[j][i][k]);
        double hi = sc_ltc_table[j + 1][i][k] +
                    fx * (sc_ltc_table[j + 1][i + 1][k] - sc_ltc_table[j + 1][i][k]);
        out[k] = lo + fy * (hi - lo);
    }
}

/* The table at (α, cos θ_v), both clamped to its range: M⁻¹'s entries (m00, m02, m11, m20),
 * the magnitude A and the Fresnel part B. */
static void lookup(double alpha, double cos_v, double minv[4], double *a, double *b)
{
    alpha = !(alpha >= SC_LTC_ALPHA_MIN) ? SC_LTC_ALPHA_MIN
            : alpha > 1.0                ? 1.0
                                         : alpha; /* NaN too */
    cos_v = !(cos_v >= 0.0) ? 0.0 : cos_v > 1.0 ? 1.0 : cos_v;
    double entry[SC_LTC_FIELDS];
    bilinear(sqrt(alpha) * (SC_LTC_SIZE - 1), sqrt(1.0 - cos_v) * (SC_LTC_SIZE - 1), entry);
    memcpy(minv, entry, 4 * sizeof(double));
    *a = entry[SC_LTC_A];
    *b = entry[SC_LTC_B];
}

/* The share of the LTC above the horizon: the cosine's mass on the side w·m >= 0 of the plane
 * that M⁻¹ makes of z = 0, m = Mᵀẑ. Lambert's edge sum over the lune between the two great
 * circles gives (1 + m̂_z)/2. With M⁻¹'s xz block [[m00, m02], [m20, 1]], Mᵀẑ ∝ (−m20, 0, m00)
 * divided by the block's determinant. */
static double mass_above_horizon(const double minv[4])
{
    double det = minv[0] - minv[1] * minv[3];
    double len = hypot(minv[0], minv[3]);
    if (det == 0.0 || len == 0.0)
        return 0.0;
    return 0.5 * (1.0 + (det > 0.0 ? minv[0] : -minv[0]) / len);
}

/* ∫ over the polygon (view frame, clipped to z >= 0, at most CLIPPED_ONCE vertices) of the LTC
 * with inverse matrix minv (m00, m02, m11, m20), restricted to the upper hemisphere and
 * renormalised to integrate to 1 there. */
static double lobe_integral(const double minv[4], vec3 *poly, int count)
{
    if (count < 3 || count > CLIPPED_ONCE)
        return 0.0;
    double mass = mass_above_horizon(minv);
    if (!(mass > 1e-6))
        return 0.0;
    vec3 carried[CLIPPED_ONCE];
    for (int i = 0; i < count; i++) {
        const double *p = poly[i];
        carried[i][0] = minv[0] * p[0] + minv[1] * p[2];
        carried[i][1] = minv[2] * p[1];
        carried[i][2] = minv[3] * p[0] + p[2];
        normalize3(carried[i]);
    }
    return cosine_form_factor(carried, count) / mass;
}

/* ---- polygons ---- */

/* The view frame: z = n, x the direction of v in the tangent plane (the frame's tangent when v
 * is along n), y = z × x. */
static void view_frame(const sc_frame *frame, const double v[3], double axes[3][3])
{
    memcpy(axes[2], frame->n, sizeof(vec3));
    double vn = dot3(v, frame->n);
    for (int c = 0; c < 3; c++)
        axes[0][c] = v[c] - vn * frame->n[c];
    if (normalize3(axes[0]) < 1e-12)
        memcpy(axes[0], frame->t, sizeof(vec3));
    cross3(axes[2], axes[0], axes[1]);
}

static int all_finite(const double *x, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

typedef enum { EMITTER_DEGENERATE, EMITTER_UNSEEN, EMITTER_SEEN } emitter_view;

/* Whether the polygon (scaled by 1/max|coordinate|) has an area, and whether the shading point
 * sees its emitting side: the right-hand (Newell) normal N = Σ v_i × v_(i+1) against the
 * centroid c: seen from the front when N·c < 0. On the plane (|N̂·c| at rounding level): unseen. */
static emitter_view classify(vec3 *w, int count, int two_sided)
{
    double normal[3] = {0, 0, 0}, centroid[3] = {0, 0, 0};
    for (int i = 0; i < count; i++) {
        double c[3];
        cross3(w[i], w[(i + 1) % count], c);
        for (int k = 0; k < 3; k++) {
            normal[k] += c[k];
            centroid[k] += w[i][k] / count;
        }
    }
    if (normalize3(normal) <= 1e-14)
        return EMITTER_DEGENERATE;
    double side = dot3(normal, centroid);
    if (fabs(side) <= 1e-12 || (!two_sided && side > 0.0))
        return EMITTER_UNSEEN;
    return EMITTER_SEEN;
}

/* The vertices scaled by one factor (solid angles do not change) so that the largest
 * coordinate is 1: no overflow in the cross products, no underflow for tiny emitters. */
static int scale_vertices(const double (*verts)[3], int count, vec3 *out)
{
    double big = 0.0;
    for (int i = 0; i < count; i++)
        for (int c = 0; c < 3; c++)
            big = fmax(big, fabs(verts[i][c]));
    if (!(big > 0.0))
        return -1;
    for (int i = 0; i < count; i++)
        for (int c = 0; c < 3; c++)
            out[i][c] = verts[i][c] / big;
    return 0;
}

/* The GGX integral F0 (A − B) + B times the lobe's share of the clipped polygon. */
static void specular(double alpha, double cos_v, const double f0[3], vec3 *poly, int count,
                     double spec[3])
{
    double minv[4], a, b;
    lookup(alpha, cos_v, minv, &a, &b);
    double share = lobe_integral(minv, poly, count);
    for (int k = 0; k < 3; k++)
        spec[k] = (f0[k] * (a - b) + b) * share;
}

int sc_ltc_polygon(const sc_frame *frame, const double v[3], double alpha, const double f0[3],
                   const double (*verts)[3], int count, int two_sided, sc_ltc_result *out)
{
    memset(out, 0, sizeof *out);
    if (count < 3 || count > SC_LTC_MAX_VERTS || !all_finite(v, 3) || !all_finite(f0, 3) ||
        !(alpha > 0.0) || !isfinite(alpha) || !all_finite(frame->n, 3))
        return -1;
    for (int i = 0; i < count; i++)
        if (!all_finite(verts[i], 3))
            return -1;
    vec3 world[SC_LTC_MAX_VERTS], local[SC_LTC_MAX_VERTS], clipped[CLIPPED_ONCE];
    if (scale_vertices(verts, count, world) < 0)
        return -1;
    emitter_view seen = classify(world, count, two_sided);
    if (seen == EMITTER_DEGENERATE)
        return -1;
    if (seen == EMITTER_UNSEEN)
        return 0;
    double axes[3][3], view[3] = {v[0], v[1], v[2]};
    if (normalize3(view) == 0.0)
        return -1;
    view_frame(frame, view, axes);
    for (int i = 0; i < count; i++) {
        for (int c = 0; c < 3; c++)
            local[i][c] = dot3(world[i], axes[c]);
        normalize3(local[i]);
    }
    int m = clip_to_horizon(local, count, clipped);
    if (m < 3)
        return 0;
    out->cosine = fmin(0.5 * fabs(edge_sum(clipped, m)), pi);
    double cos_v = dot3(view, frame->n);
    if (cos_v > 0.0)
        specular(alpha, cos_v, f0, clipped, m, out->spec);
    return 0;
}

/* ---- disks ---- */

int sc_ltc_disk(const sc_frame *frame, const double v[3], double alpha, const double f0[3],
                const double center[3], const double normal[3], double radius, int two_sided,
                sc_ltc_result *out)
{
    memset(out, 0, sizeof *out);
    double axis[3] = {normal[0], normal[1], normal[2]};
    if (!all_finite(center, 3) || !all_finite(axis, 3) || !(radius > 0.0) || !isfinite(radius) ||
        !(normalize3(axis) > 0.0))
        return -1;
    /* e1, e2 = axis × e1: counter-clockwise about the axis, so the polygon faces the axis */
    double e1[3] = {0, 0, 0}, e2[3];
    e1[fabs(axis[0]) < 0.9 ? 0 : 1] = 1.0;
    double along = dot3(e1, axis);
    for (int c = 0; c < 3; c++)
        e1[c] -= along * axis[c];
    normalize3(e1);
    cross3(axis, e1, e2);
    /* the radius of the regular polygon with the disk's area: n sin(2π/n) R'²/2 = π R² */
    const int n = SC_LTC_DISK_SIDES;
    double step = 2.0 * pi / n, r = radius * sqrt(2.0 * pi / (n * sin(step)));
    vec3 verts[SC_LTC_DISK_SIDES];
    for (int k = 0; k < n; k++)
        for (int c = 0; c < 3; c++)
            verts[k][c] = center[c] + r * (cos(k * step) * e1[c] + sin(k * step) * e2[c]);
    return sc_ltc_polygon(frame, v, alpha, f0, (const double(*)[3])verts, n, two_sided, out);
}
