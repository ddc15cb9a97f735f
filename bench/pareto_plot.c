/* `shadecalc bench --plot FILE.svg`: the speed-for-accuracy trade as a picture. Per kernel
 * (and scene), at the smallest size measured, every row as a point: ns per element (x) against
 * max ULP (y), log-log, labelled by its instruction set and tier or peer; the Pareto set of
 * bench/harness.c (max ULP against time) joined by a line. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "shadecalc/plot.h"

enum { LABEL_SIZE = 40 };

typedef struct {
    sc_plot_series *series;
    double *x, *y;
    const char **labels;
    char (*names)[LABEL_SIZE], (*titles)[LABEL_SIZE];
} plot_buffers;

static void buffers_free(plot_buffers *b)
{
    free(b->series);
    free(b->x);
    free(b->y);
    free(b->labels);
    free(b->names);
    free(b->titles);
}

static size_t smallest_n(const bench_row *rows, int n)
{
    size_t m = rows[0].n;
    for (int i = 1; i < n; i++)
        m = rows[i].n < m ? rows[i].n : m;
    return m;
}

static int same_group(const bench_row *a, const bench_row *b)
{
    return a->n == b->n && strcmp(a->kernel, b->kernel) == 0 && strcmp(a->scene, b->scene) == 0;
}

static int by_time(const void *pa, const void *pb)
{
    const bench_row *a = *(const bench_row *const *)pa, *b = *(const bench_row *const *)pb;
    return (a->ns_per_elem > b->ns_per_elem) - (a->ns_per_elem < b->ns_per_elem);
}

/* The group of rows from `first` as one series from slot k on: its Pareto rows by time
 * (joined), then the others, each after a NaN (unjoined). Returns the slots used. */
static size_t group_series(const bench_row *rows, int n, int first, plot_buffers *b, size_t k,
                           sc_plot_series *s, const char *title)
{
    const bench_row **g = malloc(sizeof *g * (size_t)n);
    if (!g)
        return 0;
    size_t m = 0, start = k;
    for (int i = first; i < n; i++)
        if (same_group(&rows[i], &rows[first]))
            g[m++] = &rows[i];
    qsort(g, m, sizeof *g, by_time);
    for (int pass = 1; pass >= 0; pass--) /* the Pareto rows first */
        for (size_t i = 0; i < m; i++) {
            if (g[i]->pareto != pass)
                continue;
            if (!pass) { /* a gap before each other row */
                b->x[k] = b->y[k] = NAN;
                b->labels[k++] = NULL;
            }
            bench_row_name(g[i], b->names[k], LABEL_SIZE);
            b->x[k] = g[i]->ns_per_elem;
            b->y[k] = g[i]->err.max_ulp;
            b->labels[k] = b->names[k];
            k++;
        }
    free(g);
    *s = (sc_plot_series){.label = title,
                          .x = b->x + start,
                          .y = b->y + start,
                          .n = k - start,
                          .point_labels = b->labels + start};
    return k - start;
}

int bench_plot_write(FILE *out, const bench_row *rows, int n)
{
    size_t slots = 2 * (size_t)n + 1;
    plot_buffers b = {calloc((size_t)n + 1, sizeof *b.series),
                      calloc(slots, sizeof *b.x),
                      calloc(slots, sizeof *b.y),
                      calloc(slots, sizeof *b.labels),
                      calloc(slots, sizeof *b.names),
                      calloc((size_t)n + 1, sizeof *b.titles)};
    int status = -1, n_series = 0;
    if (b.series && b.x && b.y && b.labels && b.names && b.titles && n > 0) {
        size_t low = smallest_n(rows, n), k = 0;
        for (int i = 0; i < n; i++) {
            int seen = 0; /* a group's first row starts its series */
            for (int j = 0; j < i && !seen; j++)
                seen = same_group(&rows[j], &rows[i]);
            if (seen || rows[i].n != low)
                continue;
            snprintf(b.titles[n_series], LABEL_SIZE, "%s%s%s", rows[i].kernel,
                     rows[i].scene[0] ? " " : "", rows[i].scene);
            size_t used = group_series(rows, n, i, &b, k, &b.series[n_series], b.titles[n_series]);
            if (used == 0)
                break;
            k += used;
            n_series++;
        }
        char title[64];
        snprintf(title, sizeof title, "speed against accuracy, n = %zu (Pareto set joined)", low);
        sc_plot p = {.title = title,
                     .xlabel = "median ns per element (log)",
                     .ylabel = "max error, ULP (log)",
                     .xlog = 1,
                     .ylog = 1,
                     .ymin = NAN,
                     .ymax = NAN,
                     .series = b.series,
                     .n_series = n_series};
        status = sc_plot_write_svg(out, &p);
    }
    buffers_free(&b);
    return status;
}
