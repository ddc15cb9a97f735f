/* shadecalc sweep --plot and --image: the rows gathered into an SVG plot (shadecalc/plot.h)
 * and an EXR image (shadecalc/image.h), both written atomically at the end. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/sweep_cli.h"
#include "shadecalc/file.h"
#include "shadecalc/image.h"
#include "shadecalc/plot.h"

enum { PLOT_MAX_VALUES = 2000000, HEATMAP_MAX_CELLS = 250000, LABEL_MAX = 160 };

struct sweep_pictures {
    sweep_picture_options o;
    const sc_sweep_grid *grid;
    const sweep_plan *plan;
    long nx, ny;   /* counts of the first and second variables (ny = 1 without one) */
    double *x, *y; /* plot: x[i]; y[(c·ny + j)·nx + i] for column c, second-variable index j */
    int grey;      /* rgb columns equal on every row so far */
    sc_image image;
};

/* The values the plot and the heat map draw, kept as they arrive. */
static int open_plot(sweep_pictures *p)
{
    const sc_sweep_grid *g = p->grid;
    double values = (double)p->nx * (double)p->ny * (double)p->plan->n_results;
    if (p->o.plot && (g->n > 2 || values > PLOT_MAX_VALUES)) {
        sc_error("sweep: --plot %s: draws one or two variables and at most %d values (this sweep "
                 "has %d variables, %.0f values)",
                 p->o.plot, PLOT_MAX_VALUES, g->n, values);
        return SC_EXIT_USAGE;
    }
    if (p->o.heatmap && (g->n != 2 || p->nx < 2 || p->ny < 2 ||
                         (double)p->nx * (double)p->ny > HEATMAP_MAX_CELLS)) {
        sc_error("sweep: --heatmap %s: draws exactly two variables of at least 2 values each and "
                 "at most %d cells (this sweep has %d variables, %.0f cells; --image writes "
                 "larger grids)",
                 p->o.heatmap, HEATMAP_MAX_CELLS, g->n, (double)p->nx * (double)p->ny);
        return SC_EXIT_USAGE;
    }
    for (int k = 0; p->o.heatmap && k < 2; k++)
        if (!(sc_sweep_var_value(&g->var[k], 0) <
              sc_sweep_var_value(&g->var[k], g->var[k].count - 1))) {
            sc_error("sweep: --heatmap %s: the variable %s must increase from its first value to "
                     "its last",
                     p->o.heatmap, g->var[k].name);
            return SC_EXIT_USAGE;
        }
    p->x = malloc((size_t)p->nx * sizeof *p->x);
    p->y = malloc((size_t)values * sizeof *p->y);
    return p->x && p->y ? SC_EXIT_OK : SC_EXIT_RUNTIME;
}

static int open_image(sweep_pictures *p)
{
    char err[256];
    int rc = sc_sweep_image_init(&p->image, p->grid, p->plan->n_results, err, sizeof err);
    if (rc == -1) {
        sc_error("sweep: --image %s: %s", p->o.image, err);
        return SC_EXIT_USAGE;
    }
    return rc == 0 ? SC_EXIT_OK : SC_EXIT_RUNTIME; /* out of memory: reported by the caller */
}

int sweep_pictures_open(sweep_pictures **out, const sweep_picture_options *o,
                        const sc_sweep_grid *g, const sweep_plan *plan)
{
    sweep_pictures *p = calloc(1, sizeof *p);
    *out = p;
    if (!p) {
        sc_error("sweep: out of memory");
        return SC_EXIT_RUNTIME;
    }
    p->o = *o;
    p->grid = g;
    p->plan = plan;
    p->grey = plan->rgb;
    p->nx = g->n > 0 ? g->var[0].count : 1;
    p->ny = g->n > 1 ? g->var[1].count : 1;
    int status = o->plot || o->heatmap ? open_plot(p) : SC_EXIT_OK;
    if (status == SC_EXIT_OK && o->image)
        status = open_image(p);
    if (status == SC_EXIT_RUNTIME)
        sc_error("sweep: out of memory for the pictures");
    return status;
}

int sweep_pictures_consume(void *user, uint64_t row, const double *vars, const double *results,
                           char *err, size_t errsize)
{
    (void)err;
    (void)errsize;
    sweep_pictures *p = user;
    long i = (long)(row % (uint64_t)p->nx), j = (long)(row / (uint64_t)p->nx);
    int n = p->plan->n_results;
    if (p->x) {
        p->x[i] = p->grid->n > 0 ? vars[0] : 0.0;
        for (int c = 0; c < n; c++)
            p->y[((size_t)c * (size_t)p->ny + (size_t)j) * (size_t)p->nx + (size_t)i] = results[c];
        if (p->grey)
            p->grey = results[0] == results[1] && results[1] == results[2];
    }
    if (p->image.data)
        sc_sweep_image_store(&p->image, row, results);
    return 0;
}

/* ---- the plot ---- */

static int write_plot_svg(FILE *out, const void *what) { return sc_plot_write_svg(out, what); }
static int write_heatmap_svg(FILE *out, const void *what)
{
    return sc_plot_write_heatmap_svg(out, what);
}

/* Writes path atomically with writer(out, what); an exit status, the error printed. */
static int write_svg(const char *path, int (*writer)(FILE *, const void *), const void *what)
{
    char err[512];
    int status = SC_EXIT_RUNTIME;
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    errno = 0;
    if (f && writer(sc_atomic_stream(f), what) == 0)
        status = sc_atomic_commit(f, err, sizeof err) == 0 ? SC_EXIT_OK : SC_EXIT_RUNTIME;
    else if (f) {
        int errnum = errno; /* of the failed write */
        sc_atomic_abort(f);
        snprintf(err, sizeof err, "%s: %s", path, errnum ? strerror(errnum) : "write error");
    }
    if (status != SC_EXIT_OK)
        sc_error("%s", err);
    return status;
}

/* The legend of column c at second-variable index j: "column, name=value", either part
 * dropped when it says nothing. */
static void curve_label(const sweep_pictures *p, int columns, int c, long j, char *buf, size_t size)
{
    const char *column = p->plan->legend[c] ? p->plan->legend[c] : p->plan->columns[c];
    size_t n = (size_t)snprintf(buf, size, "%s", columns > 1 ? column : "");
    if (p->grid->n > 1) /* ten digits are plenty for a label */
        snprintf(buf + n, size - n, "%s%s=%.10g", n ? ", " : "", p->grid->var[1].name,
                 sc_sweep_var_value(&p->grid->var[1], j));
}

/* In a polar plot whose curves are values of theta_i (the lobe at several incident angles),
 * each curve's incident direction: l = dir(θ_i, φ_i) lies at +θ_i on the plot, its mirror
 * direction at −θ_i. */
static void curve_incident(const sweep_pictures *p, long j, sc_plot_series *s)
{
    const sc_sweep_grid *g = p->grid;
    if (!p->o.polar || g->n < 2 || strcmp(g->var[1].name, "theta_i") != 0)
        return;
    s->has_incident = 1;
    s->incident_deg = sc_sweep_var_value(&g->var[1], j);
}

/* The label of variable k's axis: its name, and "(degrees)" for an angle. */
static void axis_label(const sc_sweep_grid *g, int k, char *buf, size_t size)
{
    const char *name = g->n > k ? g->var[k].name : "row";
    int angle = strncmp(name, "theta", 5) == 0 || strncmp(name, "phi", 3) == 0;
    snprintf(buf, size, "%s%s", name, angle ? " (degrees)" : "");
}

static int write_plot(const sweep_pictures *p)
{
    int columns = p->grey ? 1 : p->plan->n_results, n = columns * (int)p->ny;
    sc_plot_series *series = calloc((size_t)n, sizeof *series);
    char(*labels)[LABEL_MAX] = calloc((size_t)n, sizeof *labels);
    char xlabel[64];
    if (!series || !labels) {
        free(series);
        free(labels);
        sc_error("sweep: out of memory for the plot");
        return SC_EXIT_RUNTIME;
    }
    const sweep_picture_options *o = &p->o;
    for (int c = 0, s = 0; c < columns; c++)
        for (long j = 0; j < p->ny; j++, s++) {
            curve_label(p, columns, c, j, labels[s], sizeof labels[s]);
            series[s] = (sc_plot_series){.label = labels[s][0] ? labels[s] : NULL,
                                         .x = p->x,
                                         .y = p->y + ((size_t)c * (size_t)p->ny + (size_t)j) *
                                                         (size_t)p->nx,
                                         .n = (size_t)p->nx};
            curve_incident(p, j, &series[s]);
        }
    axis_label(p->grid, 0, xlabel, sizeof xlabel);
    sc_plot plot = {.title = o->title ? o->title : p->plan->title,
                    .xlabel = o->xlabel ? o->xlabel : xlabel,
                    .ylabel = o->ylabel ? o->ylabel : p->plan->ylabel,
                    .xlog = o->xlog,
                    .ylog = o->ylog,
                    .polar = o->polar,
                    .ymin = o->ymin,
                    .ymax = o->ymax,
                    .series = series,
                    .n_series = n,
                    .has_reference = p->plan->reference_label != NULL,
                    .reference_y = p->plan->reference_y,
                    .reference_label = p->plan->reference_label};
    int status = write_svg(o->plot, write_plot_svg, &plot);
    free(series);
    free(labels);
    return status;
}

/* ---- the heat map ---- */

/* The value a cell shows: the one result column, or the luminance of r, g, b (Rec. 709). */
static double heatmap_value(const sweep_pictures *p, size_t k, const char **label)
{
    size_t plane = (size_t)p->nx * (size_t)p->ny;
    if (!p->plan->rgb || p->grey) {
        *label = p->plan->legend[0] ? p->plan->legend[0] : p->plan->columns[0];
        return p->y[k];
    }
    *label = "luminance of r, g, b";
    return 0.2126 * p->y[k] + 0.7152 * p->y[plane + k] + 0.0722 * p->y[2 * plane + k];
}

static int write_heatmap(const sweep_pictures *p)
{
    size_t cells = (size_t)p->nx * (size_t)p->ny;
    double *ys = malloc((size_t)p->ny * sizeof *ys), *values = malloc(cells * sizeof *values);
    if (!ys || !values) {
        free(ys);
        free(values);
        sc_error("sweep: out of memory for the heat map");
        return SC_EXIT_RUNTIME;
    }
    const char *column = NULL;
    for (long j = 0; j < p->ny; j++)
        ys[j] = sc_sweep_var_value(&p->grid->var[1], j);
    for (size_t k = 0; k < cells; k++)
        values[k] = heatmap_value(p, k, &column);
    const sweep_picture_options *o = &p->o;
    char xlabel[64], ylabel[64];
    axis_label(p->grid, 0, xlabel, sizeof xlabel);
    axis_label(p->grid, 1, ylabel, sizeof ylabel);
    sc_heatmap h = {.title = o->title ? o->title : p->plan->title,
                    .xlabel = o->xlabel ? o->xlabel : xlabel,
                    .ylabel = o->ylabel ? o->ylabel : ylabel,
                    .value_label = p->plan->ylabel ? p->plan->ylabel : column,
                    .x = p->x,
                    .y = ys,
                    .nx = (size_t)p->nx,
                    .ny = (size_t)p->ny,
                    .values = values,
                    .tone = o->tone,
                    .exposure = o->exposure,
                    .sqrt_x = o->sqrt_x};
    int status = write_svg(o->heatmap, write_heatmap_svg, &h);
    free(ys);
    free(values);
    return status;
}

/* ---- the image ---- */

static int write_image(const sweep_pictures *p)
{
    char err[512];
    if (sc_sweep_image_write(p->o.image, &p->image, p->o.exr_half ? SC_PIXEL_HALF : SC_PIXEL_FLOAT,
                             p->grid, p->o.command, err, sizeof err) < 0) {
        sc_error("%s", err);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

int sweep_pictures_write(sweep_pictures *p)
{
    int status = p->o.plot ? write_plot(p) : SC_EXIT_OK;
    if (status == SC_EXIT_OK && p->o.heatmap)
        status = write_heatmap(p);
    if (status == SC_EXIT_OK && p->o.image)
        status = write_image(p);
    return status;
}

void sweep_pictures_free(sweep_pictures *p)
{
    if (!p)
        return;
    free(p->x);
    free(p->y);
    sc_image_free(&p->image);
    free(p);
}
