/* shadecalc shade — one value of the shading equation (SPEC §6) from the shell. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

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
            "  -l, --light SPEC     a light (repeatable): directional|point|spot key=value...\n"
            "  -b, --brdf SPEC      the model: lambert|phong|blinn-phong|ward|oren-nayar|\n"
            "                       cook-torrance|ads|opengl|direct3d9 key=value...\n"
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
    return k == SC_LIGHT_DIRECTIONAL ? "directional" : k == SC_LIGHT_POINT ? "point" : "spot";
}

static void explain_light(FILE *out, int k, const sc_light *light, const sc_light_terms *t,
                          const sc_model *m, sc_prec p)
{
    const sc_light_sample *ls = &t->light;
    fprintf(out, "light %d (%s)\n  l = ", k + 1, light_kind_name(light->kind));
    triple(out, ls->l, p, 0);
    fputs("  r = ", out);
    number(out, ls->r, p, 0);
    fputs("\n  f_d = ", out);
    number(out, ls->f_d, p, 0);
    fputs("  spot = ", out);
    number(out, ls->spot, p, 0);
    if (light->kind == SC_LIGHT_SPOT) {
        fputs("  cos theta_s = ", out);
        number(out, ls->cos_s, p, 0);
    }
    fputs("  E_L = ", out);
    triple(out, ls->E, p, 0);
    fputs("\n  cos theta_i = ", out);
    number(out, t->brdf.cos_i, p, 0);
    if (m->kind == SC_MODEL_BRDF) {
        fputs("  cos theta_o = ", out);
        number(out, t->brdf.cos_o, p, 0);
    }
    fputs("  cos theta_h = ", out);
    number(out, t->brdf.cos_h, p, 0);
    fputs(m->kind == SC_MODEL_BRDF ? "\n  f: diffuse " : "\n  diffuse colour ", out);
    triple(out, t->brdf.diffuse, p, 0);
    fputs(m->kind == SC_MODEL_BRDF ? "  specular " : "  specular colour ", out);
    triple(out, t->brdf.specular, p, 0);
    if (m->kind == SC_MODEL_BRDF &&
        (m->brdf.kind == SC_BRDF_COOK_TORRANCE || m->brdf.kind == SC_BRDF_WARD)) {
        fputs(m->brdf.kind == SC_BRDF_WARD ? "  exp term = " : "  D = ", out);
        number(out, t->brdf.D, p, 0);
        if (m->brdf.kind == SC_BRDF_COOK_TORRANCE) {
            fputs("  G = ", out);
            number(out, t->brdf.G, p, 0);
            fputs("  F = ", out);
            triple(out, t->brdf.F, p, 0);
        }
    }
    fputs("\n  ambient ", out);
    triple(out, t->ambient, p, 0);
    fputs("  contribution ", out);
    triple(out, t->contribution, p, 0);
    fputc('\n', out);
}

static void print_text(const shade_setup *s, const sc_shade_result *r, const shade_options *o)
{
    if (o->explain) {
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

static void json_light(const sc_light_terms *t, const sc_model *m, sc_prec p)
{
    printf("{\"l\": ");
    triple(stdout, t->light.l, p, 1);
    printf(", \"r\": ");
    number(stdout, t->light.r, p, 1);
    printf(", \"f_d\": ");
    number(stdout, t->light.f_d, p, 1);
    printf(", \"spot\": ");
    number(stdout, t->light.spot, p, 1);
    printf(", \"E_L\": ");
    triple(stdout, t->light.E, p, 1);
    printf(", \"cos_theta_i\": ");
    number(stdout, t->brdf.cos_i, p, 1);
    printf(", \"cos_theta_h\": ");
    number(stdout, t->brdf.cos_h, p, 1);
    printf(", \"diffuse\": ");
    triple(stdout, t->brdf.diffuse, p, 1);
    printf(", \"specular\": ");
    triple(stdout, t->brdf.specular, p, 1);
    if (m->kind == SC_MODEL_BRDF && m->brdf.kind == SC_BRDF_COOK_TORRANCE) {
        printf(", \"D\": ");
        number(stdout, t->brdf.D, p, 1);
        printf(", \"G\": ");
        number(stdout, t->brdf.G, p, 1);
        printf(", \"F\": ");
        triple(stdout, t->brdf.F, p, 1);
    }
    printf(", \"ambient\": ");
    triple(stdout, t->ambient, p, 1);
    printf(", \"contribution\": ");
    triple(stdout, t->contribution, p, 1);
    printf("}");
}

static void print_json(const shade_setup *s, const sc_shade_result *r, const shade_options *o)
{
    printf("{\"precision\": \"%s\", \"L\": ", sc_prec_name(o->prec));
    triple(stdout, r->L, o->prec, 1);
    if (o->explain) {
        printf(", \"ambient\": ");
        triple(stdout, r->ambient, o->prec, 1);
        printf(", \"lights\": [");
        for (int k = 0; k < s->n_lights; k++) {
            fputs(k ? ", " : "", stdout);
            json_light(&r->per_light[k], &s->model, o->prec);
        }
        printf("]");
    }
    printf("}\n");
}

/* ---- options ---- */

enum { OPT_N = 256, OPT_V, OPT_P, OPT_EYE, OPT_TANGENT };

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
    static const char *const names[] = {"n", "v", "p", "eye", "tangent"};
    switch (o->opt) {
    case 'l': return setup_add_light(s, o->arg, "");
    case 'b': return setup_set_model(s, o->arg, "");
    case 'a': return setup_set_value(s, "ambient", o->arg, "");
    default: return setup_set_value(s, names[o->opt - OPT_N], o->arg, "");
    }
}

static int parse_options(int argc, char **argv, shade_setup *s, shade_options *o)
{
    static const struct option longs[] = {
        {"light", required_argument, NULL, 'l'},  {"brdf", required_argument, NULL, 'b'},
        {"ambient", required_argument, NULL, 'a'}, {"scene", required_argument, NULL, 's'},
        {"n", required_argument, NULL, OPT_N},     {"v", required_argument, NULL, OPT_V},
        {"p", required_argument, NULL, OPT_P},     {"eye", required_argument, NULL, OPT_EYE},
        {"tangent", required_argument, NULL, OPT_TANGENT},
        {"precision", required_argument, NULL, 'p'}, {"format", required_argument, NULL, 'f'},
        {"explain", no_argument, NULL, 'e'},       {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    pending *todo = calloc((size_t)argc + 1, sizeof *todo);
    const char *scene = NULL;
    int n = 0, c, status = todo ? SC_EXIT_OK : SC_EXIT_RUNTIME;
    sc_getopt_reset();
    while (status == SC_EXIT_OK && (c = getopt_long(argc, argv, "l:b:a:s:p:f:eh", longs, NULL)) != -1) {
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
        case 'h': usage(stdout); status = -1; break;
        case '?': status = sc_usage_error("shade", argv, optopt); break;
        default: todo[n++] = (pending){c, optarg}; break;
        }
    }
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("shade: unexpected argument '%s' (specs go after --light or --brdf)", argv[optind]);
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
    if (status == SC_EXIT_OK) {
        sc_light_terms terms[SETUP_MAX_LIGHTS];
        sc_scene scene = {s->lights, s->n_lights, s->model, {s->ambient[0], s->ambient[1], s->ambient[2]}};
        sc_shade_result r = {.per_light = terms};
        sc_shade(o.prec, &scene, &at, &r);
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
