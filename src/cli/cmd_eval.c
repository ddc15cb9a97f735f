/* shadecalc eval — GLSL ES expressions evaluated from the shell in a chosen precision. */
#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/eval_file.h"
#include "cli/line_reader.h"
#include "shadecalc/expr.h"

enum { MAX_DEFINES = 32, MAX_HITS = 8 };

typedef struct {
    sc_prec prec;
    int format;
    int hex, ulp, strict;
    const char *file;    /* --file, or NULL */
    long max_iterations; /* --max-iterations */
} eval_options;

/* -D NAME=EXPR: its value in the chosen precision and in the double reference. */
typedef struct {
    char name[64];
    sc_value value, reference;
} define;

typedef struct {
    define defs[MAX_DEFINES];
    sc_expr_input inputs[MAX_DEFINES];
    sc_value values[MAX_DEFINES], references[MAX_DEFINES];
    int n;
} define_set;

/* The domain errors of one evaluation, each (column, rule) once. */
typedef struct {
    struct {
        int column;
        const char *func, *rule;
    } hit[MAX_HITS];
    int n;
} domain_hits;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc eval [OPTIONS] EXPR...\n"
            "       shadecalc eval [OPTIONS] --file F\n"
            "\n"
            "Evaluates GLSL ES expressions (one result line each; with no EXPR, one expression\n"
            "per line of standard input). Statements 'NAME = EXPR;' may precede the expression.\n"
            "\n"
            "  -p, --precision P   double|highp|mediump|lowp (default highp)\n"
            "  -f, --format F      glsl|csv|jsonl (default glsl; jsonl: JSON Lines, one\n"
            "                      object per line, also called json; csv: an expression\n"
            "                      column, then the components)\n"
            "  -D, --define N=EXPR define variable N for every expression (repeatable)\n"
            "      --hex           print bit patterns of the precision instead of decimals\n"
            "      --ulp           also print the error against the double reference, in ULP\n"
            "      --strict        an argument outside a built-in's GLSL ES domain is an error\n"
            "      --file F        run the GLSL ES program in file F ('-': standard input),\n"
            "                      printing each top-level expression statement's value\n"
            "      --max-iterations N  loop iterations a --file run may execute (10000000)\n"
            "  -h, --help          this help\n"
            "\n"
            "example: shadecalc eval 'normalize(vec3(3,0,4))'   ->   vec3(0.6, 0, 0.8)\n");
}

/* ---- domain reporting ---- */

static void record_domain(void *user, int column, const char *func, const char *rule)
{
    domain_hits *h = user;
    for (int i = 0; i < h->n; i++)
        if (h->hit[i].column == column && strcmp(h->hit[i].rule, rule) == 0)
            return;
    if (h->n < MAX_HITS) {
        h->hit[h->n].column = column;
        h->hit[h->n].func = func;
        h->hit[h->n].rule = rule;
        h->n++;
    }
}

/* Prints the domain errors; returns 1 if they are fatal (--strict). */
static int report_domain(const domain_hits *h, const char *where, int strict)
{
    for (int i = 0; i < h->n; i++) {
        if (strict)
            sc_error("%scolumn %d: %s: %s is outside the GLSL ES domain (--strict)", where,
                     h->hit[i].column, h->hit[i].func, h->hit[i].rule);
        else
            sc_warning("%scolumn %d: %s: %s is outside the GLSL ES domain; the result is the "
                       "IEEE value of its formula",
                       where, h->hit[i].column, h->hit[i].func, h->hit[i].rule);
    }
    return strict && h->n > 0;
}

/* ---- evaluation ---- */

/* Compiles src against the defines; prints the error (prefixed with `where`) on failure. */
static sc_expr *compile(const char *src, const define_set *d, const char *where)
{
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, d->inputs, d->n, &err);
    if (!e)
        sc_error("%scolumn %d: %s", where, err.column, err.message);
    return e;
}

/* Evaluates e in the chosen precision (and in double when --ulp); status as the command's. */
static int evaluate(const sc_expr *e, const define_set *d, const eval_options *o, const char *where,
                    sc_value *value, sc_value *reference)
{
    domain_hits hits = {.n = 0};
    *value = sc_expr_eval(e, o->prec, d->values, record_domain, &hits);
    if (o->ulp)
        *reference = sc_expr_eval(e, SC_DOUBLE, d->references, NULL, NULL);
    return report_domain(&hits, where, o->strict) ? SC_EXIT_RUNTIME : SC_EXIT_OK;
}

static int add_define(define_set *d, const char *arg, const eval_options *o)
{
    const char *eq = strchr(arg, '=');
    size_t len = eq ? (size_t)(eq - arg) : 0;
    if (!eq || len == 0 || len >= sizeof d->defs[0].name) {
        sc_error("eval: -D '%s': expected NAME=EXPR", arg);
        return SC_EXIT_USAGE;
    }
    if (d->n == MAX_DEFINES) {
        sc_error("eval: too many -D definitions (at most %d)", MAX_DEFINES);
        return SC_EXIT_USAGE;
    }
    char where[96];
    snprintf(where, sizeof where, "-D '%.*s': ", (int)len, arg);
    sc_expr *e = compile(eq + 1, d, where);
    if (!e)
        return SC_EXIT_USAGE;
    define *def = &d->defs[d->n];
    memcpy(def->name, arg, len);
    def->name[len] = '\0';
    eval_options both = *o;
    both.ulp = 1;
    int status = evaluate(e, d, &both, where, &d->values[d->n], &d->references[d->n]);
    d->inputs[d->n] = (sc_expr_input){def->name, sc_expr_result_type(e)};
    sc_expr_free(e);
    if (status == SC_EXIT_OK)
        d->n++;
    return status;
}

/* ---- output ---- */

static void print_number(FILE *out, double x, const eval_options *o, int json)
{
    sc_print_float(out, x, o->prec, o->hex, json);
}

static double ulp_of(const eval_options *o, const sc_value *v, const sc_value *ref, int k)
{
    return sc_ulp_error(o->prec, v->v[k], ref->v[k]);
}

static void print_ulps(FILE *out, const sc_value *v, const sc_value *ref, const eval_options *o,
                       const char *sep)
{
    for (int k = 0; k < sc_type_size(v->type); k++)
        fprintf(out, "%s%.3g", k ? sep : "", ulp_of(o, v, ref, k));
}

static void print_glsl(FILE *out, const sc_value *v, const sc_value *ref, const eval_options *o)
{
    int n = sc_type_size(v->type);
    if (v->type != SC_FLOAT)
        fprintf(out, "%s(", sc_type_name(v->type));
    for (int k = 0; k < n; k++) {
        fputs(k ? ", " : "", out);
        print_number(out, v->v[k], o, 0);
    }
    fputs(v->type != SC_FLOAT ? ")" : "", out);
    if (o->ulp) {
        fputs("  # ulp: ", out);
        print_ulps(out, v, ref, o, ", ");
    }
    fputc('\n', out);
}

static void print_json(FILE *out, const char *src, const sc_value *v, const sc_value *ref,
                       const eval_options *o)
{
    int n = sc_type_size(v->type);
    fputs("{\"expression\": ", out);
    sc_print_json_string(out, src);
    fprintf(out, ", \"precision\": \"%s\", \"type\": \"%s\", \"%s\": ", sc_prec_name(o->prec),
            sc_type_name(v->type), o->hex ? "bits" : "value");
    fputs(n > 1 ? "[" : "", out);
    for (int k = 0; k < n; k++) {
        fputs(k ? ", " : "", out);
        print_number(out, v->v[k], o, 1);
    }
    fputs(n > 1 ? "]" : "", out);
    if (o->ulp) {
        fprintf(out, ", \"ulp\": %s", n > 1 ? "[" : "");
        print_ulps(out, v, ref, o, ", ");
        fputs(n > 1 ? "]" : "", out);
    }
    fputs("}\n", out);
}

/* CSV column k of a value of type t: value | x y z w | c0r0 c0r1 ... (column-major). */
static void csv_column_name(FILE *out, sc_type t, int k)
{
    int n = sc_type_matrix_n(t);
    if (t == SC_FLOAT)
        fputs("value", out);
    else if (n)
        fprintf(out, "c%dr%d", k / n, k % n);
    else
        fputc("xyzw"[k], out);
}

/* One header for all rows: the expression, then named components when every result has the
 * same type, else `type,c0..cN` padded with empty fields. */
static void print_csv_header(FILE *out, const sc_type *types, int count, const eval_options *o)
{
    int mixed = 0, width = 0;
    for (int i = 0; i < count; i++) {
        mixed |= types[i] != types[0];
        if (sc_type_size(types[i]) > width)
            width = sc_type_size(types[i]);
    }
    fputs(mixed ? "expression,type" : "expression", out);
    for (int pass = 0; pass < 1 + o->ulp; pass++)
        for (int k = 0; k < width; k++) {
            fputc(',', out);
            if (mixed)
                fprintf(out, "c%d", k);
            else
                csv_column_name(out, types[0], k);
            fputs(pass ? "_ulp" : "", out);
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

static void print_csv(FILE *out, const char *src, const sc_value *v, const sc_value *ref,
                      const eval_options *o, int mixed, int width)
{
    int n = sc_type_size(v->type);
    sc_print_csv_field(out, src);
    if (mixed)
        fprintf(out, ",%s", sc_type_name(v->type));
    for (int k = 0; k < width; k++) {
        fputc(',', out);
        if (k < n)
            print_number(out, v->v[k], o, 0);
    }
    for (int k = 0; o->ulp && k < width; k++) {
        fputc(',', out);
        if (k < n)
            fprintf(out, "%.3g", ulp_of(o, v, ref, k));
    }
    fputc('\n', out);
}

/* One result line in the chosen format (csv: `mixed` and `width` as the header's). */
static void print_result(const char *src, const sc_value *v, const sc_value *ref,
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
    sc_expr **progs = calloc((size_t)list->count + 1, sizeof *progs);
    sc_type *types = calloc((size_t)list->count + 1, sizeof *types);
    int status = progs && types ? SC_EXIT_OK : SC_EXIT_RUNTIME, mixed = 0, width = 0;
    char where[32] = "";
    for (int i = 0; i < list->count && status == SC_EXIT_OK; i++) {
        if (list->count > 1)
            snprintf(where, sizeof where, "expression %d: ", i + 1);
        progs[i] = compile(list->src[i], d, where);
        status = progs[i] ? SC_EXIT_OK : SC_EXIT_USAGE;
        if (progs[i]) {
            types[i] = sc_expr_result_type(progs[i]);
            mixed |= types[i] != types[0];
            width = sc_type_size(types[i]) > width ? sc_type_size(types[i]) : width;
        }
    }
    if (status == SC_EXIT_OK && o->format == FMT_CSV && list->count > 0)
        print_csv_header(stdout, types, list->count, o);
    for (int i = 0; i < list->count && status == SC_EXIT_OK; i++) {
        sc_value v, ref;
        if (list->count > 1)
            snprintf(where, sizeof where, "expression %d: ", i + 1);
        status = evaluate(progs[i], d, o, where, &v, &ref);
        if (status != SC_EXIT_OK)
            break;
        print_result(list->src[i], &v, &ref, o, mixed, width);
    }
    for (int i = 0; progs && i < list->count; i++)
        sc_expr_free(progs[i]);
    free(progs);
    free(types);
    return status;
}

/* ---- standard input, streamed ---- */

/* csv from standard input: the header is the first result's type, and later lines must have
 * it too (the input is not held to look ahead). */
typedef struct {
    int printed;
    sc_type type;
} csv_header;

/* One line of standard input: compiled, evaluated and printed. Status as the command's. */
static int run_line(const char *src, const char *where, const define_set *d, const eval_options *o,
                    csv_header *header)
{
    sc_expr *e = compile(src, d, where);
    if (!e)
        return SC_EXIT_USAGE;
    sc_type t = sc_expr_result_type(e);
    sc_value v, ref;
    int status = SC_EXIT_OK;
    if (o->format == FMT_CSV && header->printed && t != header->type) {
        sc_error("%sa %s in csv under the header of a %s (the first line's type): give "
                 "expressions of one type, or several as arguments",
                 where, sc_type_name(t), sc_type_name(header->type));
        status = SC_EXIT_USAGE;
    } else {
        status = evaluate(e, d, o, where, &v, &ref);
    }
    if (status == SC_EXIT_OK && o->format == FMT_CSV && !header->printed) {
        print_csv_header(stdout, &t, 1, o);
        *header = (csv_header){1, t};
    }
    if (status == SC_EXIT_OK)
        print_result(src, &v, &ref, o, 0, sc_type_size(t));
    sc_expr_free(e);
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
    csv_header header = {0, SC_FLOAT};
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
