/* shadecalc sweep --preset: the lecture's figures in one word.
 *
 *   attenuation   every distance attenuation function (docs/formulas.md §3) against r
 *   spot          the spotlight functions (docs/formulas.md §4) against θ_s
 *   lobe          a --brdf in the plane of incidence (θ_o from −90° to 90°) at θ_i = 0, 30, 60°,
 *                 BRDF Explorer's polar view
 *   albedo        the directional albedo a(θ_i) of several models (as `shadecalc check`), every
 *                 degree up to 89°, with the line a = 1 of energy conservation
 *   area-distance the relative error of each area light method (as `shadecalc check --light`;
 *                 point and representative-point for sphere and tube, point and ltc for disk
 *                 and rect)
 *                 against the distance/size ratio d/s, GGX α = 0.3
 *   area-roughness the same against α at d/s = 3
 *
 * attenuation, spot and albedo are tables: one column per curve, each curve a spec evaluated by
 * the library function the figure is about (sc_atten_eval, sc_spot_eval, sc_albedo).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/check_area.h"
#include "cli/cli.h"
#include "cli/sweep_cli.h"
#include "shadecalc/check.h"
#include "shadecalc/scene.h"

/* The albedo preset's Gauss–Legendre order: a quarter of check's default work, and still far
 * below a pixel's worth of error on the plot. */
enum { MAX_CURVES = 8, ALBEDO_ORDER = 8 };
/* The area presets' configuration: light at 30° from the normal, the viewer at 30° on the
 * other side (the mirror direction meets the light's centre); d/s 3 and α 0.3 where fixed. */
static const double area_theta = 30.0, area_ratio = 3.0, area_alpha = 0.3;
static const double radians_per_degree = 0.017453292519943295;
typedef enum {
    CURVE_ATTEN,
    CURVE_SPOT,
    CURVE_ALBEDO,
    LOBE,
    AREA_DISTANCE,
    AREA_ROUGHNESS
} preset_kind;

typedef struct {
    const char *column, *spec, *legend;
} preset_curve;

typedef struct {
    const char *name;
    preset_kind kind;
    const char *vars[2]; /* --var arguments */
    preset_curve curves[MAX_CURVES];
    const char *title, *ylabel;
    double ymax;                 /* NaN: from the data */
    const char *reference_label; /* a dashed line at y = 1, or NULL */
} preset;

/* The area presets' curves: a shape at unit size and a method. */
/* clang-format off */
#define AREA_CURVES \
    {"sphere_representative", "sphere center=0,0,0 radius=1 method=representative-point", "sphere representative-point"}, \
    {"sphere_point", "sphere center=0,0,0 radius=1 method=point", "sphere point"}, \
    {"tube_representative", "tube p0=0,-2,0 p1=0,2,0 radius=1 method=representative-point", "tube 4:1 representative-point"}, \
    {"tube_point", "tube p0=0,-2,0 p1=0,2,0 radius=1 method=point", "tube 4:1 point"}, \
    {"disk_point", "disk center=0,0,0 normal=0,0,-1 radius=1 method=point", "disk point"}, \
    {"disk_ltc", "disk center=0,0,0 normal=0,0,-1 radius=1 method=ltc", "disk ltc"}, \
    {"rect_point", "rect center=0,0,0 edge1=2,0,0 edge2=0,1,0 method=point", "rect 2:1 point"}, \
    {"rect_ltc", "rect center=0,0,0 edge1=2,0,0 edge2=0,1,0 method=ltc", "rect 2:1 ltc"}
static const preset presets[] = {
    {"attenuation", CURVE_ATTEN, {"r=0:12:241"}, {
        {"none", "point pos=0,0,0 atten=none", "none"},
        {"inverse_square", "point pos=0,0,0 atten=inverse-square", "inverse-square 1/r^2"},
        {"clq", "point pos=0,0,0 atten=clq sc=1 sl=0.05 sq=0.02", "clq 1, 0.05, 0.02"},
        {"window", "point pos=0,0,0 atten=window rstart=2 rend=10", "window 2..10"},
        {"pixar", "point pos=0,0,0 atten=pixar fmax=2 fc=1 rc=1 se=2", "pixar fmax=2 fc=1 rc=1"},
        {"windowed", "point pos=0,0,0 atten=windowed rmax=10", "windowed rmax=10"}},
     "Distance attenuation f_d(r) (docs/formulas.md §3)", "f_d(r)", 2.0, NULL},
    {"spot", CURVE_SPOT, {"theta_s=0:60:241"}, {
        {"opengl", "spot pos=0,0,0 dir=0,0,-1 spot=opengl cutoff=45 exp=8", "opengl cutoff=45 exp=8"},
        {"directx", "spot pos=0,0,0 dir=0,0,-1 spot=directx inner=20 outer=45 exp=1", "directx 20..45 exp=1"},
        {"smoothstep", "spot pos=0,0,0 dir=0,0,-1 spot=smoothstep inner=20 outer=45", "smoothstep 20..45"}},
     "Spotlight functions I_L/I_Lmax against theta_s (docs/formulas.md §4)", "I_L / I_Lmax", NAN, NULL},
    {"lobe", LOBE, {"theta_o=-90:90:181", "theta_i=0,30,60"}, {
        {NULL, "blinn-phong diff=0 spec=1 m=32", NULL}},
     NULL, NULL, NAN, NULL},
    {"albedo", CURVE_ALBEDO, {"theta_i=0:89:90"}, {
        {"lambert", "lambert diff=1", "lambert"},
        {"phong_original", "phong form=original diff=0 spec=1 m=10", "phong original m=10"},
        {"phong_normalized", "phong form=normalized diff=0 spec=1 m=10", "phong normalized m=10"},
        {"blinn_phong", "blinn-phong diff=0 spec=1 m=32", "blinn-phong m=32"},
        {"ward_1992", "ward diff=0 spec=1 alpha=0.2", "ward 1992 alpha=0.2"},
        {"ward_duer", "ward form=duer diff=0 spec=1 alpha=0.2", "ward duer alpha=0.2"},
        {"cook_torrance", "cook-torrance diff=0 alpha=0.3 F=none", "ggx alpha=0.3, F=1"}},
     "Directional albedo a(theta_i) (docs/formulas.md §6.9)", "albedo", NAN,
     "a = 1: energy conservation"},
    {"area-distance", AREA_DISTANCE, {"ratio=1.25:20:76"}, {AREA_CURVES},
     "Area lights: relative error against d/s, GGX alpha=0.3 (docs/formulas.md §5)",
     "relative error", NAN, NULL},
    {"area-roughness", AREA_ROUGHNESS, {"alpha=0.05:1:39"}, {AREA_CURVES},
     "Area lights: relative error against alpha at d/s=3 (docs/formulas.md §5)",
     "relative error", NAN, NULL},
};
/* clang-format on */
enum { N_PRESETS = sizeof presets / sizeof presets[0] };

static const preset *find(const char *name)
{
    for (int i = 0; i < N_PRESETS; i++)
        if (strcmp(presets[i].name, name) == 0)
            return &presets[i];
    return NULL;
}

int sweep_preset_exists(const char *name) { return find(name) != NULL; }

const char *sweep_preset_names(void)
{
    return "attenuation|spot|lobe|albedo|area-distance|area-roughness";
}

int sweep_preset_vars(const char *name, sc_sweep_grid *g)
{
    const preset *p = find(name);
    sc_sweep_grid merged = {.n = 0};
    char err[256];
    for (int i = 0; i < 2 && p->vars[i]; i++) {
        sc_sweep_var v;
        sc_sweep_var_parse(p->vars[i], &v, err, sizeof err);
        int mine = sc_sweep_grid_find(g, v.name);
        if (mine >= 0) { /* the user's values for the preset's variable */
            sc_sweep_var_free(&v);
            v = g->var[mine];
            g->var[mine].list = NULL;
        }
        sc_sweep_grid_add(&merged, &v, err, sizeof err);
    }
    for (int k = 0; k < g->n; k++) {
        sc_sweep_var v = g->var[k];
        g->var[k].list = NULL;
        if (sc_sweep_grid_find(&merged, v.name) < 0 &&
            sc_sweep_grid_add(&merged, &v, err, sizeof err) < 0) {
            sc_error("sweep: %s", err);
            sc_sweep_grid_free(&merged);
            return SC_EXIT_USAGE;
        }
        sc_sweep_var_free(&v);
    }
    sc_sweep_grid_free(g);
    *g = merged;
    return SC_EXIT_OK;
}

/* ---- the table presets ---- */

typedef struct {
    preset_kind kind;
    sc_prec prec;
    int n;
    sc_light lights[MAX_CURVES];
    sc_brdf brdfs[MAX_CURVES];
    char columns[MAX_CURVES][32];
} curve_table;

static int eval_curves(void *user, int worker, const double *vars, double *results, char *err,
                       size_t errsize)
{
    (void)worker;
    (void)err;
    (void)errsize;
    const curve_table *t = user;
    for (int c = 0; c < t->n; c++) {
        if (t->kind == AREA_DISTANCE || t->kind == AREA_ROUGHNESS) {
            sc_brdf b = t->brdfs[c];
            if (t->kind == AREA_ROUGHNESS)
                b.ax = b.ay = vars[0];
            results[c] = check_area_error(&t->lights[c], t->lights[c].area.method, &b,
                                          t->kind == AREA_DISTANCE ? vars[0] : area_ratio,
                                          area_theta, area_theta);
        } else if (t->kind == CURVE_ATTEN) {
            results[c] = sc_atten_eval(t->prec, &t->lights[c].atten, vars[0]);
        } else if (t->kind == CURVE_SPOT) {
            results[c] = sc_spot_eval(t->prec, &t->lights[c].spot,
                                      cos(vars[0] * radians_per_degree));
        } else {
            sc_albedo_result a;
            sc_albedo(&t->brdfs[c], vars[0], ALBEDO_ORDER, &a);
            results[c] = a.albedo[0];
        }
    }
    return 0;
}

static void destroy_table(void *user) { free(user); }

/* Adds a curve: its spec parsed (a light, or a BRDF for albedo), its column and legend. */
static int add_curve(curve_table *t, sweep_plan *plan, const char *column, const char *spec,
                     const char *legend)
{
    char err[256];
    sc_model m;
    int c = t->n;
    int bad = t->kind == CURVE_ALBEDO ? sc_model_parse(spec, &m, err, sizeof err)
                                      : sc_light_parse(spec, &t->lights[c], err, sizeof err);
    if (bad >= 0 && t->kind == CURVE_ALBEDO && m.kind != SC_MODEL_BRDF) {
        snprintf(err, sizeof err, "%s: a lighting model has no albedo; give a BRDF", spec);
        bad = -1;
    }
    if (bad < 0) {
        sc_error("sweep: %s", err);
        return SC_EXIT_USAGE;
    }
    if (bad > 0)
        sc_warning("sweep: %s", err);
    t->brdfs[c] = m.brdf;
    if (t->kind == AREA_DISTANCE || t->kind == AREA_ROUGHNESS) {
        sc_brdf_init(&t->brdfs[c], SC_BRDF_COOK_TORRANCE);
        t->brdfs[c].ax = t->brdfs[c].ay = area_alpha;
    }
    snprintf(t->columns[c], sizeof t->columns[c], "%s", column);
    plan->columns[c] = t->columns[c];
    plan->legend[c] = legend;
    plan->n_results = ++t->n;
    return SC_EXIT_OK;
}

/* The preset's curves, or for albedo the user's --brdf models. */
static int add_curves(const preset *p, const sweep_setup_args *a, curve_table *t, sweep_plan *plan)
{
    int status = SC_EXIT_OK;
    for (int i = 0; i < a->n_items && status == SC_EXIT_OK; i++) {
        if (t->kind != CURVE_ALBEDO || a->items[i].opt != 'b' || t->n == MAX_CURVES) {
            sc_error("sweep: --preset %s takes %s", p->name,
                     t->kind == CURVE_ALBEDO ? "at most 8 --brdf" : "no --light or --brdf");
            return SC_EXIT_USAGE;
        }
        char column[32];
        snprintf(column, sizeof column, "brdf%d", t->n + 1);
        status = add_curve(t, plan, column, a->items[i].arg, a->items[i].arg);
    }
    for (int c = 0; a->n_items == 0 && status == SC_EXIT_OK && c < MAX_CURVES && p->curves[c].spec;
         c++)
        status = add_curve(t, plan, p->curves[c].column, p->curves[c].spec, p->curves[c].legend);
    return status;
}

static int table_plan(const preset *p, const sweep_setup_args *a, sc_prec prec, sweep_plan *plan)
{
    curve_table *t = calloc(1, sizeof *t);
    if (!t) {
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    t->kind = p->kind;
    t->prec = prec;
    int status = add_curves(p, a, t, plan);
    if (status != SC_EXIT_OK) {
        free(t);
        return status;
    }
    plan->eval = eval_curves;
    plan->user = t;
    plan->destroy = destroy_table;
    return SC_EXIT_OK;
}

int sweep_preset_plan(const char *name, sweep_setup_args *a, const sc_sweep_grid *g, sc_prec p,
                      int threads, sweep_plan *plan)
{
    const preset *pr = find(name);
    int status;
    if (pr->kind == LOBE) {
        int has_brdf = 0;
        for (int i = 0; i < a->n_items; i++)
            has_brdf |= a->items[i].opt == 'b';
        if (!has_brdf && a->n_items < SWEEP_MAX_ITEMS)
            a->items[a->n_items++] = (sweep_item){'b', "brdf", pr->curves[0].spec};
        status = sweep_shade_plan(a, g, p, threads, plan);
        plan->polar = 1;
        return status;
    }
    if (g->n != 1) {
        sc_error("sweep: --preset %s sweeps %s only", name, g->var[0].name);
        return SC_EXIT_USAGE;
    }
    status = table_plan(pr, a, p, plan);
    snprintf(plan->title, sizeof plan->title, "%s", pr->title);
    plan->ylabel = pr->ylabel;
    plan->ymin = isnan(pr->ymax) ? NAN : 0.0;
    plan->ymax = pr->ymax;
    plan->reference_label = pr->reference_label;
    plan->reference_y = 1.0;
    return status;
}
