/* shadecalc bench — speed against accuracy of every batch kernel × instruction set × tier,
 * measured in one run on the same inputs (bench/). */
#include <errno.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "cli/cli.h"
#include "shadecalc/file.h"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc bench [KERNEL...] [OPTIONS]\n"
            "       shadecalc bench --compare A.json B.json [-f table|csv|json] [-o FILE]\n"
            "\n"
            "Times each batch kernel (shadecalc bench --list) on every instruction set and tier\n"
            "on the same inputs: ns/element (median of K repeats after a warm-up, min, max) at\n"
            "an in-cache and a streaming size; speedups against the scalar accurate kernel and\n"
            "the plain libm loop; accuracy against the double reference (max and mean ULP, max\n"
            "relative error); the fraction of the roofline bound reached; the Pareto set (*).\n"
            "'shade' runs with several scenes: each pays only for the terms it names.\n"
            "\n"
            "  -l, --list          the table of kernels, tiers, bounds and domains\n"
            "  -i, --isa LIST      instruction sets, e.g. avx2,scalar (default: all supported)\n"
            "  -t, --tier LIST     tiers, e.g. u1,bits12 (default: all)\n"
            "  -n, --n LIST        element counts (default 4096,8388608: in cache, streaming)\n"
            "  -r, --repeat K      timed repeats per row, 1..64 (default 5)\n"
            "  -w, --warmup K      untimed calls before the repeats, 1..1000 (default 1)\n"
            "  -f, --format F      table|csv|json|markdown (default table; with -o, from the\n"
            "                      file's extension .csv, .json, .md when not given)\n"
            "  -o, --output FILE   the report into FILE (written whole or not at all)\n"
            "  -p, --plot FILE.svg the Pareto plot: ns/element against max ULP (log-log) per\n"
            "                      kernel at the smallest n, each row labelled, the Pareto set\n"
            "                      joined\n"
            "  -c, --compare A B   two JSON reports (-o X.json) row by row: the ratio B/A of\n"
            "                      the median ns/element, * where the medians differ by more\n"
            "                      than 3x their combined MAD, ~ otherwise; rows only in one\n"
            "                      report listed as such\n"
            "  -h, --help          this help\n"
            "The scalar accurate kernel and the libm loop are always measured (the baselines).\n");
}

typedef struct {
    bench_options run;
    int format, list;
    int format_given;
    const char *output;
    const char *plot;
    const char *compare, *compare_b; /* reports A and B (B: the one operand) */
} options;

/* Splits a comma list in place into out[]; returns the count, or -1 if more than max. */
static int split(char *s, const char **out, int max)
{
    int n = 0;
    for (char *tok = strtok(s, ","); tok; tok = strtok(NULL, ",")) {
        if (n == max)
            return -1;
        out[n++] = tok;
    }
    return n;
}

static int parse_isas(char *s, options *o)
{
    const char *names[SC_ISA_COUNT + 1];
    int n = split(s, names, SC_ISA_COUNT);
    for (int i = 0; i < n; i++) {
        sc_isa isa;
        if (sc_isa_parse(names[i], &isa) != 0) {
            sc_error("bench: --isa: unknown instruction set '%s' (scalar, sse4.1, avx2, avx512)",
                     names[i]);
            return SC_EXIT_USAGE;
        }
        if (!sc_isa_supported(isa)) {
            sc_error("bench: --isa: %s is not supported by this CPU or build", names[i]);
            return SC_EXIT_USAGE;
        }
        o->run.isa_mask |= 1 << isa;
    }
    if (n <= 0) {
        sc_error("bench: --isa: expected a list such as avx2,scalar");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int known_tier(const char *tier)
{
    for (int i = 0; i < sc_batch_count; i++)
        if (strcmp(sc_batch_table[i].tier, tier) == 0)
            return 1;
    return 0;
}

static int parse_tiers(char *s, options *o)
{
    o->run.n_tiers = split(s, o->run.tiers, 16);
    for (int i = 0; i < o->run.n_tiers; i++)
        if (!known_tier(o->run.tiers[i])) {
            sc_error("bench: --tier: unknown tier '%s' (see 'shadecalc bench --list')",
                     o->run.tiers[i]);
            return SC_EXIT_USAGE;
        }
    if (o->run.n_tiers <= 0) {
        sc_error("bench: --tier: expected a list such as u1,bits12");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int parse_sizes(char *s, options *o)
{
    const char *items[4];
    int n = split(s, items, 4);
    for (int i = 0; i < n; i++) {
        long v;
        if (sc_parse_long(items[i], &v) != 0 || v < 1 || v > (1L << 28)) {
            sc_error("bench: --n %s: expected element counts 1..268435456", items[i]);
            return SC_EXIT_USAGE;
        }
        o->run.sizes[i] = (size_t)v;
    }
    if (n <= 0) {
        sc_error("bench: --n: expected at most 4 counts, such as 4096,8388608");
        return SC_EXIT_USAGE;
    }
    o->run.n_sizes = n;
    return SC_EXIT_OK;
}

static int parse_format(const char *s, options *o)
{
    static const char *const names[] = {"table", "csv", "json", "markdown"};
    for (int i = 0; i < 4; i++)
        if (strcmp(s, names[i]) == 0) {
            o->format = i;
            o->format_given = 1;
            return SC_EXIT_OK;
        }
    sc_error("bench: unknown format '%s' (table, csv, json, markdown)", s);
    return SC_EXIT_USAGE;
}

/* The format a file's extension names (.csv, .json, .md), or the table */
static int format_of_path(const char *path)
{
    static const struct {
        const char *ext;
        int format;
    } exts[] = {{".csv", BENCH_CSV}, {".json", BENCH_JSON}, {".md", BENCH_MARKDOWN}};
    size_t len = strlen(path);
    for (size_t i = 0; i < sizeof exts / sizeof exts[0]; i++) {
        size_t el = strlen(exts[i].ext);
        if (len > el && strcmp(path + len - el, exts[i].ext) == 0)
            return exts[i].format;
    }
    return BENCH_TABLE;
}

/* An integer option in [lo, hi] */
static int parse_count(const char *name, const char *arg, long lo, long hi, int *out)
{
    long v;
    if (sc_parse_long(arg, &v) != 0 || v < lo || v > hi) {
        sc_error("bench: --%s %s: expected an integer %ld..%ld", name, arg, lo, hi);
        return SC_EXIT_USAGE;
    }
    *out = (int)v;
    return SC_EXIT_OK;
}

static int known_kernel(const char *kernel)
{
    for (int i = 0; i < sc_batch_count; i++)
        if (strcmp(sc_batch_table[i].kernel, kernel) == 0)
            return 1;
    return 0;
}

static int parse_kernels(int argc, char **argv, options *o)
{
    for (int i = optind; i < argc; i++) {
        if (!known_kernel(argv[i])) {
            sc_error("bench: unknown kernel '%s' (see 'shadecalc bench --list')", argv[i]);
            return SC_EXIT_USAGE;
        }
        if (o->run.n_kernels == 32) {
            sc_error("bench: too many kernels");
            return SC_EXIT_USAGE;
        }
        o->run.kernels[o->run.n_kernels++] = argv[i];
    }
    return SC_EXIT_OK;
}

static int parse_options(int argc, char **argv, options *o)
{
    static const struct option longs[] = {
        {"list", no_argument, NULL, 'l'},          {"isa", required_argument, NULL, 'i'},
        {"tier", required_argument, NULL, 't'},    {"n", required_argument, NULL, 'n'},
        {"repeat", required_argument, NULL, 'r'},  {"format", required_argument, NULL, 'f'},
        {"warmup", required_argument, NULL, 'w'},  {"output", required_argument, NULL, 'o'},
        {"compare", required_argument, NULL, 'c'}, {"plot", required_argument, NULL, 'p'},
        {"help", no_argument, NULL, 'h'},          {NULL, 0, NULL, 0}};
    int c, status = SC_EXIT_OK;
    sc_getopt_reset();
    while (status == SC_EXIT_OK &&
           (c = sc_getopt(argc, argv, "li:t:n:r:f:w:o:c:p:h", longs)) != -1) {
        switch (c) {
        case 'l': o->list = 1; break;
        case 'i': status = parse_isas(optarg, o); break;
        case 't': status = parse_tiers(optarg, o); break;
        case 'n': status = parse_sizes(optarg, o); break;
        case 'r': status = parse_count("repeat", optarg, 1, 64, &o->run.repeat); break;
        case 'w': status = parse_count("warmup", optarg, 1, 1000, &o->run.warmup); break;
        case 'o': o->output = optarg; break;
        case 'c': o->compare = optarg; break;
        case 'p': o->plot = optarg; break;
        case 'f': status = parse_format(optarg, o); break;
        case 'h': usage(stdout); return -1;
        default: return sc_usage_error("bench", argv, optopt);
        }
    }
    if (status == SC_EXIT_OK && o->output && !o->format_given)
        o->format = format_of_path(o->output);
    if (status == SC_EXIT_OK && o->compare && o->plot) {
        sc_error("bench: --plot draws a run, not a --compare");
        return SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK && o->compare && argc - optind != 1) {
        sc_error("bench: --compare A.json B.json: expected one report B after A");
        return SC_EXIT_USAGE;
    }
    return status != SC_EXIT_OK || o->compare ? status : parse_kernels(argc, argv, o);
}

typedef struct {
    const options *o;
    const bench_machine *m;
    const bench_row *rows;
    int n;
    const bench_report_file *a, *b;
} report_job;

static int write_bench(FILE *out, const report_job *j)
{
    bench_report(out, j->o->format, j->m, j->rows, j->n);
    return 0;
}

static int write_comparison(FILE *out, const report_job *j)
{
    return bench_compare(out, j->o->format, j->o->compare, j->a, j->o->compare_b, j->b);
}

static int write_plot(FILE *out, const report_job *j)
{
    return bench_plot_write(out, j->rows, j->n);
}

/* The report by writer to standard output (path NULL), or whole into the file path */
static int write_report(const report_job *j, const char *path,
                        int (*writer)(FILE *, const report_job *))
{
    if (!path) {
        if (writer(stdout, j) == 0)
            return SC_EXIT_OK;
        sc_error("bench: out of memory");
        return SC_EXIT_RUNTIME;
    }
    char err[512];
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    errno = 0;
    if (f && writer(sc_atomic_stream(f), j) != 0) {
        int errnum = errno; /* of the failed write, or 0: out of memory */
        sc_atomic_abort(f);
        snprintf(err, sizeof err, "%s: %s", path, errnum ? strerror(errnum) : "out of memory");
    } else if (f && sc_atomic_commit(f, err, sizeof err) == 0)
        return SC_EXIT_OK;
    sc_error("bench: %s", err);
    return SC_EXIT_RUNTIME;
}

static int compare(options *o, char **argv)
{
    o->compare_b = argv[optind];
    bench_report_file a, b;
    int status = bench_report_read(o->compare, &a);
    if (status != SC_EXIT_OK)
        return status;
    status = bench_report_read(o->compare_b, &b);
    if (status == SC_EXIT_OK) {
        report_job j = {o, NULL, NULL, 0, &a, &b};
        status = write_report(&j, o->output, write_comparison);
        bench_report_free(&b);
    }
    bench_report_free(&a);
    return status;
}

static int run(int argc, char **argv)
{
    options o = {{{0}, 0, 0, {0}, 0, {4096, 8388608}, 2, 5, 1}, 0, 0, 0, NULL, NULL, NULL, NULL};
    int status = parse_options(argc, argv, &o);
    if (status != SC_EXIT_OK)
        return status < 0 ? SC_EXIT_OK : status;
    if (o.compare)
        return compare(&o, argv);
    if (o.list) {
        bench_list(stdout, o.format, o.run.kernels, o.run.n_kernels);
        return SC_EXIT_OK;
    }
    bench_machine m;
    bench_machine_measure(&m);
    bench_row *rows;
    int n;
    if (bench_run(&o.run, &m, &rows, &n) != 0) {
        sc_error("bench: out of memory");
        return SC_EXIT_RUNTIME;
    }
    report_job j = {&o, &m, rows, n, NULL, NULL};
    status = write_report(&j, o.output, write_bench);
    if (status == SC_EXIT_OK && o.plot)
        status = write_report(&j, o.plot, write_plot);
    free(rows);
    return status;
}

const sc_command sc_cmd_bench = {"bench", "speed against accuracy of the batch kernels", run};
