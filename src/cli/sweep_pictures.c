/* shadecalc sweep --plot and --image: the rows gathered into an SVG plot (shadecalc/plot.h)
 * and an EXR image (shadecalc/image.h), both written atomically at the end. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/sweep_cli.h"
#include "shadecalc/file.h"
#include "shadecalc/image.h"
#include "shadecalc/plot.h"

enum { PLOT_MAX_VALUES = 2000000, LABEL_MAX = 160 };

struct sweep_pictures {
    sweep_picture_options o;
    const sc_sweep_grid *grid;
    const sweep_plan *plan;
    long nx, ny;     /* counts of the first and second variables (ny = 1 without one) */
    double *x, *y;   /* plot: x[i]; y[(c·ny + j)·nx + i] for column c, second-variable index j */
    int grey;        /* rgb columns equal on every row so far */
    sc_image image;
};

static int open_plot(sweep_pictures *p)
{
    const sc_sweep_grid *g = p->grid;
    double values = (double)p->nx * (double)p->ny * (double)p->plan->n_results;
    if (g->n > 2 || values > PLOT_MAX_VALUES) {
        sc_error("sweep: --plot %s: draws one or two variables and at most %d values (this sweep "
                 "has %d variables, %.0f values)", p->o.plot, PLOT_MAX_VALUES, g->n, values);
        return SC_EXIT_USAGE;
    }
    p->x = malloc((size_t)p->nx * sizeof *p->x);
    p->y = malloc((size_t)values * sizeof *p->y);
    return p->x && p->y ? SC_EXIT_OK : SC_EXIT_RUNTIME;
}

static int open_image(sweep_pictures *p)
{
    char err[256];
    if (sc_sweep_image_init(&p->image, p->grid, p->plan->n_results, err, sizeof err) < 0) {
        sc_error("sweep: --image %s: %s", p->o.image, err);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
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
    int status = o->plot ? open_plot(p) : SC_EXIT_OK;
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

/* The legend of column c at second-variable index j: "column, name=value", either part
 * dropped when it says nothing. */
static void curve_label(const sweep_pictures *p, int columns, int c, long j, char *buf,
                        size_t size)
{
    const char *column = p->plan->legend[c] ? p->plan->legend[c] : p->plan->columns[c];
    size_t n = (size_t)snprintf(buf, size, "%s", columns > 1 ? column : "");
    if (p->grid->n > 1) /* ten digits are plenty for a label */
        snprintf(buf + n, size - n, "%s%s=%.10g", n ? ", " : "", p->grid->var[1].name,
                 sc_sweep_var_value(&p->grid->var[1], j));
}

static void default_xlabel(const sc_sweep_grid *g, char *buf, size_t size)
{
    const char *name = g->n > 0 ? g->var[0].name : "row";
    int angle = strncmp(name, "theta", 5) == 0 || strncmp(name, "phi", 3) == 0;
    snprintf(buf, size, "%s%s", name, angle ? " (degrees)" : "");
}

static int write_plot(const sweep_pictures *p)
{
    int columns = p->grey ? 1 : p->plan->n_results, n = columns * (int)p->ny;
    sc_plot_series *series = calloc((size_t)n, sizeof *series);
    char (*labels)[LABEL_MAX] = calloc((size_t)n, sizeof *labels);
    char xlabel[64], err[512];
    if (!series || !labels) {
        free(series);
        free(labels);
        sc_error("sweep: out of memory for the plot");
        return SC_EXIT_RUNTIME;
    }
    for (int c = 0, s = 0; c < columns; c++)
        for (long j = 0; j < p->ny; j++, s++) {
            curve_label(p, columns, c, j, labels[s], sizeof labels[s]);
            series[s] = (sc_plot_series){labels[s][0] ? labels[s] : NULL, p->x,
                                         p->y + ((size_t)c * (size_t)p->ny + (size_t)j) *
                                                    (size_t)p->nx,
                                         (size_t)p->nx};
        }
    default_xlabel(p->grid, xlabel, sizeof xlabel);
    const sweep_picture_options *o = &p->o;
    sc_plot plot = {o->title ? o->title : p->plan->title, o->xlabel ? o->xlabel : xlabel,
                    o->ylabel ? o->ylabel : p->plan->ylabel, o->xlog, o->ylog, o->polar,
                    o->ymin, o->ymax, series, n};
    int status = SC_EXIT_RUNTIME;
    sc_atomic_file *f = sc_atomic_open(o->plot, err, sizeof err);
    if (f && sc_plot_write_svg(sc_atomic_stream(f), &plot) == 0)
        status = sc_atomic_commit(f, err, sizeof err) == 0 ? SC_EXIT_OK : SC_EXIT_RUNTIME;
    else if (f) {
        sc_atomic_abort(f);
        snprintf(err, sizeof err, "%s: write error", o->plot);
    }
    if (status != SC_EXIT_OK)
        sc_error("%s", err);
    free(series);
    free(labels);
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
