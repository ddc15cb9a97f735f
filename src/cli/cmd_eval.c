/* shadecalc eval — GLSL ES expressions evaluated from the shell in a chosen precision. */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/eval_file.h"
#include "cli/line_reader.h"

enum { MAX_DEFINES = 32 };

typedef struct {
    sc_prec prec;
    int format;
    int hex, ulp, strict;
    const char *file;    /* --file, or NULL */
    long max_iterations; /* --max-iterations */
} eval_options;

/* -D NAME=EXPR: a read-only variable with its value in the chosen precision and in the double
 * reference. */
typedef struct {
    char names[MAX_DEFINES][64];
    sc_lang_input inputs[MAX_DEFINES];
    sc_lvalue values[MAX_DEFINES], references[MAX_DEFINES];
    int n;
} define_set;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc eval [OPTIONS] EXPR...\n"
            "       shadecalc eval [OPTIONS] --file F\n"
            "\n"
            "Evaluates GLSL ES 3.00 expressions (one result line each; with no EXPR, one\n"
            "expression per line of standard input). Declarations and statements may precede\n"
            "the expression ('float a = 2.0; a * a'); GLSL ES converts nothing implicitly\n"
            "('1.0 + 1' is an error: write '1.0 + 1.0' or '1.0 + float(1)').\n"
            "\n"
            "  -p, --precision P   double|highp|mediump|lowp (default highp)\n"
            "  -f, --format F      glsl|csv|jsonl (default glsl; jsonl: JSON Lines, one\n"
            "                      object per line, also called json; csv: an expression\n"
            "                      column, then the components)\n"
            "  -D, --define N=EXPR define read-only variable N for every expression (repeatable)\n"
            "      --hex           print bit patterns of the precision instead of decimals\n"
            "      --ulp           also print the error against the double reference, in ULP\n"
            "      --strict        an argument outside a built-in's GLSL ES domain is an error\n"
            "      --file F        run the GLSL ES program in file F ('-': standard input),\n"
            "                      printing each top-level expression statement's value\n"
            "      --max-iterations N  loop iterations a run may execute (10000000)\n"
            "  -h, --help          this help\n"
            "\n"
            "example: shadecalc eval 'normalize(vec3(3,0,4))'   ->   vec3(0.6, 0, 0.8)\n");
}

/* ---- domain reporting ---- */

/* "column C" of a one-line expression, "line L, column C" when it spans lines. */
static const char *position(char *buf, size_t size, int line, int column)
{
    if (line > 1)
        snprintf(buf, size, "line %d, column %d", line, column);
    else
        snprintf(buf, size, "column %d", column);
    return buf;
}

/* Prints the domain errors; returns 1 if they are fatal (--strict). */
static int report_domain(const domain_hits *h, const char *where, int strict)
{
    char pos[48], at[160];
    for (int i = 0; i < h->n; i++) {
        snprintf(at, sizeof at, "%s%s", where,
                 position(pos, sizeof pos, h->hit[i].line, h->hit[i].column));
        sc_report_domain_hit(at, h->hit[i].func, h->hit[i].rule, strict);
    }
    return strict && h->n > 0;
}

/* ---- evaluation ---- */

/* Compiles src (declarations and statements, then the expression) against the defines; prints
 * the error (prefixed with `where`) on failure. */
static sc_program *compile(const char *src, const define_set *d, const eval_options *o,
                           const char *where)
{
    sc_lang_options options = {o->max_iterations, 0, 0};
    sc_lang_error err;
    char at[48];
    sc_program *prog = sc_program_compile(src, d->inputs, d->n, &options, &err);
    if (!prog) {
        sc_error("%s%s: %s", where, position(at, sizeof at, err.line, err.column), err.message);
        return NULL;
    }
    if (sc_program_values(prog) == 0) {
        sc_error("%sno expression to evaluate (the last statement must be an expression)", where);
        sc_program_free(prog);
        return NULL;
    }
    return prog;
}

/* The type of what an expression prints: its last expression statement. */
static sc_ltype result_type(const sc_program *prog)
{
    return sc_program_value_type(prog, sc_program_values(prog) - 1);
}

typedef struct {
    sc_lvalue *value;
    domain_hits *hits; /* NULL: not recorded */
} one_run;

static int keep_value(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    const one_run *run = user;
    (void)text, (void)len, (void)line;
    *run->value = *v; /* the last one stays */
    return 0;
}

static void keep_domain(void *user, int line, int column, const char *func, const char *rule)
{
    const one_run *run = user;
    if (run->hits)
        domain_hits_record(run->hits, line, column, func, rule);
}

/* One run in precision p; prints a runtime error. Status as the command's. */
static int run_once(const sc_program *prog, sc_prec p, const sc_lvalue *inputs, sc_lvalue *value,
                    domain_hits *hits, const char *where)
{
    one_run run = {value, hits};
    sc_lang_error err;
    char at[48];
    if (sc_program_run(prog, p, inputs, keep_value, keep_domain, &run, &err) < 0) {
        sc_error("%s%s: %s", where, position(at, sizeof at, err.line, err.column), err.message);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

/* Evaluates prog in the chosen precision (and in double when --ulp); status as the command's. */
static int evaluate(const sc_program *prog, const define_set *d, const eval_options *o,
                    const char *where, sc_lvalue *value, sc_lvalue *reference)
{
    domain_hits hits = {.n = 0};
    int status = run_once(prog, o->prec, d->values, value, &hits, where);
    if (status == SC_EXIT_OK && o->ulp)
        status = run_once(prog, SC_DOUBLE, d->references, reference, NULL, where);
    if (status != SC_EXIT_OK)
        return status;
    return report_domain(&hits, where, o->strict) ? SC_EXIT_RUNTIME : SC_EXIT_OK;
}

static int add_define(define_set *d, const char *arg, const eval_options *o)
{
    const char *eq = strchr(arg, '=');
    size_t len = eq ? (size_t)(eq - arg) : 0;
    if (!eq || len == 0 || len >= sizeof d->names[0]) {
        sc_error("eval: -D '%s': expected NAME=EXPR", arg);
        return SC_EXIT_USAGE;
    }
    if (d->n == MAX_DEFINES) {
        sc_error("eval: too many -D definitions (at most %d)", MAX_DEFINES);
        return SC_EXIT_USAGE;
    }
    char where[96];
    snprintf(where, sizeof where, "-D '%.*s': ", (int)len, arg);
    sc_program *prog = compile(eq + 1, d, o, where);
    if (!prog)
        return SC_EXIT_USAGE;
    memcpy(d->names[d->n], arg, len);
    d->names[d->n][len] = '\0';
    eval_options both = *o;
    both.ulp = 1;
    int status = evaluate(prog, d, &both, where, &d->values[d->n], &d->references[d->n]);
    d->inputs[d->n] = (sc_lang_input){d->names[d->n], result_type(prog)};
    sc_program_free(prog);
    if (status == SC_EXIT_OK)
        d->n++;
    return status;
}

/* ---- output ---- */

static int same_type(sc_ltype a, sc_ltype b)
{
    return a.kind == b.kind && a.cols == b.cols && a.rows == b.rows;
}

static void print_component(FILE *out, const sc_lvalue *v, int k, const eval_options *o, int json)
{
    sc_print_component(out, v->v[k], (sc_kind)v->type.kind, o->prec, o->hex, json);
}

/* The error in ULPs of the precision for a float; for an integer or bool, |value - reference|. */
static double ulp_of(const eval_options *o, const sc_lvalue *v, const sc_lvalue *ref, int k)
{
    if (v->type.kind != SC_KIND_FLOAT)
        return fabs(v->v[k] - ref->v[k]);
    return sc_ulp_error(o->prec, v->v[k], ref->v[k]);
}

static void print_ulps(FILE *out, const sc_lvalue *v, const sc_lvalue *ref, const eval_options *o,
                       const char *sep)
{
    for (int k = 0; k < sc_ltype_size(v->type); k++)
        fprintf(out, "%s%.3g", k ? sep : "", ulp_of(o, v, ref, k));
}

static void print_glsl(FILE *out, const sc_lvalue *v, const sc_lvalue *ref, const eval_options *o)
{
    char tb[16];
    int n = sc_ltype_size(v->type);
    if (n > 1)
        fprintf(out, "%s(", sc_ltype_name(v->type, tb, sizeof tb));
    for (int k = 0; k < n; k++) {
        fputs(k ? ", " : "", out);
        print_component(out, v, k, o, 0);
    }
    fputs(n > 1 ? ")" : "", out);
    if (o->ulp) {
        fputs("  # ulp: ", out);
        print_ulps(out, v, ref, o, ", ");
    }
    fputc('\n', out);
}

static void print_json(FILE *out, const char *src, const sc_lvalue *v, const sc_lvalue *ref,
                       const eval_options *o)
{
    char tb[16];
    int n = sc_ltype_size(v->type);
    fputs("{\"expression\": ", out);
    sc_print_json_string(out, src);
    fprintf(out, ", \"precision\": \"%s\", \"type\": \"%s\", \"%s\": ", sc_prec_name(o->prec),
            sc_ltype_name(v->type, tb, sizeof tb), o->hex ? "bits" : "value");
    fputs(n > 1 ? "[" : "", out);
    for (int k = 0; k < n; k++) {
        fputs(k ? ", " : "", out);
        print_component(out, v, k, o, 1);
    }
    fputs(n > 1 ? "]" : "", out);
    if (o->ulp) {
        fprintf(out, ", \"ulp\": %s", n > 1 ? "[" : "");
        print_ulps(out, v, ref, o, ", ");
        fputs(n > 1 ? "]" : "", out);
    }
    fputs("}\n", out);
}

/* One header for all rows: the expression, then named components when every result has the
 * same type, else `type,c0..cN` padded with empty fields. */
static void print_csv_header(FILE *out, const sc_ltype *types, int count, const eval_options *o)
{
    int mixed = 0, width = 0;
    for (int i = 0; i < count; i++) {
        mixed |= !same_type(types[i], types[0]);
        if (sc_ltype_size(types[i]) > width)
            width = sc_ltype_size(types[i]);
    }
    fputs(mixed ? "expression,type" : "expression", out);
    for (int pass = 0; pass < 1 + o->ulp; pass++)
        for (int k = 0; k < width; k++) {
            char name[16];
            if (mixed)
                snprintf(name, sizeof name, "c%d", k);
            else
                sc_value_column_name(name, sizeof name, types[0], k);
            fprintf(out, ",%s%s", name, pass ? "_ulp" : "");
        }
    fputc('\n', out);
}

/* A CSV field (RFC 4180): quoted, with quotes doubled, when it has a comma, quote or newline. */
void sc_print_csv_field(FILE *out, const char *s)
{
    if (!s[strcspn(s, ",\"\r\n")]) {
        fputs(s, out);
        return;
    }
    fputc('"', out);
    for (; *s; s++) {
        if (*s == '"')
            fputc('"', out);
        fputc(*s, out);
    }
    fputc('"', out);
}

static void print_csv(FILE *out, const char *src, const sc_lvalue *v, const sc_lvalue *ref,
                      const eval_options *o, int mixed, int width)
{
    char tb[16];
    int n = sc_ltype_size(v->type);
    sc_print_csv_field(out, src);
    if (mixed)
        fprintf(out, ",%s", sc_ltype_name(v->type, tb, sizeof tb));
    for (int k = 0; k < width; k++) {
        fputc(',', out);
        if (k < n)
            print_component(out, v, k, o, 0);
    }
    for (int k = 0; o->ulp && k < width; k++) {
        fputc(',', out);
        if (k < n)
            fprintf(out, "%.3g", ulp_of(o, v, ref, k));
    }
    fputc('\n', out);
}

/* One result line in the chosen format (csv: `mixed` and `width` as the header's). */
static void print_result(const char *src, const sc_lvalue *v, const sc_lvalue *ref,
                         const eval_options *o, int mixed, int width)
{
    if (o->format == FMT_GLSL)
        print_glsl(stdout, v, ref, o);
    else if (o->format == FMT_JSON)
        print_json(stdout, src, v, ref, o);
    else
        print_csv(stdout, src, v, ref, o, mixed, width);
}

/* ---- the command ---- */

typedef struct {
    char **src;
    int count;
} expression_list;

/* glsl, csv, or jsonl (JSON Lines; "json" names the same, as sweep and bench accept both). */
static int parse_format(const char *arg, int *format)
{
    static const char *const names[] = {"glsl", "csv", "jsonl", "json"};
    static const int formats[] = {FMT_GLSL, FMT_CSV, FMT_JSON, FMT_JSON};
    for (int i = 0; i < 4; i++)
        if (strcmp(arg, names[i]) == 0) {
            *format = formats[i];
            return SC_EXIT_OK;
        }
    sc_error("eval: unknown format '%s' (glsl, csv, jsonl)", arg);
    return SC_EXIT_USAGE;
}

static int parse_options(int argc, char **argv, eval_options *o, define_set *d)
{
    static const struct option longs[] = {{"precision", required_argument, NULL, 'p'},
                                          {"format", required_argument, NULL, 'f'},
                                          {"define", required_argument, NULL, 'D'},
                                          {"hex", no_argument, NULL, 'x'},
                                          {"ulp", no_argument, NULL, 'u'},
                                          {"strict", no_argument, NULL, 's'},
                                          {"file", required_argument, NULL, 'F'},
                                          {"max-iterations", required_argument, NULL, 'I'},
                                          {"help", no_argument, NULL, 'h'},
                                          {NULL, 0, NULL, 0}};
    const char *defines[MAX_DEFINES + 1];
    int n_defines = 0, c;
    sc_getopt_reset();
    while ((c = sc_getopt(argc, argv, "+p:f:D:h", longs)) != -1) {
        switch (c) {
        case 'p':
            if (sc_prec_parse(optarg, &o->prec) < 0) {
                sc_error("eval: unknown precision '%s' (double, highp, mediump, lowp)", optarg);
                return SC_EXIT_USAGE;
            }
            break;
        case 'f':
            if (parse_format(optarg, &o->format) != SC_EXIT_OK)
                return SC_EXIT_USAGE;
            break;
        case 'D':
            if (n_defines <= MAX_DEFINES)
                defines[n_defines++] = optarg;
            break;
        case 'x': o->hex = 1; break;
        case 'u': o->ulp = 1; break;
        case 's': o->strict = 1; break;
        case 'F': o->file = optarg; break;
        case 'I':
            if (sc_parse_long(optarg, &o->max_iterations) < 0 || o->max_iterations < 1) {
                sc_error("eval: --max-iterations '%s': expected a positive integer", optarg);
                return SC_EXIT_USAGE;
            }
            break;
        case 'h': usage(stdout); return -1;
        default: return sc_usage_error("eval", argv, optopt);
        }
    }
    /* Definitions are evaluated after every option is known (the precision above all). */
    for (int i = 0; i < n_defines; i++) {
        int status = add_define(d, defines[i], o);
        if (status != SC_EXIT_OK)
            return status;
    }
    return SC_EXIT_OK;
}

/* Expressions given as arguments: all compiled (and the csv header chosen) before any output. */
static int run_list(const expression_list *list, const define_set *d, const eval_options *o)
{
    sc_program **progs = calloc((size_t)list->count + 1, sizeof *progs);
    sc_ltype *types = calloc((size_t)list->count + 1, sizeof *types);
    int status = progs && types ? SC_EXIT_OK : SC_EXIT_RUNTIME, mixed = 0, width = 0;
    char where[32] = "";
    for (int i = 0; i < list->count && status == SC_EXIT_OK; i++) {
        if (list->count > 1)
            snprintf(where, sizeof where, "expression %d: ", i + 1);
        progs[i] = compile(list->src[i], d, o, where);
        status = progs[i] ? SC_EXIT_OK : SC_EXIT_USAGE;
        if (progs[i]) {
            types[i] = result_type(progs[i]);
            mixed |= !same_type(types[i], types[0]);
            width = sc_ltype_size(types[i]) > width ? sc_ltype_size(types[i]) : width;
        }
    }
    if (status == SC_EXIT_OK && o->format == FMT_CSV && list->count > 0)
        print_csv_header(stdout, types, list->count, o);
    for (int i = 0; i < list->count && status == SC_EXIT_OK; i++) {
        sc_lvalue v, ref;
        if (list->count > 1)
            snprintf(where, sizeof where, "expression %d: ", i + 1);
        status = evaluate(progs[i], d, o, where, &v, &ref);
        if (status != SC_EXIT_OK)
            break;
        print_result(list->src[i], &v, &ref, o, mixed, width);
    }
    for (int i = 0; progs && i < list->count; i++)
        sc_program_free(progs[i]);
    free(progs);
    free(types);
    return status;
}

/* ---- standard input, streamed ---- */

/* csv from standard input: the header is the first result's type, and later lines must have
 * it too (the input is not held to look ahead). */
typedef struct {
    int printed;
    sc_ltype type;
} csv_header;

/* One line of standard input: compiled, evaluated and printed. Status as the command's. */
static int run_line(const char *src, const char *where, const define_set *d, const eval_options *o,
                    csv_header *header)
{
    sc_program *prog = compile(src, d, o, where);
    if (!prog)
        return SC_EXIT_USAGE;
    sc_ltype t = result_type(prog);
    sc_lvalue v, ref;
    int status = SC_EXIT_OK;
    char tb[16], hb[16];
    if (o->format == FMT_CSV && header->printed && !same_type(t, header->type)) {
        sc_error("%sa %s in csv under the header of a %s (the first line's type): give "
                 "expressions of one type, or several as arguments",
                 where, sc_ltype_name(t, tb, sizeof tb),
                 sc_ltype_name(header->type, hb, sizeof hb));
        status = SC_EXIT_USAGE;
    } else {
        status = evaluate(prog, d, o, where, &v, &ref);
    }
    if (status == SC_EXIT_OK && o->format == FMT_CSV && !header->printed) {
        print_csv_header(stdout, &t, 1, o);
        *header = (csv_header){1, t};
    }
    if (status == SC_EXIT_OK)
        print_result(src, &v, &ref, o, 0, sc_ltype_size(t));
    sc_program_free(prog);
    return status;
}

/* Results reach a reader on a pipe or a terminal line by line, not when a buffer fills. */
static void flush_lines_if_interactive(void)
{
    struct stat st;
    if (isatty(STDOUT_FILENO) ||
        (fstat(STDOUT_FILENO, &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode))))
        setvbuf(stdout, NULL, _IOLBF, 0);
}

/* The worse of two statuses: a bad line (USAGE) over a failed evaluation (RUNTIME). */
static int worse(int a, int b) { return a > b ? a : b; }

/* Expressions from standard input, one per line, each printed when computed: a bad line is
 * reported with its number and the rest go on. Constant memory: one line at a time, of at most
 * MAX_LINE bytes (a longer line stops the reading). */
static int blank_or_comment(const char *line)
{
    const char *text = line + strspn(line, " \t");
    return *text == '\0' || *text == '#';
}

static int run_stdin(const define_set *d, const eval_options *o)
{
    enum { MAX_LINE = 1 << 20 };
    line_reader r;
    if (line_reader_init(&r, stdin, MAX_LINE, 0) < 0) {
        sc_error("eval: out of memory");
        return SC_EXIT_RUNTIME;
    }
    flush_lines_if_interactive();
    csv_header header = {0, {SC_KIND_FLOAT, 1, 1}};
    int status = SC_EXIT_OK;
    line_status ls;
    while ((ls = line_reader_next(&r)) != LINE_END) {
        char where[32];
        snprintf(where, sizeof where, "line %ld: ", r.number);
        if (ls != LINE_OK)
            status = worse(status, line_reader_report(&r, ls, "eval: standard input", where));
        else if (!blank_or_comment(r.line))
            status = worse(status, run_line(r.line, where, d, o, &header));
        if (ls != LINE_OK && ls != LINE_HAS_NUL) /* the rest of the input is lost */
            break;
        if (ferror(stdout)) { /* nobody reads the results: stop, however long the input */
            sc_error("eval: standard output: write error");
            status = worse(status, SC_EXIT_RUNTIME);
            break;
        }
    }
    line_reader_free(&r);
    return status;
}

/* --file: no expression arguments, no --ulp (a program's control flow may differ between the
 * precision and the double reference, so values cannot be paired). */
static int run_file(const eval_options *o, const define_set *d, int n_expressions)
{
    if (n_expressions > 0) {
        sc_error("eval: --file takes no expression arguments");
        return SC_EXIT_USAGE;
    }
    if (o->ulp) {
        sc_error("eval: --ulp is not supported with --file");
        return SC_EXIT_USAGE;
    }
    eval_file_options fo = {o->prec, o->format, o->hex, o->strict, o->max_iterations};
    return sc_eval_file(o->file, d->inputs, d->values, d->n, &fo);
}

static int run(int argc, char **argv)
{
    eval_options o = {.prec = SC_HIGHP, .format = FMT_GLSL};
    define_set d = {.n = 0};
    int status = parse_options(argc, argv, &o, &d);
    if (status != SC_EXIT_OK)
        return status < 0 ? SC_EXIT_OK : status;
    expression_list list = {argv + optind, argc - optind};
    if (o.file)
        return run_file(&o, &d, list.count);
    return list.count ? run_list(&list, &d, &o) : run_stdin(&d, &o);
}

const sc_command sc_cmd_eval = {"eval", "evaluate GLSL ES expressions in a chosen precision", run};
