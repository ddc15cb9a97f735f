/*
 * shadecalc/plot.h — standalone SVG line plots and polar plots (`shadecalc sweep --plot`).
 *
 *   sc_plot_series      one curve: a legend label and its points
 *   sc_plot             title, axis labels, linear or log axes, polar or cartesian, the curves
 *   sc_plot_ticks       "nice number" ticks of a linear axis (Heckbert, Graphics Gems, 1990)
 *   sc_plot_log_ticks   ticks of a log axis: powers of ten (with 2× and 5× when few decades)
 *   sc_plot_write_svg   the plot as one SVG document that any browser shows
 *   sc_plot_write_heatmap_svg   a value over two variables as a heat map with a colour bar
 *
 * The SVG holds one <g class="series"> per curve (its label in data-label) with one <polyline>
 * per unbroken run of points: a NaN or infinite value, or a value a log axis cannot show
 * (<= 0), breaks the curve. Each curve has its own colour, dash pattern and marker shape, so
 * that curves that coincide stay distinguishable. A curve with point labels has a marker at
 * every point, each labelled (a scatter: NaN between the points leaves them unconnected). The legend sits in a corner of the plot
 * that no curve crosses, or else below the plot; the canvas grows to hold it and the title,
 * so no text is clipped.
 *
 * The polar plot is BRDF Explorer's view of a lobe: x is the angle from the normal in degrees
 * (−90 left, 0 up, 90 right), y the distance from the centre (negative values at the centre).
 * Its radius range comes from the points off the horizon (|x| < 89.5°, where many models
 * diverge), and a value of 0 exactly on the horizon is not drawn.
 *
 * sc_plot_write_heatmap_svg draws a value over a grid of two variables as coloured cells, with
 * axes, a colour bar and a tone mapping: BRDF Explorer's θ_h × θ_d image slice as a figure.
 */
#ifndef SHADECALC_PLOT_H
#define SHADECALC_PLOT_H

#include <stddef.h>
#include <stdio.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef struct {
    const char *label; /* legend text; NULL for a curve without a legend entry */
    const double *x, *y;
    size_t n;
    int has_incident;                /* polar: draw the incident direction of this curve */
    double incident_deg;             /* its angle from the normal, in degrees, as x */
    const char *const *point_labels; /* NULL, or n texts (NULL entries: none): a marker at
                                        every shown point, with its text beside it */
} sc_plot_series;

typedef struct {
    const char *title, *xlabel, *ylabel; /* NULL: none */
    int xlog, ylog;                      /* log10 axes (cartesian only) */
    int polar;
    double ymin, ymax; /* y (or radius) range; NaN: from the data */
    const sc_plot_series *series;
    int n_series;
    int has_reference; /* cartesian: a dashed horizontal line at y = reference_y */
    double reference_y;
    const char *reference_label; /* its label, or NULL */
} sc_plot;

/* Ticks at multiples of a nice step (1, 2 or 5 × 10^k) covering [lo, hi] with about `target`
 * intervals: the first tick <= lo, the last >= hi. Returns the number written (at most max),
 * *step the spacing. lo < hi, both finite. */
int sc_plot_ticks(double lo, double hi, int target, double *ticks, int max, double *step);
/* Powers of ten from the one <= lo to the one >= hi (0 < lo < hi); when they are fewer than
 * three, 2× and 5× each decade too. Returns the number written (at most max). */
int sc_plot_log_ticks(double lo, double hi, double *ticks, int max);

/* Writes the document; 0, or -1 if writing failed. */
int sc_plot_write_svg(FILE *out, const sc_plot *p);

typedef enum { SC_TONE_LOG, SC_TONE_LINEAR } sc_tone;

typedef struct {
    const char *title, *xlabel, *ylabel; /* NULL: none */
    const char *value_label;             /* the colour bar's label, or NULL */
    const double *x, *y;                 /* the samples of the two variables, increasing */
    size_t nx, ny;                       /* at least 2 each */
    const double *values;                /* values[j·nx + i] at (x[i], y[j]); y grows upward */
    sc_tone tone;    /* log: six decades at most below the largest value; linear: from 0 */
    double exposure; /* stops: the colour scale tops out at max / 2^exposure */
    int sqrt_x;      /* x drawn at √((x − x0)/(x1 − x0)): BRDF Explorer's θ_h² mapping */
} sc_heatmap;

/* Writes the heat map: one cell per sample (edges halfway between samples), viridis colours,
 * axes, and a colour bar labelled in the values' units. 0, or -1 if writing failed or a range
 * is empty. */
int sc_plot_write_heatmap_svg(FILE *out, const sc_heatmap *h);

SC_END_DECLS

#endif
