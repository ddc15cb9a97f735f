/* shadecalc sweep — a grid of variables through an expression or a shading setup: a table
 * streamed in row order on any number of threads, an SVG plot, an EXR image (issue 5). */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/progress.h"
#include "cli/setup.h"
#include "cli/sweep_cli.h"
#include "shadecalc/file.h"

enum { MAX_THREADS = 256, COMMAND_MAX = 4096 };

typedef struct {
    const char *var_args[SC_SWEEP_MAX_VARS + 1];
    int n_var_args;
    const char *log_names[SC_SWEEP_MAX_VARS + 1]; /* "" for every range */
    int n_log;
    sweep_setup_args setup;
    const char *expr, *preset, *output;
    sc_prec prec;
    sc_sweep_format format;
    long threads;
    sweep_picture_options pictures;
} sweep_options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc sweep [OPTIONS] [EXPR]\n"
            "\n"
            "Evaluates EXPR (a GLSL ES expression of the variables), or the shading setup of\n"
            "--light/--brdf, at every point of a grid of variables; writes a table, a plot, an\n"
            "image. With lights a row is L_o (r,g,b); with a BRDF and no light, f(l,v) (r,g,b).\n"
            "\n"
            "      --var NAME=START:STOP:COUNT   a variable over a range, ends included\n"
            "      --var NAME=V1,V2,...  a variable over a list (repeatable; the first varies\n"
            "                           fastest); theta_i phi_i theta_o phi_o (degrees) place\n"
            "                           l and v about n; $NAME in a --light/--brdf spec\n"
            "      --log[=NAME]         geometric spacing (of every range, or of NAME's)\n"
            "  -l, --light SPEC         a light, as for 'shadecalc shade' (repeatable)\n"
            "  -b, --brdf SPEC          the model, as for 'shadecalc shade'\n"
            "  -a, --ambient C          global ambient radiance\n"
            "  -s, --scene FILE         a scene file, as for 'shadecalc shade'\n"
            "      --n, --v, --p, --eye, --tangent X,Y,Z   the geometry, as for shade\n"
            "      --preset NAME        attenuation|spot|lobe|albedo: the lecture's figures\n"
            "  -p, --precision P        double|highp|mediump|lowp (default highp)\n"
            "      --tier T             shading rows by the batch kernel's tier T (accurate|\n"
            "                           bits12), the scene compiled once; default: the\n"
            "                           scalar equation at -p\n"
            "  -f, --format F           csv|tsv|jsonl (default csv; jsonl: JSON Lines, one\n"
            "                           object per row, also called json)\n"
            "  -o, --output FILE        the table (default standard output; with --plot or\n"
            "                           --image, the table is written only when this is given)\n"
            "  -j, --threads N          worker threads (default: the number of processors)\n"
            "      --plot FILE.svg      line plot of each result column against the first\n"
            "                           variable, one curve per value of the second\n"
            "      --polar              the plot as a polar plot (the first variable an angle)\n"
            "      --title, --xlabel, --ylabel TEXT   the plot's labels\n"
            "      --xlog, --ylog       log axes\n"
            "      --yrange LO:HI       the plot's y range (polar: the radius)\n"
            "      --image FILE.exr     an image of two variables (width, height): Y or R,G,B\n"
            "      --heatmap FILE.svg   a heat map of two variables with a colour bar (rgb:\n"
            "                           luminance)\n"
            "      --tone T             the heat map's scale: log|linear (default log)\n"
            "      --exposure STOPS     the heat map's exposure (default 0)\n"
            "      --sqrt-x             the heat map's x at the square root of its position\n"
            "                           (BRDF Explorer's theta_h^2 mapping)\n"
            "      --exr-type T         half|float (default float)\n"
            "      --force              replace read-only files given to -o, --plot, --image,\n"
            "                           --heatmap\n"
            "  -h, --help               this help\n"
            "\n"
            "example: shadecalc sweep --var x=0:1:101 'pow(x, 32.0)'\n"
            "         shadecalc sweep --var theta_o=-90:90:181 --brdf 'phong m=$m' --var m=8,32\n");
}

/* ---- options ---- */

enum {
    OPT_VAR = SETUP_OPT_END,
    OPT_LOG,
    OPT_PRESET,
    OPT_TIER,
    OPT_PLOT,
    OPT_POLAR,
    OPT_TITLE,
    OPT_XLABEL,
    OPT_YLABEL,
    OPT_XLOG,
    OPT_YLOG,
    OPT_YRANGE,
    OPT_IMAGE,
    OPT_EXR_TYPE,
    OPT_HEATMAP,
    OPT_TONE,
    OPT_EXPOSURE,
    OPT_SQRT_X,
    OPT_FORCE
};

static int parse_yrange(const char *arg, sweep_picture_options *o)
{
    double r[2];
    const char *colon = strchr(arg, ':');
    char lo[64];
    if (colon && (size_t)(colon - arg) < sizeof lo) {
        memcpy(lo, arg, (size_t)(colon - arg));
        lo[colon - arg] = '\0';
        if (sc_parse_double(lo, &r[0]) == 0 && sc_parse_double(colon + 1, &r[1]) == 0 &&
            isfinite(r[0]) && isfinite(r[1]) && r[0] < r[1]) {
            o->ymin = r[0];
            o->ymax = r[1];
            return SC_EXIT_OK;
        }
    }
    sc_error("sweep: --yrange %s: expected LO:HI with LO < HI", arg);
    return SC_EXIT_USAGE;
}

static int add_item(sweep_options *o, int opt, const char *name, const char *arg)
{
    if (o->setup.n_items == SWEEP_MAX_ITEMS) {
        sc_error("sweep: too many --light, --brdf and geometry options (at most %d)",
                 SWEEP_MAX_ITEMS);
        return SC_EXIT_USAGE;
    }
    o->setup.items[o->setup.n_items++] = (sweep_item){opt, name, arg};
    return SC_EXIT_OK;
}

static int option_value(sweep_options *o, int c, const char *arg)
{
    switch (c) {
    case 'l': return add_item(o, 'l', "light", arg);
    case 'b': return add_item(o, 'b', "brdf", arg);
    case 'a': return add_item(o, 'a', "ambient", arg);
    case 's': o->setup.scene = arg; return SC_EXIT_OK;
    case OPT_TIER: o->setup.tier = arg; return SC_EXIT_OK;
    case SETUP_OPT_N:
    case SETUP_OPT_V:
    case SETUP_OPT_P:
    case SETUP_OPT_EYE:
    case SETUP_OPT_TANGENT: return add_item(o, c, setup_geometry_name(c), arg);
    case OPT_VAR:
        if (o->n_var_args == SC_SWEEP_MAX_VARS) {
            sc_error("sweep: too many --var (at most %d)", SC_SWEEP_MAX_VARS);
            return SC_EXIT_USAGE;
        }
        o->var_args[o->n_var_args++] = arg;
        return SC_EXIT_OK;
    case OPT_LOG:
        if (o->n_log <= SC_SWEEP_MAX_VARS)
            o->log_names[o->n_log++] = arg ? arg : "";
        return SC_EXIT_OK;
    case OPT_PRESET:
        o->preset = arg;
        if (sweep_preset_exists(arg))
            return SC_EXIT_OK;
        sc_error("sweep: unknown preset '%s' (%s)", arg, sweep_preset_names());
        return SC_EXIT_USAGE;
    case 'p':
        if (sc_prec_parse(arg, &o->prec) == 0)
            return SC_EXIT_OK;
        sc_error("sweep: unknown precision '%s' (double, highp, mediump, lowp)", arg);
        return SC_EXIT_USAGE;
    case 'f': /* "json" names JSON Lines too, as for eval */
        if (sc_sweep_format_parse(strcmp(arg, "json") ? arg : "jsonl", &o->format) == 0)
            return SC_EXIT_OK;
        sc_error("sweep: unknown format '%s' (csv, tsv, jsonl)", arg);
        return SC_EXIT_USAGE;
    case 'o': o->output = arg; return sc_check_output_name("sweep", "-o", arg, "table");
    case OPT_FORCE: sc_atomic_allow_read_only(1); return SC_EXIT_OK;
    case 'j':
        if (sc_parse_long(arg, &o->threads) == 0 && o->threads >= 1 && o->threads <= MAX_THREADS)
            return SC_EXIT_OK;
        sc_error("sweep: --threads %s: expected a whole number from 1 to %d", arg, MAX_THREADS);
        return SC_EXIT_USAGE;
    default: return -1;
    }
}

static int heatmap_option(sweep_picture_options *o, int c, const char *arg)
{
    switch (c) {
    case OPT_HEATMAP: o->heatmap = arg; return SC_EXIT_OK;
    case OPT_SQRT_X: o->sqrt_x = 1; return SC_EXIT_OK;
    case OPT_TONE:
        if (strcmp(arg, "log") == 0 || strcmp(arg, "linear") == 0) {
            o->tone = arg[1] == 'o' ? SC_TONE_LOG : SC_TONE_LINEAR;
            return SC_EXIT_OK;
        }
        sc_error("sweep: --tone %s: expected log or linear", arg);
        return SC_EXIT_USAGE;
    case OPT_EXPOSURE:
        if (sc_parse_double(arg, &o->exposure) == 0 && fabs(o->exposure) <= 100.0)
            return SC_EXIT_OK;
        sc_error("sweep: --exposure %s: expected a number of stops from -100 to 100", arg);
        return SC_EXIT_USAGE;
    default: return -1;
    }
}

static int picture_option(sweep_picture_options *o, int c, const char *arg)
{
    switch (c) {
    case OPT_PLOT: o->plot = arg; return sc_check_output_name("sweep", "--plot", arg, "svg");
    case OPT_POLAR: o->polar = 1; return SC_EXIT_OK;
    case OPT_TITLE: o->title = arg; return SC_EXIT_OK;
    case OPT_XLABEL: o->xlabel = arg; return SC_EXIT_OK;
    case OPT_YLABEL: o->ylabel = arg; return SC_EXIT_OK;
    case OPT_XLOG: o->xlog = 1; return SC_EXIT_OK;
    case OPT_YLOG: o->ylog = 1; return SC_EXIT_OK;
    case OPT_YRANGE: return parse_yrange(arg, o);
    case OPT_IMAGE: o->image = arg; return sc_check_output_name("sweep", "--image", arg, "exr");
    case OPT_EXR_TYPE:
        if (strcmp(arg, "half") == 0 || strcmp(arg, "float") == 0) {
            o->exr_half = arg[0] == 'h';
            return SC_EXIT_OK;
        }
        sc_error("sweep: --exr-type %s: expected half or float", arg);
        return SC_EXIT_USAGE;
    default: return heatmap_option(o, c, arg);
    }
}

static int parse_options(int argc, char **argv, sweep_options *o)
{
    static const struct option longs[] = {{"var", required_argument, NULL, OPT_VAR},
                                          {"log", optional_argument, NULL, OPT_LOG},
                                          SETUP_LONG_OPTIONS,
                                          {"preset", required_argument, NULL, OPT_PRESET},
                                          {"tier", required_argument, NULL, OPT_TIER},
                                          {"precision", required_argument, NULL, 'p'},
                                          {"format", required_argument, NULL, 'f'},
                                          {"output", required_argument, NULL, 'o'},
                                          {"threads", required_argument, NULL, 'j'},
                                          {"plot", required_argument, NULL, OPT_PLOT},
                                          {"polar", no_argument, NULL, OPT_POLAR},
                                          {"title", required_argument, NULL, OPT_TITLE},
                                          {"xlabel", required_argument, NULL, OPT_XLABEL},
                                          {"ylabel", required_argument, NULL, OPT_YLABEL},
                                          {"xlog", no_argument, NULL, OPT_XLOG},
                                          {"ylog", no_argument, NULL, OPT_YLOG},
                                          {"yrange", required_argument, NULL, OPT_YRANGE},
                                          {"image", required_argument, NULL, OPT_IMAGE},
                                          {"exr-type", required_argument, NULL, OPT_EXR_TYPE},
                                          {"heatmap", required_argument, NULL, OPT_HEATMAP},
                                          {"tone", required_argument, NULL, OPT_TONE},
                                          {"exposure", required_argument, NULL, OPT_EXPOSURE},
                                          {"sqrt-x", no_argument, NULL, OPT_SQRT_X},
                                          {"force", no_argument, NULL, OPT_FORCE},
                                          {"help", no_argument, NULL, 'h'},
                                          {NULL, 0, NULL, 0}};
    int c, status = SC_EXIT_OK;
    sc_getopt_reset();
    while (status == SC_EXIT_OK && (c = sc_getopt(argc, argv, "+l:b:a:s:p:f:o:j:h", longs)) != -1) {
        if (c == 'h') {
            usage(stdout);
            return -1;
        }
        if (c == '?')
            return sc_usage_error("sweep", argv, optopt);
        status = option_value(o, c, optarg);
        if (status < 0)
            status = picture_option(&o->pictures, c, optarg);
    }
    if (status == SC_EXIT_OK && optind < argc)
        o->expr = argv[optind++];
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("sweep: unexpected argument '%s' (one EXPR; specs go after --light or --brdf)",
                 argv[optind]);
        status = SC_EXIT_USAGE;
    }
    return status;
}

/* ---- the grid ---- */

static int apply_log(const sweep_options *o, sc_sweep_grid *g)
{
    char err[256];
    for (int i = 0; i < o->n_log; i++) {
        const char *name = o->log_names[i];
        int k = name[0] ? sc_sweep_grid_find(g, name) : -1;
        if (name[0] && k < 0) {
            sc_error("sweep: --log=%s: no such variable", name);
            return SC_EXIT_USAGE;
        }
        for (int j = 0; j < g->n; j++) {
            int chosen = name[0] ? j == k : g->var[j].spacing != SC_SPACING_LIST;
            if (chosen && sc_sweep_var_set_log(&g->var[j], err, sizeof err) < 0) {
                sc_error("sweep: %s", err);
                return SC_EXIT_USAGE;
            }
        }
    }
    return SC_EXIT_OK;
}

static int build_grid(const sweep_options *o, sc_sweep_grid *g)
{
    char err[256];
    for (int i = 0; i < o->n_var_args; i++) {
        sc_sweep_var v;
        if (sc_sweep_var_parse(o->var_args[i], &v, err, sizeof err) < 0 ||
            sc_sweep_grid_add(g, &v, err, sizeof err) < 0) {
            sc_error("sweep: %s", err);
            return SC_EXIT_USAGE;
        }
    }
    int status = o->preset ? sweep_preset_vars(o->preset, g) : SC_EXIT_OK;
    if (status == SC_EXIT_OK)
        status = apply_log(o, g);
    if (status == SC_EXIT_OK && sc_sweep_grid_rows(g) == 0) {
        sc_error("sweep: the grid has more than 2^52 rows");
        status = SC_EXIT_USAGE;
    }
    return status;
}

static int make_plan(sweep_options *o, const sc_sweep_grid *g, sweep_plan *plan)
{
    int threads = (int)o->threads;
    if (o->preset && o->expr) {
        sc_error("sweep: give a --preset or an EXPR, not both");
        return SC_EXIT_USAGE;
    }
    if (o->preset)
        return sweep_preset_plan(o->preset, &o->setup, g, o->prec, threads, plan);
    if (o->expr && (o->setup.n_items || o->setup.scene)) {
        sc_error("sweep: EXPR '%s' is evaluated on its own: drop --light, --brdf, --scene and "
                 "the geometry options (or the EXPR)",
                 o->expr);
        return SC_EXIT_USAGE;
    }
    if (o->expr && o->setup.tier) {
        sc_error("sweep: --tier %s applies to shading sweeps (--light), not to an EXPR",
                 o->setup.tier);
        return SC_EXIT_USAGE;
    }
    if (o->expr)
        return sweep_expr_plan(o->expr, g, o->prec, threads, plan);
    if (o->setup.n_items || o->setup.scene)
        return sweep_shade_plan(&o->setup, g, o->prec, threads, plan);
    sc_error("sweep: nothing to sweep: give an EXPR, --brdf SPEC, --light SPEC or --preset NAME "
             "(see 'shadecalc sweep --help')");
    return SC_EXIT_USAGE;
}

/* ---- progress on a terminal ---- */

/* Drawn once the sweep has run for a second, so that short sweeps print nothing. */
static void show_progress(sc_progress *bar, uint64_t done, uint64_t total)
{
    char rows[48];
    snprintf(rows, sizeof rows, "%llu/%llu rows", (unsigned long long)done,
             (unsigned long long)total);
    sc_progress_update(bar, (double)done / (double)total, rows);
}

/* ---- running ---- */

/* The table's columns: the variables, then the plan's results; when a result is named like a
 * variable (--var r=... and the r,g,b of a colour), every result becomes result_NAME, so that
 * the results keep one naming. */
static void table_names(const sc_sweep_grid *g, const sweep_plan *plan, const char **names,
                        char (*renamed)[SC_SWEEP_NAME_MAX + 8])
{
    int clash = 0;
    for (int k = 0; k < g->n; k++)
        names[k] = g->var[k].name;
    for (int c = 0; c < plan->n_results; c++)
        clash |= sc_sweep_grid_find(g, plan->columns[c]) >= 0;
    for (int c = 0; c < plan->n_results; c++) {
        snprintf(renamed[c], sizeof renamed[c], "result_%s", plan->columns[c]);
        names[g->n + c] = clash ? renamed[c] : plan->columns[c];
    }
}

typedef struct {
    const sweep_plan *plan;
    sweep_pictures *pictures;
    sc_progress *bar;
} job_context;

static int job_eval(void *user, int worker, const double *vars, double *results, char *err,
                    size_t errsize)
{
    const job_context *j = user;
    return j->plan->eval(j->plan->user, worker, vars, results, err, errsize);
}

static int job_eval_block(void *user, int worker, int count, const double *vars, double *results,
                          int *failure, char *err, size_t errsize)
{
    const job_context *j = user;
    return j->plan->eval_block(j->plan->user, worker, count, vars, results, failure, err, errsize);
}

static int job_consume(void *user, uint64_t row, const double *vars, const double *results,
                       char *err, size_t errsize)
{
    const job_context *j = user;
    return sweep_pictures_consume(j->pictures, row, vars, results, err, errsize);
}

static void job_progress(void *user, uint64_t done, uint64_t total)
{
    job_context *j = user;
    show_progress(j->bar, done, total);
}

/* Runs the job; the table goes to `table_path` (NULL: none). An exit status. */
static int execute(const sweep_options *o, const sc_sweep_grid *g, const sweep_plan *plan,
                   sweep_pictures *pictures, const char *table_path)
{
    const char *names[SC_SWEEP_MAX_VARS + SWEEP_MAX_RESULTS];
    char renamed[SWEEP_MAX_RESULTS][SC_SWEEP_NAME_MAX + 8];
    table_names(g, plan, names, renamed);
    sc_sweep_table table = {o->format, o->prec, names, g->n, plan->n_results};
    char err[512];
    sc_atomic_file *file = table_path ? sc_atomic_open(table_path, err, sizeof err) : NULL;
    if (table_path && !file) {
        sc_error("%s", err);
        return SC_EXIT_RUNTIME;
    }
    sc_progress bar;
    sc_progress_start(&bar, "sweep", 1.0);
    job_context ctx = {plan, pictures, &bar};
    sc_sweep_job job = {g,
                        plan->n_results,
                        plan->eval ? job_eval : NULL,
                        &ctx,
                        o->pictures.plot || o->pictures.image || o->pictures.heatmap ? job_consume
                                                                                     : NULL,
                        file ? &table : NULL,
                        file ? sc_atomic_stream(file) : NULL,
                        isatty(STDERR_FILENO) ? job_progress : NULL,
                        (int)o->threads,
                        plan->eval_block ? job_eval_block : NULL};
    sc_sweep_status status = SC_SWEEP_OK;
    if (file && sc_sweep_write_header(job.out, &table) < 0)
        status = SC_SWEEP_WRITE_ERROR;
    if (status == SC_SWEEP_OK)
        status = sc_sweep_run(&job, err, sizeof err);
    int saved = errno;
    sc_progress_clear(&bar);
    if (status == SC_SWEEP_OK) {
        if (!file || sc_atomic_commit(file, err, sizeof err) == 0)
            return SC_EXIT_OK;
        sc_error("%s", err);
        return SC_EXIT_RUNTIME;
    }
    sc_atomic_abort(file);
    if (status == SC_SWEEP_WRITE_ERROR && saved != EPIPE)
        sc_error("%s: %s", strcmp(table_path, "-") ? table_path : "standard output",
                 strerror(saved));
    else if (status != SC_SWEEP_WRITE_ERROR)
        sc_error("sweep: %s", err);
    return status == SC_SWEEP_INVALID ? SC_EXIT_USAGE : SC_EXIT_RUNTIME;
}

/* "shadecalc sweep ARGS", each argument with a space or quote in single quotes. */
static void command_line(int argc, char **argv, char *buf, size_t size)
{
    size_t n = (size_t)snprintf(buf, size, "shadecalc");
    for (int i = 0; i < argc && n < size; i++) {
        int quote = argv[i][strcspn(argv[i], " \t'\"$*()")] != '\0';
        n += (size_t)snprintf(buf + n, size - n, quote ? " '%s'" : " %s", argv[i]);
    }
}

static void default_pictures(sweep_picture_options *pic, const sweep_plan *plan,
                             const sc_sweep_grid *g)
{
    pic->polar |= plan->polar;
    if (isnan(pic->ymin)) {
        pic->ymin = plan->ymin;
        pic->ymax = plan->ymax;
    }
    pic->xlog |= g->n > 0 && g->var[0].spacing == SC_SPACING_LOG;
}

/* A variable nothing reads draws flat curves: say so. */
static void warn_unused(const sc_sweep_grid *g, const sweep_plan *plan, const char *expr)
{
    for (int k = 0; k < g->n; k++) {
        const char *name = g->var[k].name;
        if (!(plan->unused >> k & 1u))
            continue;
        if (expr)
            sc_warning("sweep: EXPR does not use variable '%s': its values all give the same "
                       "results",
                       name);
        else
            sc_warning("sweep: nothing reads variable '%s' (no spec has $%s and it is not an "
                       "angle of l or v): its values all give the same results",
                       name, name);
    }
}

static int sweep(sweep_options *o, int argc, char **argv)
{
    sc_sweep_grid grid = {.n = 0};
    sweep_plan plan = {.ymin = NAN, .ymax = NAN};
    sweep_pictures *pictures = NULL;
    char command[COMMAND_MAX];
    int status = build_grid(o, &grid);
    if (status == SC_EXIT_OK)
        status = make_plan(o, &grid, &plan);
    if (status == SC_EXIT_OK)
        warn_unused(&grid, &plan, o->expr);
    if (status == SC_EXIT_OK && o->pictures.polar && (o->pictures.xlog || o->pictures.ylog)) {
        sc_error("sweep: --polar has no log axes");
        status = SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK) {
        command_line(argc, argv, command, sizeof command);
        o->pictures.command = command;
        default_pictures(&o->pictures, &plan, &grid);
        status = sweep_pictures_open(&pictures, &o->pictures, &grid, &plan);
    }
    int pictures_asked = o->pictures.plot || o->pictures.image || o->pictures.heatmap;
    const char *table_path = o->output ? o->output : pictures_asked ? NULL : "-";
    if (status == SC_EXIT_OK)
        status = execute(o, &grid, &plan, pictures, table_path);
    if (status == SC_EXIT_OK && plan.report)
        plan.report(plan.user);
    if (status == SC_EXIT_OK)
        status = sweep_pictures_write(pictures);
    sweep_pictures_free(pictures);
    if (plan.destroy)
        plan.destroy(plan.user);
    sc_sweep_grid_free(&grid);
    return status;
}

static int run(int argc, char **argv)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    sweep_options *o = calloc(1, sizeof *o);
    if (!o) {
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    o->prec = SC_HIGHP;
    o->format = SC_SWEEP_CSV;
    o->threads = cores < 1 ? 1 : cores > MAX_THREADS ? MAX_THREADS : cores;
    o->pictures.ymin = o->pictures.ymax = NAN;
    int status = parse_options(argc, argv, o);
    signal(SIGPIPE, SIG_IGN); /* a closed pipe is a write error (EPIPE): stop quietly */
    if (status == SC_EXIT_OK)
        status = sweep(o, argc, argv);
    free(o);
    return status < 0 ? SC_EXIT_OK : status;
}

const sc_command sc_cmd_sweep = {"sweep", "sweep variables: CSV curves, SVG plots, EXR images",
                                 run};
