/* shadecalc sweep EXPR: a GLSL ES expression of the sweep variables, evaluated per row as
 * `shadecalc eval` evaluates it. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/sweep_cli.h"
#include "shadecalc/expr.h"

/* Arguments outside a built-in's GLSL ES domain, counted per worker (one example kept). */
typedef struct {
    unsigned long long count;
    int column;
    const char *func, *rule;
} domain_tally;

typedef struct {
    sc_expr *expr;
    sc_prec prec;
    int n_vars, threads;
    domain_tally *tally; /* one per worker */
    char names[SWEEP_MAX_RESULTS][24];
} expr_plan;

static void record_domain(void *user, int column, const char *func, const char *rule)
{
    domain_tally *t = user;
    if (t->count++ == 0) {
        t->column = column;
        t->func = func;
        t->rule = rule;
    }
}

static int eval_row(void *user, int worker, const double *vars, double *results, char *err,
                    size_t errsize)
{
    (void)err;
    (void)errsize;
    const expr_plan *e = user;
    sc_value in[SC_SWEEP_MAX_VARS];
    for (int k = 0; k < e->n_vars; k++)
        in[k] = (sc_value){SC_FLOAT, {vars[k]}};
    sc_value v = sc_expr_eval(e->expr, e->prec, in, record_domain, &e->tally[worker]);
    memcpy(results, v.v, (size_t)sc_type_size(v.type) * sizeof *results);
    return 0;
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
        sc_warning("sweep: %llu evaluation%s outside the GLSL ES domain (e.g. column %d: %s: %s); "
                   "the results are the IEEE values of the formulas",
                   total, total == 1 ? " was" : "s were", example->column, example->func,
                   example->rule);
}

static void destroy(void *user)
{
    expr_plan *e = user;
    sc_expr_free(e->expr);
    free(e->tally);
    free(e);
}

/* Column k of a result of type t: value | x y z w | c0r0 c0r1 ... (column-major). */
static void column_name(char *buf, size_t size, sc_type t, int k)
{
    int n = sc_type_matrix_n(t);
    if (t == SC_FLOAT)
        snprintf(buf, size, "value");
    else if (n)
        snprintf(buf, size, "c%dr%d", k / n, k % n);
    else
        snprintf(buf, size, "%c", "xyzw"[k]);
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

int sweep_expr_plan(const char *src, const sc_sweep_grid *g, sc_prec p, int threads,
                    sweep_plan *plan)
{
    sc_expr_input inputs[SC_SWEEP_MAX_VARS];
    for (int k = 0; k < g->n; k++)
        inputs[k] = (sc_expr_input){g->var[k].name, SC_FLOAT};
    sc_expr_error error;
    expr_plan *e = calloc(1, sizeof *e);
    if (e)
        e->tally = calloc((size_t)threads, sizeof *e->tally);
    if (!e || !e->tally) {
        free(e);
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    e->expr = sc_expr_compile(src, inputs, g->n, &error);
    e->prec = p;
    e->n_vars = g->n;
    e->threads = threads;
    if (!e->expr) {
        sc_error("sweep: '%s': column %d: %s", src, error.column, error.message);
        destroy(e);
        return SC_EXIT_USAGE;
    }
    sc_type t = sc_expr_result_type(e->expr);
    plan->n_results = sc_type_size(t);
    for (int k = 0; k < plan->n_results; k++) {
        column_name(e->names[k], sizeof e->names[k], t, k);
        plan->columns[k] = e->names[k];
    }
    for (int k = 0; k < g->n; k++)
        plan->unused |= (unsigned)!mentions(src, g->var[k].name) << k;
    plan->eval = eval_row;
    plan->user = e;
    plan->report = report;
    plan->destroy = destroy;
    snprintf(plan->title, sizeof plan->title, "%s", src);
    plan->ylabel = NULL; /* the title says it */
    return SC_EXIT_OK;
}
