/* shadecalc shade — one value of the shading equation (docs/formulas.md §6) from the shell. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/brdf_file_cli.h"
#include "cli/cli.h"
#include "cli/setup.h"

enum { FMT_TEXT, FMT_CSV, FMT_JSON };

typedef struct {
    sc_prec prec;
    int format;
    int explain;
} shade_options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc shade [OPTIONS]\n"
            "\n"
            "Evaluates L_o = c_amb*L_A + sum_k [c_amb*L_A,k + f(l_k, v)*E_L,k*cos(theta_i,k)]\n"
            "at one surface point and prints it as R G B.\n"
            "\n"
            "  -l, --light SPEC     a light (repeatable): directional|point|spot|sphere|tube|\n"
            "                       disk|rect key=value...\n"
            "  -b, --brdf SPEC      the model: lambert|phong|blinn-phong|ward|oren-nayar|\n"
            "                       cook-torrance|ads|opengl|direct3d9 key=value..., or\n"
            "                       file=PATH NAME=VALUE... (a BRDF Explorer .brdf file)\n"
            "  -a, --ambient C      global ambient radiance L_A (R,G,B or one number)\n"
            "  -s, --scene FILE     lines 'light SPEC', 'brdf SPEC', 'ambient C', 'n|v|p|eye|\n"
            "                       tangent X,Y,Z'; options add lights and override the rest\n"
            "      --n X,Y,Z        surface normal (default 0,0,1)\n"
            "      --v X,Y,Z        direction toward the viewer (default 0,0,1)\n"
            "      --p X,Y,Z        surface point (default 0,0,0)\n"
            "      --eye X,Y,Z      viewer position: v = normalize(eye - p)\n"
            "      --tangent X,Y,Z  tangent direction (anisotropic models)\n"
            "  -p, --precision P    double|highp|mediump|lowp (default highp)\n"
            "  -f, --format F       text|csv|json (default text)\n"
            "  -e, --explain        every intermediate, light by light (text, json)\n"
            "  -h, --help           this help\n"
            "\n"
            "example: shadecalc shade --light 'point pos=0,5,0 I=100' --brdf 'blinn-phong m=32'\n");
}

/* ---- output ---- */

static void number(FILE *out, double x, sc_prec p, int json)
{
    char buf[64];
    sc_format_shortest(buf, sizeof buf, x, p);
    int quoted = json && !(x - x == 0.0);
    fprintf(out, quoted ? "\"%s\"" : "%s", buf);
}

static void triple(FILE *out, const double v[3], sc_prec p, int json)
{
    fputs(json ? "[" : "(", out);
    for (int c = 0; c < 3; c++) {
        fputs(c ? ", " : "", out);
        number(out, v[c], p, json);
    }
    fputs(json ? "]" : ")", out);
}

static const char *light_kind_name(sc_light_kind k)
{
    static const char *const names[] = {"directional", "point", "spot", "sphere",
                                        "tube",        "disk",  "rect"};
    return names[k];
}

/* One intermediate of --explain: its label in the text form (a leading "\n" starts a line),
 * its key in the JSON form, and its 1 or 3 values. Both forms print the same list. */
typedef struct {
    const char *text, *key;
    int n;
    const double *v;
} explain_term;

enum { MAX_TERMS = 20 };

/* An area light's: its direction and distance to the centre (or the representative point),
 * the integral and, for the reference, its error estimate and nodes. */
static int area_terms(const sc_light_terms *t, double *nodes, explain_term *out)
{
    const sc_area_result *a = &t->area;
    int n = 0;
    nodes[0] = a->nodes;
    nodes[1] = (double)a->evaluations;
    nodes[2] = a->converged;
    out[n++] = (explain_term){"  l = ", "l", 3, a->l};
    out[n++] = (explain_term){"  r = ", "r", 1, &a->r};
    out[n++] = (explain_term){"\n  integral ", "integral", 3, a->L};
    out[n++] = (explain_term){"  error estimate ", "error", 3, a->error};
    out[n++] = (explain_term){"\n  nodes = ", "nodes", 1, &nodes[0]};
    out[n++] = (explain_term){"  evaluations = ", "evaluations", 1, &nodes[1]};
    out[n++] = (explain_term){"  converged = ", "converged", 1, &nodes[2]};
    out[n++] = (explain_term){"\n  ambient ", "ambient", 3, t->ambient};
    out[n++] = (explain_term){"  contribution ", "contribution", 3, t->contribution};
    return n;
}

/* The intermediates of light k, in the order they are printed; returns their count. nodes
 * holds an area light's counts as numbers. */
static int light_terms(const sc_light *light, const sc_light_terms *t, const sc_model *m,
                       double *nodes, explain_term *out)
{
    if (sc_light_is_area(light->kind))
        return area_terms(t, nodes, out);
    const sc_light_sample *ls = &t->light;
    int n = 0, brdf = m->kind == SC_MODEL_BRDF;
    int ward = brdf && m->brdf.kind == SC_BRDF_WARD;
    int cook_torrance = brdf && m->brdf.kind == SC_BRDF_COOK_TORRANCE;
    out[n++] = (explain_term){"  l = ", "l", 3, ls->l};
    out[n++] = (explain_term){"  r = ", "r", 1, &ls->r};
    out[n++] = (explain_term){"\n  f_d = ", "f_d", 1, &ls->f_d};
    out[n++] = (explain_term){"  spot = ", "spot", 1, &ls->spot};
    if (light->kind == SC_LIGHT_SPOT)
        out[n++] = (explain_term){"  cos theta_s = ", "cos_theta_s", 1, &ls->cos_s};
    out[n++] = (explain_term){"  E_L = ", "E_L", 3, ls->E};
    out[n++] = (explain_term){"\n  cos theta_i = ", "cos_theta_i", 1, &t->brdf.cos_i};
    if (brdf)
        out[n++] = (explain_term){"  cos theta_o = ", "cos_theta_o", 1, &t->brdf.cos_o};
    out[n++] = (explain_term){"  cos theta_h = ", "cos_theta_h", 1, &t->brdf.cos_h};
    if (brdf && m->brdf.kind == SC_BRDF_FILE) { /* the shader gives f alone */
        out[n++] = (explain_term){"\n  f = ", "f", 3, t->brdf.f};
    } else {
        out[n++] = (explain_term){brdf ? "\n  f: diffuse " : "\n  diffuse colour ", "diffuse", 3,
                                  t->brdf.diffuse};
        out[n++] = (explain_term){brdf ? "  specular " : "  specular colour ", "specular", 3,
                                  t->brdf.specular};
    }
    if (ward)
        out[n++] = (explain_term){"  exp term = ", "exp_term", 1, &t->brdf.D};
    if (cook_torrance) {
        out[n++] = (explain_term){"  D = ", "D", 1, &t->brdf.D};
        out[n++] = (explain_term){"  G = ", "G", 1, &t->brdf.G};
        out[n++] = (explain_term){"  F = ", "F", 3, t->brdf.F};
    }
    out[n++] = (explain_term){"\n  ambient ", "ambient", 3, t->ambient};
    out[n++] = (explain_term){"  contribution ", "contribution", 3, t->contribution};
    return n;
}

static void term_value(FILE *out, const explain_term *t, sc_prec p, int json)
{
    if (t->n == 3)
        triple(out, t->v, p, json);
    else
        number(out, t->v[0], p, json);
}

static void explain_light(FILE *out, int k, const sc_light *light, const sc_light_terms *t,
                          const sc_model *m, sc_prec p)
{
    explain_term terms[MAX_TERMS];
    double nodes[3];
    int n = light_terms(light, t, m, nodes, terms);
    fprintf(out, "light %d (%s", k + 1, light_kind_name(light->kind));
    if (sc_light_is_area(light->kind))
        fprintf(out, ", method=%s", sc_area_method_name(light->area.method));
    fputs(")\n", out);
    for (int i = 0; i < n; i++) {
        fputs(terms[i].text, out);
        term_value(out, &terms[i], p, 0);
    }
    fputc('\n', out);
}

static void print_text(const shade_setup *s, const sc_shade_result *r, const shade_options *o)
{
    if (o->explain) {
        brdf_file_explain(stdout, &s->model, o->prec, 0);
        for (int k = 0; k < s->n_lights; k++)
            explain_light(stdout, k, &s->lights[k], &r->per_light[k], &s->model, o->prec);
        fputs("global ambient c_amb*L_A ", stdout);
        triple(stdout, r->ambient, o->prec, 0);
        if (s->model.kind == SC_MODEL_OPENGL && s->model.separate_specular) {
            fputs("\nprimary ", stdout);
            triple(stdout, r->primary, o->prec, 0);
            fputs("  secondary ", stdout);
            triple(stdout, r->secondary, o->prec, 0);
        }
        fputs("\nL_o = ", stdout);
    }
    for (int c = 0; c < 3; c++) {
        fputs(c ? " " : "", stdout);
        number(stdout, r->L[c], o->prec, 0);
    }
    fputc('\n', stdout);
}

static void print_csv(const sc_shade_result *r, const shade_options *o)
{
    fputs("r,g,b\n", stdout);
    for (int c = 0; c < 3; c++) {
        fputs(c ? "," : "", stdout);
        number(stdout, r->L[c], o->prec, 0);
    }
    fputc('\n', stdout);
}

static void json_light(const sc_light *light, const sc_light_terms *t, const sc_model *m, sc_prec p)
{
    explain_term terms[MAX_TERMS];
    double nodes[3];
    int n = light_terms(light, t, m, nodes, terms);
    printf("{\"kind\": \"%s\"", light_kind_name(light->kind));
    if (sc_light_is_area(light->kind))
        printf(", \"method\": \"%s\"", sc_area_method_name(light->area.method));
    for (int i = 0; i < n; i++) {
        printf(", \"%s\": ", terms[i].key);
        term_value(stdout, &terms[i], p, 1);
    }
    printf("}");
}

static void print_json(const shade_setup *s, const sc_shade_result *r, const shade_options *o)
{
    printf("{\"precision\": \"%s\", \"L\": ", sc_prec_name(o->prec));
    triple(stdout, r->L, o->prec, 1);
    if (o->explain) {
        brdf_file_explain(stdout, &s->model, o->prec, 1);
        printf(", \"ambient\": ");
        triple(stdout, r->ambient, o->prec, 1);
        printf(", \"lights\": [");
        for (int k = 0; k < s->n_lights; k++) {
            fputs(k ? ", " : "", stdout);
            json_light(&s->lights[k], &r->per_light[k], &s->model, o->prec);
        }
        printf("]");
        if (s->model.kind == SC_MODEL_OPENGL && s->model.separate_specular) {
            printf(", \"primary\": ");
            triple(stdout, r->primary, o->prec, 1);
            printf(", \"secondary\": ");
            triple(stdout, r->secondary, o->prec, 1);
        }
    }
    printf("}\n");
}

/* ---- options ---- */

typedef struct {
    int opt;
    const char *arg;
} pending;

static int parse_format(const char *arg, int *format)
{
    static const char *const names[] = {"text", "csv", "json"};
    for (int i = 0; i < 3; i++)
        if (strcmp(arg, names[i]) == 0) {
            *format = i;
            return SC_EXIT_OK;
        }
    sc_error("shade: unknown format '%s' (text, csv, json)", arg);
    return SC_EXIT_USAGE;
}

/* Applies one command-line option to the setup (after any scene file). */
static int apply(shade_setup *s, const pending *o)
{
    switch (o->opt) {
    case 'l': return setup_add_light(s, o->arg, "");
    case 'b': return setup_set_model(s, o->arg, "");
    case 'a': return setup_set_value(s, "ambient", o->arg, "");
    default: return setup_set_value(s, setup_geometry_name(o->opt), o->arg, "");
    }
}

static int parse_options(int argc, char **argv, shade_setup *s, shade_options *o)
{
    static const struct option longs[] = {SETUP_LONG_OPTIONS,
                                          {"precision", required_argument, NULL, 'p'},
                                          {"format", required_argument, NULL, 'f'},
                                          {"explain", no_argument, NULL, 'e'},
                                          {"help", no_argument, NULL, 'h'},
                                          {NULL, 0, NULL, 0}};
    pending *todo = calloc((size_t)argc + 1, sizeof *todo);
    const char *scene = NULL;
    int n = 0, c, status = todo ? SC_EXIT_OK : SC_EXIT_RUNTIME;
    sc_getopt_reset();
    while (status == SC_EXIT_OK && (c = sc_getopt(argc, argv, "l:b:a:s:p:f:eh", longs)) != -1) {
        switch (c) {
        case 's': scene = optarg; break;
        case 'p':
            if (sc_prec_parse(optarg, &o->prec) < 0) {
                sc_error("shade: unknown precision '%s' (double, highp, mediump, lowp)", optarg);
                status = SC_EXIT_USAGE;
            }
            break;
        case 'f': status = parse_format(optarg, &o->format); break;
        case 'e': o->explain = 1; break;
        case 'h':
            usage(stdout);
            status = -1;
            break;
        case '?': status = sc_usage_error("shade", argv, optopt); break;
        default: todo[n++] = (pending){c, optarg}; break;
        }
    }
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("shade: unexpected argument '%s' (specs go after --light or --brdf)",
                 argv[optind]);
        status = SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK && scene)
        status = setup_load_file(s, scene);
    for (int i = 0; status == SC_EXIT_OK && i < n; i++)
        status = apply(s, &todo[i]);
    free(todo);
    return status;
}

static int run(int argc, char **argv)
{
    shade_setup *s = malloc(sizeof *s);
    if (!s) {
        sc_error("shade: out of memory");
        return SC_EXIT_RUNTIME;
    }
    setup_init(s);
    shade_options o = {.prec = SC_HIGHP, .format = FMT_TEXT};
    int status = parse_options(argc, argv, s, &o);
    sc_shade_point at;
    if (status == SC_EXIT_OK && s->n_lights == 0) {
        sc_error("shade: no light: give --light SPEC (see 'shadecalc shade --help')");
        status = SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK && o.explain && o.format == FMT_CSV) {
        sc_error("shade: --explain prints text or json, not csv");
        status = SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK)
        status = setup_check_range(s, o.prec);
    if (status == SC_EXIT_OK)
        status = setup_point(s, &at);
    sc_light_terms terms[SETUP_MAX_LIGHTS];
    sc_shade_result r = {.per_light = terms};
    if (status == SC_EXIT_OK) {
        sc_scene scene = {
            s->lights, s->n_lights, s->model, {s->ambient[0], s->ambient[1], s->ambient[2]}};
        sc_shade(o.prec, &scene, &at, &r);
        status = brdf_file_status(&s->model, "shade");
    }
    if (status == SC_EXIT_OK) {
        if (isinf(r.L[0]) || isinf(r.L[1]) || isinf(r.L[2]))
            sc_warning("shade: L_o overflows the %s range: inf", sc_prec_name(o.prec));
        if (o.format == FMT_TEXT)
            print_text(s, &r, &o);
        else if (o.format == FMT_JSON)
            print_json(s, &r, &o);
        else
            print_csv(&r, &o);
    }
    free(s);
    return status < 0 ? SC_EXIT_OK : status;
}

const sc_command sc_cmd_shade = {"shade", "evaluate the shading equation at one point", run};
