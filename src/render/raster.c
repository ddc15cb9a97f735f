/* Clipping, triangle setup in fixed point and the top-left fill rule (render/raster.h). */
#include "render/raster.h"

#include <math.h>

enum { SUBPIXEL = 1 << RASTER_SUBPIXEL_BITS, HALF_PIXEL = SUBPIXEL / 2 };

/* Screen coordinates are kept within ±2^21 pixels: fixed-point values below 2^29, differences
 * below 2^30, edge function products below 2^60. */
static const double max_screen_pixels = 2097152.0; /* 2^21 */

double raster_guard_band(int width, int height)
{
    int size = width > height ? width : height;
    return max_screen_pixels / size - 1.0;
}

/* ---- clipping ---- */

typedef struct {
    double near, guard;
} clip_planes;

enum { PLANE_COUNT = 5 };

/* Signed distance of v to plane k, inside when >= 0. */
static double plane_distance(const clip_planes *c, int k, const raster_vertex *v)
{
    switch (k) {
    case 0: return v->w - c->near;
    case 1: return c->guard * v->w - v->x;
    case 2: return c->guard * v->w + v->x;
    case 3: return c->guard * v->w - v->y;
    default: return c->guard * v->w + v->y;
    }
}

/* The point where the segment from `in` (inside, distance din) to `out` (distance dout < 0)
 * crosses the plane. */
static raster_vertex crossing(const raster_vertex *in, double din, const raster_vertex *out,
                              double dout)
{
    double t = din / (din - dout);
    raster_vertex r;
    r.x = in->x + t * (out->x - in->x);
    r.y = in->y + t * (out->y - in->y);
    r.w = in->w + t * (out->w - in->w);
    for (int k = 0; k < 3; k++)
        r.bc[k] = in->bc[k] + t * (out->bc[k] - in->bc[k]);
    return r;
}

/* One Sutherland–Hodgman step: the polygon poly[0..n) against plane k into out. */
static int clip_against(const clip_planes *c, int k, const raster_vertex *poly, int n,
                        raster_vertex *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const raster_vertex *a = &poly[i], *b = &poly[(i + 1) % n];
        double da = plane_distance(c, k, a), db = plane_distance(c, k, b);
        if (da >= 0)
            out[m++] = *a;
        if ((da >= 0) != (db >= 0))
            out[m++] = da >= 0 ? crossing(a, da, b, db) : crossing(b, db, a, da);
    }
    return m;
}

static int finite_vertex(const raster_vertex *v)
{
    return isfinite(v->x) && isfinite(v->y) && isfinite(v->w);
}

int raster_clip(const raster_vertex in[3], double near, double guard,
                raster_vertex out[RASTER_CLIP_MAX])
{
    /* Each plane adds at most one vertex to a convex polygon: 3 + 5 <= RASTER_CLIP_MAX. */
    raster_vertex a[RASTER_CLIP_MAX], b[RASTER_CLIP_MAX];
    raster_vertex *src = a, *dst = b, *swap;
    clip_planes c = {near, guard};
    int n = 3;
    for (int i = 0; i < 3; i++) {
        if (!finite_vertex(&in[i]))
            return 0;
        a[i] = in[i];
    }
    for (int k = 0; k < PLANE_COUNT && n > 0; k++) {
        n = clip_against(&c, k, src, n, dst);
        swap = src, src = dst, dst = swap;
    }
    for (int i = 0; i < n; i++)
        out[i] = src[i];
    return n >= 3 ? n : 0;
}

/* ---- setup ---- */

static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

static int64_t orient(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Top-left rule for the edge a→b of a positively oriented triangle (see raster.h). */
static int edge_bias(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    int top_or_left = by < ay || (by == ay && bx > ax);
    return top_or_left ? 0 : -1;
}

static void swap_vertices(raster_tri *t, int i, int j)
{
    int64_t x = t->x[i], y = t->y[i];
    double iw = t->inv_w[i], bc[3] = {t->bc[i][0], t->bc[i][1], t->bc[i][2]};
    t->x[i] = t->x[j], t->y[i] = t->y[j], t->inv_w[i] = t->inv_w[j];
    t->x[j] = x, t->y[j] = y, t->inv_w[j] = iw;
    for (int k = 0; k < 3; k++) {
        t->bc[i][k] = t->bc[j][k];
        t->bc[j][k] = bc[k];
    }
}

/* The first pixel whose centre is at or after fixed-point coordinate lo, the last at or before
 * hi, clamped to [0, size). Returns 0 if none. */
static int pixel_span(int64_t lo, int64_t hi, int size, int *first, int *last)
{
    int64_t a = -floor_div(-(lo - HALF_PIXEL), SUBPIXEL); /* ceil */
    int64_t b = floor_div(hi - HALF_PIXEL, SUBPIXEL);
    if (a < 0)
        a = 0;
    if (b > size - 1)
        b = size - 1;
    if (a > b)
        return 0;
    *first = (int)a;
    *last = (int)b;
    return 1;
}

static int64_t min3(const int64_t v[3])
{
    int64_t m = v[0] < v[1] ? v[0] : v[1];
    return m < v[2] ? m : v[2];
}

static int64_t max3(const int64_t v[3])
{
    int64_t m = v[0] > v[1] ? v[0] : v[1];
    return m > v[2] ? m : v[2];
}

int raster_setup(const raster_vertex v[3], int width, int height, int source, raster_tri *out)
{
    for (int i = 0; i < 3; i++) {
        double sx = (v[i].x / v[i].w + 1.0) * 0.5 * width;
        double sy = (1.0 - v[i].y / v[i].w) * 0.5 * height;
        /* Outside the guard band only when clipping lost all precision (|coordinates| near
         * DBL_MAX): drop the triangle rather than overflow. */
        if (!(fabs(sx) <= max_screen_pixels && fabs(sy) <= max_screen_pixels))
            return 0;
        out->x[i] = llround(sx * SUBPIXEL);
        out->y[i] = llround(sy * SUBPIXEL);
        out->inv_w[i] = 1.0 / v[i].w;
        for (int k = 0; k < 3; k++)
            out->bc[i][k] = v[i].bc[k];
    }
    out->source = source;
    out->area = orient(out->x[0], out->y[0], out->x[1], out->y[1], out->x[2], out->y[2]);
    if (out->area < 0) {
        swap_vertices(out, 1, 2);
        out->area = -out->area;
    }
    if (out->area == 0)
        return 0;
    for (int i = 0; i < 3; i++) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        out->bias[i] = edge_bias(out->x[a], out->y[a], out->x[b], out->y[b]);
    }
    return pixel_span(min3(out->x), max3(out->x), width, &out->x0, &out->x1) &&
           pixel_span(min3(out->y), max3(out->y), height, &out->y0, &out->y1);
}

/* ---- coverage and interpolation ---- */

/* Edge function i (opposite vertex i) at fixed-point point (px, py). */
static int64_t edge_value(const raster_tri *t, int i, int64_t px, int64_t py)
{
    int a = (i + 1) % 3, b = (i + 2) % 3;
    return orient(t->x[a], t->y[a], t->x[b], t->y[b], px, py);
}

static int64_t pixel_centre(int p) { return (int64_t)p * SUBPIXEL + HALF_PIXEL; }

void raster_lambda(const raster_tri *t, int x, int y, double lambda[3])
{
    for (int i = 0; i < 3; i++)
        lambda[i] = (double)edge_value(t, i, pixel_centre(x), pixel_centre(y)) / (double)t->area;
}

void raster_cover(const raster_tri *t, int x0, int y0, int x1, int y1, raster_fragment_fn *fn,
                  void *ctx)
{
    x0 = x0 > t->x0 ? x0 : t->x0;
    y0 = y0 > t->y0 ? y0 : t->y0;
    x1 = x1 < t->x1 ? x1 : t->x1;
    y1 = y1 < t->y1 ? y1 : t->y1;
    int64_t step_x[3], step_y[3], row[3];
    for (int i = 0; i < 3; i++) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        step_x[i] = -(t->y[b] - t->y[a]) * SUBPIXEL;
        step_y[i] = (t->x[b] - t->x[a]) * SUBPIXEL;
        row[i] = edge_value(t, i, pixel_centre(x0), pixel_centre(y0));
    }
    double inv_area = 1.0 / (double)t->area;
    for (int y = y0; y <= y1; y++) {
        int64_t e[3] = {row[0], row[1], row[2]};
        for (int x = x0; x <= x1; x++) {
            if (e[0] + t->bias[0] >= 0 && e[1] + t->bias[1] >= 0 && e[2] + t->bias[2] >= 0) {
                double lambda[3] = {e[0] * inv_area, e[1] * inv_area, e[2] * inv_area};
                fn(ctx, x, y, lambda);
            }
            for (int i = 0; i < 3; i++)
                e[i] += step_x[i];
        }
        for (int i = 0; i < 3; i++)
            row[i] += step_y[i];
    }
}

double raster_barycentric(const raster_tri *t, const double lambda[3], double b[3])
{
    double q[3], s = 0.0;
    for (int i = 0; i < 3; i++) {
        q[i] = lambda[i] * t->inv_w[i];
        s += q[i];
    }
    for (int k = 0; k < 3; k++)
        b[k] = (q[0] * t->bc[0][k] + q[1] * t->bc[1][k] + q[2] * t->bc[2][k]) / s;
    return s;
}
