/* The legacy lighting equations (shadecalc/shade.h): the shader-literature ADS forms of the
 * lecture, OpenGL 1.x fixed-function lighting (GL 2.1 spec §2.14.1; docs/formulas.md §6.8) and Direct3D 9
 * fixed-function lighting (docs/formulas.md §6.8). None of them is a BRDF: no 1/π, and the specular term
 * is not multiplied by n·l. */
#include <math.h>
#include <string.h>

#include "brdf/brdf_internal.h"
#include "shade/shade_internal.h"

/* The light's colour `colour` (amb, diff or spec) times its intensity. */
static void light_colour(sc_prec p, const sc_light *light, const double colour[3], double out[3])
{
    sc_mul3(p, light->intensity, colour, out);
}

/* unit(a + b), or n when the sum vanishes */
static void half_between(sc_prec p, const double a[3], const double b[3], const double n[3],
                         double h[3])
{
    double sum[3];
    for (int c = 0; c < 3; c++)
        sum[c] = sc_p_add(p, a[c], sc_round(p, b[c]));
    if (sc_p_dot(p, sum, sum, 3) > 0.0)
        sc_p_normalize(p, sum, 3, h);
    else
        memcpy(h, n, 3 * sizeof *h);
}

/* The specular base of the ADS forms: (r·v)⁺ (phong) or (n·h)⁺ (blinn-phong). */
static double ads_specular_base(sc_prec p, sc_ads_form form, const sc_shade_point *at,
                                const double l[3], double cos_i)
{
    double x[3];
    if (form == SC_ADS_PHONG) { /* r = 2(n·l)n − l */
        double two = Q(2.0 * cos_i);
        for (int c = 0; c < 3; c++)
            x[c] = sc_p_sub(p, Q(two * at->frame.n[c]), l[c]);
        return fmax(sc_p_dot(p, x, at->v, 3), 0.0);
    }
    half_between(p, l, at->v, at->frame.n, x);
    return fmax(sc_p_dot(p, at->frame.n, x, 3), 0.0);
}

static void ads_light(sc_prec p, const sc_scene *s, const sc_light *light, const sc_shade_point *at,
                      sc_light_terms *t)
{
    const sc_brdf *mat = &s->model.brdf;
    sc_light_eval(p, light, at->pos, at->frame.n, &t->light);
    double scale = sc_mul_reach(p, t->light.f_d, t->light.spot), cd[3], cs[3];
    double cos_i = sc_p_dot(p, at->frame.n, t->light.l, 3);
    t->brdf.cos_i = cos_i;
    double lobe = 0.0;
    if (s->model.ads_form != SC_ADS_LAMBERT)
        lobe = sc_lobe_pow(p, ads_specular_base(p, s->model.ads_form, at, t->light.l, cos_i),
                           mat->m);
    light_colour(p, light, light->diffuse, cd);
    light_colour(p, light, light->specular, cs);
    sc_mul3(p, cd, mat->diff, t->brdf.diffuse);
    sc_mul3(p, cs, mat->spec, t->brdf.specular);
    for (int c = 0; c < 3; c++) {
        double d = sc_mul_reach(p, t->brdf.diffuse[c], fmax(cos_i, 0.0));
        double sp = sc_mul_reach(p, t->brdf.specular[c], lobe);
        t->contribution[c] = sc_mul_reach(p, scale, Q(d + sp));
    }
    sc_mul3(p, mat->amb, light->ambient, t->ambient);
    sc_add3(p, t->contribution, t->ambient);
}

void sc_shade_ads(sc_prec p, const sc_scene *s, const sc_shade_point *at, sc_shade_result *out)
{
    sc_mul3(p, s->model.brdf.amb, s->ambient, out->ambient);
    memcpy(out->L, out->ambient, sizeof out->L);
    for (int k = 0; k < s->n_lights; k++) {
        sc_light_terms t;
        memset(&t, 0, sizeof t);
        ads_light(p, s, &s->lights[k], at, &t);
        sc_add3(p, out->L, t.contribution);
        if (out->per_light)
            out->per_light[k] = t;
    }
}

/* ---- OpenGL 1.x and Direct3D 9 ---- */

/* One light's terms: ambient + diffuse (its primary colour) and specular (its secondary). */
static void fixed_function_light(sc_prec p, const sc_model *m, const sc_light *light,
                                 const sc_shade_point *at, sc_light_terms *t, double prim[3],
                                 double spec[3])
{
    sc_light_eval(p, light, at->pos, at->frame.n, &t->light);
    double scale = sc_mul_reach(p, t->light.f_d, t->light.spot);
    if (m->kind == SC_MODEL_D3D9 && light->kind != SC_LIGHT_DIRECTIONAL &&
        t->light.r > light->range)
        scale = 0.0;
    const double *l = t->light.l, *n = at->frame.n;
    double cos_i = sc_p_dot(p, n, l, 3), h[3], colour[3];
    half_between(p, l, m->local_viewer ? at->v : m->viewer_dir, n, h);
    double cos_h = fmax(sc_p_dot(p, n, h, 3), 0.0);
    /* GL gates the specular term by n·l > 0 (f_i); Direct3D 9 documents no gate */
    int lit = m->kind == SC_MODEL_D3D9 || cos_i > 0.0;
    double lobe = lit ? sc_lobe_pow(p, cos_h, m->brdf.m) : 0.0;
    t->brdf.cos_i = cos_i;
    t->brdf.cos_h = cos_h;
    light_colour(p, light, light->ambient, colour);
    sc_mul3(p, m->brdf.amb, colour, t->ambient);
    light_colour(p, light, light->diffuse, colour);
    sc_mul3(p, m->brdf.diff, colour, t->brdf.diffuse);
    light_colour(p, light, light->specular, colour);
    sc_mul3(p, m->brdf.spec, colour, t->brdf.specular);
    for (int c = 0; c < 3; c++) {
        t->ambient[c] = sc_mul_reach(p, scale, t->ambient[c]);
        double d = sc_mul_reach(p, sc_mul_reach(p, t->brdf.diffuse[c], fmax(cos_i, 0.0)), scale);
        spec[c] = sc_mul_reach(p, sc_mul_reach(p, t->brdf.specular[c], lobe), scale);
        prim[c] = Q(t->ambient[c] + d);
        t->contribution[c] = Q(prim[c] + spec[c]);
    }
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

void sc_shade_fixed_function(sc_prec p, const sc_scene *s, const sc_shade_point *at,
                             sc_shade_result *out)
{
    const sc_model *m = &s->model;
    sc_mul3(p, m->brdf.amb, s->ambient, out->ambient);
    double primary[3], secondary[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++)
        primary[c] = sc_p_add(p, Q(m->emission[c]), out->ambient[c]);
    for (int k = 0; k < s->n_lights; k++) {
        sc_light_terms t;
        double prim[3], spec[3];
        memset(&t, 0, sizeof t);
        fixed_function_light(p, m, &s->lights[k], at, &t, prim, spec);
        for (int c = 0; c < 3; c++) {
            primary[c] = sc_p_add(p, primary[c], prim[c]);
            secondary[c] = sc_p_add(p, secondary[c], spec[c]);
        }
        if (out->per_light)
            out->per_light[k] = t;
    }
    int separate = m->separate_specular || m->kind == SC_MODEL_D3D9;
    for (int c = 0; c < 3; c++) {
        double a = separate ? primary[c] : sc_p_add(p, primary[c], secondary[c]);
        double b = separate ? secondary[c] : 0.0;
        out->primary[c] = m->clamp ? clamp01(a) : a;
        out->secondary[c] = m->clamp ? clamp01(b) : b;
        out->L[c] = m->clamp ? clamp01(sc_p_add(p, out->primary[c], out->secondary[c]))
                             : sc_p_add(p, out->primary[c], out->secondary[c]);
    }
}
