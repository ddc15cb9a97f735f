/* The float uniforms of the batch kernels from the double model types (src/simd/uniforms.h):
 * computed once, in double where it matters, rounded to float once. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "light/ltc.h"
#include "simd/uniforms.h"

static const double pi = 3.14159265358979323846;
static const double radians = 3.14159265358979323846 / 180.0;

/* ---- attenuation and spot ---- */

static int min_int(int a, int b) { return a < b ? a : b; }

void sc_uniforms_atten(const sc_atten *a, sc_atten_kind kind, sc_func_uniforms *u)
{
    memset(u, 0, sizeof *u);
    switch (kind) {
    case SC_ATTEN_CLQ: *u = (sc_func_uniforms){{(float)a->sc, (float)a->sl, (float)a->sq}}; break;
    case SC_ATTEN_WINDOW: { /* the step w = 0: its ramp is 0/1 (the kernels' window_ramp) */
        float w = (float)(a->r_end - a->r_start), s = 1.0f;
        int e = 0;
        if (w > 0.0f && w <= FLT_MAX)
            s = ldexpf(1.0f, min_int(1 - (frexpf(w, &e), e), FLT_MAX_EXP - 2)); /* w = f 2^e */
        *u = (sc_func_uniforms){{(float)a->r_start, (float)a->r_end, w * s,
                                 w > 0.0f ? 1.0f / (w * s) : 0.0f, s, w > 0.0f ? w : 1.0f}};
        break;
    }
    case SC_ATTEN_PIXAR: { /* flat where f_c = f_max: k0 = 0 */
        double k0 = log(a->f_c / a->f_max);
        *u = (sc_func_uniforms){{(float)a->f_c, (float)a->r_c, (float)a->s_e, (float)a->f_max,
                                 (float)k0, k0 == 0.0 ? 0.0f : (float)(-a->s_e / k0)}};
        break;
    }
    case SC_ATTEN_WINDOWED: {
        double r2 = a->r_max * a->r_max;
        *u = (sc_func_uniforms){{(float)a->r_max, (float)r2, (float)(1.0 / (r2 * r2))}};
        break;
    }
    default: break; /* none, inverse-square: no constants */
    }
}

static float float_at_least(double x) /* the least float >= x */
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static float float_at_most(double x)
{
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

void sc_uniforms_spot(const sc_spot *s, sc_spot_kind kind, sc_func_uniforms *u)
{
    if (kind == SC_SPOT_OPENGL) {
        *u = (sc_func_uniforms){{float_at_least(cos(s->cutoff * radians)), (float)s->exponent,
                                 s->cutoff == 180.0 ? 1.0f : 0.0f}};
        return;
    }
    double cp = cos(s->inner * radians), cu = cos(s->outer * radians);
    float cu_hi = float_at_most(cu);
    *u = (sc_func_uniforms){{float_at_least(cp), cu_hi, (float)(cu - cu_hi),
                             cp > cu ? (float)(1.0 / (cp - cu)) : 0.0f, (float)s->exponent}};
}

/* ---- BRDFs ---- */

/* The colour vectors: diffuse; specular (times F0 for Schlick's split); the third term. */
static void brdf_colours(const sc_brdf *b, sc_brdf_uniforms *u)
{
    int schlick = b->kind == SC_BRDF_COOK_TORRANCE && b->F == SC_F_SCHLICK;
    for (int c = 0; c < 3; c++) {
        u->col[0][c] = (float)b->diff[c];
        u->col[1][c] = (float)(schlick ? b->spec[c] * b->f0[c] : b->spec[c]);
        u->col[2][c] = (float)(b->kind == SC_BRDF_OREN_NAYAR ? b->diff[c] * b->diff[c]
                                                             : b->spec[c] * (1.0 - b->f0[c]));
    }
}

/* k by model: phong, blinn-phong k0 = the lobe's normalization; ward k0 = 1/(4π α_x α_y) (gmd
 * 1/(π α_x α_y)); oren-nayar A, B, 0.125 σ²/(σ²+0.09), 0.17/π σ²/(σ²+0.13); cook-torrance
 * α, η, 1/η², 4 for the 1982 form. */
static void brdf_constants(const sc_brdf *b, double ax, double ay, sc_brdf_uniforms *u)
{
    double s2 = b->sigma * b->sigma, m = b->m;
    switch (b->kind) {
    case SC_BRDF_PHONG:
        u->k[0] = (float)(b->form == SC_PHONG_NORMALIZED ? (m + 2.0) / (2.0 * pi) : 1.0 / pi);
        break;
    case SC_BRDF_BLINN_PHONG:
        u->k[0] = (float)(b->form == SC_BLINN_PLAIN ? 1.0 : (m + 8.0) / (8.0 * pi));
        break;
    case SC_BRDF_WARD:
        u->k[0] = (float)(1.0 / ((b->form == SC_WARD_GMD ? 1.0 : 4.0) * pi * ax * ay));
        break;
    case SC_BRDF_OREN_NAYAR:
        u->k[0] = (float)(1.0 - 0.5 * s2 / (s2 + 0.33));
        u->k[1] = (float)(0.45 * s2 / (s2 + 0.09));
        u->k[2] = (float)(0.125 * s2 / (s2 + 0.09));
        u->k[3] = (float)(0.17 / pi * (s2 / (s2 + 0.13)));
        break;
    case SC_BRDF_COOK_TORRANCE:
        u->k[0] = (float)ax;
        u->k[1] = (float)b->ior;
        u->k[2] = (float)(1.0 / (b->ior * b->ior));
        u->k[3] = b->form == SC_CT_1982 ? 4.0f : 1.0f;
        break;
    default: break;
    }
}

/* m when an integer in 1..SC_LOBE_INT_MAX, else 0; *cutoff 2^(−100/m), the base below which
 * the fast tiers flush m-th powers to 0 (else 0) */
static unsigned lobe_exponent(double m, float *cutoff)
{
    int integer = m >= 1.0 && m <= SC_LOBE_INT_MAX && m == floor(m);
    *cutoff = integer ? (float)exp2(-100.0 / m) : 0.0f;
    return integer ? (unsigned)m : 0u;
}

void sc_uniforms_brdf(const sc_brdf *b, sc_brdf_uniforms *u)
{
    double ax = b->ax > 1e-4 ? b->ax : 1e-4, ay = b->ay > 1e-4 ? b->ay : 1e-4;
    memset(u, 0, sizeof *u);
    u->model = b->kind >= SC_BRDF_LAMBERT && b->kind <= SC_BRDF_COOK_TORRANCE ? b->kind
                                                                              : SC_BRDF_LAMBERT;
    u->form = b->form;
    u->D = b->D;
    u->G = b->G;
    u->F = b->F;
    u->aniso = (u->model == SC_BRDF_WARD || u->model == SC_BRDF_COOK_TORRANCE) && ax != ay;
    u->m = (float)b->m;
    u->ax = (float)ax;
    u->ay = (float)ay;
    u->a2 = (float)(ax * ay);
    /* the exponent model_phong and model_blinn_phong (src/simd/light_impl.h) raise to */
    double lobe = u->model == SC_BRDF_PHONG         ? (double)u->m
                  : u->model == SC_BRDF_BLINN_PHONG ? 0.5 * (double)u->m
                                                    : 0.0;
    u->lobe_m = lobe_exponent(lobe, &u->lobe_cutoff);
    brdf_colours(b, u);
    brdf_constants(b, ax, ay, u);
}

/* ---- scenes ---- */

static int refuse(char *why, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Writes the reason and returns -1. */
static int refuse(char *why, size_t size, const char *fmt, ...)
{
    if (why && size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, size, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static int grey(const double v[3]) { return v[0] == v[1] && v[1] == v[2]; }

/* The kernel's own GGX: walter, GGX, smith-correlated, Schlick, grey F0, isotropic. */
static int own_ggx(const sc_brdf *b)
{
    return b->form == SC_CT_WALTER && b->D == SC_D_GGX && b->G == SC_G_SMITH_CORRELATED &&
           b->F == SC_F_SCHLICK && b->ax == b->ay && grey(b->f0);
}

static int brdf_uniforms_of(const sc_brdf *b, sc_shade_uniforms *u, char *why, size_t size)
{
    if (b->kind == SC_BRDF_FILE)
        return refuse(why, size,
                      "a BRDF file's GLSL runs in the interpreter, not in the batch "
                      "kernels");
    if (!(b->kind >= SC_BRDF_LAMBERT && b->kind <= SC_BRDF_COOK_TORRANCE))
        return refuse(why, size, "brdf kind %d is not covered by the batch kernels", (int)b->kind);
    sc_uniforms_brdf(b, &u->brdf);
    u->lobe = b->kind == SC_BRDF_LAMBERT                       ? SC_LOBE_NONE
              : b->kind == SC_BRDF_BLINN_PHONG                 ? SC_LOBE_BLINN
              : b->kind == SC_BRDF_COOK_TORRANCE && own_ggx(b) ? SC_LOBE_GGX
                                                               : SC_LOBE_MODEL;
    for (int c = 0; c < 3; c++) {
        u->diff_pi[c] = (float)(b->diff[c] / pi);
        u->spec[c] = (float)b->spec[c];
    }
    u->lobe_k = u->brdf.k[0];
    u->m = (float)b->m;
    u->alpha = u->brdf.ax;
    u->f0 = (float)b->f0[0];
    u->lobe_m = lobe_exponent(b->m, &u->lobe_cutoff);
    return 0;
}

static void unit_float(const double v[3], float out[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; c++)
        out[c] = (float)(len > 0.0 ? v[c] / len : 0.0);
}

/* Directional, point and spot lights, with any falloff and no range (a direct3d9 setting).
 * Another kind (a new enumerator of sc_light_kind) is refused by its number (area lights:
 * area_uniforms_of). */
static int light_uniforms_of(const sc_light *l, int k, sc_light_uniforms *u, char *why, size_t size)
{
    memset(u, 0, sizeof *u);
    switch (l->kind) {
    case SC_LIGHT_DIRECTIONAL:
    case SC_LIGHT_POINT:
    case SC_LIGHT_SPOT: break;
    default:
        return refuse(why, size, "light %d: light kind %d not covered by the batch kernels", k + 1,
                      (int)l->kind);
    }
    if (isfinite(l->range))
        return refuse(why, size,
                      "light %d: range=%g (direct3d9) is not covered by the batch kernels", k + 1,
                      l->range);
    if (l->kind != SC_LIGHT_DIRECTIONAL &&
        !(l->atten.kind >= SC_ATTEN_NONE && l->atten.kind <= SC_ATTEN_WINDOWED))
        return refuse(why, size, "light %d: attenuation kind %d not covered by the batch kernels",
                      k + 1, (int)l->atten.kind);
    if (l->kind == SC_LIGHT_SPOT &&
        !(l->spot.kind >= SC_SPOT_OPENGL && l->spot.kind <= SC_SPOT_SMOOTHSTEP))
        return refuse(why, size, "light %d: spot kind %d not covered by the batch kernels", k + 1,
                      (int)l->spot.kind);
    u->kind = l->kind;
    u->atten = l->kind == SC_LIGHT_DIRECTIONAL ? SC_ATTEN_NONE : l->atten.kind;
    u->spot = l->spot.kind;
    unit_float(l->dir, u->dir);
    for (int c = 0; c < 3; c++) {
        u->pos[c] = (float)l->pos[c];
        u->color[c] = (float)l->intensity[c];
    }
    sc_uniforms_atten(&l->atten, u->atten, &u->atten_u);
    if (l->kind == SC_LIGHT_SPOT)
        sc_uniforms_spot(&l->spot, u->spot, &u->spot_u);
    return 0;
}

/* ---- area lights ---- */

/* The corners centre ± edge1/2 ± edge2/2 in the order of light/area_ltc.c. */
const float sc_area_ring_rect[2][4] = {{-0.5f, 0.5f, 0.5f, -0.5f}, {-0.5f, -0.5f, 0.5f, 0.5f}};
/* cos and sin of 2πk/64 (printed by Python's math.cos, math.sin): the disk's polygon, as
 * sc_ltc_disk builds it */
/* clang-format off */
const float sc_area_ring_disk[2][64] = {{1.0f, 0.9951847266721969f, 0.9807852804032304f, 0.9569403357322088f, 0.9238795325112867f, 0.881921264348355f, 0.8314696123025452f, 0.773010453362737f, 0.7071067811865476f, 0.6343932841636455f, 0.5555702330196023f, 0.4713967368259978f, 0.38268343236508984f, 0.29028467725446233f, 0.19509032201612833f, 0.09801714032956077f, 6.123233995736766e-17f, -0.09801714032956065f, -0.1950903220161282f, -0.29028467725446216f, -0.3826834323650897f, -0.4713967368259977f, -0.555570233019602f, -0.6343932841636454f, -0.7071067811865475f, -0.773010453362737f, -0.8314696123025453f, -0.8819212643483549f, -0.9238795325112867f, -0.9569403357322088f, -0.9807852804032304f, -0.9951847266721968f, -1.0f, -0.9951847266721969f, -0.9807852804032304f, -0.9569403357322089f, -0.9238795325112868f, -0.881921264348355f, -0.8314696123025455f, -0.7730104533627371f, -0.7071067811865477f, -0.6343932841636459f, -0.5555702330196022f, -0.47139673682599786f, -0.38268343236509034f, -0.29028467725446244f, -0.19509032201612866f, -0.09801714032956045f, -1.8369701987210297e-16f, 0.09801714032956009f, 0.1950903220161283f, 0.29028467725446205f, 0.38268343236509f, 0.4713967368259976f, 0.5555702330196018f, 0.6343932841636456f, 0.7071067811865474f, 0.7730104533627367f, 0.8314696123025452f, 0.8819212643483548f, 0.9238795325112865f, 0.9569403357322088f, 0.9807852804032303f, 0.9951847266721969f},
                                       {0.0f, 0.0980171403295606f, 0.19509032201612825f, 0.29028467725446233f, 0.3826834323650898f, 0.47139673682599764f, 0.5555702330196022f, 0.6343932841636455f, 0.7071067811865475f, 0.773010453362737f, 0.8314696123025452f, 0.8819212643483549f, 0.9238795325112867f, 0.9569403357322089f, 0.9807852804032304f, 0.9951847266721968f, 1.0f, 0.9951847266721969f, 0.9807852804032304f, 0.9569403357322089f, 0.9238795325112867f, 0.881921264348355f, 0.8314696123025455f, 0.7730104533627371f, 0.7071067811865476f, 0.6343932841636455f, 0.5555702330196022f, 0.47139673682599786f, 0.3826834323650899f, 0.2902846772544624f, 0.1950903220161286f, 0.09801714032956083f, 1.2246467991473532e-16f, -0.09801714032956059f, -0.19509032201612836f, -0.2902846772544621f, -0.38268343236508967f, -0.47139673682599764f, -0.555570233019602f, -0.6343932841636453f, -0.7071067811865475f, -0.7730104533627367f, -0.8314696123025452f, -0.8819212643483549f, -0.9238795325112865f, -0.9569403357322088f, -0.9807852804032303f, -0.9951847266721969f, -1.0f, -0.9951847266721969f, -0.9807852804032304f, -0.9569403357322089f, -0.9238795325112866f, -0.881921264348355f, -0.8314696123025455f, -0.7730104533627369f, -0.7071067811865477f, -0.6343932841636459f, -0.5555702330196022f, -0.4713967368259979f, -0.3826834323650904f, -0.2902846772544625f, -0.19509032201612872f, -0.0980171403295605f}};
/* clang-format on */

static const char *const area_kinds[] = {"sphere", "tube", "disk", "rect"};

static void to_float3(const double v[3], float out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = (float)v[c];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The disk's polygon axes as sc_ltc_disk builds them: e1 ⊥ the axis, e2 = axis × e1, both
 * times the radius of the 64-gon of the disk's area. */
static void disk_axes(const sc_area *area, sc_area_uniforms *u)
{
    double axis[3], len = sqrt(dot3(area->normal, area->normal)), e1[3] = {0, 0, 0}, e2[3];
    for (int c = 0; c < 3; c++)
        axis[c] = area->normal[c] / len;
    e1[fabs(axis[0]) < 0.9 ? 0 : 1] = 1.0;
    double along = dot3(e1, axis);
    for (int c = 0; c < 3; c++)
        e1[c] -= along * axis[c];
    double e1_len = sqrt(dot3(e1, e1));
    for (int c = 0; c < 3; c++)
        e1[c] /= e1_len;
    cross3(axis, e1, e2);
    double step = 2.0 * pi / 64.0, r = area->radius * sqrt(2.0 * pi / (64.0 * sin(step)));
    for (int c = 0; c < 3; c++) {
        u->e1[c] = (float)(r * e1[c]);
        u->e2[c] = (float)(r * e2[c]);
    }
}

static void area_geometry(const sc_light *l, sc_area_uniforms *u)
{
    const sc_area *a = &l->area;
    double R = a->radius;
    u->radius = (float)R;
    to_float3(l->pos, u->centre);
    to_float3(a->normal, u->normal);
    u->two_sided = a->two_sided;
    u->half_along = (float)R;
    if (l->kind == SC_LIGHT_TUBE) {
        double axis[3], centre[3];
        for (int c = 0; c < 3; c++) {
            axis[c] = a->p1[c] - a->p0[c];
            centre[c] = 0.5 * (a->p0[c] + a->p1[c]);
        }
        double len = sqrt(dot3(axis, axis));
        to_float3(centre, u->centre);
        to_float3(a->p0, u->p0);
        to_float3(axis, u->axis);
        u->line = (float)(2.0 * R * len);
        u->half_along = (float)(R + 0.5 * len);
    } else if (l->kind == SC_LIGHT_RECT) {
        double nl[3];
        cross3(a->edge1, a->edge2, nl);
        to_float3(nl, u->normal);
        to_float3(a->edge1, u->e1);
        to_float3(a->edge2, u->e2);
    } else if (l->kind == SC_LIGHT_DISK && R > 0.0) {
        disk_axes(a, u);
    }
}

/* The LTC uniforms of the scene's BRDF: the colours of the specular part, and the table's
 * rows at its α, interpolated in α as light/ltc.c's bilinear lookup does first. */
_Static_assert(SC_LTC_ROWS == SC_LTC_SIZE && (int)SC_LTC_ROW == (int)SC_LTC_FIELDS, "the LTC rows");

static void ltc_uniforms_of(const sc_brdf *b, sc_shade_uniforms *u)
{
    int specular = b->kind == SC_BRDF_COOK_TORRANCE;
    for (int c = 0; c < 3; c++) {
        double f0 = b->F == SC_F_SCHLICK ? b->f0[c] : 1.0;
        u->ltc_sa[c] = specular ? (float)(b->spec[c] * f0) : 0.0f;
        u->ltc_sb[c] = specular ? (float)(b->spec[c] * (1.0 - f0)) : 0.0f;
    }
    double alpha = specular ? b->ax : 1.0;
    alpha = !(alpha >= SC_LTC_ALPHA_MIN) ? SC_LTC_ALPHA_MIN : alpha > 1.0 ? 1.0 : alpha;
    double x = sqrt(alpha) * (SC_LTC_SIZE - 1);
    int i = (int)x > SC_LTC_SIZE - 2 ? SC_LTC_SIZE - 2 : (int)x;
    double fx = x - i;
    for (int j = 0; j < SC_LTC_SIZE; j++)
        for (int k = 0; k < SC_LTC_ROW; k++)
            u->ltc_rows[j][k] = (float)(sc_ltc_table[j][i][k] +
                                        fx * (sc_ltc_table[j][i + 1][k] - sc_ltc_table[j][i][k]));
}

/* An area light (u's lobe already set): method=point as the point light of its stand-in;
 * representative-point with the kernel's own lobes; ltc with the BRDFs it applies to;
 * method=reference refused. */
static int area_uniforms_of(const sc_scene *s, int k, sc_shade_uniforms *u, char *why, size_t size)
{
    const sc_light *l = &s->lights[k];
    const char *kind = area_kinds[l->kind - SC_LIGHT_SPHERE];
    sc_area_method method = l->area.method;
    char msg[200];
    if (method == SC_AREA_POINT) {
        sc_light point;
        sc_area_stand_in(l, &point);
        return light_uniforms_of(&point, k, &u->lights[k], why, size);
    }
    if (method == SC_AREA_REFERENCE)
        return refuse(why, size,
                      "light %d: %s method=reference is not covered by the batch kernels (shade "
                      "and check evaluate it; the kernels take method=representative-point, ltc "
                      "or point)",
                      k + 1, kind);
    if (method != SC_AREA_REPRESENTATIVE && method != SC_AREA_LTC)
        return refuse(why, size, "light %d: area method %d not covered by the batch kernels", k + 1,
                      (int)method);
    if (sc_area_method_applies(l->kind, method, &s->model.brdf, msg, sizeof msg) != 0)
        return refuse(why, size, "light %d: %s %s", k + 1, kind, msg);
    if (method == SC_AREA_REPRESENTATIVE && u->lobe == SC_LOBE_MODEL)
        return refuse(why, size,
                      "light %d: %s method=representative-point with brdf %s as given is not "
                      "covered by the batch kernels (they take lambert, blinn-phong, and "
                      "cook-torrance walter D=ggx G=smith-correlated F=schlick with a grey f0 "
                      "and ax = ay)",
                      k + 1, kind, sc_brdf_kind_name(s->model.brdf.kind));
    sc_light_uniforms *lu = &u->lights[k];
    memset(lu, 0, sizeof *lu);
    lu->kind = l->kind;
    to_float3(l->intensity, lu->color);
    area_geometry(l, &lu->area);
    if (method == SC_AREA_LTC)
        ltc_uniforms_of(&s->model.brdf, u);
    return 0;
}

/* The straight-line variant of the kernel for u's lights (src/simd/uniforms.h), 0 for the
 * generic loop: 1..4 lights of one shape, directional, or point or spot with inverse-square
 * falloff, with one of the kernel's own lobes. */
static int variant_of(const sc_shade_uniforms *u)
{
    if (u->lobe == SC_LOBE_MODEL || u->n_lights < 1 || u->n_lights > SC_SHADE_FIXED_MAX)
        return 0;
    const sc_light_uniforms *first = &u->lights[0];
    int inverse_square = first->atten == SC_ATTEN_INVERSE_SQUARE;
    int shape = first->kind == SC_LIGHT_DIRECTIONAL               ? SC_SHAPE_DIRECTIONAL
                : first->kind == SC_LIGHT_POINT && inverse_square ? SC_SHAPE_POINT
                : first->kind == SC_LIGHT_SPOT && inverse_square  ? SC_SHAPE_SPOT
                                                                  : -1;
    for (int k = 1; k < u->n_lights && shape >= 0; k++)
        if (u->lights[k].kind != first->kind || u->lights[k].atten != first->atten)
            shape = -1;
    return shape < 0 ? 0 : 1 + SC_SHADE_FIXED_MAX * shape + (u->n_lights - 1);
}

static const char *const model_names[] = {"brdf", "ads", "opengl", "direct3d9"};

int sc_uniforms_shade(const sc_scene *s, sc_shade_uniforms *u, char *why, size_t size)
{
    memset(u, 0, sizeof *u);
    if (s->model.kind != SC_MODEL_BRDF)
        return refuse(why, size,
                      "model %s: the legacy fixed-function models are not covered by the batch "
                      "kernels (they compute the BRDF models)",
                      s->model.kind >= SC_MODEL_ADS && s->model.kind <= SC_MODEL_D3D9
                          ? model_names[s->model.kind]
                          : "?");
    if (s->n_lights > SC_BATCH_MAX_LIGHTS)
        return refuse(why, size, "%d lights: the batch kernels take at most %d", s->n_lights,
                      SC_BATCH_MAX_LIGHTS);
    if (brdf_uniforms_of(&s->model.brdf, u, why, size) != 0)
        return -1;
    double ambient[3] = {s->ambient[0], s->ambient[1], s->ambient[2]};
    for (int k = 0; k < s->n_lights; k++) {
        const sc_light *l = &s->lights[k];
        if (sc_light_is_area(l->kind) ? area_uniforms_of(s, k, u, why, size) != 0
                                      : light_uniforms_of(l, k, &u->lights[k], why, size) != 0)
            return -1;
        for (int c = 0; c < 3; c++)
            ambient[c] += s->lights[k].ambient[c];
    }
    u->n_lights = s->n_lights;
    for (int c = 0; c < 3; c++)
        u->amb_term[c] = (float)(s->model.brdf.amb[c] * ambient[c]);
    u->variant = variant_of(u);
    return 0;
}
