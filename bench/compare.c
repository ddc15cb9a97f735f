/* `shadecalc bench --compare A.json B.json`: two JSON reports of `bench -o X.json` read back
 * (util/json.h), their rows matched by kernel, scene, isa, tier and n, and the ratio B/A of the
 * median ns per element with a significance mark. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "cli/cli.h"
#include "util/json.h"

enum { MAX_REPORT_BYTES = 64 << 20 };

/* The whole file into *text; 0, or -1 with the error printed (unreadable or too large). */
static int read_whole(const char *path, char **text, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        sc_error("bench: %s: %s", path, strerror(errno));
        return -1;
    }
    char *buf = malloc(MAX_REPORT_BYTES + 1);
    size_t n = buf ? fread(buf, 1, MAX_REPORT_BYTES + 1, f) : 0;
    int bad = !buf || ferror(f) || n > MAX_REPORT_BYTES;
    if (bad)
        sc_error("bench: %s: %s", path,
                 !buf                   ? "out of memory"
                 : n > MAX_REPORT_BYTES ? "larger than 64 MiB"
                                        : "read error");
    fclose(f);
    if (bad) {
        free(buf);
        return -1;
    }
    *text = buf;
    *len = n;
    return 0;
}

static const char *text_member(const sc_json *row, const char *key)
{
    const sc_json *v = sc_json_member(row, key);
    return v && v->type == SC_JSON_STRING ? v->string : NULL;
}

/* A number member (null: NaN); 0, or -1 if missing or of another type */
static int number_member(const sc_json *row, const char *key, double *out)
{
    const sc_json *v = sc_json_member(row, key);
    if (!v || (v->type != SC_JSON_NUMBER && v->type != SC_JSON_NULL))
        return -1;
    *out = v->type == SC_JSON_NUMBER ? v->number : NAN;
    return 0;
}

static const char *const key_names[4] = {"kernel", "scene", "isa", "tier"}; /* with n */

/* Row i of a report; 0, or -1 with the error printed */
static int read_row(const char *path, const sc_json *j, int i, bench_cmp_row *r)
{
    const char **texts[] = {&r->kernel, &r->scene, &r->isa, &r->tier};
    for (int k = 0; k < 4; k++)
        if (!(*texts[k] = text_member(j, key_names[k]))) {
            sc_error("bench: %s: rows[%d]: \"%s\" is missing or not a string", path, i,
                     key_names[k]);
            return -1;
        }
    const char *bad = NULL;
    double n;
    if (number_member(j, "n", &n) != 0 || !(n >= 0 && n <= 1e15 && n == floor(n)))
        bad = "n";
    else if (number_member(j, "ns_per_elem", &r->ns) != 0 || r->ns < 0)
        bad = "ns_per_elem";
    else if (number_member(j, "ns_mad", &r->mad) != 0 || r->mad < 0)
        bad = "ns_mad";
    if (bad) {
        sc_error("bench: %s: rows[%d]: \"%s\" is missing or not a non-negative number", path, i,
                 bad);
        return -1;
    }
    r->n = (size_t)n;
    return 0;
}

static int read_rows(const char *path, bench_report_file *rep)
{
    const sc_json *rows = sc_json_member(rep->doc, "rows");
    if (!rows || rows->type != SC_JSON_ARRAY) {
        sc_error("bench: %s: not a bench report: no \"rows\" array", path);
        return -1;
    }
    int n = 0;
    for (const sc_json *j = rows->child; j; j = j->next)
        n++;
    rep->rows = calloc((size_t)n + 1, sizeof *rep->rows);
    if (!rep->rows) {
        sc_error("bench: out of memory");
        return -1;
    }
    int i = 0;
    for (const sc_json *j = rows->child; j; j = j->next, i++)
        if (j->type != SC_JSON_OBJECT) {
            sc_error("bench: %s: rows[%d]: not an object", path, i);
            return -1;
        } else if (read_row(path, j, i, &rep->rows[i]) != 0)
            return -1;
    rep->n = n;
    return 0;
}

int bench_report_read(const char *path, bench_report_file *rep)
{
    memset(rep, 0, sizeof *rep);
    char *text, err[160];
    size_t len;
    if (read_whole(path, &text, &len) != 0)
        return SC_EXIT_RUNTIME;
    rep->doc = sc_json_parse(text, len, err, sizeof err);
    free(text);
    if (!rep->doc) {
        sc_error("bench: %s: %s", path, err);
        return SC_EXIT_USAGE;
    }
    if (read_rows(path, rep) != 0) {
        bench_report_free(rep);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

void bench_report_free(bench_report_file *rep)
{
    sc_json_free(rep->doc);
    free(rep->rows);
    memset(rep, 0, sizeof *rep);
}

static int same_key(const bench_cmp_row *a, const bench_cmp_row *b)
{
    return a->n == b->n && strcmp(a->kernel, b->kernel) == 0 && strcmp(a->scene, b->scene) == 0 &&
           strcmp(a->isa, b->isa) == 0 && strcmp(a->tier, b->tier) == 0;
}

/* ---- output ---- */

typedef struct {
    const bench_cmp_row *a, *b; /* either NULL: the row is only in the other report */
} pair;

/* '*' when the medians differ by more than 3 × their combined MAD, '~' otherwise, ' ' when
 * a median is missing */
static char significance(const pair *p)
{
    double spread = sqrt(p->a->mad * p->a->mad + p->b->mad * p->b->mad);
    if (!isfinite(p->a->ns) || !isfinite(p->b->ns))
        return ' ';
    return fabs(p->b->ns - p->a->ns) > 3.0 * (isfinite(spread) ? spread : 0.0) ? '*' : '~';
}

static void csv_text(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s; s++)
        fprintf(out, *s == '"' ? "\"\"" : "%c", *s);
    fputc('"', out);
}

static void number_or(FILE *out, double v, const char *fmt, const char *none)
{
    if (isfinite(v))
        fprintf(out, fmt, v);
    else
        fputs(none, out);
}

static void table_pair(FILE *out, const pair *p)
{
    const bench_cmp_row *k = p->a ? p->a : p->b;
    fprintf(out, "%-11s %-17s %-10s %-8s %9zu ", k->kernel, k->scene[0] ? k->scene : "-", k->isa,
            k->tier, k->n);
    if (!p->a || !p->b) {
        fprintf(out, "%10s %10s %7s  only in %s\n", "", "", "-", p->a ? "A" : "B");
        return;
    }
    number_or(out, p->a->ns, "%10.4g ", "         - ");
    number_or(out, p->b->ns, "%10.4g ", "         - ");
    number_or(out, p->b->ns / p->a->ns, "%7.3f", "      -");
    fprintf(out, "  %c\n", significance(p));
}

static const char *const value_names[3] = {"ns_a", "ns_b", "ratio"};

/* The key's texts, the two medians and their ratio (NaN where a side is missing), and the
 * significance: 1, 0, or -1 for rows only in one report */
static int pair_fields(const pair *p, const char *texts[4], double values[3])
{
    const bench_cmp_row *k = p->a ? p->a : p->b;
    texts[0] = k->kernel, texts[1] = k->scene, texts[2] = k->isa, texts[3] = k->tier;
    values[0] = p->a ? p->a->ns : NAN;
    values[1] = p->b ? p->b->ns : NAN;
    values[2] = values[1] / values[0];
    char mark = p->a && p->b ? significance(p) : ' ';
    return mark == '*' ? 1 : mark == '~' ? 0 : -1;
}

static const char *only_in(const pair *p) { return p->a && p->b ? NULL : p->a ? "A" : "B"; }

static void csv_pair(FILE *out, const pair *p)
{
    const char *texts[4];
    double values[3];
    int significant = pair_fields(p, texts, values);
    for (int i = 0; i < 4; i++) {
        csv_text(out, texts[i]);
        fputc(',', out);
    }
    fprintf(out, "%zu", (p->a ? p->a : p->b)->n);
    for (int i = 0; i < 3; i++) {
        fputc(',', out);
        number_or(out, values[i], "%.6g", "");
    }
    fprintf(out, ",%s,%s\n",
            significant == 1   ? "1"
            : significant == 0 ? "0"
                               : "",
            only_in(p) ? only_in(p) : "");
}

static void json_pair(FILE *out, const pair *p, int first)
{
    const char *texts[4];
    double values[3];
    int significant = pair_fields(p, texts, values);
    fputs(first ? "    {" : ",\n    {", out);
    for (int i = 0; i < 4; i++) {
        fprintf(out, "\"%s\": \"", key_names[i]);
        bench_json_text(out, texts[i]);
        fputs("\", ", out);
    }
    fprintf(out, "\"n\": %zu", (p->a ? p->a : p->b)->n);
    for (int i = 0; i < 3; i++) {
        fprintf(out, ", \"%s\": ", value_names[i]);
        number_or(out, values[i], "%.6g", "null");
    }
    fprintf(out, ", \"significant\": %s, \"only_in\": %s%s%s}",
            significant == 1   ? "true"
            : significant == 0 ? "false"
                               : "null",
            only_in(p) ? "\"" : "null", only_in(p) ? only_in(p) : "", only_in(p) ? "\"" : "");
}

static void write_pair(FILE *out, int format, const pair *p, int first)
{
    if (format == BENCH_CSV)
        csv_pair(out, p);
    else if (format == BENCH_JSON)
        json_pair(out, p, first);
    else
        table_pair(out, p);
}

static void header(FILE *out, int format, const char *path_a, const char *path_b)
{
    if (format == BENCH_CSV) {
        fputs("kernel,scene,isa,tier,n,ns_a,ns_b,ratio,significant,only_in\n", out);
    } else if (format == BENCH_JSON) {
        fputs("{\n  \"a\": \"", out);
        bench_json_text(out, path_a);
        fputs("\", \"b\": \"", out);
        bench_json_text(out, path_b);
        fputs("\",\n  \"rows\": [\n", out);
    } else {
        fprintf(out,
                "# A %s, B %s; ratio: B/A of the median ns per element; * where the medians "
                "differ by more than 3 x their combined MAD, ~ otherwise\n",
                path_a, path_b);
        fprintf(out, "%-11s %-17s %-10s %-8s %9s %10s %10s %7s  %s\n", "kernel", "scene", "isa",
                "tier", "n", "A_ns", "B_ns", "B/A", "sig");
    }
}

int bench_compare(FILE *out, int format, const char *path_a, const bench_report_file *a,
                  const char *path_b, const bench_report_file *b)
{
    char *matched = calloc((size_t)b->n + 1, 1); /* B's rows paired with one of A's */
    if (!matched)
        return -1;
    header(out, format, path_a, path_b);
    int first = 1;
    for (int i = 0; i < a->n; i++, first = 0) {
        pair p = {&a->rows[i], NULL};
        for (int j = 0; j < b->n && !p.b; j++)
            if (!matched[j] && same_key(&a->rows[i], &b->rows[j])) {
                p.b = &b->rows[j];
                matched[j] = 1;
            }
        write_pair(out, format, &p, first);
    }
    for (int j = 0; j < b->n; j++)
        if (!matched[j]) {
            pair p = {NULL, &b->rows[j]};
            write_pair(out, format, &p, first);
            first = 0;
        }
    free(matched);
    if (format == BENCH_JSON)
        fputs(first ? "  ]\n}\n" : "\n  ]\n}\n", out);
    return 0;
}
