/* Rows of a sweep as CSV, TSV or JSON lines (shadecalc/sweep.h). */
#include "shadecalc/sweep.h"

#include <stdarg.h>
#include <string.h>

enum { NUMBER_MAX = 32 }; /* "-2.2250738585072014e-308" and the quotes of JSON */

int sc_sweep_format_parse(const char *name, sc_sweep_format *out)
{
    static const char *const names[] = {"csv", "tsv", "jsonl"};
    for (int i = 0; i < 3; i++)
        if (strcmp(name, names[i]) == 0) {
            *out = (sc_sweep_format)i;
            return 0;
        }
    return -1;
}

static char separator(const sc_sweep_table *t) { return t->format == SC_SWEEP_TSV ? '\t' : ','; }

int sc_sweep_write_header(FILE *out, const sc_sweep_table *t)
{
    if (t->format == SC_SWEEP_JSONL)
        return 0;
    for (int k = 0; k < t->n_vars + t->n_results; k++) {
        if (k)
            fputc(separator(t), out);
        fputs(t->names[k], out);
    }
    return fputc('\n', out) == EOF ? -1 : 0;
}

size_t sc_sweep_row_max(const sc_sweep_table *t)
{
    size_t max = 2;
    for (int k = 0; k < t->n_vars + t->n_results; k++)
        max += NUMBER_MAX + 2 + (t->format == SC_SWEEP_JSONL ? 2 * strlen(t->names[k]) + 6 : 0);
    return max;
}

/* Appends printf-style text at *n; -1 once it no longer fits. */
static int append(char *buf, size_t size, size_t *n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(buf + *n, size - *n, fmt, ap);
    va_end(ap);
    if (len < 0 || (size_t)len >= size - *n)
        return -1;
    *n += (size_t)len;
    return 0;
}

/* A JSON string of an identifier-like name: quotes and backslashes escaped, controls dropped. */
static int append_json_name(char *buf, size_t size, size_t *n, const char *name)
{
    int bad = append(buf, size, n, "\"");
    for (const char *p = name; *p && !bad; p++)
        if ((unsigned char)*p >= 0x20)
            bad = append(buf, size, n, *p == '"' || *p == '\\' ? "\\%c" : "%c", *p);
    return bad ? -1 : append(buf, size, n, "\": ");
}

/* Appends one character at *n; -1 once it no longer fits. */
static int append_char(char *buf, size_t size, size_t *n, char c)
{
    if (*n + 1 >= size)
        return -1;
    buf[(*n)++] = c;
    buf[*n] = '\0';
    return 0;
}

/* Appends the shortest decimal of x (sc_format_shortest) at *n; -1 once it no longer fits. */
static int append_number(char *buf, size_t size, size_t *n, double x, sc_prec p)
{
    int len = sc_format_shortest(buf + *n, size - *n, x, p);
    if (len < 0 || (size_t)len >= size - *n)
        return -1;
    *n += (size_t)len;
    return 0;
}

static int append_value(char *buf, size_t size, size_t *n, const sc_sweep_table *t, int k, double x,
                        sc_prec p)
{
    if (t->format != SC_SWEEP_JSONL)
        return (k && append_char(buf, size, n, separator(t)) < 0)
                   ? -1
                   : append_number(buf, size, n, x, p);
    if (append(buf, size, n, k ? ", " : "{") < 0 || append_json_name(buf, size, n, t->names[k]))
        return -1;
    const char *quote = x - x == 0.0 ? "" : "\""; /* JSON has no NaN or infinity */
    if (append(buf, size, n, "%s", quote) < 0 || append_number(buf, size, n, x, p) < 0)
        return -1;
    return append(buf, size, n, "%s", quote);
}

int sc_sweep_format_row(char *buf, size_t size, const sc_sweep_table *t, const double *vars,
                        const double *results)
{
    size_t n = 0;
    for (int k = 0; k < t->n_vars + t->n_results; k++) {
        int is_var = k < t->n_vars;
        double x = is_var ? vars[k] : results[k - t->n_vars];
        if (append_value(buf, size, &n, t, k, x, is_var ? SC_DOUBLE : t->prec) < 0)
            return -1;
    }
    if ((t->format == SC_SWEEP_JSONL && append_char(buf, size, &n, '}') < 0) ||
        append_char(buf, size, &n, '\n') < 0)
        return -1;
    return (int)n;
}
