/* The SVG heat map (shadecalc/plot.h): a value over a grid of two variables as coloured cells,
 * with axes, a colour bar and a tone mapping. BRDF Explorer shows a BRDF's θ_h × θ_d slice
 * this way (θ_d = 0 at the bottom; θ_h optionally drawn at √θ_h, its "θ_h²" mapping, which
 * gives the narrow specular peak near θ_h = 0 more room). */
#include "shadecalc/plot.h"

#include <math.h>
#include <string.h>

#include "plot/plot_internal.h"

enum {
    MAP_LEFT = 78,
    MAP_TOP = 44,
    MAP_SIZE = 480,
    MAP_BOTTOM = 58,
    BAR_GAP = 24,
    BAR_WIDTH = 18,
    BAR_STEPS = 64
};

/* viridis (van der Walt and Smith, matplotlib 2015), sampled at nine evenly spaced points:
 * perceptually uniform and readable in grey and by colour-blind readers */
static const double viridis[9][3] = {
    {0.267, 0.005, 0.329}, {0.279, 0.175, 0.483}, {0.230, 0.322, 0.546},
    {0.173, 0.449, 0.558}, {0.128, 0.567, 0.551}, {0.153, 0.680, 0.504},
    {0.361, 0.785, 0.388}, {0.668, 0.862, 0.196}, {0.993, 0.906, 0.144}};

static void colour_of(double t, char out[8])
{
    t = isnan(t) ? 0.0 : t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double u = t * 8.0;
    int k = u >= 8.0 ? 7 : (int)u;
    double f = u - k, rgb[3];
    for (int c = 0; c < 3; c++)
        rgb[c] = viridis[k][c] + f * (viridis[k + 1][c] - viridis[k][c]);
    snprintf(out, 8, "#%02x%02x%02x", (int)lround(rgb[0] * 255.0), (int)lround(rgb[1] * 255.0),
             (int)lround(rgb[2] * 255.0));
}

/* ---- tone mapping: value → [0, 1] ---- */

typedef struct {
    int log;
    double scale;  /* 2^exposure */
    double lo, hi; /* the values (after scaling) at 0 and 1 */
} tone;

static void tone_make(tone *t, const sc_heatmap *h)
{
    double max = 0.0, min_positive = INFINITY;
    for (size_t k = 0; k < h->nx * h->ny; k++) {
        double v = h->values[k];
        if (isfinite(v) && v > max)
            max = v;
        if (isfinite(v) && v > 0.0 && v < min_positive)
            min_positive = v;
    }
    t->log = h->tone == SC_TONE_LOG;
    t->scale = exp2(h->exposure);
    /* exposure brightens: the value at the top of the scale is max / 2^exposure */
    t->hi = max > 0.0 ? max : 1.0;
    if (t->log) { /* at most six decades below the top */
        double decades = isfinite(min_positive) ? log10(t->hi / min_positive) : 1.0;
        decades = decades < 1.0 ? 1.0 : decades > 6.0 ? 6.0 : ceil(decades);
        t->lo = t->hi / pow(10.0, decades);
    } else {
        t->lo = 0.0;
    }
}

static double tone_map(const tone *t, double v)
{
    v *= t->scale;
    if (!t->log)
        return (v - t->lo) / (t->hi - t->lo);
    return v > 0.0 ? (log10(v) - log10(t->lo)) / (log10(t->hi) - log10(t->lo)) : 0.0;
}

/* The value (before exposure) at position s of the colour bar. */
static double tone_value(const tone *t, double s)
{
    double v = t->log ? t->lo * pow(t->hi / t->lo, s) : t->lo + s * (t->hi - t->lo);
    return v / t->scale;
}

/* ---- axes of the map ---- */

typedef struct {
    double lo, hi;
    int sqrt_map;
    double left, length; /* pixels */
    int vertical;        /* y grows upward */
} map_axis;

static double map_place(const map_axis *a, double v)
{
    double t = (v - a->lo) / (a->hi - a->lo);
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    t = a->sqrt_map ? sqrt(t) : t;
    return a->vertical ? a->left + (1.0 - t) * a->length : a->left + t * a->length;
}

/* The cell edges of sample i of n: halfway to the neighbours, the ends at the range. */
static void cell_edges(const double *x, size_t n, size_t i, double *a, double *b)
{
    *a = i == 0 ? x[0] : 0.5 * (x[i - 1] + x[i]);
    *b = i + 1 == n ? x[n - 1] : 0.5 * (x[i] + x[i + 1]);
}

static void map_ticks(FILE *out, const map_axis *a, double other)
{
    plot_axis t; /* the √ mapping spreads the low end: ticks three times as dense */
    plot_axis_make_count(&t, a->lo, a->hi, a->sqrt_map ? 18 : 6);
    double last = -1e9, end = map_place(a, t.ticks[t.n_ticks - 1]);
    for (int i = 0; i < t.n_ticks; i++) { /* both ends, and the ticks 26 pixels clear of them */
        double p = map_place(a, t.ticks[i]);
        int is_end = i == 0 || i + 1 == t.n_ticks;
        if (!is_end && (fabs(p - last) < 26.0 || fabs(end - p) < 26.0))
            continue;
        char label[32];
        plot_tick_label(label, sizeof label, &t, t.ticks[i]);
        if (a->vertical)
            fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">%s</text>\n", other - 6,
                    p + 4, label);
        else
            fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%s</text>\n", p,
                    other + 17, label);
        last = p;
    }
}

/* ---- the parts ---- */

static void write_cells(FILE *out, const sc_heatmap *h, const map_axis *ax, const map_axis *ay,
                        const tone *t)
{
    fputs("<g class=\"cells\" shape-rendering=\"crispEdges\">\n", out);
    for (size_t j = 0; j < h->ny; j++) {
        double y0, y1;
        cell_edges(h->y, h->ny, j, &y0, &y1);
        double top = map_place(ay, y1), bottom = map_place(ay, y0);
        for (size_t i = 0; i < h->nx; i++) {
            double x0, x1;
            cell_edges(h->x, h->nx, i, &x0, &x1);
            double left = map_place(ax, x0), right = map_place(ax, x1);
            char colour[8];
            colour_of(tone_map(t, h->values[j * h->nx + i]), colour);
            fprintf(out,
                    "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n",
                    left, top, right - left, bottom - top, colour);
        }
    }
    fputs("</g>\n", out);
}

static void write_bar(FILE *out, const sc_heatmap *h, const tone *t, double x, double top,
                      double height)
{
    fputs("<g class=\"colour-bar\">\n", out);
    for (int k = 0; k < BAR_STEPS; k++) {
        char colour[8];
        colour_of((k + 0.5) / BAR_STEPS, colour);
        double y = top + height * (1.0 - (k + 1.0) / BAR_STEPS);
        fprintf(out,
                "<rect x=\"%.2f\" y=\"%.2f\" width=\"%d\" height=\"%.2f\" fill=\"%s\" "
                "shape-rendering=\"crispEdges\"/>\n",
                x, y, BAR_WIDTH, height / BAR_STEPS + 0.5, colour);
    }
    fprintf(out,
            "<rect x=\"%.2f\" y=\"%.2f\" width=\"%d\" height=\"%.2f\" fill=\"none\" "
            "stroke=\"#222\"/>\n",
            x, top, BAR_WIDTH, height);
    for (int k = 0; k <= 4; k++) { /* five labels, in the values' own units */
        double s = k / 4.0;
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\">%.3g</text>\n", x + BAR_WIDTH + 5,
                top + (1.0 - s) * height + 4, tone_value(t, s));
    }
    if (h->value_label) {
        double cy = top + height / 2.0, lx = x + BAR_WIDTH + 62;
        fprintf(out,
                "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" "
                "transform=\"rotate(90 %.2f %.2f)\">",
                lx, cy, lx, cy);
        plot_xml_text(out, h->value_label);
        fprintf(out, " (%s%s)</text>\n", t->log ? "log scale" : "linear",
                h->exposure != 0.0 ? ", exposure" : "");
    }
    fputs("</g>\n", out);
}

int sc_plot_write_heatmap_svg(FILE *out, const sc_heatmap *h)
{
    tone t;
    tone_make(&t, h);
    map_axis ax = {h->x[0], h->x[h->nx - 1], h->sqrt_x, MAP_LEFT, MAP_SIZE, 0};
    map_axis ay = {h->y[0], h->y[h->ny - 1], 0, MAP_TOP, MAP_SIZE, 1};
    if (!(ax.lo < ax.hi) || !(ay.lo < ay.hi))
        return -1;
    double bar_x = MAP_LEFT + MAP_SIZE + BAR_GAP;
    double value_w = h->value_label ? plot_text_width(h->value_label) + 120.0 : 0.0;
    double width = bar_x + BAR_WIDTH + 80.0, height = MAP_TOP + MAP_SIZE + MAP_BOTTOM;
    double title_w = h->title ? plot_text_width(h->title) * 15.0 / PLOT_FONT_SIZE + 24.0 : 0.0;
    width = fmax(width, title_w);
    height = fmax(height, MAP_TOP + value_w);
    plot_svg_begin(out, width, height, h->title ? h->title : "shadecalc heat map");
    write_cells(out, h, &ax, &ay, &t);
    fprintf(out,
            "<g class=\"axes\" fill=\"#222\">\n<rect x=\"%d\" y=\"%d\" width=\"%d\" "
            "height=\"%d\" fill=\"none\" stroke=\"#222\"/>\n",
            MAP_LEFT, MAP_TOP, MAP_SIZE, MAP_SIZE);
    map_ticks(out, &ax, MAP_TOP + MAP_SIZE);
    map_ticks(out, &ay, MAP_LEFT);
    fputs("</g>\n", out);
    write_bar(out, h, &t, bar_x, MAP_TOP, MAP_SIZE);
    if (h->title)
        plot_text_at(out, "title", width / 2.0, 26, " font-size=\"15\"", h->title);
    if (h->xlabel)
        plot_text_at(out, "xlabel", MAP_LEFT + MAP_SIZE / 2.0, MAP_TOP + MAP_SIZE + 44, "",
                     h->xlabel);
    if (h->ylabel) {
        char rotate[64];
        double cy = MAP_TOP + MAP_SIZE / 2.0;
        snprintf(rotate, sizeof rotate, " transform=\"rotate(-90 18 %.2f)\"", cy);
        plot_text_at(out, "ylabel", 18, cy, rotate, h->ylabel);
    }
    fputs("</svg>\n", out);
    return fflush(out) == EOF || ferror(out) ? -1 : 0;
}
