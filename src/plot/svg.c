/* The SVG plot writer (shadecalc/plot.h): cartesian line plots and BRDF Explorer's polar view. */
#include "shadecalc/plot.h"

#include <math.h>
#include <string.h>

enum { WIDTH = 760, HEIGHT = 480, MARGIN_LEFT = 78, MARGIN_RIGHT = 24, MARGIN_TOP = 44,
       MARGIN_BOTTOM = 58, LEGEND_WIDTH = 190, MAX_TICKS = 64 };

static const double RADIANS_PER_DEGREE = 0.017453292519943295; /* π/180 */

/* tab10, the palette of matplotlib and Vega */
static const char *const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                      "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

typedef struct {
    double lo, hi; /* in data units */
    int log;
    double ticks[MAX_TICKS];
    int n_ticks;
    double step; /* linear ticks: their spacing, for the labels' decimals */
} axis;

typedef struct {
    double left, top, width, height; /* the plot area in pixels */
} frame;

static void xml_text(FILE *out, const char *s)
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

static int shown(double v, int log) { return isfinite(v) && (!log || v > 0.0); }

/* ---- axes ---- */

/* The range of the shown values of x (which = 0) or y (1); 0 if there is none. */
static int data_range(const sc_plot *p, int which, int log, double *lo, double *hi)
{
    int any = 0;
    for (int s = 0; s < p->n_series; s++)
        for (size_t i = 0; i < p->series[s].n; i++) {
            double v = which ? p->series[s].y[i] : p->series[s].x[i];
            if (!shown(v, log))
                continue;
            *lo = any && *lo < v ? *lo : v;
            *hi = any && *hi > v ? *hi : v;
            any = 1;
        }
    return any;
}

/* Fixes the axis to [lo, hi], widened to whole ticks unless tight (then only the ticks
 * inside are kept). */
static void axis_make(axis *a, double lo, double hi, int log, int tight)
{
    if (!(lo < hi)) { /* one value: a range around it */
        double mid = lo;
        lo = log ? mid / 2.0 : mid - (mid == 0.0 ? 1.0 : fabs(mid) / 2.0);
        hi = log ? mid * 2.0 : mid + (mid == 0.0 ? 1.0 : fabs(mid) / 2.0);
    }
    a->log = log;
    a->n_ticks = log ? sc_plot_log_ticks(lo, hi, a->ticks, MAX_TICKS)
                     : sc_plot_ticks(lo, hi, 6, a->ticks, MAX_TICKS, &a->step);
    if (!tight) {
        a->lo = a->ticks[0];
        a->hi = a->ticks[a->n_ticks - 1];
        return;
    }
    double slack = 1e-9 * (hi - lo);
    int kept = 0;
    for (int i = 0; i < a->n_ticks; i++)
        if (a->ticks[i] >= lo - slack && a->ticks[i] <= hi + slack)
            a->ticks[kept++] = a->ticks[i];
    a->n_ticks = kept;
    a->lo = lo;
    a->hi = hi;
}

static void axis_from_data(axis *a, const sc_plot *p, int which, int log, double fixed_lo,
                           double fixed_hi, int tight)
{
    double lo = log ? 1.0 : 0.0, hi = log ? 10.0 : 1.0;
    data_range(p, which, log, &lo, &hi);
    lo = isnan(fixed_lo) ? lo : fixed_lo;
    hi = isnan(fixed_hi) ? hi : fixed_hi;
    axis_make(a, lo, hi, log, tight);
}

/* Position of v along the axis, 0 at lo and 1 at hi; kept finite far outside. */
static double axis_place(const axis *a, double v)
{
    double t = a->log ? (log10(v) - log10(a->lo)) / (log10(a->hi) - log10(a->lo))
                      : (v - a->lo) / (a->hi - a->lo);
    return t < -100.0 ? -100.0 : t > 100.0 ? 100.0 : t;
}

static void tick_label(char *buf, size_t size, const axis *a, double v)
{
    int decimals = a->log ? 0 : (int)-floor(log10(a->step) + 1e-9);
    if (a->log || fabs(v) >= 1e6 || decimals > 6)
        snprintf(buf, size, "%g", v);
    else
        snprintf(buf, size, "%.*f", decimals > 0 ? decimals : 0, v);
}

/* ---- cartesian ---- */

static void cartesian_axes(FILE *out, const frame *f, const axis *x, const axis *y)
{
    char label[32];
    fputs("<g class=\"grid\" stroke=\"#e0e0e0\" stroke-width=\"1\">\n", out);
    for (int i = 0; i < x->n_ticks; i++) {
        double px = f->left + axis_place(x, x->ticks[i]) * f->width;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", px, f->top, px,
                f->top + f->height);
    }
    for (int i = 0; i < y->n_ticks; i++) {
        double py = f->top + (1.0 - axis_place(y, y->ticks[i])) * f->height;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", f->left, py,
                f->left + f->width, py);
    }
    fputs("</g>\n<g class=\"axes\" fill=\"#222\">\n", out);
    fprintf(out, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" "
                 "stroke=\"#222\"/>\n", f->left, f->top, f->width, f->height);
    for (int i = 0; i < x->n_ticks; i++) {
        tick_label(label, sizeof label, x, x->ticks[i]);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%s</text>\n",
                f->left + axis_place(x, x->ticks[i]) * f->width, f->top + f->height + 17, label);
    }
    for (int i = 0; i < y->n_ticks; i++) {
        tick_label(label, sizeof label, y, y->ticks[i]);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">%s</text>\n", f->left - 6,
                f->top + (1.0 - axis_place(y, y->ticks[i])) * f->height + 4, label);
    }
    fputs("</g>\n", out);
}

/* Pixel position of a point; 0 if it cannot be shown. */
static int cartesian_point(const frame *f, const axis *x, const axis *y, double vx, double vy,
                           double *px, double *py)
{
    if (!shown(vx, x->log) || !shown(vy, y->log))
        return 0;
    *px = f->left + axis_place(x, vx) * f->width;
    *py = f->top + (1.0 - axis_place(y, vy)) * f->height;
    return 1;
}

/* ---- polar ---- */

static void polar_frame(const frame *f, double *cx, double *cy, double *radius)
{
    *radius = fmin(f->width / 2.0, f->height - 20.0);
    *cx = f->left + f->width / 2.0;
    *cy = f->top + f->height - 10.0;
}

static void polar_axes(FILE *out, const frame *f, const axis *r)
{
    double cx, cy, R;
    polar_frame(f, &cx, &cy, &R);
    char label[32];
    fputs("<g class=\"grid\" stroke=\"#e0e0e0\" stroke-width=\"1\" fill=\"none\">\n", out);
    for (int i = 1; i < r->n_ticks; i++) {
        double rr = axis_place(r, r->ticks[i]) * R;
        fprintf(out, "<path d=\"M %.2f %.2f A %.2f %.2f 0 0 1 %.2f %.2f\"/>\n", cx - rr, cy, rr,
                rr, cx + rr, cy);
    }
    for (int deg = -90; deg <= 90; deg += 15)
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", cx, cy,
                cx + R * sin(deg * RADIANS_PER_DEGREE), cy - R * cos(deg * RADIANS_PER_DEGREE));
    fputs("</g>\n<g class=\"axes\" fill=\"#222\">\n", out);
    for (int deg = -90; deg <= 90; deg += 30)
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%d°</text>\n",
                cx + (R + 14) * sin(deg * RADIANS_PER_DEGREE),
                cy - (R + 14) * cos(deg * RADIANS_PER_DEGREE) + 4, deg);
    for (int i = 0; i < r->n_ticks; i++) {
        tick_label(label, sizeof label, r, r->ticks[i]);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%s</text>\n",
                cx + axis_place(r, r->ticks[i]) * R, cy + 16, label);
    }
    fputs("</g>\n", out);
}

static int polar_point(const frame *f, const axis *r, double deg, double value, double *px,
                       double *py)
{
    if (!isfinite(deg) || !isfinite(value))
        return 0;
    double cx, cy, R;
    polar_frame(f, &cx, &cy, &R);
    double rr = axis_place(r, value > 0.0 ? value : 0.0) * R;
    *px = cx + rr * sin(deg * RADIANS_PER_DEGREE);
    *py = cy - rr * cos(deg * RADIANS_PER_DEGREE);
    return 1;
}

/* ---- curves, legend, labels ---- */

static void write_series(FILE *out, const sc_plot *p, const frame *f, const axis *x,
                         const axis *y, int s)
{
    const sc_plot_series *c = &p->series[s];
    fputs("<g class=\"series\" data-label=\"", out);
    xml_text(out, c->label);
    fprintf(out, "\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.6\" "
                 "clip-path=\"url(#plot-area)\">\n", palette[s % 10]);
    int open = 0;
    for (size_t i = 0; i < c->n; i++) {
        double px, py;
        int ok = p->polar ? polar_point(f, y, c->x[i], c->y[i], &px, &py)
                          : cartesian_point(f, x, y, c->x[i], c->y[i], &px, &py);
        if (!ok) {
            fputs(open ? "\"/>\n" : "", out);
            open = 0;
            continue;
        }
        fprintf(out, open ? " %.2f,%.2f" : "<polyline points=\"%.2f,%.2f", px, py);
        open = 1;
    }
    fputs(open ? "\"/>\n</g>\n" : "</g>\n", out);
}

static int has_legend(const sc_plot *p)
{
    for (int s = 0; s < p->n_series; s++)
        if (p->series[s].label && p->series[s].label[0])
            return 1;
    return 0;
}

static void write_legend(FILE *out, const sc_plot *p, const frame *f)
{
    double x = f->left + f->width + 16, y = f->top + 8;
    fputs("<g class=\"legend\">\n", out);
    for (int s = 0; s < p->n_series; s++) {
        if (!p->series[s].label || !p->series[s].label[0])
            continue;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                     "stroke-width=\"2.5\"/>\n<text x=\"%.2f\" y=\"%.2f\">", x, y, x + 22, y,
                palette[s % 10], x + 28, y + 4);
        xml_text(out, p->series[s].label);
        fputs("</text>\n", out);
        y += 18;
    }
    fputs("</g>\n", out);
}

static void write_labels(FILE *out, const sc_plot *p, const frame *f)
{
    if (p->title) {
        fprintf(out, "<text class=\"title\" x=\"%.2f\" y=\"26\" text-anchor=\"middle\" "
                     "font-size=\"15\">", f->left + f->width / 2.0);
        xml_text(out, p->title);
        fputs("</text>\n", out);
    }
    if (p->xlabel) {
        fprintf(out, "<text class=\"xlabel\" x=\"%.2f\" y=\"%d\" text-anchor=\"middle\">",
                f->left + f->width / 2.0, HEIGHT - 14);
        xml_text(out, p->xlabel);
        fputs("</text>\n", out);
    }
    if (p->ylabel) {
        double cy = f->top + f->height / 2.0;
        fprintf(out, "<text class=\"ylabel\" x=\"18\" y=\"%.2f\" text-anchor=\"middle\" "
                     "transform=\"rotate(-90 18 %.2f)\">", cy, cy);
        xml_text(out, p->ylabel);
        fputs("</text>\n", out);
    }
}

int sc_plot_write_svg(FILE *out, const sc_plot *p)
{
    int legend = has_legend(p);
    frame f = {MARGIN_LEFT, MARGIN_TOP,
               WIDTH - MARGIN_LEFT - MARGIN_RIGHT - (legend ? LEGEND_WIDTH : 0),
               HEIGHT - MARGIN_TOP - MARGIN_BOTTOM};
    axis x = {0}, y = {0};
    if (p->polar) {
        axis_from_data(&y, p, 1, 0, isnan(p->ymin) ? 0.0 : p->ymin, p->ymax, 0);
    } else { /* x spans the swept range exactly; y is widened to whole ticks */
        axis_from_data(&x, p, 0, p->xlog, NAN, NAN, 1);
        axis_from_data(&y, p, 1, p->ylog, p->ymin, p->ymax, 0);
    }
    fprintf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                 "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n<title>",
            WIDTH, HEIGHT, WIDTH, HEIGHT);
    xml_text(out, p->title ? p->title : "shadecalc plot");
    fprintf(out, "</title>\n<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n"
                 "<defs><clipPath id=\"plot-area\"><rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" "
                 "height=\"%.2f\"/></clipPath></defs>\n",
            WIDTH, HEIGHT, f.left - (p->polar ? 30 : 0), f.top - (p->polar ? 30 : 0),
            f.width + (p->polar ? 60 : 0), f.height + (p->polar ? 30 : 0));
    if (p->polar)
        polar_axes(out, &f, &y);
    else
        cartesian_axes(out, &f, &x, &y);
    for (int s = 0; s < p->n_series; s++)
        write_series(out, p, &f, &x, &y, s);
    if (legend)
        write_legend(out, p, &f);
    write_labels(out, p, &f);
    fputs("</svg>\n", out);
    return fflush(out) == EOF || ferror(out) ? -1 : 0;
}
