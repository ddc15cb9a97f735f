/*
 * shadecalc/plot.h — standalone SVG line plots and polar plots (`shadecalc sweep --plot`).
 *
 *   sc_plot_series      one curve: a legend label and its points
 *   sc_plot             title, axis labels, linear or log axes, polar or cartesian, the curves
 *   sc_plot_ticks       "nice number" ticks of a linear axis (Heckbert, Graphics Gems, 1990)
 *   sc_plot_log_ticks   ticks of a log axis: powers of ten (with 2× and 5× when few decades)
 *   sc_plot_write_svg   the plot as one SVG document that any browser shows
 *
 * The SVG holds one <g class="series"> per curve (its label in data-label) with one <polyline>
 * per unbroken run of points: a NaN or infinite value, or a value a log axis cannot show
 * (<= 0), breaks the curve. The polar plot is BRDF Explorer's view of a lobe: x is the angle
 * from the normal in degrees (−90 left, 0 up, 90 right), y the distance from the centre
 * (negative values at the centre).
 */
#ifndef SHADECALC_PLOT_H
#define SHADECALC_PLOT_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    const char *label; /* legend text; NULL for a curve without a legend entry */
    const double *x, *y;
    size_t n;
} sc_plot_series;

typedef struct {
    const char *title, *xlabel, *ylabel; /* NULL: none */
    int xlog, ylog; /* log10 axes (cartesian only) */
    int polar;
    double ymin, ymax; /* y (or radius) range; NaN: from the data */
    const sc_plot_series *series;
    int n_series;
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

#endif
