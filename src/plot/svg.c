/* The SVG plot writer (shadecalc/plot.h): cartesian line plots and BRDF Explorer's polar view.
 *
 * The layout is computed before anything is written: the legend goes into a corner of the plot
 * where no point of a curve lies, or else below the plot, and the canvas grows to hold it and
 * the title, so that no text is clipped at the edge of the document. */
#include "shadecalc/plot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"

enum {
    WIDTH = 760,
    HEIGHT = 480,
    MARGIN_LEFT = 78,
    MARGIN_RIGHT = 24,
    MARGIN_TOP = 44,
    MARGIN_BOTTOM = 58,
    POLAR_SIDE = 56,
    LEGEND_ROW = 18,
    LEGEND_SAMPLE = 34,
    MARKERS_PER_CURVE = 8,
    POLAR_RANGE_ANGLE = 80
};

static const double RADIANS_PER_DEGREE = 0.017453292519943295; /* π/180 */

typedef struct {
    double left, top, width, height; /* the plot area in pixels */
} frame;

typedef enum { LEGEND_NONE, LEGEND_INSIDE, LEGEND_BELOW } legend_place;

typedef struct {
    double width, height;  /* the canvas */
    frame f;               /* cartesian plot area; polar: the half disc's bounding box */
    double cx, cy, radius; /* polar */
    legend_place legend;
    double lx, ly, lw, lh; /* the legend's box */
    double entry_width;
    int legend_columns;
    double labels_y; /* baseline of the axis labels */
} layout;

static int shown(double v, int log) { return isfinite(v) && (!log || v > 0.0); }

/* ---- axes ---- */

/* The range of the shown values of x (which = 0) or y (1); 0 if there is none. With
 * max_angle, only the points at most that far from the normal (a polar plot's radius range
 * leaves out the last degrees before the horizon, where many models have a grazing spike that
 * would shrink the lobes to dots). */
static int data_range(const sc_plot *p, int which, int log, double max_angle, double *lo,
                      double *hi)
{
    int any = 0;
    for (int s = 0; s < p->n_series; s++)
        for (size_t i = 0; i < p->series[s].n; i++) {
            double v = which ? p->series[s].y[i] : p->series[s].x[i];
            if (!shown(v, log) || !(fabs(p->series[s].x[i]) <= max_angle))
                continue;
            *lo = any && *lo < v ? *lo : v;
            *hi = any && *hi > v ? *hi : v;
            any = 1;
        }
    return any;
}

static void axis_from_data(plot_axis *a, const sc_plot *p, int which, int log, double fixed_lo,
                           double fixed_hi, int tight)
{
    double lo = log ? 1.0 : 0.0, hi = log ? 10.0 : 1.0;
    if (!(p->polar && which == 1 && data_range(p, 1, log, POLAR_RANGE_ANGLE, &lo, &hi)))
        data_range(p, which, log, INFINITY, &lo, &hi);
    lo = isnan(fixed_lo) ? lo : fixed_lo;
    hi = isnan(fixed_hi) ? hi : fixed_hi;
    plot_axis_make(a, lo, hi, log, tight);
}

static void write_tick_text(FILE *out, const plot_axis *a, double v, double x, double y,
                            const char *anchor)
{
    char label[32];
    plot_tick_label(label, sizeof label, a, v);
    fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\">%s</text>\n", x, y, anchor, label);
}

/* ---- cartesian ---- */

static void cartesian_axes(FILE *out, const frame *f, const plot_axis *x, const plot_axis *y)
{
    fputs("<g class=\"grid\" stroke=\"#e0e0e0\" stroke-width=\"1\">\n", out);
    for (int i = 0; i < x->n_ticks; i++) {
        double px = f->left + plot_axis_place(x, x->ticks[i]) * f->width;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", px, f->top, px,
                f->top + f->height);
    }
    for (int i = 0; i < y->n_ticks; i++) {
        double py = f->top + (1.0 - plot_axis_place(y, y->ticks[i])) * f->height;
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", f->left, py,
                f->left + f->width, py);
    }
    fputs("</g>\n<g class=\"axes\" fill=\"#222\">\n", out);
    fprintf(out,
            "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" "
            "stroke=\"#222\"/>\n",
            f->left, f->top, f->width, f->height);
    for (int i = 0; i < x->n_ticks; i++)
        write_tick_text(out, x, x->ticks[i], f->left + plot_axis_place(x, x->ticks[i]) * f->width,
                        f->top + f->height + 17, "middle");
    for (int i = 0; i < y->n_ticks; i++)
        write_tick_text(out, y, y->ticks[i], f->left - 6,
                        f->top + (1.0 - plot_axis_place(y, y->ticks[i])) * f->height + 4, "end");
    fputs("</g>\n", out);
}

/* Pixel position of a point; 0 if it cannot be shown. */
static int cartesian_point(const frame *f, const plot_axis *x, const plot_axis *y, double vx,
                           double vy, double *px, double *py)
{
    if (!shown(vx, x->log) || !shown(vy, y->log))
        return 0;
    *px = f->left + plot_axis_place(x, vx) * f->width;
    *py = f->top + (1.0 - plot_axis_place(y, vy)) * f->height;
    return 1;
}

/* The dashed line y = reference, labelled at the right end. */
static void reference_line(FILE *out, const sc_plot *p, const frame *f, const plot_axis *y)
{
    double t = plot_axis_place(y, p->reference_y);
    if (!p->has_reference || !shown(p->reference_y, y->log) || t < 0.0 || t > 1.0)
        return;
    double py = f->top + (1.0 - t) * f->height;
    fprintf(out,
            "<g class=\"reference\" stroke=\"#555\" fill=\"#555\">\n<line x1=\"%.2f\" "
            "y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke-dasharray=\"3 3\"/>\n",
            f->left, py, f->left + f->width, py);
    if (p->reference_label) {
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\" stroke=\"none\">",
                f->left + f->width - 4, py - 4);
        plot_xml_text(out, p->reference_label);
        fputs("</text>\n", out);
    }
    fputs("</g>\n", out);
}

/* ---- polar ---- */

static void polar_axes(FILE *out, const layout *l, const plot_axis *r)
{
    double cx = l->cx, cy = l->cy, R = l->radius;
    fputs("<g class=\"grid\" stroke=\"#e0e0e0\" stroke-width=\"1\" fill=\"none\">\n", out);
    for (int i = 1; i < r->n_ticks; i++) {
        double rr = plot_axis_place(r, r->ticks[i]) * R;
        fprintf(out, "<path d=\"M %.2f %.2f A %.2f %.2f 0 0 1 %.2f %.2f\"/>\n", cx - rr, cy, rr, rr,
                cx + rr, cy);
    }
    for (int deg = -90; deg <= 90; deg += 15)
        fprintf(out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", cx, cy,
                cx + R * sin(deg * RADIANS_PER_DEGREE), cy - R * cos(deg * RADIANS_PER_DEGREE));
    fputs("</g>\n<g class=\"axes\" fill=\"#222\">\n", out);
    for (int deg = -90; deg <= 90; deg += 30) { /* outside the arc; ±90° above the horizon */
        const char *anchor = deg < 0 ? "end" : deg > 0 ? "start" : "middle";
        double dy = deg == 90 || deg == -90 ? -6.0 : 4.0 - 6.0 * cos(deg * RADIANS_PER_DEGREE);
        fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\">%d°</text>\n",
                cx + (R + 8) * sin(deg * RADIANS_PER_DEGREE),
                cy - (R + 8) * cos(deg * RADIANS_PER_DEGREE) + dy, anchor, deg);
    }
    for (int i = 0; i < r->n_ticks; i++) { /* the radius, below the horizon on both sides */
        double rr = plot_axis_place(r, r->ticks[i]) * R;
        write_tick_text(out, r, r->ticks[i], cx + rr, cy + 16, "middle");
        if (rr > 0.5)
            write_tick_text(out, r, r->ticks[i], cx - rr, cy + 16, "middle");
    }
    fputs("</g>\n", out);
}

/* Pixel position of value `value` at `deg` from the normal; 0 if it is not drawn: not finite,
 * or on the horizon itself (|deg| >= 90), where the direction lies in the surface and a value
 * would only draw a line along the horizon. */
static int polar_point(const layout *l, const plot_axis *r, double deg, double value, double *px,
                       double *py)
{
    if (!isfinite(deg) || !isfinite(value) || fabs(deg) >= 90.0)
        return 0;
    double rr = plot_axis_place(r, value > 0.0 ? value : 0.0) * l->radius;
    *px = l->cx + rr * sin(deg * RADIANS_PER_DEGREE);
    *py = l->cy - rr * cos(deg * RADIANS_PER_DEGREE);
    return 1;
}

/* Under the title, when the radius range leaves out larger values near the horizon. */
static void polar_clip_note(FILE *out, const sc_plot *p, const layout *l, const plot_axis *r)
{
    double lo = 0.0, hi = 0.0;
    if (!isnan(p->ymax) || !data_range(p, 1, 0, 89.999, &lo, &hi) || hi <= r->hi)
        return;
    fprintf(out,
            "<text class=\"note\" x=\"%.2f\" y=\"44\" text-anchor=\"middle\" "
            "font-size=\"11\" fill=\"#555\">radius scaled to the values within %d° of "
            "the normal; larger values near the horizon (up to %.3g) are clipped</text>\n",
            l->width / 2.0, POLAR_RANGE_ANGLE, hi);
}

/* The incident direction of curve s: an arrow from the arc to the centre. */
static void incident_arrow(FILE *out, const layout *l, int s, double deg)
{
    double sx = sin(deg * RADIANS_PER_DEGREE), cy = -cos(deg * RADIANS_PER_DEGREE);
    double x0 = l->cx + l->radius * sx, y0 = l->cy + l->radius * cy;
    double x1 = l->cx + 0.1 * l->radius * sx, y1 = l->cy + 0.1 * l->radius * cy;
    fprintf(out,
            "<g class=\"incident\" stroke=\"%s\" fill=\"%s\" stroke-width=\"1.2\">\n"
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke-dasharray=\"%s\"/>\n",
            plot_colour(s), plot_colour(s), x0, y0, x1, y1, plot_dashes(s));
    double px = -cy, py = sx; /* perpendicular to the arrow: its head */
    fprintf(out, "<path d=\"M %.2f %.2f L %.2f %.2f L %.2f %.2f z\"/>\n", x1, y1,
            x1 + 10 * sx + 4 * px, y1 + 10 * cy + 4 * py, x1 + 10 * sx - 4 * px,
            y1 + 10 * cy - 4 * py);
    fprintf(out,
            "<text x=\"%.2f\" y=\"%.2f\" stroke=\"none\" text-anchor=\"middle\">l</text>\n"
            "</g>\n",
            l->cx + (l->radius - 12) * sx + 8 * px, l->cy + (l->radius - 12) * cy + 8 * py);
}

/* ---- curves ---- */

static int curve_point(const sc_plot *p, const layout *l, const plot_axis *x, const plot_axis *y,
                       int s, size_t i, double *px, double *py)
{
    const sc_plot_series *c = &p->series[s];
    return p->polar ? polar_point(l, y, c->x[i], c->y[i], px, py)
                    : cartesian_point(&l->f, x, y, c->x[i], c->y[i], px, py);
}

/* Markers at MARKERS_PER_CURVE places, staggered between the curves so that the markers of
 * coinciding curves do not cover each other. */
static void curve_markers(FILE *out, const sc_plot *p, const layout *l, const plot_axis *x,
                          const plot_axis *y, int s)
{
    size_t n = p->series[s].n;
    double offset = (s + 1.0) / (p->n_series + 1.0);
    for (int k = 0; k < MARKERS_PER_CURVE; k++) {
        size_t i = (size_t)((k + offset) * (double)n / MARKERS_PER_CURVE);
        double px, py;
        if (i < n && curve_point(p, l, x, y, s, i, &px, &py))
            plot_marker(out, s, px, py);
    }
}

/* The boxes of the point labels placed so far, so that later labels avoid them. */
typedef struct {
    double (*box)[4]; /* left, top, right, bottom */
    size_t n, max;
} label_boxes;

static int box_free(const label_boxes *b, const frame *f, const double *box)
{
    if (box[0] < f->left || box[2] > f->left + f->width || box[1] < f->top ||
        box[3] > f->top + f->height)
        return 0;
    for (size_t i = 0; i < b->n; i++)
        if (box[0] < b->box[i][2] && b->box[i][0] < box[2] && box[1] < b->box[i][3] &&
            b->box[i][1] < box[3])
            return 0;
    return 1;
}

/* The label of a point at (px, py): the first of 16 places beside it (the side towards the
 * middle of the plot first, then the other; above, below, then a line further each time) whose text
 * stays in the frame and clear of the labels placed before; the first place if none is. */
static void place_label(FILE *out, label_boxes *b, const frame *f, double px, double py,
                        const char *text)
{
    enum { PLACES = 16 };
    /* above and below, one label height (15 pixels) further each time */
    static const double dys[PLACES / 2] = {-5.0, 14.0, -20.0, 29.0, -35.0, 44.0, -50.0, 59.0};
    double w = plot_text_width(text), box[4] = {0}, x = 0, y = 0;
    int inward = px < f->left + f->width / 2.0 ? 1 : -1, side = inward;
    for (int k = 0; k <= PLACES; k++) {
        int c = k < PLACES ? k : 0; /* none free: the first place */
        side = c % 2 ? -inward : inward;
        x = px + 6.0 * side;
        y = py + dys[c / 2];
        box[0] = side > 0 ? x : x - w;
        box[2] = box[0] + w;
        box[1] = y - PLOT_FONT_SIZE;
        box[3] = y + 3.0;
        if (k == PLACES || box_free(b, f, box))
            break;
    }
    if (b->n < b->max)
        memcpy(b->box[b->n++], box, sizeof box);
    fprintf(out,
            "<text class=\"point-label\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"%s\" "
            "stroke=\"none\" fill=\"#222\">",
            x, y, side > 0 ? "start" : "end");
    plot_xml_text(out, text);
    fputs("</text>\n", out);
}

/* A marker at every point of curve s, with its label beside it. */
static void labelled_points(FILE *out, const sc_plot *p, const layout *l, const plot_axis *x,
                            const plot_axis *y, int s, label_boxes *b)
{
    const sc_plot_series *c = &p->series[s];
    for (size_t i = 0; i < c->n; i++) {
        double px, py;
        if (!curve_point(p, l, x, y, s, i, &px, &py))
            continue;
        plot_marker(out, s, px, py);
        if (c->point_labels[i] && c->point_labels[i][0])
            place_label(out, b, &l->f, px, py, c->point_labels[i]);
    }
}

static void write_series(FILE *out, const sc_plot *p, const layout *l, const plot_axis *x,
                         const plot_axis *y, int s, label_boxes *b)
{
    const sc_plot_series *c = &p->series[s];
    fputs("<g class=\"series\" data-label=\"", out);
    plot_xml_text(out, c->label);
    fprintf(out,
            "\" fill=\"white\" stroke=\"%s\" stroke-width=\"1.6\" "
            "clip-path=\"url(#plot-area)\">\n",
            plot_colour(s));
    int open = 0;
    for (size_t i = 0; i < c->n; i++) {
        double px, py;
        if (!curve_point(p, l, x, y, s, i, &px, &py)) {
            fputs(open ? "\"/>\n" : "", out);
            open = 0;
            continue;
        }
        if (!open)
            fprintf(out, "<polyline fill=\"none\" stroke-dasharray=\"%s\" points=\"%.2f,%.2f",
                    plot_dashes(s), px, py);
        else
            fprintf(out, " %.2f,%.2f", px, py);
        open = 1;
    }
    fputs(open ? "\"/>\n" : "", out);
    if (c->point_labels)
        labelled_points(out, p, l, x, y, s, b);
    else
        curve_markers(out, p, l, x, y, s);
    fputs("</g>\n", out);
    if (p->polar && c->has_incident && isfinite(c->incident_deg))
        incident_arrow(out, l, s, c->incident_deg);
}

/* ---- legend ---- */

static int legend_entries(const sc_plot *p, double *widest)
{
    int n = 0;
    *widest = 0.0;
    for (int s = 0; s < p->n_series; s++)
        if (p->series[s].label && p->series[s].label[0]) {
            double w = plot_text_width(p->series[s].label);
            *widest = w > *widest ? w : *widest;
            n++;
        }
    return n;
}

/* The number of curve points inside the box (x, y, w, h), with a margin of 4 pixels. */
static long points_inside(const sc_plot *p, const layout *l, const plot_axis *x, const plot_axis *y,
                          double bx, double by, double bw, double bh)
{
    long n = 0;
    for (int s = 0; s < p->n_series; s++)
        for (size_t i = 0; i < p->series[s].n; i++) {
            double px, py;
            if (curve_point(p, l, x, y, s, i, &px, &py) && px > bx - 4 && px < bx + bw + 4 &&
                py > by - 4 && py < by + bh + 4)
                n++;
        }
    return n;
}

/* A box clear of the half disc, its labels and the incident arrows. */
static int clear_of_disc(const layout *l, double bx, double by, double bw, double bh)
{
    double nx = fmax(bx, fmin(l->cx, bx + bw)), ny = fmax(by, fmin(l->cy, by + bh));
    return hypot(nx - l->cx, ny - l->cy) > l->radius + 36.0;
}

/* A corner of the plot where the legend hides nothing; 0 if there is none. */
static int place_inside(const sc_plot *p, layout *l, const plot_axis *x, const plot_axis *y)
{
    const frame *f = &l->f;
    double pad = 8.0;
    double xs[2] = {f->left + f->width - l->lw - pad, f->left + pad};
    double ys[2] = {f->top + pad, f->top + f->height - l->lh - pad};
    if (!p->polar && (l->lw > 0.6 * f->width || l->lh > 0.7 * f->height))
        return 0;
    for (int corner = 0; corner < 4; corner++) {
        double bx = xs[corner % 2], by = ys[corner / 2];
        if (p->polar ? (corner < 2 && clear_of_disc(l, bx, by, l->lw, l->lh))
                     : points_inside(p, l, x, y, bx, by, l->lw, l->lh) == 0) {
            l->lx = bx;
            l->ly = by;
            return 1;
        }
    }
    return 0;
}

/* Below the plot, in as many columns as fit; the canvas grows to hold it. */
static void place_below(layout *l, int entries)
{
    double usable = l->width - 32.0;
    if (l->entry_width > usable) {
        l->width = l->entry_width + 32.0;
        usable = l->entry_width;
    }
    l->legend_columns = (int)(usable / l->entry_width);
    l->legend_columns = l->legend_columns < 1         ? 1
                        : l->legend_columns > entries ? entries
                                                      : l->legend_columns;
    int rows = (entries + l->legend_columns - 1) / l->legend_columns;
    l->lw = l->legend_columns * l->entry_width;
    l->lh = rows * LEGEND_ROW + 8.0;
    l->lx = (l->width - l->lw) / 2.0;
    l->ly = l->height;
    l->height += l->lh + 8.0;
}

static void place_legend(const sc_plot *p, layout *l, const plot_axis *x, const plot_axis *y)
{
    double widest;
    int entries = legend_entries(p, &widest);
    l->legend = LEGEND_NONE;
    if (entries == 0)
        return;
    l->entry_width = LEGEND_SAMPLE + 6.0 + widest + 14.0;
    l->legend_columns = 1;
    l->lw = l->entry_width;
    l->lh = entries * LEGEND_ROW + 8.0;
    if (place_inside(p, l, x, y)) {
        l->legend = LEGEND_INSIDE;
        return;
    }
    l->legend = LEGEND_BELOW;
    place_below(l, entries);
}

static void write_legend(FILE *out, const sc_plot *p, const layout *l)
{
    fprintf(out,
            "<g class=\"legend\">\n<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
            "fill=\"white\" fill-opacity=\"0.9\" stroke=\"#bbb\"/>\n",
            l->lx, l->ly, l->lw, l->lh);
    int k = 0;
    for (int s = 0; s < p->n_series; s++) {
        if (!p->series[s].label || !p->series[s].label[0])
            continue;
        double x = l->lx + 6.0 + (k % l->legend_columns) * l->entry_width;
        double y = l->ly + 4.0 + LEGEND_ROW / 2.0 + (k / l->legend_columns) * LEGEND_ROW;
        fprintf(out,
                "<g stroke=\"%s\" fill=\"white\" stroke-width=\"1.6\"><line x1=\"%.2f\" "
                "y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke-dasharray=\"%s\"/>\n",
                plot_colour(s), x, y, x + LEGEND_SAMPLE, y, plot_dashes(s));
        plot_marker(out, s, x + LEGEND_SAMPLE / 2.0, y);
        fprintf(out, "</g>\n<text x=\"%.2f\" y=\"%.2f\" fill=\"#222\">", x + LEGEND_SAMPLE + 6.0,
                y + 4.0);
        plot_xml_text(out, p->series[s].label);
        fputs("</text>\n", out);
        k++;
    }
    fputs("</g>\n", out);
}

/* ---- labels ---- */

static void write_labels(FILE *out, const sc_plot *p, const layout *l)
{
    if (p->title)
        plot_text_at(out, "title", l->width / 2.0, 26, " font-size=\"15\"", p->title);
    if (p->polar) { /* the angle on the left, the radius on the right, under the horizon */
        if (p->xlabel)
            plot_text_at(out, "xlabel", l->cx - l->radius / 2.0, l->labels_y, "", p->xlabel);
        if (p->ylabel)
            plot_text_at(out, "ylabel", l->cx + l->radius / 2.0, l->labels_y, "", p->ylabel);
        return;
    }
    if (p->xlabel)
        plot_text_at(out, "xlabel", l->f.left + l->f.width / 2.0, l->labels_y, "", p->xlabel);
    if (p->ylabel) {
        double cy = l->f.top + l->f.height / 2.0;
        char rotate[64];
        snprintf(rotate, sizeof rotate, " transform=\"rotate(-90 18 %.2f)\"", cy);
        plot_text_at(out, "ylabel", 18, cy, rotate, p->ylabel);
    }
}

/* ---- the document ---- */

static void make_layout(const sc_plot *p, layout *l, const plot_axis *x, const plot_axis *y)
{
    memset(l, 0, sizeof *l);
    l->width = WIDTH;
    if (p->polar) {
        l->radius = (WIDTH - 2.0 * POLAR_SIDE) / 2.0;
        l->cx = WIDTH / 2.0;
        l->cy = MARGIN_TOP + 30.0 + l->radius;
        l->f = (frame){l->cx - l->radius, l->cy - l->radius, 2.0 * l->radius, l->radius};
        l->labels_y = l->cy + 38.0;
        l->height = l->cy + 52.0;
    } else {
        l->f = (frame){MARGIN_LEFT, MARGIN_TOP, WIDTH - MARGIN_LEFT - MARGIN_RIGHT,
                       HEIGHT - MARGIN_TOP - MARGIN_BOTTOM};
        l->labels_y = HEIGHT - 14.0;
        l->height = HEIGHT;
    }
    place_legend(p, l, x, y);
    double title = p->title ? plot_text_width(p->title) * 15.0 / PLOT_FONT_SIZE + 24.0 : 0.0;
    double shift = title > l->width ? (title - l->width) / 2.0 : 0.0;
    if (shift > 0.0) { /* a long title widens the canvas on both sides */
        l->width = title;
        l->f.left += shift;
        l->cx += shift;
        l->lx += shift;
    }
}

static void write_clip(FILE *out, const sc_plot *p, const layout *l)
{
    fputs("<defs><clipPath id=\"plot-area\">", out);
    if (p->polar) /* the half disc, a little enlarged for the line width */
        fprintf(out, "<path d=\"M %.2f %.2f A %.2f %.2f 0 0 1 %.2f %.2f Z\"/>",
                l->cx - l->radius - 2, l->cy + 1, l->radius + 2, l->radius + 2,
                l->cx + l->radius + 2, l->cy + 1);
    else
        fprintf(out, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/>", l->f.left,
                l->f.top, l->f.width, l->f.height);
    fputs("</clipPath></defs>\n", out);
}

int sc_plot_write_svg(FILE *out, const sc_plot *p)
{
    plot_axis x = {0}, y = {0};
    if (p->polar) {
        axis_from_data(&y, p, 1, 0, isnan(p->ymin) ? 0.0 : p->ymin, p->ymax, 0);
    } else { /* x spans the swept range exactly; y is widened to whole ticks */
        axis_from_data(&x, p, 0, p->xlog, NAN, NAN, 1);
        axis_from_data(&y, p, 1, p->ylog, p->ymin, p->ymax, 0);
    }
    layout l;
    make_layout(p, &l, &x, &y);
    plot_svg_begin(out, l.width, l.height, p->title ? p->title : "shadecalc plot");
    write_clip(out, p, &l);
    if (p->polar) {
        polar_axes(out, &l, &y);
        polar_clip_note(out, p, &l, &y);
    } else
        cartesian_axes(out, &l.f, &x, &y);
    if (!p->polar)
        reference_line(out, p, &l.f, &y);
    label_boxes boxes = {NULL, 0, 0}; /* without memory, labels are placed without avoiding */
    for (int s = 0; s < p->n_series; s++)
        boxes.max += p->series[s].point_labels ? p->series[s].n : 0;
    boxes.box = boxes.max ? malloc(boxes.max * sizeof *boxes.box) : NULL;
    boxes.max = boxes.box ? boxes.max : 0;
    for (int s = 0; s < p->n_series; s++)
        write_series(out, p, &l, &x, &y, s, &boxes);
    free(boxes.box);
    if (l.legend != LEGEND_NONE)
        write_legend(out, p, &l);
    write_labels(out, p, &l);
    fputs("</svg>\n", out);
    return fflush(out) == EOF || ferror(out) ? -1 : 0;
}
