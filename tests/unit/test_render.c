/* sc_render (shadecalc/render.h): shading modes against closed forms and ray-traced references,
 * the z-buffer, threads, the exact mode on a sphere, the comparison's ordering, EXR output. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "render/shade_span.h"
#include "render/view.h"
#include "shadecalc/precision.h"
#include "shadecalc/render.h"
#include "shadecalc/scene.h"

static const double pi = 3.14159265358979323846;

/* A square [-s, s]² in the plane z = height, counter-clockwise seen from +z, normals +z. */
typedef struct {
    float pos[12], normal[12];
    int tri[6];
    sc_mesh mesh;
} square;

static void make_square(square *q, double s, double height)
{
    const double corner[4][2] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};
    const int tri[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 4; i++) {
        q->pos[3 * i] = (float)corner[i][0];
        q->pos[3 * i + 1] = (float)corner[i][1];
        q->pos[3 * i + 2] = (float)height;
        q->normal[3 * i] = q->normal[3 * i + 1] = 0.0f;
        q->normal[3 * i + 2] = 1.0f;
    }
    memcpy(q->tri, tri, sizeof tri);
    q->mesh = (sc_mesh){4, 2, q->pos, q->normal, NULL, q->tri};
}

typedef struct {
    sc_light light;
    sc_scene scene;
} scene_box;

static void make_scene(scene_box *b, const char *light, const char *model)
{
    char err[256];
    assert_int_equal(sc_light_parse(light, &b->light, err, sizeof err), 0);
    memset(&b->scene, 0, sizeof b->scene);
    assert_int_equal(sc_model_parse(model, &b->scene.model, err, sizeof err), 0);
    b->scene.lights = &b->light;
    b->scene.n_lights = 1;
}

static const sc_camera above = {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40};

static void render_ok(const sc_mesh *m, const sc_surface *s, const sc_scene *scene, sc_shading mode,
                      const sc_camera *cam, int threads, sc_framebuffer *fb)
{
    char err[256];
    sc_render_params p = {.mesh = m,
                          .surface = s,
                          .scene = scene,
                          .prec = SC_DOUBLE,
                          .shading = mode,
                          .camera = *cam,
                          .threads = threads};
    if (sc_render(&p, fb, err, sizeof err) < 0)
        fail_msg("sc_render: %s", err);
}

/* Lambert ρ = 0.8 under a directional light at cos θ = 0.8: L = ρ/π · E · cos θ (docs/formulas.md §6) at
 * every covered pixel, in every mesh mode; the square's projection covers its area in pixels
 * (2s · S/(2·d·tan 20°))², up to its perimeter. */
static void flat_square_matches_lambert(void **state)
{
    (void)state;
    enum { S = 64 };
    square q;
    scene_box b;
    make_square(&q, 1.0, 0.0);
    make_scene(&b, "directional dir=0,0.6,0.8 I=1", "lambert diff=0.8");
    const double want = 0.8 / pi * 0.8;
    const sc_shading modes[] = {SC_SHADING_FLAT, SC_SHADING_GOURAUD, SC_SHADING_PHONG};
    for (int m = 0; m < 3; m++) {
        sc_framebuffer fb;
        assert_int_equal(sc_framebuffer_init(&fb, S, S), 0);
        render_ok(&q.mesh, NULL, &b.scene, modes[m], &above, 2, &fb);
        int covered = 0;
        for (int i = 0; i < S * S; i++) {
            if (fb.rgba[4 * i + 3] == 0.0f)
                continue;
            covered++;
            for (int c = 0; c < 3; c++)
                if (fabs(fb.rgba[4 * i + c] - want) > 1e-6 * want)
                    fail_msg("mode %d pixel %d: %.9g, want %.9g", m, i, fb.rgba[4 * i + c], want);
            assert_true(fb.normal[3 * i + 2] == 1.0f);
            assert_true(fabs(fb.depth[i] - 5.0) < 1e-6);
        }
        double side = 2.0 * S / (2.0 * 5.0 * tan(20.0 * pi / 180.0));
        assert_true(fabs(covered - side * side) <= 4.0 * side);
        sc_framebuffer_free(&fb);
    }
}

/* The ray from the eye through pixel (x, y)'s centre meets the plane z = 0 at *hit. */
static void ray_hit_plane(const sc_camera *cam, int size, int x, int y, double hit[3])
{
    /* camera looking down −z with up +y: right = +x */
    double t = tan(cam->fov * pi / 360.0);
    double dx = (2.0 * (x + 0.5) / size - 1.0) * t, dy = (1.0 - 2.0 * (y + 0.5) / size) * t;
    double s = cam->eye[2]; /* distance to z = 0 along −z */
    hit[0] = cam->eye[0] + s * dx;
    hit[1] = cam->eye[1] + s * dy;
    hit[2] = 0.0;
}

/* Phong on a flat square under a close point light equals sc_shade at the ray's hit point
 * (the snapped vertices move the hit by under 1/512 pixel: 1e-3 relative here). Gouraud,
 * which interpolates the four corner colours, is far off at the centre. */
static void phong_matches_ray_traced_point(void **state)
{
    (void)state;
    enum { S = 48 };
    square q;
    scene_box b;
    make_square(&q, 1.0, 0.0);
    make_scene(&b, "point pos=0.2,-0.1,0.6 I=1", "blinn-phong diff=0.5 spec=0.5 m=20");
    sc_framebuffer phong, gouraud;
    assert_int_equal(sc_framebuffer_init(&phong, S, S), 0);
    assert_int_equal(sc_framebuffer_init(&gouraud, S, S), 0);
    render_ok(&q.mesh, NULL, &b.scene, SC_SHADING_PHONG, &above, 1, &phong);
    render_ok(&q.mesh, NULL, &b.scene, SC_SHADING_GOURAUD, &above, 1, &gouraud);
    double worst = 0.0, gouraud_worst = 0.0;
    for (int y = 0; y < S; y++)
        for (int x = 0; x < S; x++) {
            int i = y * S + x;
            if (phong.rgba[4 * i + 3] == 0.0f)
                continue;
            sc_shade_point at = {.v = {0, 0, 0}};
            sc_shade_result r = {.per_light = NULL};
            ray_hit_plane(&above, S, x, y, at.pos);
            double n[3] = {0, 0, 1}, len = 0.0;
            for (int c = 0; c < 3; c++)
                len += (above.eye[c] - at.pos[c]) * (above.eye[c] - at.pos[c]);
            for (int c = 0; c < 3; c++)
                at.v[c] = (above.eye[c] - at.pos[c]) / sqrt(len);
            sc_frame_make(n, NULL, &at.frame);
            sc_shade(SC_DOUBLE, &b.scene, &at, &r);
            worst = fmax(worst, fabs(phong.rgba[4 * i] - r.L[0]) / r.L[0]);
            gouraud_worst = fmax(gouraud_worst, fabs(gouraud.rgba[4 * i] - r.L[0]) / r.L[0]);
        }
    if (worst > 1e-3)
        fail_msg("phong off by %g (relative)", worst);
    assert_true(gouraud_worst > 0.5);
    sc_framebuffer_free(&phong);
    sc_framebuffer_free(&gouraud);
}

/* Two squares at z = 0 and z = 1 in either order: the nearer (view depth 4) wins. */
static void z_buffer_keeps_nearest(void **state)
{
    (void)state;
    enum { S = 32 };
    square lo, hi;
    scene_box b;
    make_square(&lo, 1.0, 0.0);
    make_square(&hi, 0.5, 1.0);
    make_scene(&b, "directional dir=0,0,1 I=1", "lambert diff=0.8");
    for (int order = 0; order < 2; order++) {
        float pos[24], normal[24];
        int tri[12];
        const square *first = order ? &hi : &lo, *second = order ? &lo : &hi;
        memcpy(pos, first->pos, sizeof first->pos);
        memcpy(pos + 12, second->pos, sizeof second->pos);
        memcpy(normal, first->normal, sizeof first->normal);
        memcpy(normal + 12, second->normal, sizeof second->normal);
        for (int k = 0; k < 6; k++) {
            tri[k] = first->tri[k];
            tri[6 + k] = second->tri[k] + 4;
        }
        sc_mesh m = {8, 4, pos, normal, NULL, tri};
        sc_framebuffer fb;
        assert_int_equal(sc_framebuffer_init(&fb, S, S), 0);
        render_ok(&m, NULL, &b.scene, SC_SHADING_FLAT, &above, 1, &fb);
        int centre = S / 2 * S + S / 2, rim = S / 2 * S + 9; /* 6.5 px off: 5.5 < 6.5 < 8.8 */
        assert_true(fabs(fb.depth[centre] - 4.0) < 1e-6);
        assert_true(fabs(fb.depth[rim] - 5.0) < 1e-6);
        assert_true(isinf(fb.depth[0]) && fb.rgba[3] == 0.0f);
        sc_framebuffer_free(&fb);
    }
}

static sc_surface *sphere(void)
{
    char err[256];
    sc_surface *s = sc_surface_parse("sphere", err, sizeof err);
    if (!s)
        fail_msg("%s", err);
    return s;
}

static void tessellate(const sc_surface *s, int n, sc_mesh *m)
{
    char err[256];
    if (sc_surface_tessellate(s, n, m, err, sizeof err) < 0)
        fail_msg("%s", err);
}

static const sc_camera side_view = {{0.5, -3.2, 1.1}, {0, 0, 0}, {0, 0, 1}, 40};

/* The unit sphere in about `triangles` triangles, under a point light, Blinn-Phong m = 40. */
static sc_surface *lit_sphere(int triangles, sc_mesh *m, scene_box *b)
{
    sc_surface *s = sphere();
    tessellate(s, triangles, m);
    make_scene(b, "point pos=2,-3,3 I=20", "blinn-phong m=40");
    return s;
}

/* Tiles go to threads in any order; each pixel is computed the same: identical images. Each
 * tile clears its own pixels: `many` starts full of garbage (as a previous render would leave
 * it) and S is not a multiple of the tile size, yet every pixel, the empty corners included,
 * comes out as in `one`. */
static void threads_give_the_same_image(void **state)
{
    (void)state;
    enum { S = 150 };
    sc_mesh m;
    scene_box b;
    sc_surface *s = lit_sphere(2000, &m, &b);
    sc_framebuffer one, many;
    assert_int_equal(sc_framebuffer_init(&one, S, S), 0);
    assert_int_equal(sc_framebuffer_init(&many, S, S), 0);
    for (int i = 0; i < S * S; i++) {
        many.rgba[4 * i + 3] = many.normal[3 * i] = 7.0f;
        many.depth[i] = 1.0f;
    }
    render_ok(&m, s, &b.scene, SC_SHADING_PHONG, &side_view, 1, &one);
    render_ok(&m, s, &b.scene, SC_SHADING_PHONG, &side_view, 5, &many);
    assert_memory_equal(one.rgba, many.rgba, 4 * S * S * sizeof(float));
    assert_memory_equal(one.depth, many.depth, S * S * sizeof(float));
    assert_memory_equal(one.normal, many.normal, 3 * S * S * sizeof(float));
    assert_true(isinf(one.depth[0]) && one.rgba[3] == 0.0f); /* a corner the sphere misses */
    sc_framebuffer_free(&one);
    sc_framebuffer_free(&many);
    sc_mesh_free(&m);
    sc_surface_free(s);
}

/* A framebuffer without depth or normals renders the same colours as one with every plane, and
 * sc_render_image_take hands its RGBA array to the image (no copy) with the same pixels as
 * sc_render_image; planes it lacks cannot be asked of it. S² RGBA floats are 2.4 MiB: a
 * mapping (util/bigalloc.h), as a full-size render's. */
static void colour_only_framebuffer_renders_and_moves(void **state)
{
    (void)state;
    enum { S = 400 };
    sc_mesh m;
    scene_box b;
    sc_surface *s = lit_sphere(800, &m, &b);
    sc_framebuffer all, colour, bad;
    assert_int_equal(sc_framebuffer_init(&all, S, S), 0);
    assert_int_equal(sc_framebuffer_init_planes(&colour, S, S, 0), 0);
    assert_null(colour.depth);
    assert_null(colour.normal);
    assert_int_equal(sc_framebuffer_init_planes(&bad, S, S, SC_FRAMEBUFFER_ALL + 1), -1);
    assert_int_equal(sc_framebuffer_init_planes(&bad, S, S, -1), -1);
    render_ok(&m, s, &b.scene, SC_SHADING_PHONG, &side_view, 2, &all);
    render_ok(&m, s, &b.scene, SC_SHADING_PHONG, &side_view, 2, &colour);
    assert_memory_equal(all.rgba, colour.rgba, 4 * S * S * sizeof(float));
    sc_image copied, taken, none;
    assert_int_equal(sc_render_image(&colour, 1, 0, &none), -1);
    assert_int_equal(sc_render_image_take(&colour, 0, 1, &none), -1);
    assert_int_equal(sc_render_image(&all, 0, 0, &copied), 0);
    const float *array = colour.rgba;
    assert_int_equal(sc_render_image_take(&colour, 0, 0, &taken), 0);
    assert_ptr_equal(taken.data, array);
    assert_null(colour.rgba);
    assert_int_equal(taken.n_channels, 4);
    assert_string_equal(taken.channel[3], "A");
    assert_memory_equal(taken.data, copied.data, 4 * S * S * sizeof(float));
    assert_int_equal(sc_render_image_take(&colour, 0, 0, &none), -1); /* nothing left */
    sc_image_free(&taken);
    sc_image_free(&copied);
    sc_framebuffer_free(&colour);
    sc_framebuffer_free(&all);
    sc_mesh_free(&m);
    sc_surface_free(s);
}

/* highp shading of scenes the batch kernel computes goes through it (render/shade_span.c):
 * the image matches the double sc_shade image within the kernel's accurate-tier bound
 * (relative 2^-16 plus the float rounding of the inputs), for each of its BRDFs, with a
 * directional, a point and a spot light. */
static void batch_kernel_matches_sc_shade(void **state)
{
    (void)state;
    enum { S = 64 };
    static const char *const models[] = {"lambert", "blinn-phong m=40",
                                         "cook-torrance alpha=0.3 f0=0.04"};
    sc_surface *s = sphere();
    sc_mesh m;
    tessellate(s, 1500, &m);
    char err[256];
    sc_light lights[3];
    assert_int_equal(sc_light_parse("point pos=2,-3,3 I=20", &lights[0], err, sizeof err), 0);
    assert_int_equal(sc_light_parse("directional dir=-1,-1,1 E=0.5", &lights[1], err, sizeof err),
                     0);
    assert_int_equal(
        sc_light_parse("spot pos=0,-4,0 dir=0,1,0 I=30 spot=directx inner=10 outer=20 exp=2",
                       &lights[2], err, sizeof err),
        0);
    for (size_t k = 0; k < sizeof models / sizeof models[0]; k++) {
        sc_scene scene = {lights, 3, {0}, {0.1, 0.1, 0.1}};
        assert_int_equal(sc_model_parse(models[k], &scene.model, err, sizeof err), 0);
        sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", sc_isa_active(), err,
                                                    sizeof err);
        if (!plan) /* the kernel's path is taken */
            fail_msg("%s: no plan: %s", models[k], err);
        assert_string_equal(sc_batch_plan_entry(plan)->tier, "accurate");
        sc_batch_plan_free(plan);
        sc_framebuffer ref, fast;
        assert_int_equal(sc_framebuffer_init(&ref, S, S), 0);
        assert_int_equal(sc_framebuffer_init(&fast, S, S), 0);
        sc_render_params p = {.mesh = &m,
                              .surface = s,
                              .scene = &scene,
                              .prec = SC_DOUBLE,
                              .shading = SC_SHADING_PHONG,
                              .camera = side_view,
                              .threads = 1};
        assert_int_equal(sc_render(&p, &ref, err, sizeof err), 0);
        p.prec = SC_HIGHP;
        assert_int_equal(sc_render(&p, &fast, err, sizeof err), 0);
        double worst = 0.0, peak = 0.0;
        for (int i = 0; i < 4 * S * S; i++) {
            worst = fmax(worst, fabs(fast.rgba[i] - ref.rgba[i]));
            peak = fmax(peak, fabs(ref.rgba[i]));
        }
        if (worst > 1e-4 * peak)
            fail_msg("%s: highp differs from double by %g (peak %g)", models[k], worst, peak);
        sc_framebuffer_free(&ref);
        sc_framebuffer_free(&fast);
    }
    sc_mesh_free(&m);
    sc_surface_free(s);
}

/* What the kernels do not cover stays with sc_shade: legacy models and ranges; the plan says
 * which. Every BRDF, falloff and spot function is covered. */
static void other_scenes_keep_sc_shade(void **state)
{
    (void)state;
    static const struct {
        const char *light, *model, *why;
    } cases[] = {
        {"point pos=0,0,3 I=5 range=4", "lambert", "light 1: range=4"},
        {"point pos=0,0,3 I=5", "opengl", "model opengl"},
        {"point pos=0,0,3 I=5", "ads", "model ads"},
    };
    static const struct {
        const char *light, *model;
    } covered[] = {
        {"spot pos=0,0,3 dir=0,0,-1 I=5 atten=window rstart=1 rend=9", "lambert"},
        {"point pos=0,0,3 I=5 atten=clq sc=1 sl=0.1 sq=0.01", "lambert"},
        {"point pos=0,0,3 I=5", "phong m=20"},
        {"point pos=0,0,3 I=5", "blinn-phong form=plain"},
        {"point pos=0,0,3 I=5", "cook-torrance D=beckmann"},
        {"point pos=0,0,3 I=5", "cook-torrance ax=0.2 ay=0.4"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scene_box b;
        char why[256] = "";
        make_scene(&b, cases[k].light, cases[k].model);
        assert_null(sc_batch_plan_compile(&b.scene, "accurate", sc_isa_active(), why, sizeof why));
        if (!strstr(why, cases[k].why))
            fail_msg("%s / %s: reason '%s' lacks '%s'", cases[k].light, cases[k].model, why,
                     cases[k].why);
    }
    for (size_t k = 0; k < sizeof covered / sizeof covered[0]; k++) {
        scene_box b;
        char why[256] = "";
        make_scene(&b, covered[k].light, covered[k].model);
        sc_batch_plan *plan = sc_batch_plan_compile(&b.scene, "accurate", sc_isa_active(), why,
                                                    sizeof why);
        if (!plan)
            fail_msg("%s / %s: %s", covered[k].light, covered[k].model, why);
        sc_batch_plan_free(plan);
    }
    scene_box b;
    char why[256] = "";
    make_scene(&b, "point pos=0,0,3 I=5", "lambert");
    assert_null(sc_batch_plan_compile(&b.scene, "u7", sc_isa_active(), why, sizeof why));
    assert_non_null(strstr(why, "tier u7"));
}

/* render's tier: each tier of the shading kernel stays within its bound of the double image
 * (bits12: 2^-12 relative, plus the same absolute allowance), and the fast tier really is
 * different code (its image differs from the accurate one). */
static void render_tiers_within_their_bounds(void **state)
{
    (void)state;
    enum { S = 48 };
    static const struct {
        const char *tier;
        double bound;
    } tiers[] = {{"accurate", 0x1p-15}, {"bits12", 0x1p-12}};
    enum { N_TIERS = sizeof tiers / sizeof tiers[0] };
    sc_surface *s = sphere();
    sc_mesh m;
    scene_box b;
    char err[256];
    tessellate(s, 1500, &m);
    make_scene(&b, "point pos=2,-3,3 I=20", "cook-torrance alpha=0.3 f0=0.04");
    sc_framebuffer ref, img[N_TIERS];
    assert_int_equal(sc_framebuffer_init(&ref, S, S), 0);
    sc_render_params p = {.mesh = &m,
                          .surface = s,
                          .scene = &b.scene,
                          .prec = SC_DOUBLE,
                          .shading = SC_SHADING_PHONG,
                          .camera = side_view,
                          .threads = 1};
    assert_int_equal(sc_render(&p, &ref, err, sizeof err), 0);
    double peak = 0.0;
    for (int i = 0; i < 4 * S * S; i++)
        peak = fmax(peak, fabs(ref.rgba[i]));
    for (int t = 0; t < N_TIERS; t++) {
        assert_int_equal(sc_framebuffer_init(&img[t], S, S), 0);
        p.prec = SC_HIGHP;
        p.tier = tiers[t].tier;
        assert_int_equal(sc_render(&p, &img[t], err, sizeof err), 0);
        double worst = 0.0;
        for (int i = 0; i < 4 * S * S; i++)
            worst = fmax(worst,
                         fabs(img[t].rgba[i] - ref.rgba[i]) / (fabs(ref.rgba[i]) + 1e-3 * peak));
        if (worst > 2.0 * tiers[t].bound + 1e-5) /* plus the float rounding of the inputs */
            fail_msg("tier %s: relative error %g over its bound %g", tiers[t].tier, worst,
                     tiers[t].bound);
    }
    assert_memory_not_equal(img[0].rgba, img[1].rgba, 4 * S * S * sizeof(float));
    for (int t = 0; t < N_TIERS; t++)
        sc_framebuffer_free(&img[t]);
    sc_framebuffer_free(&ref);
    sc_mesh_free(&m);
    sc_surface_free(s);
}

/* The unit normal of the unit sphere where the ray through pixel (x, y)'s centre meets it
 * first (|eye + s·d|² = 1), and the cosine between that normal and the ray; 0 if it misses. */
static double ray_sphere_normal(const render_view *view, int size, int x, int y, double n[3])
{
    double ndc_x = 2.0 * (x + 0.5) / size - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / size, d[3];
    double a = 0.0, half_b = 0.0, c = -1.0, cos_ray = 0.0;
    for (int k = 0; k < 3; k++) {
        d[k] = view->forward[k] + ndc_x / view->scale_x * view->right[k] +
               ndc_y / view->scale_y * view->up[k];
        a += d[k] * d[k];
        half_b += view->eye[k] * d[k];
        c += view->eye[k] * view->eye[k];
    }
    double disc = half_b * half_b - a * c;
    if (disc < 0.0)
        return 0.0;
    double s = (-half_b - sqrt(disc)) / a;
    for (int k = 0; k < 3; k++) {
        n[k] = view->eye[k] + s * d[k];
        cos_ray -= n[k] * d[k] / sqrt(a);
    }
    return cos_ray;
}

/* Exact shading on the unit sphere, seen from the side and from above a pole: no hole inside
 * the disc, and the normal at each pixel is the sphere's where the pixel's ray meets it. The
 * mesh lies within (π/40)²/8 ≈ 8e-4 of the sphere (6320 triangles: 40 rows), the (u, v) found on
 * it maps to a point that far from the ray's hit divided by the cosine between ray and normal:
 * below 5e-3 where that cosine is at least 0.3 (the rim, excluded, is where it tends to 0). */
static void exact_sphere_normals_match_ray_intersection(void **state)
{
    (void)state;
    enum { S = 65 };
    sc_surface *s = sphere();
    sc_mesh m;
    scene_box b;
    tessellate(s, 6320, &m);
    make_scene(&b, "directional dir=0,-1,1 I=1", "lambert");
    const sc_camera cams[2] = {{{0, -4, 0}, {0, 0, 0}, {0, 0, 1}, 40},
                               {{0.1, 0.2, 4}, {0, 0, 0}, {0, 1, 0}, 40}};
    for (int k = 0; k < 2; k++) {
        sc_framebuffer fb;
        render_view view;
        double worst = 0.0;
        int compared = 0;
        assert_int_equal(sc_framebuffer_init(&fb, S, S), 0);
        render_ok(&m, s, &b.scene, SC_SHADING_EXACT, &cams[k], 2, &fb);
        render_view_make(&cams[k], S, S, &view);
        for (int i = 0; i < S * S; i++) {
            double n[3];
            if (ray_sphere_normal(&view, S, i % S, i / S, n) < 0.3)
                continue;
            assert_true(fb.rgba[4 * i + 3] == 1.0f);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, fabs(fb.normal[3 * i + c] - n[c]));
            compared++;
        }
        assert_true(compared > S * S / 4);
        if (worst > 5e-3)
            fail_msg("camera %d: exact normals off by %g", k, worst);
        sc_framebuffer_free(&fb);
    }
    sc_mesh_free(&m);
    sc_surface_free(s);
}

/* The lecture's comparison as a property, at a small size: against the exact image, Phong at
 * 6320 triangles beats Gouraud at 6320, and Gouraud improves with the triangle count. */
static void comparison_ordering(void **state)
{
    (void)state;
    enum { S = 96 };
    const int counts[3] = {1024, 6320, 40000};
    sc_surface *s = sphere();
    sc_mesh m[3];
    scene_box b;
    make_scene(&b, "directional dir=-0.4,-1,1.1 I=2", "blinn-phong diff=0.5 spec=0.4 m=200");
    sc_framebuffer exact, img;
    assert_int_equal(sc_framebuffer_init(&exact, S, S), 0);
    assert_int_equal(sc_framebuffer_init(&img, S, S), 0);
    for (int k = 0; k < 3; k++)
        tessellate(s, counts[k], &m[k]);
    render_ok(&m[2], s, &b.scene, SC_SHADING_EXACT, &side_view, 2, &exact);
    sc_render_error e[3], phong, self;
    for (int k = 0; k < 3; k++) {
        render_ok(&m[k], s, &b.scene, SC_SHADING_GOURAUD, &side_view, 2, &img);
        sc_render_compare(&img, &exact, NULL, &e[k]);
    }
    render_ok(&m[1], s, &b.scene, SC_SHADING_PHONG, &side_view, 2, &img);
    sc_render_compare(&img, &exact, NULL, &phong);
    sc_render_compare(&exact, &exact, NULL, &self);
    assert_true(self.rmse == 0.0 && self.max_error == 0.0 && self.pixels > S * S / 4);
    if (!(phong.rmse < e[1].rmse && e[2].rmse < e[1].rmse && e[1].rmse < e[0].rmse))
        fail_msg("rmse: gouraud %g %g %g, phong %g", e[0].rmse, e[1].rmse, e[2].rmse, phong.rmse);
    for (int k = 0; k < 3; k++)
        sc_mesh_free(&m[k]);
    sc_framebuffer_free(&exact);
    sc_framebuffer_free(&img);
    sc_surface_free(s);
}

/* By hand: ref covers pixel 0 only; differences (0.3, 0, 0.4) → rmse sqrt(0.25/3), max 0.4. */
static void compare_metric_by_hand(void **state)
{
    (void)state;
    sc_framebuffer a, ref;
    assert_int_equal(sc_framebuffer_init(&a, 2, 1), 0);
    assert_int_equal(sc_framebuffer_init(&ref, 2, 1), 0);
    const float av[8] = {0.5f, 0.25f, 1.0f, 1.0f, 9.0f, 9.0f, 9.0f, 1.0f};
    const float rv[8] = {0.2f, 0.25f, 0.6f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    memcpy(a.rgba, av, sizeof av);
    memcpy(ref.rgba, rv, sizeof rv);
    float map[2];
    sc_render_error e;
    sc_render_compare(&a, &ref, map, &e);
    assert_int_equal(e.pixels, 1);
    double d0 = 0.5 - (double)0.2f, d2 = 1.0 - (double)0.6f;
    assert_true(fabs(e.rmse - sqrt((d0 * d0 + d2 * d2) / 3.0)) < 1e-15);
    assert_true(e.max_error == d2);
    assert_true(map[0] == (float)d2 && map[1] == 0.0f);
    sc_framebuffer_free(&a);
    sc_framebuffer_free(&ref);
}

/* Writes the image as half and as float, reads it back: size, channel names in order, the
 * command-line attribute, values (float exact, half as the project's half rounding). */
static void check_exr_round_trip(const sc_image *img, const char *const *names)
{
    char path[] = "/tmp/test_render_XXXXXX", err[512];
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    const sc_image_attr attrs[] = {{"shadecalc:command", "shadecalc render -o x.exr"}};
    size_t values = (size_t)img->width * (size_t)img->height * (size_t)img->n_channels;
    for (int type = 0; type < 2; type++) {
        sc_image back;
        sc_image_attr *got;
        int n_got, found = 0;
        if (sc_exr_write(path, img, (sc_pixel_type)type, attrs, 1, err, sizeof err) < 0 ||
            sc_exr_read(path, &back, &got, &n_got, err, sizeof err) < 0)
            fail_msg("%s", err);
        assert_int_equal(back.width, img->width);
        assert_int_equal(back.height, img->height);
        assert_int_equal(back.n_channels, img->n_channels);
        for (int c = 0; c < img->n_channels; c++)
            assert_string_equal(back.channel[c], names[c]);
        for (int k = 0; k < n_got; k++)
            found |= strcmp(got[k].name, "shadecalc:command") == 0 &&
                     strcmp(got[k].value, "shadecalc render -o x.exr") == 0;
        assert_true(found);
        for (size_t i = 0; i < values; i++) {
            double want = type ? img->data[i] : sc_round_half(img->data[i]);
            if (!(back.data[i] == (float)want || (isinf(want) && isinf(back.data[i]))))
                fail_msg("%s value %zu (channel %s): %g, want %g", type ? "float" : "half", i,
                         names[i % (size_t)img->n_channels], back.data[i], want);
        }
        sc_image_attrs_free(got, n_got);
        sc_image_free(&back);
    }
    unlink(path);
}

/* RGBA (the default) and RGBA + Z + N, colours distinct per channel. */
static void exr_reads_back(void **state)
{
    (void)state;
    enum { SW = 17, SH = 9 };
    square q;
    scene_box b;
    make_square(&q, 1.0, 0.0);
    make_scene(&b, "point pos=0,0,1 I=1", "blinn-phong diff=0.6,0.3,0.1 spec=0.2");
    sc_framebuffer fb;
    assert_int_equal(sc_framebuffer_init(&fb, SW, SH), 0);
    render_ok(&q.mesh, NULL, &b.scene, SC_SHADING_PHONG, &above, 1, &fb);
    const char *names[] = {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z"};
    for (int extra = 0; extra < 2; extra++) {
        sc_image img;
        assert_int_equal(sc_render_image(&fb, extra, extra, &img), 0);
        assert_int_equal(img.n_channels, extra ? 8 : 4);
        check_exr_round_trip(&img, names);
        sc_image_free(&img);
    }
    sc_framebuffer_free(&fb);
}

static void invalid_inputs_fail_cleanly(void **state)
{
    (void)state;
    square q;
    scene_box b;
    char err[256];
    make_square(&q, 1.0, 0.0);
    make_scene(&b, "directional dir=0,0,1", "lambert");
    sc_framebuffer fb;
    assert_int_equal(sc_framebuffer_init(&fb, 8, 8), 0);
    sc_render_params p = {.mesh = &q.mesh,
                          .scene = &b.scene,
                          .shading = SC_SHADING_EXACT,
                          .camera = above,
                          .threads = 1};
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), -1);
    assert_non_null(strstr(err, "exact"));
    sc_mesh no_normals = q.mesh;
    no_normals.normal = NULL;
    p.mesh = &no_normals;
    p.shading = SC_SHADING_GOURAUD;
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), -1);
    assert_non_null(strstr(err, "normals"));
    p.shading = SC_SHADING_FLAT; /* flat needs no vertex normals */
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), 0);
    q.tri[4] = 7;
    p.mesh = &q.mesh;
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), -1);
    assert_non_null(strstr(err, "triangle 1"));
    q.tri[4] = 2;
    p.camera.eye[2] = 0.0;
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), -1);
    assert_non_null(strstr(err, "equals --at"));
    p.camera = above;
    sc_image taken;
    assert_int_equal(sc_render_image_take(&fb, 0, 0, &taken), 0);
    assert_int_equal(sc_render(&p, &fb, err, sizeof err), -1); /* its colours were taken */
    assert_non_null(strstr(err, "colour array"));
    sc_image_free(&taken);
    sc_framebuffer_free(&fb);
    assert_int_equal(sc_framebuffer_init(&fb, 0, 8), -1);
    assert_int_equal(sc_framebuffer_init(&fb, SC_RENDER_MAX_SIDE, SC_RENDER_MAX_SIDE), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(flat_square_matches_lambert),
        cmocka_unit_test(phong_matches_ray_traced_point),
        cmocka_unit_test(z_buffer_keeps_nearest),
        cmocka_unit_test(threads_give_the_same_image),
        cmocka_unit_test(colour_only_framebuffer_renders_and_moves),
        cmocka_unit_test(batch_kernel_matches_sc_shade),
        cmocka_unit_test(other_scenes_keep_sc_shade),
        cmocka_unit_test(render_tiers_within_their_bounds),
        cmocka_unit_test(exact_sphere_normals_match_ray_intersection),
        cmocka_unit_test(comparison_ordering),
        cmocka_unit_test(compare_metric_by_hand),
        cmocka_unit_test(exr_reads_back),
        cmocka_unit_test(invalid_inputs_fail_cleanly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
