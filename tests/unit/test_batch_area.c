/* The area-light batch kernels and plans (src/simd/area_impl.h) beyond their table rows
 * (tests/unit/test_batch.c checks those on 10^6 inputs): the other BRDFs each method takes,
 * the edge cases of shadecalc/area.h (a point inside or on a sphere or tube, an emitter
 * behind the surface or across its horizon, a point in the plane of a disk or rect or behind a
 * one-sided one, a zero-size emitter) on every instruction set against the double
 * approximation of src/light/ within the row's bound and never NaN; what plans accept and
 * refuse, and that a plan shades an area light as its kernel does. SHADECALC_BATCH_SEED=k draws
 * another set of random inputs (tests/unit/scale.h). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/batch.h"
#include "shadecalc/scene.h"

#include "batch/reference.h"
#include "batch/reference_light.h"
#include "tests/support/batch_buffers.h"
#include "tests/unit/scale.h"

enum { N_RANDOM = 100003, N_EDGE = 4099 }; /* not multiples of 8: the tails run too */

static uint64_t rng = 0x9E3779B97F4A7C15ULL;

typedef struct {
    sc_light light;
    sc_scene scene;
} one_light;

/* A scene of one light and a BRDF, parsed from their specs. */
static void scene_of(one_light *s, const char *light, const char *brdf)
{
    char err[256];
    memset(s, 0, sizeof *s);
    if (sc_light_parse(light, &s->light, err, sizeof err) != 0 ||
        sc_model_parse(brdf, &s->scene.model, err, sizeof err) != 0)
        fail_msg("%s / %s: %s", light, brdf, err);
    s->scene.lights = &s->light;
    s->scene.n_lights = 1;
}

static void set3(batch_buffers *b, int first, size_t i, const float v[3])
{
    for (int c = 0; c < 3; c++)
        b->in[first + c][i] = v[c];
}

/* The largest change of the double approximation (first's reference) at element i of b when a
 * coordinate of p moves by one ULP either way: what no float kernel avoids where the
 * approximation is steep (next to an emitter's surface, where one ULP of p moved a sphere's
 * by 1.6e-4 relative, 1.3 times the bound, 2^-12 outside it). */
static double one_ulp_of_p(const sc_batch_entry *first, const batch_buffers *b, size_t i)
{
    float in[9];
    double ref[4], worst = 0.0;
    sc_batch_args a = b->args;
    a.n = 1;
    for (int j = 0; j < 9; j++) {
        in[j] = b->in[j][i];
        a.in[j] = &in[j];
    }
    for (int k = 6; k < 9; k++)
        for (int up = 0; up < 2; up++) {
            float at = in[k];
            in[k] = nextafterf(at, up ? INFINITY : -INFINITY);
            first->ref(&a, 0, ref);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, fabs(ref[c] - b->ref[4 * i + c]));
            in[k] = at;
        }
    return worst;
}

/* Element i's error against its reference within the row's bound, or else within the bound
 * plus the change one ulp of p makes (one_ulp_of_p; the rows' domain says so), which widens
 * ref[3] for the ISAs after (widened[i]): measured only where the bound alone fails. */
static void error_with_steepness(const sc_batch_entry *first, const sc_batch_entry *e,
                                 batch_buffers *b, size_t i, unsigned char *widened,
                                 sc_batch_error *acc)
{
    sc_batch_error probe;
    sc_batch_error_init(&probe);
    if (!widened[i] && sc_batch_error_against(e, &b->args, i, b->ref + 4 * i, &probe) > 1.0) {
        b->ref[4 * i + 3] += one_ulp_of_p(first, b, i) / first->bound_abs; /* bound_abs × ref[3] */
        widened[i] = 1;
    }
    sc_batch_error_against(e, &b->args, i, b->ref + 4 * i, acc);
}

/* The kernel of the light's kind on every instruction set against the double approximation
 * (the row's reference on b's inputs) within the row's bound (error_with_steepness), never
 * NaN. */
static void check_kernel(const char *kernel, batch_buffers *b, const char *what)
{
    const sc_batch_entry *first = sc_batch_find(kernel, "accurate", SC_ISA_SCALAR);
    assert_non_null(first);
    unsigned char *widened = calloc(b->args.n, 1);
    assert_non_null(widened);
    for (size_t i = 0; i < b->args.n; i++)
        first->ref(&b->args, i, b->ref + 4 * i);
    for (int isa = 0; isa < SC_ISA_COUNT; isa++) {
        const sc_batch_entry *e = sc_batch_find(kernel, "accurate", (sc_isa)isa);
        if (!e || !sc_isa_supported(e->isa))
            continue;
        e->fn(&b->args);
        sc_batch_error acc;
        sc_batch_error_init(&acc);
        for (size_t i = 0; i < b->args.n; i++) {
            error_with_steepness(first, e, b, i, widened, &acc);
            for (int j = 0; j < 3; j++)
                if (isnan(b->out[j][i]))
                    fail_msg("%s %s (%s): NaN at element %zu", kernel, sc_isa_name(e->isa), what,
                             i);
        }
        if (acc.max_ratio > 1.0) {
            size_t w = acc.worst;
            fail_msg("%s %s (%s): %.3g× the bound at n = (%a, %a, %a), v = (%a, %a, %a), "
                     "p = (%a, %a, %a): %a against %a",
                     kernel, sc_isa_name(e->isa), what, acc.max_ratio, (double)b->in[0][w],
                     (double)b->in[1][w], (double)b->in[2][w], (double)b->in[3][w],
                     (double)b->in[4][w], (double)b->in[5][w], (double)b->in[6][w],
                     (double)b->in[7][w], (double)b->in[8][w], (double)b->out[0][w], b->ref[4 * w]);
        }
    }
    free(widened);
}

/* N_RANDOM random n, v, p (the rows' generator; a sample under the sanitizers) with the scene */
static void check_random(const char *kernel, const one_light *s, const char *what)
{
    batch_buffers b;
    size_t n = sc_test_inputs(N_RANDOM);
    batch_buffers_alloc(&b, n, &s->scene);
    for (size_t i = 0; i < n; i++) {
        float v[9];
        sc_batch_gen_shade(&rng, v);
        for (int j = 0; j < 9; j++)
            b.in[j][i] = v[j];
    }
    check_kernel(kernel, &b, what);
    batch_buffers_release(&b);
}

/* A point of the rect row's scene whose first clip's horizon chord passes within 5e-6 of the
 * origin of the view frame: the carried chord crosses its own horizon at x = 0, and the crossing
 * interpolated with an FMA (x -6.7e-8 beside y -4.7e-6) turned by 0.014 rad, 3.5 times the
 * bound on avx2 and avx512 before the crossing was put on the y axis exactly. */
static void rect_chord_near_origin(void **state)
{
    (void)state;
    static const float input[9] = {-0x1.e24ab8p-7f, -0x1.41e1c6p-4f, -0x1.14b9dep-4f,
                                   0x1.f2db44p-2f,  -0x1.46bb5cp+0f, -0x1.4dfaeep-2f,
                                   -0x1.383d1p-3f,  0x1.6a699ep+0f,  -0x1.8411d2p-4f};
    batch_buffers b;
    batch_buffers_alloc(&b, 17, &sc_batch_test_area_rect);
    for (size_t i = 0; i < b.args.n; i++)
        for (int j = 0; j < 9; j++)
            b.in[j][i] = input[j];
    check_kernel("area_rect", &b, "horizon chord near the origin");
    batch_buffers_release(&b);
}

/* The representative point with lambert and both forms of blinn-phong; LTC with lambert and
 * GGX without Fresnel (F = 1), and a two-sided disk and one-sided rect. */
static void other_brdfs(void **state)
{
    (void)state;
    static const char *const rp_brdfs[] = {"lambert", "blinn-phong m=32",
                                           "blinn-phong m=10.5 form=plain"};
    static const char *const rp_lights[][2] = {
        {"area_sphere", "sphere center=0.3,1.5,-0.2 radius=0.6 L=2 method=representative-point"},
        {"area_tube", "tube p0=-1,1.2,0 p1=1,1.6,0.4 radius=0.25 L=2 "
                      "method=representative-point"}};
    static const char *const ltc_brdfs[] = {
        "lambert", "cook-torrance D=ggx G=smith-correlated F=none alpha=0.1 spec=0.5"};
    static const char *const ltc_lights[][2] = {
        {"area_disk", "disk center=0,1.5,0 normal=0.2,-1,0.1 radius=0.8 two-sided=1 L=2 "
                      "method=ltc"},
        {"area_rect", "rect center=0.2,1.4,-0.1 edge1=1.5,0,0.2 edge2=0,0.3,1 L=2 method=ltc"}};
    one_light s;
    for (int l = 0; l < 2; l++) {
        for (size_t k = 0; k < sizeof rp_brdfs / sizeof rp_brdfs[0]; k++) {
            scene_of(&s, rp_lights[l][1], rp_brdfs[k]);
            check_random(rp_lights[l][0], &s, rp_brdfs[k]);
        }
        for (size_t k = 0; k < sizeof ltc_brdfs / sizeof ltc_brdfs[0]; k++) {
            scene_of(&s, ltc_lights[l][1], ltc_brdfs[k]);
            check_random(ltc_lights[l][0], &s, ltc_brdfs[k]);
        }
    }
}

static double uniform(double lo, double hi)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return lo + (hi - lo) * (double)(rng >> 11) * 0x1p-53;
}

/* A unit vector: uniform on the sphere */
static void random_unit(float out[3])
{
    double z = uniform(-1.0, 1.0), phi = uniform(0.0, 6.283185307179586), r = sqrt(1.0 - z * z);
    out[0] = (float)(r * cos(phi));
    out[1] = (float)(r * sin(phi));
    out[2] = (float)z;
}

/* n and v random (v above n's horizon), p from `place` for each element */
typedef void (*place_fn)(size_t i, float p[3], float n[3]);

static void check_places(const char *kernel, const one_light *s, place_fn place, const char *what)
{
    batch_buffers b;
    batch_buffers_alloc(&b, N_EDGE, &s->scene);
    for (size_t i = 0; i < N_EDGE; i++) {
        float n[3], v[3], p[3];
        random_unit(n);
        place(i, p, n);
        do
            random_unit(v);
        while (n[0] * v[0] + n[1] * v[1] + n[2] * v[2] < 0.02f);
        set3(&b, 0, i, n);
        set3(&b, 3, i, v);
        set3(&b, 6, i, p);
    }
    check_kernel(kernel, &b, what);
    batch_buffers_release(&b);
}

/* A point at distance r from (0, 2, 0) in a random direction. */
static void around_centre(double r, float p[3])
{
    float d[3];
    random_unit(d);
    p[0] = (float)(r * d[0]);
    p[1] = (float)(2.0 + r * d[1]);
    p[2] = (float)(r * d[2]);
}

/* At the centre of the sphere of radius 1 about (0, 2, 0), inside it, and next to its surface
 * on both sides: 2^-12 in or out, not on it, where the double approximation jumps (inside, the
 * whole hemisphere is the light) and a rounding of p decides. */
static void inside_sphere(size_t i, float p[3], float n[3])
{
    static const double at[] = {0.0, 1.0 - 0x1p-12, 1.0 + 0x1p-12};
    (void)n;
    around_centre(i % 2 ? uniform(0.0, 0.999) : at[i / 2 % 3], p);
}

/* inside the tube of radius 1 about p0 = (−0.5, 2, 0), p1 = (0.5, 2, 0), near its centre:
 * within 1 of the centre and of the axis point nearest to any ray */
static void inside_tube(size_t i, float p[3], float n[3])
{
    (void)n;
    around_centre(i % 3 ? uniform(0.0, 0.45) : 0.0, p);
}

/* inside the capsule of radius 0.3 about p0 = (−2, 2, 0), p1 = (2, 2, 0), mostly far from the
 * ball about its centre: along the axis and in its end caps, 10^-4 to 0.2 from the axis, where
 * the line's irradiance would diverge (1/distance) and a rounding of the point would move it
 * by more than the bound (the kernel measured 2.9 times it at 0.003 from a tube's axis) */
static void along_tube_axis(size_t i, float p[3], float n[3])
{
    (void)n, (void)i;
    double r = pow(10.0, uniform(-4.0, -0.7)), phi = uniform(0.0, 6.283185307179586);
    p[0] = (float)uniform(-2.2, 2.2);
    p[1] = (float)(2.0 + r * cos(phi));
    p[2] = (float)(r * sin(phi));
}

/* on the plane y = 0 under lights above it, n tilted so that they are behind the surface,
 * across its horizon, or in front */
static void under_lights(size_t i, float p[3], float n[3])
{
    p[0] = (float)uniform(-2.0, 2.0);
    p[1] = 0.0f;
    p[2] = (float)uniform(-2.0, 2.0);
    double tilt = uniform(-3.14159, 3.14159);
    n[0] = (float)sin(tilt);
    n[1] = (float)cos(tilt);
    n[2] = 0.0f;
    (void)i;
}

/* in the plane y = 2 of the disk and rect (inside and outside their outline), and behind */
static void in_plane(size_t i, float p[3], float n[3])
{
    p[0] = (float)uniform(-2.0, 2.0);
    p[1] = i % 2 ? 2.0f : (float)uniform(2.0, 4.0);
    p[2] = (float)uniform(-2.0, 2.0);
    (void)n;
}

static void edge_cases(void **state)
{
    (void)state;
    static const struct {
        const char *kernel, *light, *what;
        place_fn place;
    } cases[] = {
        {"area_sphere", "sphere center=0,2,0 radius=1 L=3 method=representative-point",
         "inside, at the centre and next to a sphere", inside_sphere},
        {"area_tube", "tube p0=-0.5,2,0 p1=0.5,2,0 radius=1 L=3 method=representative-point",
         "inside a tube and at its centre", inside_tube},
        {"area_tube", "tube p0=-2,2,0 p1=2,2,0 radius=0.3 L=3 method=representative-point",
         "inside a tube along its axis, far from its centre", along_tube_axis},
        {"area_sphere", "sphere center=0,1,0 radius=0.8 L=3 method=representative-point",
         "behind and across the horizon", under_lights},
        {"area_tube", "tube p0=-2,0.5,0 p1=2,0.5,0 radius=0.3 L=3 method=representative-point",
         "behind and across the horizon", under_lights},
        {"area_disk", "disk center=0,1,0 normal=0.3,-1,0 radius=1.5 L=3 method=ltc",
         "behind and across the horizon", under_lights},
        {"area_rect", "rect center=0,1,0 edge1=3,0,0 edge2=0,0.5,2 L=3 method=ltc",
         "behind and across the horizon", under_lights},
        {"area_disk", "disk center=0,2,0 normal=0,-1,0 radius=1 L=3 method=ltc",
         "in the plane of a one-sided disk and behind it", in_plane},
        {"area_rect", "rect center=0,2,0 edge1=1,0,0 edge2=0,0,1 two-sided=1 L=3 method=ltc",
         "in the plane of a two-sided rect and above it", in_plane},
        {"area_sphere", "sphere center=0,1,0 radius=0 L=3 method=representative-point",
         "zero radius", under_lights},
        {"area_tube", "tube p0=-1,1,0 p1=1,1,0 radius=0 L=3 method=representative-point",
         "zero radius", under_lights},
        {"area_disk", "disk center=0,1,0 normal=0,-1,0 radius=0 L=3 method=ltc", "zero radius",
         under_lights}};
    one_light s;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scene_of(&s, cases[k].light,
                 "cook-torrance D=ggx G=smith-correlated F=schlick alpha=0.3 f0=0.04");
        check_places(cases[k].kernel, &s, cases[k].place, cases[k].what);
    }
}

/* Mirror rays r = 2(n·v)n − v within 0.01 to 0.3 rad of a long tube's axis, from points in
 * and around it: the closest point of the axis to r is then a ratio of small quantities
 * (src/simd/area_impl.h, closest_centre), which the kernel computed with a cancellation that
 * cost 4e-3 of the specular part. Closer to the axis the approximation itself is steep in n
 * and v (at 10^-3 rad one ulp of n moves it by 4e-4 relative, 1.3 times the bound). */
static void rays_along_tube_axis(void **state)
{
    (void)state;
    one_light s;
    scene_of(&s, "tube p0=-2,2,0 p1=2,2,0 radius=0.3 L=3 method=representative-point",
             "cook-torrance D=ggx G=smith-correlated F=schlick alpha=0.3 f0=0.04");
    batch_buffers b;
    batch_buffers_alloc(&b, N_EDGE, &s.scene);
    for (size_t i = 0; i < N_EDGE; i++) {
        double e = pow(10.0, uniform(-2.0, -0.5)), phi = uniform(0.0, 6.283185307179586);
        double len = sqrt(1.0 + e * e), sign = i % 2 ? 1.0 : -1.0;
        double r[3] = {sign / len, e * cos(phi) / len, e * sin(phi) / len};
        float n[3], v[3], p[3];
        double nr;
        do { /* n toward r, then v its mirror image: n·v = n·r */
            random_unit(n);
            nr = n[0] * r[0] + n[1] * r[1] + n[2] * r[2];
        } while (nr < 0.05);
        for (int c = 0; c < 3; c++)
            v[c] = (float)(2.0 * nr * n[c] - r[c]);
        p[0] = (float)uniform(-2.5, 2.5);
        p[1] = (float)(2.0 + uniform(-0.6, 0.6));
        p[2] = (float)uniform(-0.6, 0.6);
        set3(&b, 0, i, n);
        set3(&b, 3, i, v);
        set3(&b, 6, i, p);
    }
    check_kernel("area_tube", &b, "mirror rays along the tube's axis");
    batch_buffers_release(&b);
}

/* A zero-size emitter gives exactly 0 away from it, as the double approximation does. */
static void zero_size_gives_zero(void **state)
{
    (void)state;
    static const char *const lights[][2] = {
        {"area_sphere", "sphere center=0,1,0 radius=0 L=3 method=representative-point"},
        {"area_disk", "disk center=0,1,0 normal=0,-1,0 radius=0 L=3 method=ltc"}};
    for (int l = 0; l < 2; l++) {
        one_light s;
        scene_of(&s, lights[l][1], "cook-torrance D=ggx G=smith-correlated alpha=0.3");
        batch_buffers b;
        batch_buffers_alloc(&b, 9, &s.scene);
        for (size_t i = 0; i < 9; i++) {
            float n[3] = {0, 1, 0}, v[3] = {0.6f, 0.8f, 0}, p[3] = {(float)i - 4.0f, 0, 0.5f};
            set3(&b, 0, i, n);
            set3(&b, 3, i, v);
            set3(&b, 6, i, p);
        }
        for (int isa = 0; isa < SC_ISA_COUNT; isa++) {
            const sc_batch_entry *e = sc_batch_find(lights[l][0], "accurate", (sc_isa)isa);
            if (!e || !sc_isa_supported(e->isa))
                continue;
            e->fn(&b.args);
            for (size_t i = 0; i < 9; i++)
                for (int c = 0; c < 3; c++)
                    assert_true(b.out[c][i] == 0.0f);
        }
        batch_buffers_release(&b);
    }
}

static sc_batch_plan *plan_of(const one_light *s, const char *tier, char *why, size_t size)
{
    return sc_batch_plan_compile(&s->scene, tier, SC_ISA_AVX512, why, size);
}

static void plans_accept_and_refuse(void **state)
{
    (void)state;
    static const char *const accepted[][2] = {
        {"sphere center=0,2,0 radius=0.5 method=representative-point", "blinn-phong"},
        {"tube p0=0,2,0 p1=1,2,0 radius=0.1 method=representative-point", "lambert"},
        {"disk center=0,2,0 normal=0,-1,0 radius=0.5 method=ltc",
         "cook-torrance D=ggx G=smith-correlated"},
        {"rect center=0,2,0 edge1=1,0,0 edge2=0,0,1 method=ltc", "lambert"},
        {"rect center=0,2,0 edge1=1,0,0 edge2=0,0,1 method=point", "ward"},
        {"tube p0=0,2,0 p1=1,2,0 radius=0.1 method=point", "phong"}};
    /* each refusal names the light, its method and what the kernels take instead */
    static const char *const refused[][3] = {
        {"sphere center=0,2,0 radius=0.5", "lambert", "method=reference"},
        {"disk center=0,2,0 normal=0,-1,0 radius=0.5 method=reference", "lambert",
         "shade and check"},
        {"sphere center=0,2,0 radius=0.5 method=representative-point", "phong",
         "representative-point with brdf phong"},
        {"rect center=0,2,0 edge1=1,0,0 edge2=0,0,1 method=ltc", "blinn-phong", "method=ltc"}};
    char why[512];
    one_light s;
    for (size_t k = 0; k < sizeof accepted / sizeof accepted[0]; k++) {
        scene_of(&s, accepted[k][0], accepted[k][1]);
        for (int t = 0; t < 2; t++) {
            sc_batch_plan *plan = plan_of(&s, t == 0 ? "accurate" : "bits12", why, sizeof why);
            if (!plan)
                fail_msg("%s with %s: %s", accepted[k][0], accepted[k][1], why);
            sc_batch_plan_free(plan);
        }
    }
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++) {
        scene_of(&s, refused[k][0], refused[k][1]);
        why[0] = '\0';
        assert_null(plan_of(&s, "accurate", why, sizeof why));
        if (!strstr(why, refused[k][2]) || !strstr(why, "light 1"))
            fail_msg("%s with %s: \"%s\" does not name %s", refused[k][0], refused[k][1], why,
                     refused[k][2]);
    }
}

/* n random inputs of the rows' domain into b */
static void random_inputs(batch_buffers *b)
{
    for (size_t i = 0; i < b->args.n; i++) {
        float v[9];
        sc_batch_gen_shade(&rng, v);
        for (int j = 0; j < 9; j++)
            b->in[j][i] = v[j];
    }
}

/* An accurate plan of the table's area scenes shades as the area kernel of the same
 * instruction set does, bit for bit (the same lanes, in the plan's loop over lights);
 * method=point as the plan of its point-light stand-in. */
static void plans_shade_as_the_kernels(void **state)
{
    (void)state;
    static const char *const kernels[] = {"area_sphere", "area_tube", "area_disk", "area_rect"};
    const sc_scene *scenes[] = {&sc_batch_test_area_sphere, &sc_batch_test_area_tube,
                                &sc_batch_test_area_disk, &sc_batch_test_area_rect};
    enum { N = 1003 };
    batch_buffers b, p;
    char why[256];
    for (int k = 0; k < 4; k++)
        for (int isa = 0; isa < SC_ISA_COUNT; isa++) {
            const sc_batch_entry *e = sc_batch_find(kernels[k], "accurate", (sc_isa)isa);
            if (!sc_isa_supported((sc_isa)isa))
                continue;
            sc_batch_plan *plan = sc_batch_plan_compile(scenes[k], "accurate", (sc_isa)isa, why,
                                                        sizeof why);
            if (!plan)
                fail_msg("%s: %s", kernels[k], why);
            batch_buffers_alloc(&b, N, scenes[k]);
            batch_buffers_alloc(&p, N, plan);
            random_inputs(&b);
            for (int j = 0; j < 9; j++)
                memcpy(p.in[j], b.in[j], N * sizeof(float));
            e->fn(&b.args);
            sc_batch_plan_shade(plan, (const float *const *)p.in, p.out, N);
            for (int j = 0; j < 3; j++)
                assert_memory_equal(b.out[j], p.out[j], N * sizeof(float));
            batch_buffers_release(&b);
            batch_buffers_release(&p);
            sc_batch_plan_free(plan);
        }
    /* method=point: the plan of the stand-in */
    one_light area, point;
    scene_of(&area, "tube p0=0,2,0 p1=1,2.5,0 radius=0.2 L=2 method=point", "blinn-phong");
    scene_of(&point, "point pos=0,2,0 I=1", "blinn-phong");
    sc_area_stand_in(&area.light, &point.light);
    sc_batch_plan *pa = plan_of(&area, "accurate", why, sizeof why),
                  *pp = plan_of(&point, "accurate", why, sizeof why);
    assert_non_null(pa);
    assert_non_null(pp);
    batch_buffers_alloc(&b, N, NULL);
    batch_buffers_alloc(&p, N, NULL);
    random_inputs(&b);
    sc_batch_plan_shade(pa, (const float *const *)b.in, b.out, N);
    sc_batch_plan_shade(pp, (const float *const *)b.in, p.out, N);
    for (int j = 0; j < 3; j++)
        assert_memory_equal(b.out[j], p.out[j], N * sizeof(float));
    batch_buffers_release(&b);
    batch_buffers_release(&p);
    sc_batch_plan_free(pa);
    sc_batch_plan_free(pp);
}

int main(void)
{
    rng = sc_test_seeded(rng);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plans_accept_and_refuse),
        cmocka_unit_test(plans_shade_as_the_kernels),
        cmocka_unit_test(zero_size_gives_zero),
        cmocka_unit_test(edge_cases),
        cmocka_unit_test(rays_along_tube_axis),
        cmocka_unit_test(rect_chord_near_origin),
        cmocka_unit_test(other_brdfs),
    };
    return cmocka_run_group_tests_name("batch_area", tests, NULL, NULL);
}
