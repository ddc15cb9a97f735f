/* shadecalc sweep over a shading setup: `$name` in --light and --brdf specs, and the angles
 * theta_i phi_i theta_o phi_o placing l and v about n (docs/formulas.md §1:
 * dir(θ, φ) = sinθ cosφ t + sinθ sinφ b + cosθ n, in degrees), or the half-vector angles
 * theta_h phi_h theta_d phi_d (Rusinkiewicz 1998, BRDF Explorer's image slice):
 * h = dir(θ_h, φ_h), and l, v = R_z(φ_h) R_y(θ_h) dir(θ_d, φ_d), dir(θ_d, φ_d + 180°); phi_h
 * defaults to 0, phi_d to 90° (as in BRDF Explorer).
 *
 * With lights, a row is L_o of the shading equation (docs/formulas.md §6), as `shadecalc shade` computes
 * it; theta_i and phi_i set the direction of every directional light, theta_o and phi_o the
 * viewer. With a BRDF and no light, a row is f(l, v) itself (no cos θ_i), as BRDF Explorer
 * plots it. phi_o defaults to phi_i (the plane of incidence), phi_i to 0; without theta_o or
 * phi_o, v comes from --v or --eye (default n); without theta_i, l = n.
 */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/brdf_file_cli.h"
#include "cli/cli.h"
#include "cli/setup.h"
#include "cli/sweep_cli.h"
#include "shadecalc/batch.h"

enum { SPEC_MAX = 1024 };
static const double radians_per_degree = 0.017453292519943295;

/* A --light or --brdf spec with `$name` in it, re-parsed when its text changes. */
typedef struct {
    const char *text;
    int light; /* index in the setup's lights, or -1 for the model */
} template_spec;

/* What a worker keeps between rows: its lights and model, and the texts they came from. */
typedef struct {
    sc_light lights[SETUP_MAX_LIGHTS];
    sc_model model;
    char (*last)[SPEC_MAX]; /* per template */
} worker_state;

typedef struct {
    shade_setup setup;   /* row 1's values */
    sc_batch_plan *plan; /* --tier: the scene compiled once for the batch kernel, or NULL */
    sc_shade_point at;
    sc_prec prec;
    int brdf_only;
    int angle[8]; /* variable index of each of angle_names, -1 if absent */
    int halfway;  /* l and v from theta_h phi_h theta_d phi_d */
    const sc_sweep_grid *grid;
    template_spec templates[SWEEP_MAX_ITEMS];
    int n_templates;
    worker_state *workers;
    int threads;
} shade_plan;

enum { THETA_I, PHI_I, THETA_O, PHI_O, THETA_H, PHI_H, THETA_D, PHI_D };
static const char *const angle_names[8] = {"theta_i", "phi_i", "theta_o", "phi_o",
                                           "theta_h", "phi_h", "theta_d", "phi_d"};

static void to_frame(const sc_frame *f, const double local[3], double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = local[0] * f->t[k] + local[1] * f->b[k] + local[2] * f->n[k];
}

static void direction(const sc_frame *f, double theta_deg, double phi_deg, double out[3])
{
    double th = theta_deg * radians_per_degree, ph = phi_deg * radians_per_degree;
    const double local[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
    to_frame(f, local, out);
}

/* l and v from the half-vector angles (header comment). */
static void halfway_directions(const sc_frame *f, double theta_h, double phi_h, double theta_d,
                               double phi_d, double l[3], double v[3])
{
    double th = theta_h * radians_per_degree, ph = phi_h * radians_per_degree;
    double td = theta_d * radians_per_degree, pd = phi_d * radians_per_degree;
    for (int side = 0; side < 2; side++) {
        double s = side ? -1.0 : 1.0; /* v is d turned 180° about h */
        double dx = s * sin(td) * cos(pd), dy = s * sin(td) * sin(pd), dz = cos(td);
        double x = dx * cos(th) + dz * sin(th), z = -dx * sin(th) + dz * cos(th);
        const double local[3] = {x * cos(ph) - dy * sin(ph), x * sin(ph) + dy * cos(ph), z};
        to_frame(f, local, side ? v : l);
    }
}

static double angle_or(const shade_plan *s, const double *vars, int a, double fallback)
{
    return s->angle[a] >= 0 ? vars[s->angle[a]] : fallback;
}

/* l, and at->v when the row's angles give it. */
static void place(const shade_plan *s, const double *vars, sc_shade_point *at, double l[3])
{
    if (s->halfway) {
        halfway_directions(&at->frame, angle_or(s, vars, THETA_H, 0.0),
                           angle_or(s, vars, PHI_H, 0.0), angle_or(s, vars, THETA_D, 0.0),
                           angle_or(s, vars, PHI_D, 90.0), l, at->v);
        return;
    }
    double phi_i = angle_or(s, vars, PHI_I, 0.0);
    direction(&at->frame, angle_or(s, vars, THETA_I, 0.0), phi_i, l);
    if (s->angle[THETA_O] >= 0 || s->angle[PHI_O] >= 0)
        direction(&at->frame, angle_or(s, vars, THETA_O, 0.0), angle_or(s, vars, PHI_O, phi_i),
                  at->v);
}

/* Whether the angles move l (and so the directional lights). */
static int moves_l(const shade_plan *s)
{
    return s->halfway || s->angle[THETA_I] >= 0 || s->angle[PHI_I] >= 0;
}

/* Re-parses the templates whose text changed at this row: 0, or SC_SWEEP_ROW_INVALID with the
 * error (the row's values make a spec invalid: a usage error, as when it is given so). */
static int update_specs(const shade_plan *s, worker_state *w, const double *vars, char *err,
                        size_t errsize)
{
    for (int i = 0; i < s->n_templates; i++) {
        const template_spec *t = &s->templates[i];
        char text[SPEC_MAX], why[256];
        if (sc_sweep_substitute(t->text, s->grid, vars, text, sizeof text, why, sizeof why) < 0) {
            snprintf(err, errsize, "%s", why);
            return SC_SWEEP_ROW_INVALID;
        }
        if (strcmp(text, w->last[i]) == 0)
            continue;
        int bad = t->light >= 0 ? sc_light_parse(text, &w->lights[t->light], why, sizeof why)
                                : sc_model_parse(text, &w->model, why, sizeof why);
        if (bad >= 0 && /* a value beyond the precision would round to inf: never NaN */
            (t->light >= 0 ? sc_light_check_range(s->prec, &w->lights[t->light], why, sizeof why)
                           : sc_brdf_check_range(s->prec, &w->model.brdf, why, sizeof why)) < 0)
            bad = -1;
        if (bad < 0) { /* an ignored key (bad = 1) was reported when the setup was built */
            w->last[i][0] = '\0';
            snprintf(err, errsize, "'%s': %s", text, why);
            return SC_SWEEP_ROW_INVALID;
        }
        memcpy(w->last[i], text, sizeof text);
    }
    return 0;
}

/* L_o at `at` by the plan (one element; float inputs): 1, or 0 where the kernel's float sums
 * overflowed to NaN (0·inf), which sc_shade then computes, as render does. */
static int shade_by_plan(const sc_batch_plan *plan, const sc_shade_point *at, double L[3])
{
    float in[9], out[3];
    for (int c = 0; c < 3; c++) {
        in[c] = (float)at->frame.n[c];
        in[3 + c] = (float)at->v[c];
        in[6 + c] = (float)at->pos[c];
    }
    const float *const ins[9] = {in,     in + 1, in + 2, in + 3, in + 4,
                                 in + 5, in + 6, in + 7, in + 8};
    float *const outs[3] = {out, out + 1, out + 2};
    sc_batch_plan_shade(plan, ins, outs, 1);
    if (isnan(out[0]) || isnan(out[1]) || isnan(out[2]))
        return 0;
    for (int c = 0; c < 3; c++)
        L[c] = out[c];
    return 1;
}

/* -1 with the error if the model's GLSL (a BRDF file) failed at run time (its loop bound). */
static int shader_failed(const sc_model *m, char *err, size_t errsize)
{
    const char *why = brdf_file_failure(m);
    if (why)
        snprintf(err, errsize, "%s", why);
    return why ? -1 : 0;
}

/* eval of shading with lights: L_o of one row. */
static int eval_row(void *user, int worker, const double *vars, double *results, char *err,
                    size_t errsize)
{
    const shade_plan *s = user;
    worker_state *w = &s->workers[worker];
    int invalid = update_specs(s, w, vars, err, errsize);
    if (invalid < 0)
        return invalid;
    sc_shade_point at = s->at;
    double l[3];
    place(s, vars, &at, l);
    for (int k = 0; moves_l(s) && k < s->setup.n_lights; k++)
        if (w->lights[k].kind == SC_LIGHT_DIRECTIONAL)
            memcpy(w->lights[k].dir, l, sizeof l);
    sc_scene scene = {w->lights,
                      s->setup.n_lights,
                      w->model,
                      {s->setup.ambient[0], s->setup.ambient[1], s->setup.ambient[2]}};
    if (s->plan && shade_by_plan(s->plan, &at, results))
        return 0;
    sc_shade_result r = {.per_light = NULL};
    sc_shade(s->prec, &scene, &at, &r);
    memcpy(results, r.L, sizeof r.L);
    return shader_failed(&w->model, err, errsize);
}

/* The rows of a BRDF alone (no light) that share one BRDF (rows first .. first + n - 1 of the
 * block), evaluated together; the rows done, as eval_block counts them. */
typedef struct {
    sc_brdf brdf;
    int first, n;
} brdf_run;

static int flush_run(const shade_plan *s, const brdf_run *run, const sc_brdf_point *pts,
                     sc_brdf_terms *terms, double *results, char *err, size_t errsize)
{
    int done = sc_brdf_eval_many(s->prec, &run->brdf, run->n, pts + run->first, terms + run->first);
    for (int i = run->first; i < run->first + done; i++)
        memcpy(results + 3 * (size_t)i, terms[i].f, sizeof terms[i].f);
    if (done < run->n)
        snprintf(err, errsize, "%s", sc_brdf_file_error(run->brdf.file));
    return run->first + done;
}

static int eval_brdf_rows_in(const shade_plan *s, worker_state *w, int count, const double *vars,
                             double *results, sc_brdf_point *pts, sc_brdf_terms *terms,
                             int *failure, char *err, size_t errsize)
{
    brdf_run run = {w->model.brdf, 0, 0};
    for (int i = 0; i < count; i++) {
        const double *row = vars + (size_t)i * (size_t)s->grid->n;
        if (update_specs(s, w, row, err, errsize) < 0) {
            char why[256];
            snprintf(why, sizeof why, "%s", err); /* the rows before it first */
            int done = flush_run(s, &run, pts, terms, results, err, errsize);
            if (done == i) {
                snprintf(err, errsize, "%s", why);
                *failure = SC_SWEEP_ROW_INVALID;
            }
            return done;
        }
        if (memcmp(&run.brdf, &w->model.brdf, sizeof run.brdf) != 0) {
            int done = flush_run(s, &run, pts, terms, results, err, errsize);
            if (done < i)
                return done;
            run = (brdf_run){w->model.brdf, i, 0};
        }
        sc_shade_point at = s->at;
        place(s, row, &at, pts[i].l);
        pts[i].frame = &s->at.frame;
        memcpy(pts[i].v, at.v, sizeof at.v);
        run.n++;
    }
    return flush_run(s, &run, pts, terms, results, err, errsize);
}

/* eval_block of a BRDF alone: f(l, v) of many rows through sc_brdf_eval_many (a BRDF file's
 * shader in blocks), the same values as eval_row gives row by row. */
static int eval_brdf_rows(void *user, int worker, int count, const double *vars, double *results,
                          int *failure, char *err, size_t errsize)
{
    *failure = -1; /* a shader's failure; an invalid spec sets SC_SWEEP_ROW_INVALID */
    const shade_plan *s = user;
    sc_brdf_point *pts = malloc((size_t)count * sizeof *pts);
    sc_brdf_terms *terms = malloc((size_t)count * sizeof *terms);
    int done = 0;
    if (pts && terms)
        done = eval_brdf_rows_in(s, &s->workers[worker], count, vars, results, pts, terms, failure,
                                 err, errsize);
    else
        snprintf(err, errsize, "out of memory");
    free(pts);
    free(terms);
    return done;
}

static void destroy(void *user)
{
    shade_plan *s = user;
    sc_batch_plan_free(s->plan);
    for (int w = 0; s->workers && w < s->threads; w++)
        free(s->workers[w].last);
    free(s->workers);
    free(s);
}

/* Applies one option; a spec with `$` is applied with row 1's values and kept as a template. */
static int apply_item(shade_plan *s, const sweep_item *item, const double *row1)
{
    char text[SPEC_MAX], why[256];
    const char *what = item->opt == 'l' ? "--light" : item->opt == 'b' ? "--brdf" : item->name;
    int templated = strchr(item->arg, '$') != NULL;
    if (templated && item->opt != 'l' && item->opt != 'b') {
        sc_error("sweep: --%s %s: $variables work in --light and --brdf specs only", item->name,
                 item->arg);
        return SC_EXIT_USAGE;
    }
    if (sc_sweep_substitute(item->arg, s->grid, row1, text, sizeof text, why, sizeof why) < 0) {
        sc_error("sweep: %s '%s': %s", what, item->arg, why);
        return SC_EXIT_USAGE;
    }
    if (templated)
        s->templates[s->n_templates++] = (template_spec){item->arg,
                                                         item->opt == 'l' ? s->setup.n_lights : -1};
    switch (item->opt) {
    case 'l': return setup_add_light(&s->setup, text, "");
    case 'b': return setup_set_model(&s->setup, text, "");
    default: return setup_set_value(&s->setup, item->name, text, "");
    }
}

static int check_angles(const shade_plan *s)
{
    int has_directional = 0;
    for (int k = 0; k < s->setup.n_lights; k++)
        has_directional |= s->setup.lights[k].kind == SC_LIGHT_DIRECTIONAL;
    int i_o = 0;
    for (int a = THETA_I; a <= PHI_O; a++)
        i_o |= s->angle[a] >= 0;
    if (s->halfway && i_o) {
        sc_error("sweep: give the angles of l and v (theta_i phi_i theta_o phi_o) or of h "
                 "(theta_h phi_h theta_d phi_d), not both");
        return SC_EXIT_USAGE;
    }
    if (!s->brdf_only && moves_l(s) && !has_directional) {
        sc_error("sweep: the angles of l set the direction of directional lights, and there is "
                 "none (point and spot lights keep their positions)");
        return SC_EXIT_USAGE;
    }
    if (s->brdf_only && s->setup.model.kind != SC_MODEL_BRDF) {
        sc_error("sweep: --brdf %s is a lighting model, not a BRDF: give a --light to shade with "
                 "it",
                 s->setup.model.kind == SC_MODEL_ADS      ? "ads"
                 : s->setup.model.kind == SC_MODEL_OPENGL ? "opengl"
                                                          : "direct3d9");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

/* --tier: the scene compiled once, when one scene serves every row: a tier of the shading
 * kernel, highp, lights (not a BRDF alone), no $variables in the specs, no angle moving
 * directional lights, no anisotropic roughness (whose frame the kernels build from n, not from
 * --tangent). */
static int compile_tier(shade_plan *s, const char *tier)
{
    const char *why = NULL;
    const sc_brdf *b = &s->setup.model.brdf;
    int directional = 0;
    for (int k = 0; k < s->setup.n_lights; k++)
        directional |= s->setup.lights[k].kind == SC_LIGHT_DIRECTIONAL;
    if (!sc_batch_find("shade", tier, SC_ISA_SCALAR))
        why = "expected accurate or bits12";
    else if (s->prec != SC_HIGHP)
        why = "the batch kernels compute highp";
    else if (s->brdf_only)
        why = "a BRDF without lights is f(l, v), not shading: give a --light";
    else if (s->n_templates > 0)
        why = "$variables in --light/--brdf change the scene from row to row";
    else if (moves_l(s) && directional)
        why = "theta_i/phi_i (or the half-vector angles) turn the directional lights row by row";
    else if (b->ax != b->ay && (b->kind == SC_BRDF_WARD || b->kind == SC_BRDF_COOK_TORRANCE))
        why = "the kernels build the anisotropic frame from n alone, not from --tangent";
    if (why) {
        sc_error("sweep: --tier %s: %s", tier, why);
        return SC_EXIT_USAGE;
    }
    sc_scene scene = {s->setup.lights,
                      s->setup.n_lights,
                      s->setup.model,
                      {s->setup.ambient[0], s->setup.ambient[1], s->setup.ambient[2]}};
    char reason[256];
    s->plan = sc_batch_plan_compile(&scene, tier, sc_isa_active(), reason, sizeof reason);
    if (!s->plan) {
        sc_error("sweep: --tier %s: the batch kernels do not cover this scene: %s", tier, reason);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int make_workers(shade_plan *s)
{
    s->workers = calloc((size_t)s->threads, sizeof *s->workers);
    for (int w = 0; s->workers && w < s->threads; w++) {
        memcpy(s->workers[w].lights, s->setup.lights, sizeof s->setup.lights);
        s->workers[w].model = s->setup.model;
        s->workers[w].last = calloc((size_t)s->n_templates + 1, sizeof *s->workers[w].last);
        if (!s->workers[w].last)
            return -1;
    }
    return s->workers ? 0 : -1;
}

/* Whether spec text has $name or ${name}. */
static int mentions(const char *text, const char *name)
{
    size_t len = strlen(name);
    for (const char *p = strchr(text, '$'); p; p = strchr(p + 1, '$')) {
        const char *q = p + 1 + (p[1] == '{');
        char after = q[strncmp(q, name, len) == 0 ? len : 0];
        if (strncmp(q, name, len) == 0 && !isalnum((unsigned char)after) && after != '_')
            return 1;
    }
    return 0;
}

/* The variables nothing reads: neither an angle placing l and v nor a $name of a spec. */
static unsigned unused_vars(const shade_plan *s)
{
    unsigned used = 0;
    for (int a = 0; a < 8; a++)
        used |= s->angle[a] >= 0 ? 1u << s->angle[a] : 0u;
    for (int k = 0; k < s->grid->n; k++)
        for (int i = 0; i < s->n_templates; i++)
            used |= (unsigned)mentions(s->templates[i].text, s->grid->var[k].name) << k;
    return ~used & ((1u << s->grid->n) - 1u);
}

static void describe(const shade_plan *s, const sweep_setup_args *a, sweep_plan *plan)
{
    size_t n = 0;
    for (int i = 0; i < a->n_items && n < sizeof plan->title; i++)
        if (a->items[i].opt == 'l' || a->items[i].opt == 'b')
            n += (size_t)snprintf(plan->title + n, sizeof plan->title - n, "%s%s", n ? ", " : "",
                                  a->items[i].arg);
    if (n == 0)
        snprintf(plan->title, sizeof plan->title, "%s", s->brdf_only ? "lambert" : "shade");
    plan->ylabel = s->brdf_only ? "f(l, v) [1/sr]" : "L_o";
}

int sweep_shade_plan(const sweep_setup_args *a, const sc_sweep_grid *g, sc_prec p, int threads,
                     sweep_plan *plan)
{
    shade_plan *s = calloc(1, sizeof *s);
    if (!s) {
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    setup_init(&s->setup);
    s->prec = p;
    s->grid = g;
    s->threads = threads;
    for (int k = 0; k < 8; k++) {
        s->angle[k] = sc_sweep_grid_find(g, angle_names[k]);
        s->halfway |= k >= THETA_H && s->angle[k] >= 0;
    }
    double row1[SC_SWEEP_MAX_VARS];
    sc_sweep_grid_point(g, 0, row1);
    int status = a->scene ? setup_load_file(&s->setup, a->scene) : SC_EXIT_OK;
    for (int i = 0; status == SC_EXIT_OK && i < a->n_items; i++)
        status = apply_item(s, &a->items[i], row1);
    s->brdf_only = s->setup.n_lights == 0;
    if (status == SC_EXIT_OK)
        status = check_angles(s);
    if (status == SC_EXIT_OK)
        status = setup_check_range(&s->setup, p);
    if (status == SC_EXIT_OK)
        status = setup_point(&s->setup, &s->at);
    if (status == SC_EXIT_OK && a->tier)
        status = compile_tier(s, a->tier);
    if (status == SC_EXIT_OK && make_workers(s) < 0) {
        sc_error("sweep: out of memory");
        status = SC_EXIT_RUNTIME;
    }
    if (status != SC_EXIT_OK) {
        destroy(s);
        return status;
    }
    plan->n_results = 3;
    plan->columns[0] = "r";
    plan->columns[1] = "g";
    plan->columns[2] = "b";
    plan->rgb = 1;
    plan->unused = unused_vars(s);
    if (s->brdf_only)
        plan->eval_block = eval_brdf_rows;
    else
        plan->eval = eval_row;
    plan->user = s;
    plan->destroy = destroy;
    describe(s, a, plan);
    return SC_EXIT_OK;
}
