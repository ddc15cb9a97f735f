/* The shading equation of docs/formulas.md §6 over any number of lights (shadecalc/shade.h). */
#include "shadecalc/shade.h"

#include <stdlib.h>
#include <string.h>

#include "shade/shade_internal.h"

void sc_model_init(sc_model *m, sc_model_kind kind)
{
    memset(m, 0, sizeof *m);
    m->kind = kind;
    sc_brdf_init(&m->brdf, kind == SC_MODEL_BRDF ? SC_BRDF_LAMBERT : SC_BRDF_BLINN_PHONG);
    m->ads_form = SC_ADS_BLINN_PHONG;
    m->local_viewer = kind == SC_MODEL_D3D9;
    m->viewer_dir[2] = 1.0;
    m->clamp = 1;
    if (kind == SC_MODEL_OPENGL || kind == SC_MODEL_D3D9)
        for (int c = 0; c < 3; c++) { /* the GL material defaults (docs/formulas.md §6.8) */
            m->brdf.amb[c] = 0.2;
            m->brdf.diff[c] = 0.8;
            m->brdf.spec[c] = 0.0;
            m->brdf.m = 0.0;
        }
}

void sc_mul3(sc_prec p, const double a[3], const double b[3], double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = sc_mul_reach(p, sc_round(p, a[c]), sc_round(p, b[c]));
}

void sc_add3(sc_prec p, double acc[3], const double x[3])
{
    for (int c = 0; c < 3; c++)
        acc[c] = sc_p_add(p, acc[c], x[c]);
}

/* c_amb ⊙ L_A,k + ∫ f(l, v) L_e cos̄θ_i dω over an area light, by its method (in double). */
static void area_light(sc_prec p, const sc_scene *s, const sc_light *light,
                       const sc_shade_point *at, sc_light_terms *t)
{
    sc_light_eval(p, light, at->pos, at->frame.n, &t->light);
    sc_area_eval(light, light->area.method, &s->model.brdf, &at->frame, at->pos, at->v, &t->area);
    sc_brdf_eval(p, &s->model.brdf, &at->frame, t->area.l, at->v, &t->brdf);
    sc_mul3(p, s->model.brdf.amb, light->ambient, t->ambient);
    for (int c = 0; c < 3; c++)
        t->contribution[c] = sc_p_add(p, t->ambient[c], sc_round(p, t->area.L[c]));
}

/* t's contribution c_amb ⊙ L_A,k + f(l, v) ⊙ E_L · cos̄θ_i from its light and BRDF terms. */
static void light_contribution(sc_prec p, const sc_scene *s, const sc_light *light,
                               sc_light_terms *t)
{
    sc_mul3(p, s->model.brdf.amb, light->ambient, t->ambient);
    double cos_i = t->brdf.cos_i > 0.0 ? t->brdf.cos_i : 0.0, fe[3];
    sc_mul3(p, t->brdf.f, t->light.E, fe);
    for (int c = 0; c < 3; c++)
        t->contribution[c] = sc_p_add(p, t->ambient[c], sc_mul_reach(p, fe[c], cos_i));
}

static void brdf_light(sc_prec p, const sc_scene *s, const sc_light *light,
                       const sc_shade_point *at, sc_light_terms *t)
{
    if (sc_light_is_area(light->kind)) {
        area_light(p, s, light, at, t);
        return;
    }
    sc_light_eval(p, light, at->pos, at->frame.n, &t->light);
    sc_brdf_eval(p, &s->model.brdf, &at->frame, t->light.l, at->v, &t->brdf);
    light_contribution(p, s, light, t);
}

static void clear_result(sc_shade_result *out)
{
    memset(out->L, 0, sizeof out->L);
    memset(out->ambient, 0, sizeof out->ambient);
    memset(out->primary, 0, sizeof out->primary);
    memset(out->secondary, 0, sizeof out->secondary);
}

static void shade_brdf(sc_prec p, const sc_scene *s, const sc_shade_point *at, sc_shade_result *out)
{
    sc_mul3(p, s->model.brdf.amb, s->ambient, out->ambient);
    memcpy(out->L, out->ambient, sizeof out->L);
    for (int k = 0; k < s->n_lights; k++) {
        sc_light_terms t;
        memset(&t, 0, sizeof t);
        brdf_light(p, s, &s->lights[k], at, &t);
        sc_add3(p, out->L, t.contribution);
        if (out->per_light)
            out->per_light[k] = t;
    }
}

void sc_shade(sc_prec p, const sc_scene *scene, const sc_shade_point *at, sc_shade_result *out)
{
    clear_result(out);
    switch (scene->model.kind) {
    case SC_MODEL_BRDF: shade_brdf(p, scene, at, out); break;
    case SC_MODEL_ADS: sc_shade_ads(p, scene, at, out); break;
    default: sc_shade_fixed_function(p, scene, at, out); break;
    }
}

/* ---- many points ---- */

/* Whether sc_shade_many evaluates f in batches: a BRDF file and no area light. */
static int batches_brdf(const sc_scene *s)
{
    if (s->model.kind != SC_MODEL_BRDF || s->model.brdf.kind != SC_BRDF_FILE)
        return 0;
    for (int k = 0; k < s->n_lights; k++)
        if (sc_light_is_area(s->lights[k].kind))
            return 0;
    return 1;
}

/* shade_brdf at n points, one light after the other: each point's L sums the same terms in the
 * same order as shade_brdf (t, pts, f: n entries of scratch). */
static void shade_brdf_many(sc_prec p, const sc_scene *s, int n, const sc_shade_point *at,
                            sc_shade_result *out, sc_light_terms *t, sc_brdf_point *pts,
                            sc_brdf_terms *f)
{
    for (int i = 0; i < n; i++) {
        clear_result(&out[i]);
        sc_mul3(p, s->model.brdf.amb, s->ambient, out[i].ambient);
        memcpy(out[i].L, out[i].ambient, sizeof out[i].L);
    }
    for (int k = 0; k < s->n_lights; k++) {
        const sc_light *light = &s->lights[k];
        for (int i = 0; i < n; i++) {
            memset(&t[i], 0, sizeof t[i]);
            sc_light_eval(p, light, at[i].pos, at[i].frame.n, &t[i].light);
            pts[i].frame = &at[i].frame;
            memcpy(pts[i].l, t[i].light.l, sizeof pts[i].l);
            memcpy(pts[i].v, at[i].v, sizeof pts[i].v);
        }
        sc_brdf_eval_many(p, &s->model.brdf, n, pts, f);
        for (int i = 0; i < n; i++) {
            t[i].brdf = f[i];
            light_contribution(p, s, light, &t[i]);
            sc_add3(p, out[i].L, t[i].contribution);
            if (out[i].per_light)
                out[i].per_light[k] = t[i];
        }
    }
}

void sc_shade_many(sc_prec p, const sc_scene *scene, int n, const sc_shade_point *at,
                   sc_shade_result *out)
{
    int batch = n > 0 && batches_brdf(scene);
    sc_light_terms *t = batch ? malloc((size_t)n * sizeof *t) : NULL;
    sc_brdf_point *pts = t ? malloc((size_t)n * sizeof *pts) : NULL;
    sc_brdf_terms *f = pts ? malloc((size_t)n * sizeof *f) : NULL;
    if (f)
        shade_brdf_many(p, scene, n, at, out, t, pts, f);
    else /* another model, an area light, or out of memory: one point at a time */
        for (int i = 0; i < n; i++)
            sc_shade(p, scene, &at[i], &out[i]);
    free(t);
    free(pts);
    free(f);
}
