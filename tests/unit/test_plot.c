/* SVG plots (shadecalc/plot.h): nice-number ticks against hand-worked cases (Heckbert 1990),
 * log ticks, and the document: one polyline run per unbroken stretch of a curve, every shown
 * point drawn, text escaped, polar points on the unit circle where the value is the radius. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/plot.h"

static void assert_ticks(const double *got, int n, const double *want, int m)
{
    assert_int_equal(n, m);
    for (int i = 0; i < n; i++)
        if (fabs(got[i] - want[i]) > 1e-12 * fmax(1.0, fabs(want[i])))
            fail_msg("tick %d: got %.17g, want %.17g", i, got[i], want[i]);
}

static void linear_ticks_are_nice_numbers(void **state)
{
    (void)state;
    double t[32], step;
    /* range 1 -> nice 1, step nice(1/5 = 0.2) = 0.2 */
    int n = sc_plot_ticks(0.0, 1.0, 5, t, 32, &step);
    assert_ticks(t, n, (const double[]){0, 0.2, 0.4, 0.6, 0.8, 1.0}, 6);
    assert_true(fabs(step - 0.2) < 1e-15);
    /* 0..12: range nice(12) = 20, step nice(20/6 = 3.33) = 5; covers 12 with 15 */
    n = sc_plot_ticks(0.0, 12.0, 6, t, 32, &step);
    assert_ticks(t, n, (const double[]){0, 5, 10, 15}, 4);
    /* -90..90: range nice(180) = 200, step nice(200/6 = 33.3) = 50 */
    n = sc_plot_ticks(-90.0, 90.0, 6, t, 32, &step);
    assert_ticks(t, n, (const double[]){-100, -50, 0, 50, 100}, 5);
    /* 0.013..0.0137: range nice(0.0007) = 0.001, step nice(0.001/6) = 0.0002; 65 × 0.0002
     * rounds above 0.013, so the first tick is 64 × 0.0002 */
    n = sc_plot_ticks(0.013, 0.0137, 6, t, 32, &step);
    assert_true(t[0] <= 0.013 && t[n - 1] >= 0.0137);
    assert_true(fabs(step - 0.0002) < 1e-18);
}

static void ticks_never_print_minus_zero(void **state)
{
    (void)state;
    double t[32], step;
    int n = sc_plot_ticks(-1.0, 1.0, 4, t, 32, &step);
    for (int i = 0; i < n; i++)
        if (t[i] == 0.0)
            assert_false(signbit(t[i]));
}

static void log_ticks_are_decades(void **state)
{
    (void)state;
    double t[64];
    int n = sc_plot_log_ticks(1.0, 1e4, t, 64);
    assert_ticks(t, n, (const double[]){1, 10, 100, 1000, 10000}, 5);
    n = sc_plot_log_ticks(3.0, 40.0, t, 64); /* two decades: 2× and 5× too */
    assert_ticks(t, n, (const double[]){1, 2, 5, 10, 20, 50, 100}, 7);
    n = sc_plot_log_ticks(1e-30, 1e30, t, 64); /* sixty decades: every sixth labelled */
    assert_true(n <= 11);
    assert_true(t[0] <= 1e-30 && t[n - 1] >= 1e30);
}

/* ---- the document ---- */

/* What a writer wrote, read back from a temporary file as one string. */
static char *read_back(FILE *f)
{
    long size = ftell(f);
    assert_true(size > 0);
    char *text = malloc((size_t)size + 1);
    assert_non_null(text);
    rewind(f);
    assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    return text;
}

static char *write_to_text(const sc_plot *p)
{
    FILE *out = tmpfile();
    assert_non_null(out);
    assert_int_equal(sc_plot_write_svg(out, p), 0);
    return read_back(out);
}

static int count(const char *text, const char *what)
{
    int n = 0;
    for (const char *p = strstr(text, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

/* Points of the polylines of the series labelled `label`. */
static int points_of(const char *text, const char *label)
{
    char key[128];
    snprintf(key, sizeof key, "data-label=\"%s\"", label);
    const char *g = strstr(text, key);
    assert_non_null(g);
    const char *end = strstr(g, "</g>");
    int n = 0;
    for (const char *p = strstr(g, "points=\""); p && p < end; p = strstr(p + 1, "points=\"")) {
        const char *close = strchr(p + 8, '"');
        for (const char *c = p + 8; c < close; c++)
            n += *c == ',';
    }
    return n;
}

static void every_point_is_drawn_and_gaps_break_the_line(void **state)
{
    (void)state;
    double x[50], a[50], b[50];
    for (int i = 0; i < 50; i++) {
        x[i] = i;
        a[i] = sin(i / 5.0);
        b[i] = i == 20 ? NAN : i == 30 ? INFINITY : cos(i / 5.0);
    }
    const sc_plot_series s[] = {{.label = "sin", .x = x, .y = a, .n = 50},
                                {.label = "cos & <gaps>", .x = x, .y = b, .n = 50}};
    sc_plot p = {.title = "a \"title\"",
                 .xlabel = "x",
                 .ylabel = "y",
                 .ymin = NAN,
                 .ymax = NAN,
                 .series = s,
                 .n_series = 2};
    char *text = write_to_text(&p);
    assert_int_equal(count(text, "class=\"series\""), 2);
    assert_int_equal(points_of(text, "sin"), 50);
    assert_int_equal(points_of(text, "cos &amp; &lt;gaps&gt;"), 48);
    assert_int_equal(count(text, "<polyline"), 1 + 3);
    assert_non_null(strstr(text, "a &quot;title&quot;"));
    assert_non_null(strstr(text, "class=\"legend\""));
    free(text);
}

static void log_axis_drops_what_it_cannot_show(void **state)
{
    (void)state;
    const double x[] = {1, 10, 100, 1000}, y[] = {0.0, 1e-3, -1.0, 1e3};
    const sc_plot_series s[] = {{.label = NULL, .x = x, .y = y, .n = 4}};
    sc_plot p = {.xlog = 1, .ylog = 1, .ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    assert_int_equal(points_of(text, ""), 2);
    assert_null(strstr(text, "class=\"legend\"")); /* no labels, no legend */
    assert_null(strstr(text, "nan"));
    free(text);
}

/* Point labels: one text per labelled shown point, escaped, on the side of the point that
 * keeps it inside the frame; a curve without them has none. */
static void point_labels_mark_every_point(void **state)
{
    (void)state;
    const double x[] = {1, NAN, 10, 100}, y[] = {1, NAN, 3, 2};
    const char *const labels[] = {"left", NULL, NULL, "b<c"};
    const sc_plot_series s[] = {{.label = "k", .x = x, .y = y, .n = 4, .point_labels = labels},
                                {.label = "plain", .x = x, .y = y, .n = 4}};
    sc_plot p = {.xlog = 1, .ymin = NAN, .ymax = NAN, .series = s, .n_series = 2};
    char *text = write_to_text(&p);
    assert_int_equal(count(text, "class=\"point-label\""), 2);
    const char *left = strstr(text, ">left</text>"), *right = strstr(text, ">b&lt;c</text>");
    assert_non_null(left);
    assert_non_null(right);
    /* the leftmost point's label reads rightwards from it, the rightmost one's leftwards */
    const char *start = strstr(text, "class=\"point-label\"");
    assert_true(start < left && strstr(start, "text-anchor=\"start\"") < left);
    const char *second = strstr(start + 1, "class=\"point-label\"");
    assert_true(second < right && strstr(second, "text-anchor=\"end\"") < right);
    free(text);
}

/* Labels of coinciding points take different places: no two of their boxes (width at most
 * PLOT_CHAR_WIDTH 7.2 a character, 15 pixels high) intersect. */
static void point_labels_do_not_overlap(void **state)
{
    (void)state;
    const double x[] = {1, 1, 1, 1, 10}, y[] = {5, 5, 5, 5, 1};
    const char *const labels[] = {"first", "second", "third", "fourth", "far"};
    const sc_plot_series s[] = {{.label = "k", .x = x, .y = y, .n = 5, .point_labels = labels}};
    sc_plot p = {.ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    double box[4][4];
    const char *at = text;
    for (int i = 0; i < 4; i++) {
        at = strstr(at + 1, "class=\"point-label\"");
        assert_non_null(at);
        double tx, ty;
        char anchor[8];
        assert_int_equal(sscanf(at,
                                "class=\"point-label\" x=\"%lf\" y=\"%lf\" text-anchor=\"%5[a-z]",
                                &tx, &ty, anchor),
                         3);
        double w = 7.2 * (double)strlen(labels[i]);
        box[i][0] = strcmp(anchor, "end") == 0 ? tx - w : tx;
        box[i][1] = ty - 12.0;
        box[i][2] = box[i][0] + w;
        box[i][3] = ty + 3.0;
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < i; j++)
            assert_false(box[i][0] < box[j][2] && box[j][0] < box[i][2] && box[i][1] < box[j][3] &&
                         box[j][1] < box[i][3]);
    free(text);
}

/* The polar plot puts value r at angle θ from the vertical: the points of a constant curve lie
 * on one circle about the centre. */
static void polar_points_lie_on_a_circle(void **state)
{
    (void)state;
    double theta[19], r[19];
    for (int i = 0; i < 19; i++) {
        theta[i] = -90.0 + 10.0 * i;
        r[i] = 1.0;
    }
    const sc_plot_series s[] = {{.x = theta, .y = r, .n = 19}};
    sc_plot p = {.polar = 1, .ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    assert_int_equal(points_of(text, ""), 17); /* ±90°, on the horizon, are not drawn */
    const char *pts = strstr(strstr(text, "class=\"series\""), "points=\"") + 8;
    double px[17], py[17];
    for (int i = 0; i < 17; i++) { /* θ = −80° … 80° */
        char *end;
        px[i] = strtod(pts, &end);
        py[i] = strtod(end + 1, &end);
        pts = end;
    }
    /* θ = 0 is straight up from the centre, θ = 80° at R sin 80° to its right */
    double cx = px[8], radius = (px[16] - cx) / sin(80.0 * 0.017453292519943295),
           cy = py[8] + radius;
    assert_true(radius > 50.0);
    for (int i = 0; i < 17; i++) {
        double d = hypot(px[i] - cx, py[i] - cy);
        if (fabs(d - radius) > 0.05) /* two decimals in the file */
            fail_msg("point %d at distance %g, want %g", i, d, radius);
    }
    free(text);
}

static void fixed_y_range_is_kept(void **state)
{
    (void)state;
    const double x[] = {0, 1}, y[] = {0, 1e4};
    const sc_plot_series s[] = {{.label = "f", .x = x, .y = y, .n = 2}};
    sc_plot p = {.ymin = 0.0, .ymax = 2.0, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    assert_non_null(strstr(text, ">2.0</text>"));
    assert_null(strstr(text, ">10000</text>"));
    assert_non_null(strstr(text, "clip-path=\"url(#plot-area)\""));
    free(text);
}

static void write_failure_is_reported(void **state)
{
    (void)state;
    FILE *full = fopen("/dev/full", "w");
    if (!full)
        skip();
    const double x[] = {0, 1}, y[] = {0, 1};
    const sc_plot_series s[] = {{.label = "f", .x = x, .y = y, .n = 2}};
    sc_plot p = {.ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    assert_int_equal(sc_plot_write_svg(full, &p), -1);
    fclose(full);
}

/* The number after `key="` at or after `from`. */
static double attr(const char *from, const char *key)
{
    char pattern[64];
    snprintf(pattern, sizeof pattern, "%s=\"", key);
    const char *at = strstr(from, pattern);
    assert_non_null(at);
    return strtod(at + strlen(pattern), NULL);
}

/* Curves that coincide are still told apart: every curve has its own colour, dash pattern and
 * marker, and the legend shows each. */
static void coinciding_curves_have_distinct_styles(void **state)
{
    (void)state;
    double x[40], y[40];
    for (int i = 0; i < 40; i++) {
        x[i] = i;
        y[i] = 1.0 / (1.0 + i);
    }
    sc_plot_series s[6];
    char labels[6][8];
    for (int k = 0; k < 6; k++) {
        snprintf(labels[k], sizeof labels[k], "c%d", k);
        s[k] = (sc_plot_series){.label = labels[k], .x = x, .y = y, .n = 40};
    }
    sc_plot p = {.ymin = NAN, .ymax = NAN, .series = s, .n_series = 6};
    char *text = write_to_text(&p);
    char seen[6][64];
    const char *g = text;
    for (int k = 0; k < 6; k++) {
        g = strstr(g + 1, "class=\"series\"");
        const char *stroke = strstr(g, "stroke=\"") + 8,
                   *dash = strstr(g, "stroke-dasharray=\"") + 18;
        snprintf(seen[k], sizeof seen[k], "%.7s|%.*s", stroke, (int)(strchr(dash, '"') - dash),
                 dash);
        for (int j = 0; j < k; j++)
            if (strcmp(seen[j], seen[k]) == 0)
                fail_msg("curves %d and %d share the style %s", j, k, seen[k]);
    }
    assert_true(count(text, "<path d=") >= 6 * 8); /* eight markers a curve */
    free(text);
}

/* A legend entry wider than the plot goes below it, and the canvas grows to hold it. */
static void long_legend_is_not_clipped(void **state)
{
    (void)state;
    const double x[] = {0, 1}, y[] = {0, 1};
    char label[201];
    memset(label, 'w', 200);
    label[200] = '\0';
    const sc_plot_series s[] = {{.label = label, .x = x, .y = y, .n = 2}};
    sc_plot p = {.ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    double width = attr(text, "width"), height = attr(text, "height");
    const char *legend = strstr(text, "class=\"legend\"");
    assert_non_null(legend);
    double lx = attr(legend, "x"), lw = attr(legend, "width"), ly = attr(legend, "y");
    assert_true(lx >= 0.0 && lx + lw <= width);
    assert_true(lw >= 200 * 6.0); /* room for every character */
    assert_true(ly + attr(legend, "height") <= height);
    free(text);
}

/* A tight x axis labels both of its ends, even between nice ticks. */
static void both_ends_of_x_are_labelled(void **state)
{
    (void)state;
    const double x[] = {0, 89}, y[] = {0, 1};
    const sc_plot_series s[] = {{.x = x, .y = y, .n = 2}};
    sc_plot p = {.ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    assert_non_null(strstr(text, ">0</text>"));
    assert_non_null(strstr(text, ">89</text>"));
    free(text);
}

static void reference_line_is_drawn_inside_the_range(void **state)
{
    (void)state;
    const double x[] = {0, 1}, y[] = {0, 2};
    const sc_plot_series s[] = {{.x = x, .y = y, .n = 2}};
    sc_plot p = {.ymin = NAN,
                 .ymax = NAN,
                 .series = s,
                 .n_series = 1,
                 .has_reference = 1,
                 .reference_y = 1.0,
                 .reference_label = "a = 1"};
    char *text = write_to_text(&p);
    assert_non_null(strstr(text, "class=\"reference\""));
    assert_non_null(strstr(text, ">a = 1</text>"));
    p.reference_y = 5.0; /* outside [0, 2]: not drawn */
    free(text);
    text = write_to_text(&p);
    assert_null(strstr(text, "class=\"reference\""));
    free(text);
}

/* The polar plot's radius comes from the points within 80° of the normal: a grazing spike is
 * clipped (and said so) instead of shrinking the lobe. */
static void polar_spike_at_grazing_is_clipped(void **state)
{
    (void)state;
    double theta[181], r[181];
    for (int i = 0; i < 181; i++) {
        theta[i] = i - 90.0;
        r[i] = fabs(theta[i]) > 85.0 ? 1000.0 : 1.0;
    }
    const sc_plot_series s[] = {{.x = theta, .y = r, .n = 181}};
    sc_plot p = {.polar = 1, .ymin = NAN, .ymax = NAN, .series = s, .n_series = 1};
    char *text = write_to_text(&p);
    assert_non_null(strstr(text, "class=\"note\""));
    assert_null(strstr(text, ">1000</text>"));
    free(text);
}

static char *heatmap_text(const sc_heatmap *h)
{
    FILE *out = tmpfile();
    assert_non_null(out);
    assert_int_equal(sc_plot_write_heatmap_svg(out, h), 0);
    return read_back(out);
}

/* One cell per sample; the second variable grows upward; the largest value takes the top
 * colour of the bar and, on a linear scale, 0 the bottom one. */
static void heatmap_cells_grow_upward(void **state)
{
    (void)state;
    const double x[] = {0, 1, 2}, y[] = {0, 10};
    const double v[] = {0, 1, 2, 3, 4, 5}; /* v[j·3 + i] */
    sc_heatmap h = {
        .x = x, .y = y, .nx = 3, .ny = 2, .values = v, .tone = SC_TONE_LINEAR, .value_label = "f"};
    char *text = heatmap_text(&h);
    const char *cells = strstr(text, "class=\"cells\"");
    assert_int_equal(count(cells, "<rect") - count(strstr(cells, "</g>"), "<rect"), 6);
    const char *first = strstr(cells, "<rect"), *fourth = first;
    for (int k = 0; k < 3; k++)
        fourth = strstr(fourth + 1, "<rect");
    assert_true(attr(first, "y") > attr(fourth, "y"));       /* y[0] below y[1] */
    assert_non_null(strstr(first, "fill=\"#440154\""));      /* 0: viridis' first colour */
    assert_non_null(strstr(fourth + 1, "fill=\"#fde725\"")); /* 5 is the top */
    free(text);
}

static void heatmap_rejects_an_empty_range(void **state)
{
    (void)state;
    const double x[] = {1, 1}, y[] = {0, 1}, v[] = {0, 0, 0, 0};
    sc_heatmap h = {.x = x, .y = y, .nx = 2, .ny = 2, .values = v};
    FILE *out = fopen("/dev/null", "w");
    assert_int_equal(sc_plot_write_heatmap_svg(out, &h), -1);
    fclose(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(coinciding_curves_have_distinct_styles),
        cmocka_unit_test(long_legend_is_not_clipped),
        cmocka_unit_test(both_ends_of_x_are_labelled),
        cmocka_unit_test(reference_line_is_drawn_inside_the_range),
        cmocka_unit_test(polar_spike_at_grazing_is_clipped),
        cmocka_unit_test(heatmap_cells_grow_upward),
        cmocka_unit_test(heatmap_rejects_an_empty_range),
        cmocka_unit_test(linear_ticks_are_nice_numbers),
        cmocka_unit_test(ticks_never_print_minus_zero),
        cmocka_unit_test(log_ticks_are_decades),
        cmocka_unit_test(every_point_is_drawn_and_gaps_break_the_line),
        cmocka_unit_test(log_axis_drops_what_it_cannot_show),
        cmocka_unit_test(point_labels_mark_every_point),
        cmocka_unit_test(point_labels_do_not_overlap),
        cmocka_unit_test(polar_points_lie_on_a_circle),
        cmocka_unit_test(fixed_y_range_is_kept),
        cmocka_unit_test(write_failure_is_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
