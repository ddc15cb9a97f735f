/* shadecalc sweep EXPR: a GLSL ES program of the sweep variables (floats), compiled once as
 * `shadecalc eval` compiles an expression and run over the rows in blocks (sc_program_run_block:
 * each instruction dispatched once per block of rows). */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/eval_file.h"
#include "cli/sweep_cli.h"
#include "shadecalc/lang.h"

/* Rows handed to the program at once: its inputs and results as columns on the stack. */
enum { CHUNK = 256 };

/* Arguments outside a built-in's GLSL ES domain, counted per worker (one example kept). */
typedef struct {
    unsigned long long count;
    int line, column;
    const char *func, *rule;
} domain_tally;

typedef struct {
    sc_program *prog;
    sc_prec prec;
    int n_vars, n_results, value, threads;
    domain_tally *tally; /* one per worker */
    char names[SWEEP_MAX_RESULTS][24];
} expr_plan;

static void record_domain(void *user, long element, int line, int column, const char *func,
                          const char *rule)
{
    domain_tally *t = user;
    (void)element;
    if (t->count++ == 0) {
        t->line = line;
        t->column = column;
        t->func = func;
        t->rule = rule;
    }
}

/* Rows [0, count) (count <= CHUNK) through the program: variables and results row after row. */
static long eval_chunk(const expr_plan *e, int worker, int count, const double *vars,
                       double *results, sc_lang_error *err)
{
    double in[SC_SWEEP_MAX_VARS][CHUNK], out[SWEEP_MAX_RESULTS][CHUNK];
    const double *in_cols[SC_SWEEP_MAX_VARS];
    double *out_cols[SWEEP_MAX_RESULTS];
    for (int k = 0; k < e->n_vars; k++) {
        for (int i = 0; i < count; i++)
            in[k][i] = vars[(size_t)i * (size_t)e->n_vars + (size_t)k];
        in_cols[k] = in[k];
    }
    for (int k = 0; k < e->n_results; k++)
        out_cols[k] = out[k];
    sc_lang_block job = {e->prec,  count,         in_cols,          e->value,
                         out_cols, record_domain, &e->tally[worker]};
    long done = sc_program_run_block(e->prog, &job, err);
    for (long i = 0; i < done; i++)
        for (int k = 0; k < e->n_results; k++)
            results[i * e->n_results + k] = out[k][i];
    return done;
}

static int eval_rows(void *user, int worker, int count, const double *vars, double *results,
                     int *failure, char *err, size_t errsize)
{
    *failure = -1; /* a failure of the program's evaluation is a run-time one */
    const expr_plan *e = user;
    for (int first = 0; first < count; first += CHUNK) {
        int n = count - first < CHUNK ? count - first : CHUNK;
        sc_lang_error error;
        long done = eval_chunk(e, worker, n, vars + (size_t)first * (size_t)e->n_vars,
                               results + (size_t)first * (size_t)e->n_results, &error);
        if (done < n) {
            snprintf(err, errsize, "column %d: %s", error.column, error.message);
            return first + (int)done;
        }
    }
    return count;
}

static void report(void *user)
{
    const expr_plan *e = user;
    unsigned long long total = 0;
    const domain_tally *example = NULL;
    for (int w = 0; w < e->threads; w++) {
        total += e->tally[w].count;
        example = !example && e->tally[w].count ? &e->tally[w] : example;
    }
    if (example)
        sc_warning("sweep: %llu evaluation%s outside the GLSL ES domain or undefined (e.g. column "
                   "%d: %s: %s); the results are the IEEE values of the formulas",
                   total, total == 1 ? " was" : "s were", example->column, example->func,
                   example->rule);
}

static void destroy(void *user)
{
    expr_plan *e = user;
    sc_program_free(e->prog);
    free(e->tally);
    free(e);
}

static int is_word_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* Whether identifier `name` occurs in src as a word (not after a '.', where it is a swizzle). */
static int mentions(const char *src, const char *name)
{
    size_t len = strlen(name);
    for (const char *p = strstr(src, name); p; p = strstr(p + 1, name)) {
        char before = p > src ? p[-1] : ' ';
        if (!is_word_char(before) && before != '.' && !is_word_char(p[len]))
            return 1;
    }
    return 0;
}

/* Compiles src; the result it prints must be a float, vector or matrix. An exit status. */
static int compile(expr_plan *e, const char *src, const sc_sweep_grid *g)
{
    sc_lang_input inputs[SC_SWEEP_MAX_VARS];
    for (int k = 0; k < g->n; k++)
        inputs[k] = (sc_lang_input){g->var[k].name, {SC_KIND_FLOAT, 1, 1}};
    sc_lang_error error;
    e->prog = sc_program_compile(src, inputs, g->n, NULL, &error);
    if (!e->prog) {
        sc_error("sweep: '%s': column %d: %s", src, error.column, error.message);
        return SC_EXIT_USAGE;
    }
    char tb[16];
    int values = sc_program_values(e->prog);
    if (values == 0) {
        sc_error("sweep: '%s': no expression to evaluate (the last statement must be an "
                 "expression)",
                 src);
        return SC_EXIT_USAGE;
    }
    sc_ltype t = sc_program_value_type(e->prog, values - 1);
    if (t.kind != SC_KIND_FLOAT) {
        sc_error("sweep: '%s' is of type %s: the result columns are floats (convert it: "
                 "float(...), vec2(...) ...)",
                 src, sc_ltype_name(t, tb, sizeof tb));
        return SC_EXIT_USAGE;
    }
    e->value = values - 1;
    e->n_results = sc_ltype_size(t);
    for (int k = 0; k < e->n_results; k++)
        sc_value_column_name(e->names[k], sizeof e->names[k], t, k);
    return SC_EXIT_OK;
}

int sweep_expr_plan(const char *src, const sc_sweep_grid *g, sc_prec p, int threads,
                    sweep_plan *plan)
{
    expr_plan *e = calloc(1, sizeof *e);
    if (e)
        e->tally = calloc((size_t)threads, sizeof *e->tally);
    if (!e || !e->tally) {
        free(e);
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    e->prec = p;
    e->n_vars = g->n;
    e->threads = threads;
    int status = compile(e, src, g);
    if (status != SC_EXIT_OK) {
        destroy(e);
        return status;
    }
    plan->n_results = e->n_results;
    for (int k = 0; k < plan->n_results; k++)
        plan->columns[k] = e->names[k];
    for (int k = 0; k < g->n; k++)
        plan->unused |= (unsigned)!mentions(src, g->var[k].name) << k;
    plan->eval_block = eval_rows;
    plan->user = e;
    plan->report = report;
    plan->destroy = destroy;
    snprintf(plan->title, sizeof plan->title, "%s", src);
    plan->ylabel = NULL; /* the title says it */
    return SC_EXIT_OK;
}
