/* Sweeps (shadecalc/sweep.h): variables and their values against closed forms, the grid's
 * order, `$name` substitution, the row formats, the runner (rows in order on any number of
 * threads, failures, memory that does not grow with rows) and the EXR of a two-variable sweep
 * read back through OpenEXR. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "shadecalc/sweep.h"

static char err[512];

static sc_sweep_var var(const char *arg)
{
    sc_sweep_var v;
    if (sc_sweep_var_parse(arg, &v, err, sizeof err) < 0)
        fail_msg("%s: %s", arg, err);
    return v;
}

static void grid_of(sc_sweep_grid *g, const char *const *args, int n)
{
    g->n = 0;
    for (int i = 0; i < n; i++) {
        sc_sweep_var v = var(args[i]);
        assert_int_equal(sc_sweep_grid_add(g, &v, err, sizeof err), 0);
    }
}

/* ---- variables ---- */

static void range_includes_both_ends(void **state)
{
    (void)state;
    sc_sweep_var v = var("x=0:1:11");
    assert_string_equal(v.name, "x");
    assert_int_equal(v.count, 11);
    for (long i = 0; i < 11; i++) /* i/10 correctly rounded, as written in decimal */
        assert_true(sc_sweep_var_value(&v, i) == (double)i / 10.0);
    sc_sweep_var w = var("theta_o=-90:90:181");
    assert_true(sc_sweep_var_value(&w, 0) == -90.0);
    assert_true(sc_sweep_var_value(&w, 90) == 0.0);
    assert_true(sc_sweep_var_value(&w, 180) == 90.0);
    sc_sweep_var one = var("r=5:7:1");
    assert_true(sc_sweep_var_value(&one, 0) == 5.0);
}

static void log_spacing_is_geometric(void **state)
{
    (void)state;
    sc_sweep_var v = var("m=1:10000:5");
    assert_int_equal(sc_sweep_var_set_log(&v, err, sizeof err), 0);
    const double want[] = {1, 10, 100, 1000, 10000};
    for (int i = 0; i < 5; i++) /* decades exactly */
        assert_true(sc_sweep_var_value(&v, i) == want[i]);
    sc_sweep_var w = var("a=2:3:7"); /* ratio (3/2)^(1/6) */
    assert_int_equal(sc_sweep_var_set_log(&w, err, sizeof err), 0);
    for (int i = 0; i < 7; i++)
        assert_true(fabs(sc_sweep_var_value(&w, i) - 2.0 * pow(1.5, i / 6.0)) <= 1e-15 * 3.0);
    sc_sweep_var neg = var("a=-8:-0.5:5"); /* ratio 1/16: -8 -4 -2 -1 -0.5 */
    assert_int_equal(sc_sweep_var_set_log(&neg, err, sizeof err), 0);
    assert_true(fabs(sc_sweep_var_value(&neg, 2) + 2.0) <= 4e-15);
    /* 10^log10(DBL_MAX) rounds past DBL_MAX: the values stay within the ends (a fuzz finding) */
    sc_sweep_var top = var("k=1.7976931348623157e308:1.7976931348623157e308:3");
    assert_int_equal(sc_sweep_var_set_log(&top, err, sizeof err), 0);
    for (int i = 0; i < 3; i++)
        assert_true(sc_sweep_var_value(&top, i) == DBL_MAX);
}

static void log_spacing_needs_ends_of_one_sign(void **state)
{
    (void)state;
    sc_sweep_var v = var("x=0:1:3");
    assert_int_equal(sc_sweep_var_set_log(&v, err, sizeof err), -1);
    assert_non_null(strstr(err, "x=0:1"));
    sc_sweep_var w = var("x=-1:1:3");
    assert_int_equal(sc_sweep_var_set_log(&w, err, sizeof err), -1);
    sc_sweep_var l = var("x=1,2,3");
    assert_int_equal(sc_sweep_var_set_log(&l, err, sizeof err), -1);
    assert_non_null(strstr(err, "list"));
    sc_sweep_var_free(&l);
}

static void list_keeps_its_order(void **state)
{
    (void)state;
    sc_sweep_var v = var("theta_i=60,0,30,1e-3");
    assert_int_equal(v.spacing, SC_SPACING_LIST);
    assert_int_equal(v.count, 4);
    const double want[] = {60, 0, 30, 1e-3};
    for (int i = 0; i < 4; i++)
        assert_true(sc_sweep_var_value(&v, i) == want[i]);
    sc_sweep_var_free(&v);
    sc_sweep_var one = var("k=2.5");
    assert_int_equal(one.count, 1);
    assert_true(sc_sweep_var_value(&one, 0) == 2.5);
    sc_sweep_var_free(&one);
}

static void bad_variables_are_named(void **state)
{
    (void)state;
    static const char *const bad[] = {"x",         "=1:2:3",
                                      "1x=1:2:3",  "x=1:2",
                                      "x=1:2:3:4", "x=a:2:3",
                                      "x=1:2:0",   "x=1:2:-1",
                                      "x=1:2:1.5", "x=1,,2",
                                      "x=",        "x=1,b",
                                      "x=inf:1:2", "x=1:nan:2",
                                      "x y=1",     "x=1:2:99999999999999999999",
                                      "x= 1:2:3",  "a_very_long_name_of_more_than_31_chars=1"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sc_sweep_var v;
        if (sc_sweep_var_parse(bad[i], &v, err, sizeof err) == 0)
            fail_msg("'%s' was accepted", bad[i]);
        assert_non_null(strstr(err, "--var"));
    }
}

/* ---- the grid ---- */

static void first_variable_varies_fastest(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"a=0:2:3", "b=10,20", "c=7"}, 3);
    assert_int_equal(sc_sweep_grid_rows(&g), 6);
    for (uint64_t row = 0; row < 6; row++) {
        double v[3];
        sc_sweep_grid_point(&g, row, v);
        assert_true(v[0] == (double)(row % 3));
        assert_true(v[1] == (row / 3 == 0 ? 10.0 : 20.0));
        assert_true(v[2] == 7.0);
    }
    sc_sweep_grid_free(&g);
}

static void grid_refuses_duplicates_and_too_many_rows(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:1:3"}, 1);
    sc_sweep_var again = var("x=5,6");
    assert_int_equal(sc_sweep_grid_add(&g, &again, err, sizeof err), -1);
    assert_non_null(strstr(err, "twice"));
    sc_sweep_grid_free(&g);
    grid_of(&g, (const char *const[]){"a=0:1:100000000", "b=0:1:100000000"}, 2);
    assert_int_equal(sc_sweep_grid_rows(&g), 0); /* 10^16 > 2^52 */
    sc_sweep_grid_free(&g);
    sc_sweep_grid none = {.n = 0};
    assert_int_equal(sc_sweep_grid_rows(&none), 1);
}

/* ---- substitution ---- */

static void substitution_writes_round_trip_values(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"r=0:1:4", "m=8,32", "rr=5"}, 3);
    const double values[3] = {1.0 / 3.0, 32, 5};
    char out[256];
    assert_int_equal(sc_sweep_substitute("point pos=0,0,$r I=1 m=${m}0 $rr", &g, values, out,
                                         sizeof out, err, sizeof err),
                     0);
    assert_string_equal(out, "point pos=0,0,0.3333333333333333 I=1 m=320 5");
    assert_true(strtod(out + strlen("point pos=0,0,"), NULL) == 1.0 / 3.0);
    sc_sweep_grid_free(&g);
}

static void substitution_errors(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"r=0:1:4"}, 1);
    const double values[1] = {0.5};
    char out[16];
    assert_int_equal(sc_sweep_substitute("pos=$q", &g, values, out, sizeof out, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "$q"));
    assert_int_equal(sc_sweep_substitute("a $ b", &g, values, out, sizeof out, err, sizeof err),
                     -1);
    assert_int_equal(sc_sweep_substitute("${r", &g, values, out, sizeof out, err, sizeof err), -1);
    assert_int_equal(
        sc_sweep_substitute("0123456789 $r $r", &g, values, out, sizeof out, err, sizeof err), -1);
    assert_non_null(strstr(err, "too long"));
    sc_sweep_grid_free(&g);
}

/* ---- rows ---- */

static const char *const names3[] = {"x", "value", "y"};

static void csv_and_tsv_rows(void **state)
{
    (void)state;
    sc_sweep_table t = {SC_SWEEP_CSV, SC_HIGHP, names3, 1, 2};
    char buf[256];
    const double vars[1] = {0.1}, results[2] = {(double)0.1f, -INFINITY}; /* highp: floats */
    assert_int_equal(sc_sweep_format_row(buf, sizeof buf, &t, vars, results), 13);
    /* the variable as a double, the results as highp values (0.1f prints as 0.1) */
    assert_string_equal(buf, "0.1,0.1,-inf\n");
    t.format = SC_SWEEP_TSV;
    sc_sweep_format_row(buf, sizeof buf, &t, vars, results);
    assert_string_equal(buf, "0.1\t0.1\t-inf\n");
    const double third[1] = {1.0 / 3.0}, r3[2] = {(double)(1.0f / 3.0f), 30};
    t.format = SC_SWEEP_CSV;
    sc_sweep_format_row(buf, sizeof buf, &t, third, r3);
    assert_string_equal(buf, "0.3333333333333333,0.33333334,30\n");
    assert_true(sc_sweep_format_row(buf, 8, &t, third, r3) < 0); /* does not fit */
}

static void jsonl_rows_quote_what_json_lacks(void **state)
{
    (void)state;
    sc_sweep_table t = {SC_SWEEP_JSONL, SC_DOUBLE, names3, 1, 2};
    char buf[256];
    const double vars[1] = {2}, results[2] = {NAN, 0.25};
    sc_sweep_format_row(buf, sizeof buf, &t, vars, results);
    assert_string_equal(buf, "{\"x\": 2, \"value\": \"nan\", \"y\": 0.25}\n");
    assert_true(strlen(buf) < sc_sweep_row_max(&t));
}

static void header_lists_the_columns(void **state)
{
    (void)state;
    FILE *f = tmpfile();
    sc_sweep_table t = {SC_SWEEP_CSV, SC_HIGHP, names3, 1, 2};
    assert_int_equal(sc_sweep_write_header(f, &t), 0);
    t.format = SC_SWEEP_JSONL; /* none */
    assert_int_equal(sc_sweep_write_header(f, &t), 0);
    rewind(f);
    char line[64] = "";
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "x,value,y\n");
    assert_null(fgets(line, sizeof line, f));
    fclose(f);
}

/* ---- the runner ---- */

/* f(x, y) = x² + 3y (exact in double for the grids below), and row checks. */
typedef struct {
    uint64_t next_row; /* consume must see rows in order */
    int out_of_order;
    double fail_at; /* eval fails when x equals this */
} runner_state;

static int eval_poly(void *user, int worker, const double *vars, double *results, char *e,
                     size_t size)
{
    (void)worker;
    const runner_state *s = user;
    if (vars[0] == s->fail_at) {
        snprintf(e, size, "x=%g is refused", vars[0]);
        return -1;
    }
    results[0] = vars[0] * vars[0] + 3.0 * vars[1];
    return 0;
}

/* The same through eval_block: count rows at once, the index of the first that fails. */
static int eval_poly_block(void *user, int worker, int count, const double *vars, double *results,
                           int *failure, char *e, size_t size)
{
    for (int i = 0; i < count; i++)
        if ((*failure = eval_poly(user, worker, vars + 2 * i, results + i, e, size)) < 0)
            return i;
    return count;
}

static int use_blocks; /* run_to_text gives the runner eval_block instead of eval */

static int consume_in_order(void *user, uint64_t row, const double *vars, const double *results,
                            char *e, size_t size)
{
    (void)e;
    (void)size;
    runner_state *s = user;
    s->out_of_order |= row != s->next_row++ || results[0] != vars[0] * vars[0] + 3.0 * vars[1];
    return 0;
}

static char *run_to_text(const sc_sweep_grid *g, int threads, runner_state *s,
                         sc_sweep_status *status)
{
    static const char *const names[] = {"x", "y", "value"};
    sc_sweep_table t = {SC_SWEEP_CSV, SC_DOUBLE, names, 2, 1};
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    sc_sweep_job job = {
        g,    1,       use_blocks ? NULL : eval_poly,      s, consume_in_order, &t, out,
        NULL, threads, use_blocks ? eval_poly_block : NULL};
    /* eval and consume share the state: eval only reads fail_at */
    *status = sc_sweep_run(&job, err, sizeof err);
    fclose(out);
    return text;
}

static void rows_come_in_order_on_any_number_of_threads(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:1000:10001", "y=0,1,2"}, 2);
    runner_state one = {.fail_at = -1}, many = {.fail_at = -1};
    sc_sweep_status s1, s4;
    char *a = run_to_text(&g, 1, &one, &s1), *b = run_to_text(&g, 4, &many, &s4);
    assert_int_equal(s1, SC_SWEEP_OK);
    assert_int_equal(s4, SC_SWEEP_OK);
    assert_string_equal(a, b);
    assert_int_equal(one.next_row, 30003);
    assert_int_equal(many.next_row, 30003);
    assert_false(one.out_of_order || many.out_of_order);
    /* row 10001 + 5 is x = 0.5, y = 1: 3.25 */
    const char *line = a;
    for (int i = 0; i < 10006; i++)
        line = strchr(line, '\n') + 1;
    assert_memory_equal(line, "0.5,1,3.25\n", 11);
    free(a);
    free(b);
    sc_sweep_grid_free(&g);
}

static void a_failing_row_stops_after_the_rows_before_it(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:99:100", "y=0"}, 2);
    for (int threads = 1; threads <= 3; threads += 2) {
        runner_state s = {.fail_at = 42};
        sc_sweep_status status;
        char *text = run_to_text(&g, threads, &s, &status);
        assert_int_equal(status, SC_SWEEP_FAILED);
        assert_string_equal(err, "row 43: x=42 is refused");
        int lines = 0;
        for (const char *p = text; *p; p++)
            lines += *p == '\n';
        assert_int_equal(lines, 42);
        assert_int_equal(s.next_row, 42);
        free(text);
    }
    sc_sweep_grid_free(&g);
}

/* eval_block gives the same text, and a failing row stops the sweep after the rows before it
 * with the same message, on one thread and on three. */
static void rows_in_blocks_equal_rows_one_by_one(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:999:1000", "y=0,1"}, 2);
    for (int threads = 1; threads <= 3; threads += 2) {
        for (double fail_at = -1; fail_at <= 700; fail_at += 701) {
            runner_state rows = {.fail_at = fail_at}, blocks = {.fail_at = fail_at};
            sc_sweep_status s_rows, s_blocks;
            use_blocks = 0;
            char *a = run_to_text(&g, threads, &rows, &s_rows), row_err[sizeof err];
            memcpy(row_err, err, sizeof err);
            use_blocks = 1;
            char *b = run_to_text(&g, threads, &blocks, &s_blocks);
            use_blocks = 0;
            assert_int_equal(s_rows, fail_at < 0 ? SC_SWEEP_OK : SC_SWEEP_FAILED);
            assert_int_equal(s_blocks, s_rows);
            assert_string_equal(a, b);
            assert_int_equal(blocks.next_row, rows.next_row);
            assert_false(blocks.out_of_order);
            if (fail_at >= 0)
                assert_string_equal(err, row_err);
            free(a);
            free(b);
        }
    }
    sc_sweep_grid_free(&g);
}

static void write_errors_are_reported(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:1:100000", "y=0"}, 2);
    FILE *full = fopen("/dev/full", "w");
    if (!full)
        skip();
    static const char *const names[] = {"x", "y", "value"};
    sc_sweep_table t = {SC_SWEEP_CSV, SC_DOUBLE, names, 2, 1};
    runner_state s = {.fail_at = -1};
    sc_sweep_job job = {&g, 1, eval_poly, &s, NULL, &t, full, NULL, 2, NULL};
    assert_int_equal(sc_sweep_run(&job, err, sizeof err), SC_SWEEP_WRITE_ERROR);
    fclose(full);
    sc_sweep_grid_free(&g);
}

/* The runner's memory is a ring of blocks: with output to /dev/null, the heap it uses at its
 * peak is the same for 10^4 and 3·10^5 rows. Measured as the growth of the process's peak
 * resident set over the run, which a leak of 4 bytes or more per row would raise by 1 MB. */
static long peak_rss_kb(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    long kb = -1;
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, "VmHWM:", 6) == 0)
            kb = strtol(line + 6, NULL, 10);
    if (f)
        fclose(f);
    return kb;
}

static void memory_does_not_grow_with_rows(void **state)
{
    (void)state;
    FILE *null = fopen("/dev/null", "w");
    if (!null || peak_rss_kb() < 0)
        skip();
    static const char *const names[] = {"x", "y", "value"};
    sc_sweep_table t = {SC_SWEEP_CSV, SC_HIGHP, names, 2, 1};
    runner_state s = {.fail_at = -1};
    sc_sweep_grid small, large; /* integers: quick to print */
    grid_of(&small, (const char *const[]){"x=0:9999:10000", "y=0"}, 2);
    grid_of(&large, (const char *const[]){"x=0:299999:300000", "y=0"}, 2);
    sc_sweep_job job = {&small, 1, eval_poly, &s, NULL, &t, null, NULL, 2, NULL};
    assert_int_equal(sc_sweep_run(&job, err, sizeof err), SC_SWEEP_OK); /* warms the heap */
    long before = peak_rss_kb();
    job.grid = &large;
    assert_int_equal(sc_sweep_run(&job, err, sizeof err), SC_SWEEP_OK);
    long growth = peak_rss_kb() - before;
    if (growth > 1024)
        fail_msg("peak RSS grew by %ld kB over 3*10^5 rows", growth);
    fclose(null);
    sc_sweep_grid_free(&small);
    sc_sweep_grid_free(&large);
}

/* ---- images ---- */

static void image_reads_back_with_values_and_ranges(void **state)
{
    (void)state;
    char dir[] = "/tmp/test_sweep_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[64];
    snprintf(path, sizeof path, "%s/slice.exr", dir);
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"x=0:3:4", "y=10,20,30"}, 2);
    sc_image img;
    assert_int_equal(sc_sweep_image_init(&img, &g, 1, err, sizeof err), 0);
    assert_int_equal(img.width, 4);
    assert_int_equal(img.height, 3);
    assert_string_equal(img.channel[0], "Y");
    for (uint64_t row = 0; row < 12; row++) {
        double v[2], r;
        sc_sweep_grid_point(&g, row, v);
        r = v[0] * v[0] + 3.0 * v[1];
        sc_sweep_image_store(&img, row, &r);
    }
    assert_int_equal(sc_sweep_image_write(path, &img, SC_PIXEL_FLOAT, &g,
                                          "shadecalc sweep --var x=0:3:4 --var y=10,20,30", err,
                                          sizeof err),
                     0);
    sc_image back;
    sc_image_attr *attrs;
    int n_attrs;
    assert_int_equal(sc_exr_read(path, &back, &attrs, &n_attrs, err, sizeof err), 0);
    assert_int_equal(back.width, 4);
    assert_int_equal(back.height, 3);
    for (int y = 0; y < 3; y++) /* the bottom row (y = 2) is the second variable's first value */
        for (int x = 0; x < 4; x++)
            assert_true(*sc_image_pixel(&back, x, y) == (float)(x * x + 3 * 10 * (3 - y)));
    int found = 0;
    for (int i = 0; i < n_attrs; i++) {
        found += strcmp(attrs[i].name, "shadecalc:x_range") == 0 &&
                 strcmp(attrs[i].value, "x=0:3:4") == 0;
        found += strcmp(attrs[i].name, "shadecalc:y_range") == 0 &&
                 strcmp(attrs[i].value, "y=10,20,30") == 0;
        found += strcmp(attrs[i].name, "shadecalc:command") == 0 &&
                 strstr(attrs[i].value, "--var y=10,20,30") != NULL;
    }
    assert_int_equal(found, 3);
    sc_image_attrs_free(attrs, n_attrs);
    sc_image_free(&back);
    sc_image_free(&img);
    sc_sweep_grid_free(&g);
    unlink(path);
    rmdir(dir);
}

static void image_channels_follow_the_results(void **state)
{
    (void)state;
    sc_sweep_grid g;
    grid_of(&g, (const char *const[]){"a=0:1:2", "b=0:1:2"}, 2);
    sc_image img;
    assert_int_equal(sc_sweep_image_init(&img, &g, 3, err, sizeof err), 0);
    assert_string_equal(img.channel[0], "R");
    assert_string_equal(img.channel[2], "B");
    sc_image_free(&img);
    assert_int_equal(sc_sweep_image_init(&img, &g, 5, err, sizeof err), -1);
    sc_sweep_grid_free(&g);
    grid_of(&g, (const char *const[]){"a=0:1:2"}, 1);
    assert_int_equal(sc_sweep_image_init(&img, &g, 1, err, sizeof err), -1);
    assert_non_null(strstr(err, "two variables"));
    sc_sweep_grid_free(&g);
}

static void log_range_is_described(void **state)
{
    (void)state;
    sc_sweep_var v = var("m=1:1000:4");
    sc_sweep_var_set_log(&v, err, sizeof err);
    char buf[64];
    sc_sweep_describe_var(&v, buf, sizeof buf);
    assert_string_equal(buf, "m=1:1000:4 log");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(range_includes_both_ends),
        cmocka_unit_test(log_spacing_is_geometric),
        cmocka_unit_test(log_spacing_needs_ends_of_one_sign),
        cmocka_unit_test(list_keeps_its_order),
        cmocka_unit_test(bad_variables_are_named),
        cmocka_unit_test(first_variable_varies_fastest),
        cmocka_unit_test(grid_refuses_duplicates_and_too_many_rows),
        cmocka_unit_test(substitution_writes_round_trip_values),
        cmocka_unit_test(substitution_errors),
        cmocka_unit_test(csv_and_tsv_rows),
        cmocka_unit_test(jsonl_rows_quote_what_json_lacks),
        cmocka_unit_test(header_lists_the_columns),
        cmocka_unit_test(rows_come_in_order_on_any_number_of_threads),
        cmocka_unit_test(a_failing_row_stops_after_the_rows_before_it),
        cmocka_unit_test(write_errors_are_reported),
        cmocka_unit_test(memory_does_not_grow_with_rows),
        cmocka_unit_test(image_reads_back_with_values_and_ranges),
        cmocka_unit_test(image_channels_follow_the_results),
        cmocka_unit_test(log_range_is_described),
        cmocka_unit_test(rows_in_blocks_equal_rows_one_by_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
