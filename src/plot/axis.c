/* Axes, text and curve styles shared by the SVG writers (src/plot/plot_internal.h). */
#include "plot/plot_internal.h"

#include <math.h>

#include "shadecalc/plot.h"

/* ---- axes ---- */

/* Ticks of a tight axis lie inside [lo, hi]; an end farther than a quarter step from the
 * nearest tick gets a tick of its own, so that both ends are labelled. */
static void keep_inside_and_label_ends(plot_axis *a, double lo, double hi)
{
    double slack = 1e-9 * (hi - lo), inside[PLOT_MAX_TICKS];
    int kept = 0;
    for (int i = 0; i < a->n_ticks; i++)
        if (a->ticks[i] >= lo - slack && a->ticks[i] <= hi + slack)
            inside[kept++] = a->ticks[i];
    double near = a->log ? 0.0 : 0.25 * a->step;
    a->n_ticks = 0;
    if (!a->log && (kept == 0 || inside[0] - lo > near))
        a->ticks[a->n_ticks++] = lo;
    for (int i = 0; i < kept && a->n_ticks < PLOT_MAX_TICKS - 1; i++)
        a->ticks[a->n_ticks++] = inside[i];
    if (!a->log && (kept == 0 || hi - inside[kept - 1] > near))
        a->ticks[a->n_ticks++] = hi;
}

static void axis_make(plot_axis *a, double lo, double hi, int log, int tight, int count);

void plot_axis_make(plot_axis *a, double lo, double hi, int log, int tight)
{
    axis_make(a, lo, hi, log, tight, 6);
}

void plot_axis_make_count(plot_axis *a, double lo, double hi, int count)
{
    axis_make(a, lo, hi, 0, 1, count);
}

static void axis_make(plot_axis *a, double lo, double hi, int log, int tight, int count)
{
    if (!(lo < hi)) { /* one value: a range around it */
        double mid = lo;
        lo = log ? mid / 2.0 : mid - (mid == 0.0 ? 1.0 : fabs(mid) / 2.0);
        hi = log ? mid * 2.0 : mid + (mid == 0.0 ? 1.0 : fabs(mid) / 2.0);
    }
    a->log = log;
    a->n_ticks = log ? sc_plot_log_ticks(lo, hi, a->ticks, PLOT_MAX_TICKS)
                     : sc_plot_ticks(lo, hi, count, a->ticks, PLOT_MAX_TICKS, &a->step);
    if (!tight) {
        a->lo = a->ticks[0];
        a->hi = a->ticks[a->n_ticks - 1];
        return;
    }
    keep_inside_and_label_ends(a, lo, hi);
    a->lo = lo;
    a->hi = hi;
}

double plot_axis_place(const plot_axis *a, double v)
{
    double t = a->log ? (log10(v) - log10(a->lo)) / (log10(a->hi) - log10(a->lo))
                      : (v - a->lo) / (a->hi - a->lo);
    return t < -100.0 ? -100.0 : t > 100.0 ? 100.0 : t;
}

void plot_tick_label(char *buf, size_t size, const plot_axis *a, double v)
{
    int decimals = a->log ? 0 : (int)-floor(log10(a->step) + 1e-9);
    double rounded = decimals > 0 && decimals <= 6 ? v : round(v);
    if (a->log || fabs(v) >= 1e6 || decimals > 6)
        snprintf(buf, size, "%g", v);
    else if (rounded != v) /* an end of a tight axis between ticks: its own digits */
        snprintf(buf, size, "%.4g", v);
    else
        snprintf(buf, size, "%.*f", decimals > 0 ? decimals : 0, v);
}

/* ---- text ---- */

void plot_xml_text(FILE *out, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", out); break;
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '"': fputs("&quot;", out); break;
        default:
            if ((unsigned char)*s >= 0x20 || *s == '\t')
                fputc(*s, out);
        }
    }
}

void plot_svg_begin(FILE *out, double width, double height, const char *title)
{
    width = ceil(width);
    height = ceil(height);
    fprintf(out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
            "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"%d\">\n<title>",
            width, height, width, height, PLOT_FONT_SIZE);
    plot_xml_text(out, title);
    fprintf(out, "</title>\n<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", width,
            height);
}

void plot_text_at(FILE *out, const char *cls, double x, double y, const char *extra,
                  const char *text)
{
    fprintf(out, "<text class=\"%s\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\"%s>", cls, x, y,
            extra);
    plot_xml_text(out, text);
    fputs("</text>\n", out);
}

double plot_text_width(const char *s)
{
    int n = 0;
    for (; s && *s; s++)
        n += ((unsigned char)*s & 0xC0) != 0x80; /* continuation bytes do not count */
    return n * PLOT_CHAR_WIDTH;
}

/* ---- curve styles: colour, dashes and markers differ, so that coinciding curves stay
 * distinguishable ---- */

/* tab10, the palette of matplotlib and Vega */
static const char *const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                      "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
static const char *const dashes[] = {"", "8 4", "2 3", "10 3 2 3", "4 4", "1 4"};
enum { N_PALETTE = 10, N_DASHES = 6, N_MARKERS = 6 };

const char *plot_colour(int s) { return palette[s % N_PALETTE]; }
const char *plot_dashes(int s) { return dashes[s % N_DASHES]; }

void plot_marker(FILE *out, int s, double x, double y)
{
    switch (s % N_MARKERS) {
    case 0: /* circle */
        fprintf(out, "<path d=\"M %.2f %.2f a 3.5 3.5 0 1 0 7 0 a 3.5 3.5 0 1 0 -7 0\"/>\n",
                x - 3.5, y);
        break;
    case 1: /* square */
        fprintf(out, "<path d=\"M %.2f %.2f h 6.5 v 6.5 h -6.5 z\"/>\n", x - 3.25, y - 3.25);
        break;
    case 2: /* triangle up */
        fprintf(out, "<path d=\"M %.2f %.2f l 4 7 h -8 z\"/>\n", x, y - 4.5);
        break;
    case 3: /* diamond */
        fprintf(out, "<path d=\"M %.2f %.2f l 4.5 4.5 l -4.5 4.5 l -4.5 -4.5 z\"/>\n", x, y - 4.5);
        break;
    case 4: /* triangle down */
        fprintf(out, "<path d=\"M %.2f %.2f l 4 -7 h -8 z\"/>\n", x, y + 4.5);
        break;
    default: /* cross */
        fprintf(out, "<path d=\"M %.2f %.2f l 8 8 m 0 -8 l -8 8\"/>\n", x - 4, y - 4);
    }
}
