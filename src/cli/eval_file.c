/* shadecalc eval --file F: the program is compiled whole (a syntax or type error is reported as
 * F:LINE:COLUMN, exit status 2), then run; each top-level expression's value is printed when
 * the run reaches it (a runtime error, F:LINE:COLUMN, exit status 1). */
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/eval_file.h"

enum { MAX_SOURCE = 16 << 20 };

/* The whole of `in`, NUL-terminated; NULL with a message if unreadable, too long or binary. */
static char *read_source(FILE *in, const char *name)
{
    size_t len = 0, cap = 4096;
    char *buf = malloc(cap);
    while (buf) {
        if (len + 1 >= cap) {
            char *bigger = cap >= MAX_SOURCE ? NULL : realloc(buf, cap * 2);
            if (!bigger) {
                sc_error("eval: %s: %s", name,
                         cap >= MAX_SOURCE ? "longer than 16 MiB" : "out of memory");
                break;
            }
            buf = bigger, cap *= 2;
        }
        size_t got = fread(buf + len, 1, cap - 1 - len, in);
        len += got;
        if (got == 0 && ferror(in)) {
            sc_error("eval: %s: read error", name);
            break;
        }
        if (got == 0) {
            buf[len] = '\0';
            if (strlen(buf) == len)
                return buf;
            sc_error("eval: %s: contains a NUL byte (not a text file)", name);
            break;
        }
    }
    free(buf);
    return NULL;
}

/* ---- one run ---- */

typedef struct {
    const eval_file_options *o;
    const char *name;
    domain_hits hits;
    int header_printed;
    sc_ltype header_type;
    int status;
} file_run;

void domain_hits_record(domain_hits *h, int line, int column, const char *func, const char *rule)
{
    for (int i = 0; i < h->n; i++)
        if (h->hit[i].line == line && h->hit[i].column == column &&
            strcmp(h->hit[i].rule, rule) == 0)
            return;
    if (h->n < DOMAIN_MAX_HITS) {
        h->hit[h->n].line = line;
        h->hit[h->n].column = column;
        h->hit[h->n].func = func;
        h->hit[h->n].rule = rule;
        h->n++;
    }
}

static void record_domain(void *user, int line, int column, const char *func, const char *rule)
{
    file_run *run = user;
    domain_hits_record(&run->hits, line, column, func, rule);
}

void sc_report_domain_hit(const char *at, const char *func, const char *rule, int strict)
{
    if (strict)
        sc_error("%s: %s: %s is outside the GLSL ES domain (--strict)", at, func, rule);
    else if (strncmp(func, "operator", 8) == 0)
        sc_warning("%s: %s: %s is undefined in GLSL ES; the result is shadecalc's (man page, "
                   "EVAL FILES)",
                   at, func, rule);
    else
        sc_warning("%s: %s: %s is outside the GLSL ES domain; the result is the IEEE value of "
                   "its formula",
                   at, func, rule);
}

/* Reports the domain errors since the last value; 1 if they are fatal (--strict). */
static int report_domain(file_run *run)
{
    const domain_hits *h = &run->hits;
    for (int i = 0; i < h->n; i++) {
        char at[1100];
        snprintf(at, sizeof at, "%.1024s:%d:%d", run->name, h->hit[i].line, h->hit[i].column);
        sc_report_domain_hit(at, h->hit[i].func, h->hit[i].rule, run->o->strict);
    }
    int fatal = run->o->strict && h->n > 0;
    run->hits.n = 0;
    return fatal;
}

/* ---- printing ---- */

void sc_print_component(FILE *out, double x, sc_kind kind, sc_prec p, int hex, int json)
{
    if (kind == SC_KIND_BOOL) {
        fputs(x != 0.0 ? "true" : "false", out);
        return;
    }
    if (kind != SC_KIND_FLOAT) {
        int bits = sc_int_bits(p);
        unsigned long long u = (unsigned long long)(long long)x & ((1ULL << bits) - 1);
        if (hex)
            fprintf(out, json ? "\"0x%0*llx\"" : "0x%0*llx", (bits + 3) / 4, u);
        else
            fprintf(out, "%.0f", x);
        return;
    }
    sc_print_float(out, x, p, hex, json);
}

void sc_value_column_name(char *buf, size_t size, sc_ltype t, int k)
{
    if (sc_ltype_size(t) == 1)
        snprintf(buf, size, "value");
    else if (t.cols == 1)
        snprintf(buf, size, "%c", "xyzw"[k]);
    else
        snprintf(buf, size, "c%dr%d", k / t.rows, k % t.rows);
}

void sc_print_float(FILE *out, double x, sc_prec p, int hex, int json)
{
    char buf[64];
    if (hex)
        sc_format_bits(buf, sizeof buf, x, p);
    else
        sc_format_shortest(buf, sizeof buf, x, p);
    int quoted = json && (hex || x != x || x - x != 0.0); /* JSON has no NaN or Inf */
    fprintf(out, quoted ? "\"%s\"" : "%s", buf);
}

static void print_components(FILE *out, const file_run *run, const sc_lvalue *v, const char *sep,
                             int json)
{
    for (int k = 0; k < sc_ltype_size(v->type); k++) {
        fputs(k ? sep : "", out);
        sc_print_component(out, v->v[k], (sc_kind)v->type.kind, run->o->prec, run->o->hex, json);
    }
}

static void print_glsl(const file_run *run, const sc_lvalue *v)
{
    char tb[16];
    int scalar = sc_ltype_size(v->type) == 1;
    if (!scalar)
        printf("%s(", sc_ltype_name(v->type, tb, sizeof tb));
    print_components(stdout, run, v, ", ", 0);
    puts(scalar ? "" : ")");
}

static void print_json(const file_run *run, const char *text, int line, const sc_lvalue *v)
{
    char tb[16];
    int n = sc_ltype_size(v->type);
    fputs("{\"expression\": ", stdout);
    sc_print_json_string(stdout, text);
    printf(", \"line\": %d, \"precision\": \"%s\", \"type\": \"%s\", \"%s\": %s", line,
           sc_prec_name(run->o->prec), sc_ltype_name(v->type, tb, sizeof tb),
           run->o->hex ? "bits" : "value", n > 1 ? "[" : "");
    print_components(stdout, run, v, ", ", 1);
    puts(n > 1 ? "]}" : "}");
}

static void print_csv_header(sc_ltype t)
{
    char name[16];
    fputs("expression", stdout);
    for (int k = 0; k < sc_ltype_size(t); k++) {
        sc_value_column_name(name, sizeof name, t, k);
        printf(",%s", name);
    }
    fputc('\n', stdout);
}

static int print_csv(file_run *run, const char *text, int line, const sc_lvalue *v)
{
    char tb[16], hb[16];
    if (!run->header_printed) {
        print_csv_header(v->type);
        run->header_printed = 1;
        run->header_type = v->type;
    } else if (memcmp(&run->header_type, &v->type, sizeof v->type) != 0) {
        sc_error("%s:%d: a %s in csv under the header of a %s (the first value's type): print "
                 "values of one type",
                 run->name, line, sc_ltype_name(v->type, tb, sizeof tb),
                 sc_ltype_name(run->header_type, hb, sizeof hb));
        run->status = SC_EXIT_USAGE;
        return 1;
    }
    sc_print_csv_field(stdout, text);
    fputc(',', stdout);
    print_components(stdout, run, v, ",", 0);
    fputc('\n', stdout);
    return 0;
}

static int on_value(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    file_run *run = user;
    if (report_domain(run)) {
        run->status = SC_EXIT_RUNTIME;
        return 1;
    }
    char *src = malloc((size_t)len + 1);
    if (!src) {
        sc_error("eval: out of memory");
        run->status = SC_EXIT_RUNTIME;
        return 1;
    }
    memcpy(src, text, (size_t)len);
    src[len] = '\0';
    int stop = 0;
    if (run->o->format == FMT_GLSL)
        print_glsl(run, v);
    else if (run->o->format == FMT_JSON)
        print_json(run, src, line, v);
    else
        stop = print_csv(run, src, line, v);
    free(src);
    if (!stop && ferror(stdout)) {
        sc_error("eval: standard output: write error");
        run->status = SC_EXIT_RUNTIME;
        stop = 1;
    }
    return stop;
}

/* ---- the command ---- */

static int run_program(const sc_program *prog, const char *name, const sc_lvalue *inputs,
                       const eval_file_options *o)
{
    file_run run = {.o = o, .name = name, .status = SC_EXIT_OK};
    sc_lang_error err;
    int rc = sc_program_run(prog, o->prec, inputs, on_value, record_domain, &run, &err);
    if (rc < 0) {
        sc_error("%s:%d:%d: %s", name, err.line, err.column, err.message);
        return SC_EXIT_RUNTIME;
    }
    if (rc == 0 && report_domain(&run))
        return SC_EXIT_RUNTIME;
    return run.status;
}

int sc_eval_file(const char *path, const sc_lang_input *defines, const sc_lvalue *values,
                 int n_defines, const eval_file_options *o)
{
    int is_stdin = strcmp(path, "-") == 0;
    const char *name = is_stdin ? "<stdin>" : path;
    FILE *in = is_stdin ? stdin : fopen(path, "r");
    if (!in) {
        sc_error("eval: cannot open '%s'", path);
        return SC_EXIT_USAGE;
    }
    char *src = read_source(in, name);
    if (!is_stdin)
        fclose(in);
    if (!src)
        return SC_EXIT_USAGE;
    sc_lang_options options = {o->max_iterations, 0, 0};
    sc_lang_error err;
    sc_program *prog = sc_program_compile(src, defines, n_defines, &options, &err);
    free(src);
    if (!prog) {
        sc_error("%s:%d:%d: %s", name, err.line, err.column, err.message);
        return SC_EXIT_USAGE;
    }
    int status = run_program(prog, name, values, o);
    sc_program_free(prog);
    return status;
}
