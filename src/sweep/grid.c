/* Sweep variables and their cartesian grid (shadecalc/sweep.h). */
#include "shadecalc/sweep.h"
#include "sweep/sweep_internal.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_LIST = 1 << 20 };

size_t sc_sweep_identifier_length(const char *s)
{
    if (!isalpha((unsigned char)s[0]) && s[0] != '_')
        return 0;
    size_t n = 1;
    while (isalnum((unsigned char)s[n]) || s[n] == '_')
        n++;
    return n;
}

/* A finite number filling [s, end) exactly. */
static int parse_number(const char *s, const char *end, double *out)
{
    char buf[64];
    size_t len = (size_t)(end - s);
    if (len == 0 || len >= sizeof buf)
        return -1;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *stop;
    *out = strtod(buf, &stop);
    return *stop == '\0' && isfinite(*out) && !isspace((unsigned char)buf[0]) ? 0 : -1;
}

static int parse_range(const char *arg, const char *text, sc_sweep_var *v, char *err,
                       size_t errsize)
{
    const char *c1 = strchr(text, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    char *stop;
    errno = 0;
    long count = c2 ? strtol(c2 + 1, &stop, 10) : 0;
    if (!c2 || strchr(c2 + 1, ':') || parse_number(text, c1, &v->start) < 0 ||
        parse_number(c1 + 1, c2, &v->stop) < 0 || stop == c2 + 1 || *stop != '\0' ||
        errno == ERANGE || count < 1) {
        snprintf(err, errsize,
                 "--var %s: expected NAME=START:STOP:COUNT (finite numbers, "
                 "COUNT >= 1) or NAME=V1,V2,...",
                 arg);
        return -1;
    }
    v->count = count;
    v->spacing = SC_SPACING_LINEAR;
    return 0;
}

static int parse_list(const char *arg, const char *text, sc_sweep_var *v, char *err, size_t errsize)
{
    long n = 1;
    for (const char *p = text; *p; p++)
        n += *p == ',';
    if (n > MAX_LIST) {
        snprintf(err, errsize, "--var %.40s...: more than %d values", arg, MAX_LIST);
        return -1;
    }
    v->list = malloc((size_t)n * sizeof *v->list);
    if (!v->list) {
        snprintf(err, errsize, "--var: out of memory");
        return -1;
    }
    const char *p = text;
    for (long i = 0; i < n; i++) {
        const char *end = strchr(p, ',');
        end = end ? end : p + strlen(p);
        if (parse_number(p, end, &v->list[i]) < 0) {
            snprintf(err, errsize, "--var %s: '%.*s' is not a finite number", arg, (int)(end - p),
                     p);
            sc_sweep_var_free(v);
            return -1;
        }
        p = end + 1;
    }
    v->count = n;
    v->spacing = SC_SPACING_LIST;
    v->start = v->list[0];
    v->stop = v->list[n - 1];
    return 0;
}

int sc_sweep_var_parse(const char *arg, sc_sweep_var *out, char *err, size_t errsize)
{
    memset(out, 0, sizeof *out);
    size_t len = sc_sweep_identifier_length(arg);
    if (len == 0 || arg[len] != '=' || len >= SC_SWEEP_NAME_MAX) {
        snprintf(err, errsize,
                 "--var %s: expected NAME=... with NAME an identifier of at most "
                 "%d characters",
                 arg, SC_SWEEP_NAME_MAX - 1);
        return -1;
    }
    memcpy(out->name, arg, len);
    const char *text = arg + len + 1;
    return strchr(text, ':') ? parse_range(arg, text, out, err, errsize)
                             : parse_list(arg, text, out, err, errsize);
}

int sc_sweep_var_set_log(sc_sweep_var *v, char *err, size_t errsize)
{
    if (v->spacing == SC_SPACING_LIST) {
        snprintf(err, errsize, "--log: %s is a list, not a range START:STOP:COUNT", v->name);
        return -1;
    }
    if (!(v->start * v->stop > 0.0)) {
        snprintf(err, errsize,
                 "--log: %s=%g:%g: geometric spacing needs ends of the same sign, "
                 "not zero",
                 v->name, v->start, v->stop);
        return -1;
    }
    v->spacing = SC_SPACING_LOG;
    return 0;
}

double sc_sweep_var_value(const sc_sweep_var *v, long i)
{
    if (v->spacing == SC_SPACING_LIST)
        return v->list[i];
    if (i == 0 || v->count == 1)
        return v->start;
    if (i == v->count - 1)
        return v->stop;
    if (v->spacing == SC_SPACING_LOG) { /* evenly in log10, so that decades land exactly */
        double a = log10(fabs(v->start)), b = log10(fabs(v->stop));
        double x = pow(10.0, a + (b - a) * (double)i / (double)(v->count - 1));
        /* the rounding of log10 and pow must not step past an end (10^log10(DBL_MAX) is inf) */
        double lo = fmin(fabs(v->start), fabs(v->stop)), hi = fmax(fabs(v->start), fabs(v->stop));
        return copysign(fmin(fmax(x, lo), hi), v->start);
    }
    double steps = (double)(v->count - 1), span = v->stop - v->start;
    if (isfinite(span * steps)) /* span·i then one division: 0:1:11 gives 0.3, not 0.30…04 */
        return v->start + span * (double)i / steps;
    double t = (double)i / steps; /* ends near ±DBL_MAX */
    return v->start * (1.0 - t) + v->stop * t;
}

void sc_sweep_var_free(sc_sweep_var *v)
{
    free(v->list);
    v->list = NULL;
}

int sc_sweep_grid_add(sc_sweep_grid *g, sc_sweep_var *v, char *err, size_t errsize)
{
    const char *why = g->n == SC_SWEEP_MAX_VARS             ? "too many variables"
                      : sc_sweep_grid_find(g, v->name) >= 0 ? "given twice"
                                                            : NULL;
    if (why) {
        snprintf(err, errsize, "--var %s: %s (at most %d distinct names)", v->name, why,
                 SC_SWEEP_MAX_VARS);
        sc_sweep_var_free(v);
        return -1;
    }
    g->var[g->n++] = *v;
    v->list = NULL;
    return 0;
}

int sc_sweep_grid_find(const sc_sweep_grid *g, const char *name)
{
    for (int k = 0; k < g->n; k++)
        if (strcmp(g->var[k].name, name) == 0)
            return k;
    return -1;
}

uint64_t sc_sweep_grid_rows(const sc_sweep_grid *g)
{
    double rows = 1.0;
    for (int k = 0; k < g->n; k++)
        rows *= (double)g->var[k].count;
    return rows > SC_SWEEP_MAX_ROWS ? 0 : (uint64_t)rows;
}

void sc_sweep_grid_point(const sc_sweep_grid *g, uint64_t row, double *values)
{
    for (int k = 0; k < g->n; k++) {
        uint64_t count = (uint64_t)g->var[k].count;
        values[k] = sc_sweep_var_value(&g->var[k], (long)(row % count));
        row /= count;
    }
}

void sc_sweep_grid_free(sc_sweep_grid *g)
{
    for (int k = 0; k < g->n; k++)
        sc_sweep_var_free(&g->var[k]);
    g->n = 0;
}
