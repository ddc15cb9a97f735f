/* Shared by the SVG writers of src/plot: axes, text, and the drawing styles of the curves. */
#ifndef SHADECALC_PLOT_INTERNAL_H
#define SHADECALC_PLOT_INTERNAL_H

#include <stddef.h>
#include <stdio.h>

enum { PLOT_MAX_TICKS = 64, PLOT_FONT_SIZE = 12 };

/* An upper bound on the width of one character of the 12-pixel sans-serif text, in pixels
 * (about 0.6 em: wider than the average glyph of the common sans-serif fonts), used to size
 * every box that holds text so that nothing is clipped. */
#define PLOT_CHAR_WIDTH 7.2

typedef struct {
    double lo, hi; /* in data units */
    int log;
    double ticks[PLOT_MAX_TICKS];
    int n_ticks;
    double step; /* linear ticks: their spacing, for the labels' decimals */
} plot_axis;

/* Fixes the axis to [lo, hi], widened to whole ticks unless tight; a tight axis keeps the ticks
 * inside and labels both ends. */
void plot_axis_make(plot_axis *a, double lo, double hi, int log, int tight);
/* A tight linear axis with about `count` intervals. */
void plot_axis_make_count(plot_axis *a, double lo, double hi, int count);
/* Position of v along the axis, 0 at lo and 1 at hi; kept finite far outside. */
double plot_axis_place(const plot_axis *a, double v);
void plot_tick_label(char *buf, size_t size, const plot_axis *a, double v);

/* The document's start: the XML declaration, the <svg> element of the canvas (rounded up to
 * whole pixels), its <title> and a white background. */
void plot_svg_begin(FILE *out, double width, double height, const char *title);
/* A <text> element of class cls centred at (x, y); extra: more attributes (" a=\"b\""). */
void plot_text_at(FILE *out, const char *cls, double x, double y, const char *extra,
                  const char *text);

/* Text escaped for XML; control characters dropped. */
void plot_xml_text(FILE *out, const char *s);
/* The width of s in pixels, at most (UTF-8 sequences count as one character). */
double plot_text_width(const char *s);

/* The style of curve s: a colour, a dash pattern ("" for solid) and a marker shape. */
const char *plot_colour(int s);
const char *plot_dashes(int s);
/* An SVG path of the marker of curve s centred at (x, y). */
void plot_marker(FILE *out, int s, double x, double y);

#endif
