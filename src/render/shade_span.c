/* Shading a span of pixels (render/shade_span.h): through a plan of the SIMD batch shading
 * kernel (shadecalc/batch.h) in highp when the scene is one it computes, through sc_shade per
 * point otherwise (other precisions, models, falloffs). */
#include "render/shade_span.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shadecalc/batch.h"

enum { CHUNK = 64 };

/* Up to CHUNK points through the kernel: structure of arrays in, rgb interleaved out. */
static void shade_chunk(const sc_batch_plan *plan, const double eye[3], int n,
                        const render_shade_input *in, float *rgb)
{
    float soa[9][CHUNK], out[3][CHUNK];
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            soa[c][i] = (float)in[i].normal[c];
            soa[3 + c][i] = (float)(eye[c] - in[i].pos[c]);
            soa[6 + c][i] = (float)in[i].pos[c];
        }
    const float *const in_arrays[9] = {soa[0], soa[1], soa[2], soa[3], soa[4],
                                       soa[5], soa[6], soa[7], soa[8]};
    float *const out_arrays[3] = {out[0], out[1], out[2]};
    sc_batch_plan_shade(plan, in_arrays, out_arrays, (size_t)n);
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = out[c][i];
}

/* The point of in seen from eye; -1 if its normal makes no frame. */
static int shade_point(const double eye[3], const render_shade_input *in, sc_shade_point *at)
{
    double v[3], len2 = 0.0;
    for (int c = 0; c < 3; c++) {
        at->pos[c] = in->pos[c];
        v[c] = eye[c] - in->pos[c];
        len2 += v[c] * v[c];
    }
    double len = sqrt(len2);
    for (int c = 0; c < 3; c++)
        at->v[c] = len > 0.0 ? v[c] / len : in->normal[c];
    return sc_frame_make(in->normal, NULL, &at->frame);
}

static void shade_one(const sc_scene *scene, sc_prec prec, const double eye[3],
                      const render_shade_input *in, float rgb[3])
{
    sc_shade_point at;
    sc_shade_result r = {.per_light = NULL};
    if (shade_point(eye, in, &at) < 0) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return;
    }
    sc_shade(prec, scene, &at, &r);
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)r.L[c];
}

/* Up to CHUNK points through sc_shade_many (a BRDF file's shader in blocks). */
static void shade_many(const sc_scene *scene, sc_prec prec, const double eye[3], int n,
                       const render_shade_input *in, float *rgb)
{
    sc_shade_point at[CHUNK];
    sc_shade_result r[CHUNK];
    int index[CHUNK], m = 0;
    memset(at, 0, sizeof at); /* gcc -fsanitize: "may be used uninitialized" when m = 0 */
    for (int i = 0; i < n; i++) {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = 0.0f;
        if (shade_point(eye, &in[i], &at[m]) == 0) {
            r[m].per_light = NULL;
            index[m++] = i;
        }
    }
    sc_shade_many(prec, scene, m, at, r);
    for (int j = 0; j < m; j++)
        for (int c = 0; c < 3; c++)
            rgb[3 * index[j] + c] = (float)r[j].L[c];
}

int render_shader_init(render_shader *sh, const sc_scene *scene, sc_prec prec, const char *tier,
                       char *why, size_t size)
{
    sh->scene = scene;
    sh->prec = prec;
    sh->plan = NULL;
    if (prec != SC_HIGHP)
        return snprintf(why, size, "%s: the shading kernel computes highp", sc_prec_name(prec)), 0;
    sh->plan = sc_batch_plan_compile(scene, tier ? tier : "accurate", sc_isa_active(), why, size);
    return sh->plan != NULL;
}

void render_shader_free(render_shader *sh)
{
    sc_batch_plan_free(sh->plan);
    sh->plan = NULL;
}

void render_shade_span(const render_shader *sh, const double eye[3], int n,
                       const render_shade_input *in, float *rgb)
{
    for (int i = 0; i < n; i += CHUNK) {
        int count = n - i < CHUNK ? n - i : CHUNK;
        if (sh->plan)
            shade_chunk(sh->plan, eye, count, in + i, rgb + 3 * i);
        else
            shade_many(sh->scene, sh->prec, eye, count, in + i, rgb + 3 * i);
    }
    for (int i = 0; sh->plan && i < n; i++) /* the kernel's 0·inf where its float sums overflow */
        if (isnan(rgb[3 * i]) || isnan(rgb[3 * i + 1]) || isnan(rgb[3 * i + 2]))
            shade_one(sh->scene, sh->prec, eye, &in[i], rgb + 3 * i);
}
