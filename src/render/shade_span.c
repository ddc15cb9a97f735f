/* Shading a span of pixels (render/shade_span.h): through the SIMD batch shading kernel
 * (shadecalc/batch.h, tier "accurate") in highp when the scene is one it computes, through
 * sc_shade per point otherwise (other precisions, models, falloffs). */
#include "render/shade_span.h"

#include <math.h>

#include "shadecalc/batch.h"

enum { CHUNK = 64 };

static int same3(const double v[3]) { return v[0] == v[1] && v[1] == v[2]; }

/* The BRDFs the kernel computes: lambert, normalized blinn-phong, and cook-torrance with GGX,
 * Smith height-correlated masking and Schlick's Fresnel with a grey F0, isotropic. */
static int batch_brdf_of(const sc_brdf *b, sc_batch_scene *out)
{
    switch (b->kind) {
    case SC_BRDF_LAMBERT: out->brdf = SC_BATCH_LAMBERT; return 1;
    case SC_BRDF_BLINN_PHONG:
        out->brdf = SC_BATCH_BLINN_PHONG;
        return b->form == SC_BLINN_NORMALIZED && b->m >= 1.0;
    case SC_BRDF_COOK_TORRANCE:
        out->brdf = SC_BATCH_GGX;
        return b->form == SC_CT_WALTER && b->D == SC_D_GGX && b->G == SC_G_SMITH_CORRELATED &&
               b->F == SC_F_SCHLICK && b->ax == b->ay && b->ax >= 1e-4 && same3(b->f0);
    default: return 0;
    }
}

/* The spot of a light as the kernel's uniforms: cosines of the half-angles. */
static void batch_spot_of(const sc_spot *spot, sc_batch_light *out)
{
    static const sc_batch_spot kinds[] = {SC_BATCH_SPOT_OPENGL, SC_BATCH_SPOT_DIRECTX,
                                          SC_BATCH_SPOT_SMOOTHSTEP};
    const double radians = 0.017453292519943295;
    out->spot = kinds[spot->kind];
    out->exponent = (float)spot->exponent;
    if (spot->kind == SC_SPOT_OPENGL) {
        out->cos_outer = spot->cutoff == 180.0 ? -2.0f : (float)cos(spot->cutoff * radians);
        return;
    }
    out->cos_outer = (float)cos(spot->outer * radians);
    out->cos_inner = (float)cos(spot->inner * radians);
}

static void unit_float(const double v[3], float out[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; c++)
        out[c] = (float)(len > 0.0 ? v[c] / len : 0.0);
}

/* Directional lights, and point and spot lights with inverse-square falloff (the kernel's
 * 1/max(r², 10^-4) is light.h's), without a range. */
static int batch_light_of(const sc_light *l, sc_batch_light *out)
{
    static const sc_batch_light_kind kinds[] = {SC_BATCH_DIRECTIONAL, SC_BATCH_POINT,
                                                SC_BATCH_SPOT};
    int directional = l->kind == SC_LIGHT_DIRECTIONAL;
    if (isfinite(l->range) ||
        l->atten.kind != (directional ? SC_ATTEN_NONE : SC_ATTEN_INVERSE_SQUARE))
        return 0;
    out->kind = kinds[l->kind];
    unit_float(l->dir, out->dir);
    for (int c = 0; c < 3; c++) {
        out->pos[c] = (float)l->pos[c];
        out->color[c] = (float)l->intensity[c];
    }
    if (l->kind == SC_LIGHT_SPOT)
        batch_spot_of(&l->spot, out);
    return 1;
}

int render_batch_scene(const sc_scene *s, sc_batch_scene *out)
{
    const sc_brdf *b = &s->model.brdf;
    if (s->model.kind != SC_MODEL_BRDF || s->n_lights > SC_BATCH_MAX_LIGHTS ||
        !batch_brdf_of(b, out))
        return 0;
    double ambient[3] = {s->ambient[0], s->ambient[1], s->ambient[2]};
    for (int k = 0; k < s->n_lights; k++) {
        if (!batch_light_of(&s->lights[k], &out->lights[k]))
            return 0;
        for (int c = 0; c < 3; c++)
            ambient[c] += s->lights[k].ambient[c];
    }
    out->n_lights = s->n_lights;
    for (int c = 0; c < 3; c++) {
        out->diff[c] = (float)b->diff[c];
        out->spec[c] = (float)b->spec[c];
        out->amb_term[c] = (float)(b->amb[c] * ambient[c]);
    }
    out->m = (float)b->m;
    out->alpha = (float)b->ax;
    out->f0 = (float)b->f0[0];
    return 1;
}

/* Up to CHUNK points through the kernel: structure of arrays in, rgb interleaved out. */
static void shade_chunk(const sc_batch_scene *bs, const double eye[3], int n,
                        const render_shade_input *in, float *rgb)
{
    float soa[9][CHUNK], out[3][CHUNK];
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            soa[c][i] = (float)in[i].normal[c];
            soa[3 + c][i] = (float)(eye[c] - in[i].pos[c]);
            soa[6 + c][i] = (float)in[i].pos[c];
        }
    sc_batch_args a = {{soa[0], soa[1], soa[2], soa[3], soa[4], soa[5], soa[6], soa[7], soa[8]},
                       {out[0], out[1], out[2]}, (size_t)n, bs, NULL};
    sc_batch_run("shade", "accurate", &a);
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = out[c][i];
}

static void shade_one(const sc_scene *scene, sc_prec prec, const double eye[3],
                      const render_shade_input *in, float rgb[3])
{
    sc_shade_point at;
    double v[3], len2 = 0.0;
    for (int c = 0; c < 3; c++) {
        at.pos[c] = in->pos[c];
        v[c] = eye[c] - in->pos[c];
        len2 += v[c] * v[c];
    }
    double len = sqrt(len2);
    for (int c = 0; c < 3; c++)
        at.v[c] = len > 0.0 ? v[c] / len : in->normal[c];
    sc_shade_result r = {.per_light = NULL};
    if (sc_frame_make(in->normal, NULL, &at.frame) < 0) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return;
    }
    sc_shade(prec, scene, &at, &r);
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)r.L[c];
}

void render_shader_init(render_shader *sh, const sc_scene *scene, sc_prec prec)
{
    sh->scene = scene;
    sh->prec = prec;
    sh->batch = prec == SC_HIGHP && render_batch_scene(scene, &sh->bs);
}

void render_shade_span(const render_shader *sh, const double eye[3], int n,
                       const render_shade_input *in, float *rgb)
{
    if (sh->batch)
        for (int i = 0; i < n; i += CHUNK)
            shade_chunk(&sh->bs, eye, n - i < CHUNK ? n - i : CHUNK, in + i, rgb + 3 * i);
    for (int i = 0; i < n; i++) /* the kernel's 0·inf where its float sums overflow: sc_shade */
        if (!sh->batch || isnan(rgb[3 * i]) || isnan(rgb[3 * i + 1]) || isnan(rgb[3 * i + 2]))
            shade_one(sh->scene, sh->prec, eye, &in[i], rgb + 3 * i);
}
