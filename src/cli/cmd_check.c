/* shadecalc check — directional albedo and reciprocity of BRDFs (are the models physical?). */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/check_area.h"
#include "cli/brdf_file_cli.h"
#include "cli/cli.h"
#include "shadecalc/check.h"
#include "shadecalc/scene.h"

enum { MAX_BRDFS = 16, MAX_THETAS = 64 };
enum { FMT_TABLE, FMT_CSV, FMT_JSON };

typedef struct {
    const char *specs[MAX_BRDFS];
    sc_model models[MAX_BRDFS];
    int n;
    double theta[MAX_THETAS];
    int n_theta;
    int order;
    int format;
    const char *light_spec; /* --light: the area light mode */
    sc_light light;
} check_options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc check --brdf SPEC [--brdf SPEC...] [OPTIONS]\n"
            "       shadecalc check --light SPEC --brdf SPEC [--format F]\n"
            "\n"
            "For each BRDF: the directional albedo a(theta_i) = integral of f(l,v) cos(theta_o)\n"
            "over the hemisphere, with an error estimate; its maximum; the worst reciprocity\n"
            "error |f(l,v) - f(v,l)| / max(f); flags for albedo > 1 and non-reciprocity.\n"
            "With --light (a sphere, tube, disk or rect light): each method's maximum and mean\n"
            "relative error against the converged reference over a standard set of\n"
            "configurations (distance/size, light and view angles, roughness), its worst\n"
            "configuration and its time per evaluation.\n"
            "\n"
            "  -b, --brdf SPEC     a BRDF as for 'shadecalc shade', file=PATH too (repeatable)\n"
            "  -l, --light SPEC    an area light as for 'shadecalc shade' (its shape is kept,\n"
            "                      its position is each configuration's)\n"
            "  -t, --theta LIST    angles of incidence in degrees (default 0,5,...,85,89,89.9)\n"
            "  -o, --order N       Gauss-Legendre nodes per panel, 2..32 (default 16)\n"
            "  -f, --format F      table|csv, and json with --light (default table)\n"
            "  -h, --help          this help\n");
}

typedef struct {
    sc_albedo_result a[MAX_THETAS];
    double max_albedo, max_at, max_error, reciprocity;
} check_result;

static double max3(const double v[3]) { return fmax(v[0], fmax(v[1], v[2])); }

static void compute(const sc_brdf *b, const check_options *o, check_result *r)
{
    r->max_albedo = -1.0;
    r->max_error = 0.0;
    for (int i = 0; i < o->n_theta; i++) {
        sc_albedo(b, o->theta[i], o->order, &r->a[i]);
        double a = max3(r->a[i].albedo);
        if (a > r->max_albedo) {
            r->max_albedo = a;
            r->max_at = o->theta[i];
        }
        r->max_error = fmax(r->max_error, max3(r->a[i].error));
    }
    r->reciprocity = sc_reciprocity_error(b, NULL, NULL);
}

/* Flags: albedo above 1 beyond the error estimate; reciprocity error above 1e-9. */
static int exceeds_one(const check_result *r) { return r->max_albedo > 1.0 + r->max_error + 1e-9; }
static int reciprocal(const check_result *r) { return r->reciprocity <= 1e-9; }

static void print_table(const char *spec, const check_options *o, const check_result *r)
{
    printf("brdf %s\n%8s  %-10s %-10s %-10s %s\n", spec, "theta_i", "albedo_r", "albedo_g",
           "albedo_b", "error");
    for (int i = 0; i < o->n_theta; i++) {
        const sc_albedo_result *a = &r->a[i];
        printf("%8g  %-10.6f %-10.6f %-10.6f %.1e\n", o->theta[i], a->albedo[0], a->albedo[1],
               a->albedo[2], max3(a->error));
    }
    printf("max albedo %.6f at theta_i = %g: %s\n", r->max_albedo, r->max_at,
           isinf(r->max_error) ? "UNRESOLVED (a lobe narrower than the quadrature resolves)"
           : exceeds_one(r)    ? "EXCEEDS 1 (not energy conserving)"
                               : "<= 1 (energy conserving)");
    printf("reciprocity error %.3g: %s\n\n", r->reciprocity,
           reciprocal(r) ? "reciprocal" : "NOT RECIPROCAL");
}

static void print_csv_rows(const char *spec, const check_options *o, const check_result *r)
{
    for (int i = 0; i < o->n_theta; i++) {
        const sc_albedo_result *a = &r->a[i];
        printf("\"%s\",%g,%.9g,%.9g,%.9g,%.3g,%.9g,%.3g,%d,%d\n", spec, o->theta[i], a->albedo[0],
               a->albedo[1], a->albedo[2], max3(a->error), r->max_albedo, r->reciprocity,
               !exceeds_one(r), reciprocal(r));
    }
}

static int parse_thetas(const char *arg, check_options *o)
{
    const char *p = arg;
    o->n_theta = 0;
    for (;;) {
        char *end;
        double t = strtod(p, &end);
        if (end == p || !(t >= 0.0 && t < 90.0) || o->n_theta == MAX_THETAS) {
            sc_error("check: --theta %s: expected up to %d angles in [0, 90) separated by commas",
                     arg, MAX_THETAS);
            return SC_EXIT_USAGE;
        }
        o->theta[o->n_theta++] = t;
        if (*end == '\0')
            return SC_EXIT_OK;
        if (*end != ',') {
            sc_error("check: --theta %s: expected numbers separated by commas", arg);
            return SC_EXIT_USAGE;
        }
        p = end + 1;
    }
}

static int add_brdf(check_options *o, const char *spec)
{
    char err[512];
    if (o->n == MAX_BRDFS) {
        sc_error("check: too many --brdf (at most %d)", MAX_BRDFS);
        return SC_EXIT_USAGE;
    }
    int parsed = sc_model_parse(spec, &o->models[o->n], err, sizeof err);
    if (parsed < 0) {
        sc_error("%s", err);
        return SC_EXIT_USAGE;
    }
    if (parsed > 0)
        sc_warning("%s", err);
    if (o->models[o->n].kind != SC_MODEL_BRDF) {
        sc_error("check: '%s' is a legacy shading model, not a BRDF", spec);
        return SC_EXIT_USAGE;
    }
    o->specs[o->n++] = spec;
    return SC_EXIT_OK;
}

static int set_light(check_options *o, const char *spec)
{
    char err[256];
    int parsed = sc_light_parse(spec, &o->light, err, sizeof err);
    if (parsed < 0) {
        sc_error("%s", err);
        return SC_EXIT_USAGE;
    }
    if (parsed > 0)
        sc_warning("%s", err);
    if (o->light_spec || !sc_light_is_area(o->light.kind)) {
        sc_error("check: --light %s: %s", spec,
                 o->light_spec ? "give one --light" : "an area light (sphere, tube, disk, rect)");
        return SC_EXIT_USAGE;
    }
    o->light_spec = spec;
    return SC_EXIT_OK;
}

static int parse_format(check_options *o, const char *arg)
{
    static const char *const names[] = {"table", "csv", "json"};
    for (int i = 0; i < 3; i++)
        if (strcmp(arg, names[i]) == 0) {
            o->format = i;
            return SC_EXIT_OK;
        }
    sc_error("check: unknown format '%s' (table, csv, json)", arg);
    return SC_EXIT_USAGE;
}

/* The combinations the two modes take. */
static int check_mode(const check_options *o)
{
    if (o->n == 0) {
        sc_error("check: no --brdf SPEC given (see 'shadecalc check --help')");
        return SC_EXIT_USAGE;
    }
    if (o->light_spec && o->n != 1) {
        sc_error("check: --light takes one --brdf");
        return SC_EXIT_USAGE;
    }
    if (!o->light_spec && o->format == FMT_JSON) {
        sc_error("check: --format json is for --light (area lights); the albedo table is "
                 "table or csv");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int parse_options(int argc, char **argv, check_options *o)
{
    static const struct option longs[] = {{"brdf", required_argument, NULL, 'b'},
                                          {"theta", required_argument, NULL, 't'},
                                          {"light", required_argument, NULL, 'l'},
                                          {"order", required_argument, NULL, 'o'},
                                          {"format", required_argument, NULL, 'f'},
                                          {"help", no_argument, NULL, 'h'},
                                          {NULL, 0, NULL, 0}};
    int c, status = SC_EXIT_OK;
    long order;
    sc_getopt_reset();
    while (status == SC_EXIT_OK && (c = sc_getopt(argc, argv, "b:l:t:o:f:h", longs)) != -1) {
        switch (c) {
        case 'b': status = add_brdf(o, optarg); break;
        case 'l': status = set_light(o, optarg); break;
        case 't': status = parse_thetas(optarg, o); break;
        case 'o':
            if (sc_parse_long(optarg, &order) < 0 || order < 2 || order > 32) {
                sc_error("check: --order %s: expected an integer 2..32", optarg);
                status = SC_EXIT_USAGE;
            }
            o->order = (int)order;
            break;
        case 'f': status = parse_format(o, optarg); break;
        case 'h': usage(stdout); return -1;
        default: return sc_usage_error("check", argv, optopt);
        }
    }
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("check: unexpected argument '%s'", argv[optind]);
        status = SC_EXIT_USAGE;
    }
    return status == SC_EXIT_OK ? check_mode(o) : status;
}

static int run(int argc, char **argv)
{
    check_options *o = calloc(1, sizeof *o);
    check_result *r = malloc(sizeof *r);
    if (!o || !r) {
        free(o);
        free(r);
        sc_error("check: out of memory");
        return SC_EXIT_RUNTIME;
    }
    static const double default_theta[] = {0,  5,  10, 15, 20, 25, 30, 35, 40, 45,
                                           50, 55, 60, 65, 70, 75, 80, 85, 89, 89.9};
    o->n_theta = (int)(sizeof default_theta / sizeof default_theta[0]);
    memcpy(o->theta, default_theta, sizeof default_theta);
    o->order = 16;
    int status = parse_options(argc, argv, o);
    if (status == SC_EXIT_OK && o->light_spec) {
        static const check_area_format formats[] = {CHECK_AREA_TABLE, CHECK_AREA_CSV,
                                                    CHECK_AREA_JSON};
        status = check_area_run(o->light_spec, &o->light, o->specs[0], &o->models[0].brdf,
                                formats[o->format]);
        if (status == SC_EXIT_OK)
            status = brdf_file_status(&o->models[0], "check");
        o->n = 0;
    }
    if (status == SC_EXIT_OK && o->format == FMT_CSV && !o->light_spec)
        printf("brdf,theta_i,albedo_r,albedo_g,albedo_b,error,max_albedo,reciprocity_error,"
               "energy_conserving,reciprocal\n");
    for (int i = 0; status == SC_EXIT_OK && i < o->n; i++) {
        compute(&o->models[i].brdf, o, r);
        if ((status = brdf_file_status(&o->models[i], "check")) != SC_EXIT_OK)
            break;
        if (o->format == FMT_CSV)
            print_csv_rows(o->specs[i], o, r);
        else
            print_table(o->specs[i], o, r);
    }
    free(o);
    free(r);
    return status < 0 ? SC_EXIT_OK : status;
}

const sc_command sc_cmd_check = {"check",
                                 "albedo and reciprocity of BRDFs; error and cost of area "
                                 "light methods",
                                 run};
