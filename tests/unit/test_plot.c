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

static char *write_to_text(const sc_plot *p)
{
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    assert_int_equal(sc_plot_write_svg(out, p), 0);
    fclose(out);
    return text;
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
    const sc_plot_series s[] = {{"sin", x, a, 50}, {"cos & <gaps>", x, b, 50}};
    sc_plot p = {"a \"title\"", "x", "y", 0, 0, 0, NAN, NAN, s, 2};
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
    const sc_plot_series s[] = {{NULL, x, y, 4}};
    sc_plot p = {NULL, NULL, NULL, 1, 1, 0, NAN, NAN, s, 1};
    char *text = write_to_text(&p);
    assert_int_equal(points_of(text, ""), 2);
    assert_null(strstr(text, "class=\"legend\"")); /* no labels, no legend */
    assert_null(strstr(text, "nan"));
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
    const sc_plot_series s[] = {{NULL, theta, r, 19}};
    sc_plot p = {NULL, NULL, NULL, 0, 0, 1, NAN, NAN, s, 1};
    char *text = write_to_text(&p);
    const char *pts = strstr(strstr(text, "class=\"series\""), "points=\"") + 8;
    double px[19], py[19];
    for (int i = 0; i < 19; i++) {
        char *end;
        px[i] = strtod(pts, &end);
        py[i] = strtod(end + 1, &end);
        pts = end;
    }
    double cx = px[9], cy = py[18]; /* θ = 0 is straight up; θ = 90° level with the centre */
    double radius = cy - py[9];
    assert_true(radius > 50.0);
    for (int i = 0; i < 19; i++) {
        double d = hypot(px[i] - cx, py[i] - cy);
        if (fabs(d - radius) > 0.02) /* two decimals in the file */
            fail_msg("point %d at distance %g, want %g", i, d, radius);
    }
    free(text);
}

static void fixed_y_range_is_kept(void **state)
{
    (void)state;
    const double x[] = {0, 1}, y[] = {0, 1e4};
    const sc_plot_series s[] = {{"f", x, y, 2}};
    sc_plot p = {NULL, NULL, NULL, 0, 0, 0, 0.0, 2.0, s, 1};
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
    const sc_plot_series s[] = {{"f", x, y, 2}};
    sc_plot p = {NULL, NULL, NULL, 0, 0, 0, NAN, NAN, s, 1};
    assert_int_equal(sc_plot_write_svg(full, &p), -1);
    fclose(full);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_ticks_are_nice_numbers),
        cmocka_unit_test(ticks_never_print_minus_zero),
        cmocka_unit_test(log_ticks_are_decades),
        cmocka_unit_test(every_point_is_drawn_and_gaps_break_the_line),
        cmocka_unit_test(log_axis_drops_what_it_cannot_show),
        cmocka_unit_test(polar_points_lie_on_a_circle),
        cmocka_unit_test(fixed_y_range_is_kept),
        cmocka_unit_test(write_failure_is_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
