/* The rasterizer (src/render/raster.h): the top-left rule on hand-counted triangles,
 * watertightness of closed meshes, interpolation at the vertices, perspective-correct
 * barycentrics against an independent ray–plane intersection, clipping. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render/raster.h"
#include "render/view.h"

enum { W = 8, H = 8 };

/* A clip-space vertex that lands exactly on screen point (sx, sy) of a w_screen × h_screen
 * screen, at depth w. */
static raster_vertex at_screen(double sx, double sy, double w, int ws, int hs, int corner)
{
    raster_vertex v = {(2.0 * sx / ws - 1.0) * w, (1.0 - 2.0 * sy / hs) * w, w, {0, 0, 0}};
    v.bc[corner] = 1.0;
    return v;
}

typedef struct {
    int width;
    int *count;
} counter;

static void count_pixel(void *ctx, int x, int y, const double lambda[3])
{
    counter *c = ctx;
    (void)lambda;
    c->count[y * c->width + x]++;
}

static void cover_all(const raster_tri *t, int width, int height, int *count)
{
    counter c = {width, count};
    raster_cover(t, 0, 0, width - 1, height - 1, count_pixel, &c);
}

static void draw_screen_triangle(const double xy[3][2], int *count)
{
    raster_vertex v[3];
    raster_tri t;
    for (int k = 0; k < 3; k++)
        v[k] = at_screen(xy[k][0], xy[k][1], 1.0, W, H, k);
    if (raster_setup(v, W, H, 0, &t))
        cover_all(&t, W, H, count);
}

/* Vertices on pixel centres: the left edge x = 1.5 and the top edge y = 1.5 are drawn, the
 * hypotenuse x + y = 7 (a right edge) is not. By hand: pixels (i, j) with i, j >= 1 and
 * i + j <= 5. */
static void top_left_rule_small_triangle(void **state)
{
    (void)state;
    const double tri[3][2] = {{1.5, 1.5}, {5.5, 1.5}, {1.5, 5.5}};
    const double reversed[3][2] = {{1.5, 1.5}, {1.5, 5.5}, {5.5, 1.5}};
    static const char *const want[H] = {"........", ".####...", ".###....", ".##.....",
                                        ".#......", "........", "........", "........"};
    for (int order = 0; order < 2; order++) {
        int count[W * H] = {0};
        draw_screen_triangle(order ? reversed : tri, count);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (count[y * W + x] != (want[y][x] == '#'))
                    fail_msg("order %d pixel (%d,%d): covered %d times", order, x, y,
                             count[y * W + x]);
    }
}

/* The other half of the square claims the shared hypotenuse's centres; its right edge x = 5.5
 * and bottom edge y = 5.5 are not drawn: the square covers i, j in 1..4, each once. */
static void shared_edge_drawn_once(void **state)
{
    (void)state;
    const double a[3][2] = {{1.5, 1.5}, {5.5, 1.5}, {1.5, 5.5}};
    const double b[3][2] = {{5.5, 1.5}, {5.5, 5.5}, {1.5, 5.5}};
    int count[W * H] = {0};
    draw_screen_triangle(a, count);
    draw_screen_triangle(b, count);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int inside = x >= 1 && x <= 4 && y >= 1 && y <= 4;
            if (count[y * W + x] != inside)
                fail_msg("pixel (%d,%d): covered %d times", x, y, count[y * W + x]);
        }
}

/* A fan of 12 thin triangles around a pixel centre, edges through other centres: every pixel
 * of the 12-gon drawn once, the centre included. */
static void fan_around_pixel_centre(void **state)
{
    (void)state;
    enum { S = 32 };
    int count[S * S] = {0};
    const double cx = 16.5, cy = 16.5, r = 12.0, pi = 3.14159265358979323846;
    for (int k = 0; k < 12; k++) {
        double a0 = 2 * pi * k / 12, a1 = 2 * pi * (k + 1) / 12;
        raster_vertex v[3] = {at_screen(cx, cy, 1.0, S, S, 0),
                              at_screen(cx + r * cos(a0), cy + r * sin(a0), 1.0, S, S, 1),
                              at_screen(cx + r * cos(a1), cy + r * sin(a1), 1.0, S, S, 2)};
        raster_tri t;
        assert_true(raster_setup(v, S, S, k, &t));
        cover_all(&t, S, S, count);
    }
    for (int i = 0; i < S * S; i++) {
        double dx = i % S + 0.5 - cx, dy = i / S + 0.5 - cy;
        assert_true(count[i] <= 1);
        if (dx * dx + dy * dy < (0.9 * r) * (0.9 * r)) /* well inside the 12-gon */
            assert_int_equal(count[i], 1);
    }
}

/* ---- closed meshes seen through a camera ---- */

static void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Draws every triangle of a closed mesh; counts the front-facing (seen counter-clockwise from
 * the eye) and back-facing coverage per pixel separately. */
static void draw_closed_mesh(const double (*pos)[3], const int (*tri)[3], int n_tri,
                             const sc_camera *cam, int size, int *front, int *back)
{
    render_view view;
    render_view_make(cam, size, size, &view);
    for (int t = 0; t < n_tri; t++) {
        raster_vertex v[3], poly[RASTER_CLIP_MAX];
        double e1[3], e2[3], n[3], facing = 0.0;
        for (int k = 0; k < 3; k++) {
            render_view_project(&view, pos[tri[t][k]], &v[k]);
            v[k].bc[0] = v[k].bc[1] = v[k].bc[2] = 0.0;
            v[k].bc[k] = 1.0;
        }
        for (int c = 0; c < 3; c++) {
            e1[c] = pos[tri[t][1]][c] - pos[tri[t][0]][c];
            e2[c] = pos[tri[t][2]][c] - pos[tri[t][0]][c];
        }
        cross(e1, e2, n);
        for (int c = 0; c < 3; c++)
            facing += n[c] * (cam->eye[c] - pos[tri[t][0]][c]);
        int m = raster_clip(v, view.near, raster_guard_band(size, size), poly);
        for (int i = 1; i + 1 < m; i++) {
            raster_vertex fan[3] = {poly[0], poly[i], poly[i + 1]};
            raster_tri rt;
            if (raster_setup(fan, size, size, t, &rt))
                cover_all(&rt, size, size, facing > 0 ? front : back);
        }
    }
}

static const double octa_pos[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
static const int octa_tri[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

/* A ray enters a closed mesh as often as it leaves it: front coverage = back coverage, and for
 * a convex mesh both are at most 1. Pixels well inside the silhouette are drawn. */
static void octahedron_watertight(void **state)
{
    (void)state;
    enum { S = 96 };
    const sc_camera cams[] = {{{0.3, 0.2, 4}, {0, 0, 0}, {0, 1, 0}, 45},
                              {{2.1, -1.7, 1.3}, {0.05, 0.1, 0}, {0, 0, 1}, 60},
                              {{0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 50}}; /* a vertex on the axis */
    for (size_t c = 0; c < sizeof cams / sizeof cams[0]; c++) {
        int *front = calloc(S * S, sizeof *front), *back = calloc(S * S, sizeof *back);
        draw_closed_mesh(octa_pos, octa_tri, 8, &cams[c], S, front, back);
        int drawn = 0;
        for (int i = 0; i < S * S; i++) {
            if (front[i] != back[i] || front[i] > 1)
                fail_msg("camera %zu pixel (%d,%d): front %d back %d", c, i % S, i / S, front[i],
                         back[i]);
            drawn += front[i];
        }
        assert_true(drawn > S * S / 10);
        free(front);
        free(back);
    }
}

/* A UV sphere of 2·48·24 triangles (generic vertex positions, many shared edges and a fan at
 * each pole), seen from generic directions: front = back <= 1, no hole inside the disc. */
static void sphere_mesh_watertight(void **state)
{
    (void)state;
    enum { NU = 48, NV = 24, S = 128 };
    const double pi = 3.14159265358979323846;
    static double pos[(NU + 1) * (NV + 1)][3];
    static int tri[2 * NU * NV][3];
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i <= NU; i++) {
            double th = pi * j / NV, ph = 2 * pi * (i % NU) / NU;
            double *p = pos[j * (NU + 1) + i];
            p[0] = sin(th) * cos(ph), p[1] = sin(th) * sin(ph), p[2] = -cos(th);
        }
    int n = 0;
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            int a = j * (NU + 1) + i, b = a + 1, c = a + NU + 1, d = c + 1;
            tri[n][0] = a, tri[n][1] = b, tri[n][2] = d, n++;
            tri[n][0] = a, tri[n][1] = d, tri[n][2] = c, n++;
        }
    const sc_camera cams[] = {{{0.4, -2.9, 1.1}, {0, 0, 0}, {0, 0, 1}, 45},
                              {{0, 0, 3.2}, {0, 0, 0}, {0, 1, 0}, 45}}; /* a pole in view */
    for (size_t c = 0; c < 2; c++) {
        int *front = calloc(S * S, sizeof *front), *back = calloc(S * S, sizeof *back);
        draw_closed_mesh((const double(*)[3])pos, (const int(*)[3])tri, n, &cams[c], S, front,
                         back);
        render_view view;
        render_view_make(&cams[c], S, S, &view);
        double dist = sqrt(cams[c].eye[0] * cams[c].eye[0] + cams[c].eye[1] * cams[c].eye[1] +
                           cams[c].eye[2] * cams[c].eye[2]);
        double disc = S / 2.0 * view.scale_y * tan(asin(1.0 / dist)); /* pixels */
        for (int i = 0; i < S * S; i++) {
            double dx = i % S + 0.5 - S / 2.0, dy = i / S + 0.5 - S / 2.0;
            if (front[i] != back[i] || front[i] > 1)
                fail_msg("camera %zu pixel (%d,%d): front %d back %d", c, i % S, i / S, front[i],
                         back[i]);
            if (dx * dx + dy * dy < 0.9 * disc * 0.9 * disc)
                assert_int_equal(front[i], 1);
        }
        free(front);
        free(back);
    }
}

/* ---- interpolation ---- */

/* At a pixel whose centre is a vertex, λ and the perspective-correct b are that vertex's unit
 * vector exactly, so an interpolated attribute is the vertex's value. */
static void interpolation_at_vertices(void **state)
{
    (void)state;
    enum { S = 64 };
    const double xy[3][2] = {{3.5, 4.5}, {50.5, 12.5}, {20.5, 60.5}}, w[3] = {1.0, 3.5, 7.25};
    const double attr[3] = {0.125, -2.0, 9.75};
    raster_vertex v[3];
    raster_tri t;
    for (int k = 0; k < 3; k++)
        v[k] = at_screen(xy[k][0], xy[k][1], w[k], S, S, k);
    assert_true(raster_setup(v, S, S, 0, &t));
    for (int k = 0; k < 3; k++) {
        double lambda[3], b[3];
        raster_lambda(&t, (int)xy[k][0], (int)xy[k][1], lambda);
        double inv_w = raster_barycentric(&t, lambda, b);
        for (int j = 0; j < 3; j++) {
            assert_true(lambda[j] == (j == k));
            assert_true(b[j] == (j == k));
        }
        assert_true(inv_w == 1.0 / w[k]);
        assert_true(b[0] * attr[0] + b[1] * attr[1] + b[2] * attr[2] == attr[k]);
    }
}

/* Reference: the ray from the eye through the pixel centre meets the triangle's plane at X;
 * its barycentrics are the ratios of the sub-triangle areas (double, no 1/w formula). */
static void ray_barycentrics(const render_view *view, int size, int x, int y, const double p[3][3],
                             double b[3])
{
    double ndc_x = 2.0 * (x + 0.5) / size - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / size;
    double d[3], e1[3], e2[3], n[3], dn = 0.0, pn = 0.0;
    for (int c = 0; c < 3; c++) {
        d[c] = view->forward[c] + ndc_x / view->scale_x * view->right[c] +
               ndc_y / view->scale_y * view->up[c];
        e1[c] = p[1][c] - p[0][c];
        e2[c] = p[2][c] - p[0][c];
    }
    cross(e1, e2, n);
    for (int c = 0; c < 3; c++) {
        dn += d[c] * n[c];
        pn += (p[0][c] - view->eye[c]) * n[c];
    }
    double X[3], area = 0.0, sub[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++)
        X[c] = view->eye[c] + pn / dn * d[c];
    for (int k = 0; k < 3; k++) {
        double a[3], bb[3], s[3];
        for (int c = 0; c < 3; c++) {
            a[c] = p[(k + 1) % 3][c] - X[c];
            bb[c] = p[(k + 2) % 3][c] - X[c];
        }
        cross(a, bb, s);
        for (int c = 0; c < 3; c++)
            sub[k] += s[c] * n[c];
    }
    for (int c = 0; c < 3; c++)
        area += n[c] * n[c];
    for (int k = 0; k < 3; k++)
        b[k] = sub[k] / area;
}

typedef struct {
    const render_view *view;
    const raster_tri *tri;
    const double (*p)[3];
    int size, pixels;
    double worst, worst_affine;
} perspective_check;

static void check_pixel(void *ctx, int x, int y, const double lambda[3])
{
    perspective_check *c = ctx;
    double b[3], want[3];
    raster_barycentric(c->tri, lambda, b);
    ray_barycentrics(c->view, c->size, x, y, c->p, want);
    for (int k = 0; k < 3; k++) {
        c->worst = fmax(c->worst, fabs(b[k] - want[k]));
        c->worst_affine = fmax(c->worst_affine, fabs(lambda[k] - want[k]));
    }
    c->pixels++;
}

/* Snapping the vertices to 1/256 pixel moves b by about (1/512)/(triangle size in pixels)
 * times the depth ratio: below 1e-3 here. Screen-space (affine) λ is off by far more. */
static void check_perspective(const sc_camera *cam, const double p[3][3], int size,
                              int expect_clipped)
{
    render_view view;
    render_view_make(cam, size, size, &view);
    raster_vertex v[3], poly[RASTER_CLIP_MAX];
    for (int k = 0; k < 3; k++) {
        render_view_project(&view, p[k], &v[k]);
        v[k].bc[0] = v[k].bc[1] = v[k].bc[2] = 0.0;
        v[k].bc[k] = 1.0;
    }
    int m = raster_clip(v, view.near, raster_guard_band(size, size), poly);
    assert_true(expect_clipped ? m > 3 : m == 3);
    perspective_check c = {&view, NULL, p, size, 0, 0.0, 0.0};
    for (int i = 1; i + 1 < m; i++) {
        raster_vertex fan[3] = {poly[0], poly[i], poly[i + 1]};
        raster_tri t;
        if (!raster_setup(fan, size, size, 0, &t))
            continue;
        c.tri = &t;
        raster_cover(&t, 0, 0, size - 1, size - 1, check_pixel, &c);
    }
    assert_true(c.pixels > 100);
    if (c.worst > 1e-3)
        fail_msg("perspective-correct barycentrics off by %g", c.worst);
    if (!expect_clipped && c.worst_affine < 0.02)
        fail_msg("affine interpolation is too close (%g): the test would not see an error",
                 c.worst_affine);
}

static void perspective_correct_against_ray(void **state)
{
    (void)state;
    const sc_camera cam = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60};
    const double p[3][3] = {{-1, -1, -1.2}, {2.5, -0.5, -8}, {-0.5, 1.5, -3}};
    check_perspective(&cam, p, 128, 0);
}

/* A triangle with a vertex behind the eye: clipped at the near plane, the pieces still
 * interpolate as the whole. */
static void near_clipped_triangle_interpolates(void **state)
{
    (void)state;
    const sc_camera cam = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60};
    const double p[3][3] = {{-1, -1, -2}, {1.5, -0.8, -3}, {0.2, 0.4, 2}};
    check_perspective(&cam, p, 128, 1);
}

/* Clips v and sets up the fan; counts coverage; returns how many screen triangles. */
static int clip_and_cover(const raster_vertex v[3], int size, int *count, raster_tri *last)
{
    raster_vertex poly[RASTER_CLIP_MAX];
    int m = raster_clip(v, 1e-3, raster_guard_band(size, size), poly), drawn = 0;
    for (int i = 1; i + 1 < m; i++) {
        raster_vertex fan[3] = {poly[0], poly[i], poly[i + 1]};
        if (raster_setup(fan, size, size, 0, last)) {
            cover_all(last, size, size, count);
            drawn++;
        }
    }
    return drawn;
}

/* A triangle far larger than the screen (guard band clipping): every pixel once. */
static void huge_triangle_covers_screen_once(void **state)
{
    (void)state;
    enum { S = 16 };
    raster_vertex v[3] = {
        {-1e7, -1e7, 1, {1, 0, 0}}, {3e7, -1e7, 1, {0, 1, 0}}, {-1e7, 3e7, 1, {0, 0, 1}}};
    int count[S * S] = {0};
    raster_tri t;
    assert_true(clip_and_cover(v, S, count, &t) > 0);
    for (int i = 0; i < S * S; i++)
        assert_int_equal(count[i], 1);
}

/* Coordinates so large that clipping loses all precision: whatever is drawn keeps its
 * fixed-point coordinates inside the range that makes the edge functions exact (and UBSan
 * sees no overflow). */
static void absurd_coordinates_stay_in_range(void **state)
{
    (void)state;
    enum { S = 16 };
    raster_vertex v[3] = {{-1e30, -1e30, 1, {1, 0, 0}},
                          {3e30, -1e30, 1, {0, 1, 0}},
                          {-1e30, 3e300, 1e-300, {0, 0, 1}}};
    int count[S * S] = {0};
    raster_tri t;
    if (clip_and_cover(v, S, count, &t) > 0)
        for (int k = 0; k < 3; k++) {
            assert_true(llabs(t.x[k]) < (1LL << 30));
            assert_true(llabs(t.y[k]) < (1LL << 30));
        }
}

static void non_finite_or_behind_is_dropped(void **state)
{
    (void)state;
    raster_vertex poly[RASTER_CLIP_MAX];
    raster_vertex nan_v[3] = {{NAN, 0, 1, {1, 0, 0}}, {1, 0, 1, {0, 1, 0}}, {0, 1, 1, {0, 0, 1}}};
    raster_vertex inf_v[3] = {
        {0, 0, INFINITY, {1, 0, 0}}, {1, 0, 1, {0, 1, 0}}, {0, 1, 1, {0, 0, 1}}};
    raster_vertex behind[3] = {{0, 0, -1, {1, 0, 0}}, {1, 0, -2, {0, 1, 0}}, {0, 1, -1, {0, 0, 1}}};
    assert_int_equal(raster_clip(nan_v, 1e-3, 100, poly), 0);
    assert_int_equal(raster_clip(inf_v, 1e-3, 100, poly), 0);
    assert_int_equal(raster_clip(behind, 1e-3, 100, poly), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(top_left_rule_small_triangle),
        cmocka_unit_test(shared_edge_drawn_once),
        cmocka_unit_test(fan_around_pixel_centre),
        cmocka_unit_test(octahedron_watertight),
        cmocka_unit_test(sphere_mesh_watertight),
        cmocka_unit_test(interpolation_at_vertices),
        cmocka_unit_test(perspective_correct_against_ray),
        cmocka_unit_test(near_clipped_triangle_interpolates),
        cmocka_unit_test(huge_triangle_covers_screen_once),
        cmocka_unit_test(absurd_coordinates_stay_in_range),
        cmocka_unit_test(non_finite_or_behind_is_dropped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
