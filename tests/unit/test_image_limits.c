/* The limits of images and atomic files (shadecalc/image.h, sweep.h, file.h): sizes whose byte
 * count overflows, sweep images past SC_EXR_MAX_VALUES, long value lists
 * shortened in descriptions, and an atomic open that meets only existing temporaries. */
#include <errno.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "shadecalc/file.h"
#include "shadecalc/image.h"
#include "shadecalc/sweep.h"
#include "util/bigalloc.h"

static const char *const rgba[] = {"R", "G", "B", "A"};

/* sc_big_calloc (util/bigalloc.h) on both sides of its 2 MiB switch to mappings: every byte
 * zero and writable, the array aligned at least as calloc's, each array released by
 * sc_big_free (under AddressSanitizer, calloc's blocks all: a leak or overrun would show);
 * sizes beyond size_t refused. */
static void big_arrays_are_zeroed_and_released(void **state)
{
    (void)state;
    static const size_t sizes[] = {
        0, 1, 4095, (2u << 20) - 1, 2u << 20, (2u << 20) + 1, (5u << 20) + 3};
    for (int round = 0; round < 3; round++) /* reused memory comes back zeroed too */
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            unsigned char *p = sc_big_calloc(sizes[k], 1);
            assert_non_null(p);
            assert_int_equal((uintptr_t)p % 16, 0);
            for (size_t i = 0; i < sizes[k]; i++)
                if (p[i] != 0)
                    fail_msg("size %zu: byte %zu is %d", sizes[k], i, p[i]);
            memset(p, 0xa5, sizes[k]);
            sc_big_free(p);
        }
    assert_null(sc_big_calloc(SIZE_MAX / 2, 4));
    assert_null(sc_big_calloc(1, SIZE_MAX));
    assert_null(sc_big_calloc(SIZE_MAX - 100, 1));
    sc_big_free(NULL);
}

/* INT_MAX² pixels of 4 floats is 2^66 bytes: more than size_t holds on a 64-bit machine. */
static void image_size_overflow_is_refused(void **state)
{
    (void)state;
    sc_image img;
    assert_int_equal(sc_image_init(&img, INT_MAX, INT_MAX, 4, rgba), -1);
    assert_null(img.data);
    sc_image_free(&img); /* safe on a failed image */
}

static void grid_of(sc_sweep_grid *g, const char *a, const char *b)
{
    char err[256];
    memset(g, 0, sizeof *g);
    const char *args[] = {a, b};
    for (int i = 0; i < 2; i++) {
        sc_sweep_var v;
        assert_int_equal(sc_sweep_var_parse(args[i], &v, err, sizeof err), 0);
        assert_int_equal(sc_sweep_grid_add(g, &v, err, sizeof err), 0);
    }
}

/* 2^15 × 2^15 pixels of one channel is 2^30 values, 4 times SC_EXR_MAX_VALUES (2^28). */
static void sweep_image_past_the_exr_limit_is_refused(void **state)
{
    (void)state;
    sc_sweep_grid g;
    char err[256];
    sc_image img;
    grid_of(&g, "x=0:1:32768", "y=0:1:32768");
    assert_int_equal(sc_sweep_image_init(&img, &g, 1, err, sizeof err), -1);
    assert_string_equal(err, "an image of 32768 x 32768 pixels is too large");
    assert_null(img.data);
    sc_sweep_grid_free(&g);
}

/* A list of 300 values (1000..1299) is shortened to about 200 characters: "k=" and the first
 * values in order, each as written, then ",..."; a list of 3 is written whole. */
static void long_lists_are_shortened(void **state)
{
    (void)state;
    char arg[2048] = "k=", buf[512], err[256];
    for (int i = 0; i < 300; i++)
        snprintf(arg + strlen(arg), sizeof arg - strlen(arg), "%s%d", i ? "," : "", 1000 + i);
    sc_sweep_var v;
    assert_int_equal(sc_sweep_var_parse(arg, &v, err, sizeof err), 0);
    sc_sweep_describe_var(&v, buf, sizeof buf);
    size_t len = strlen(buf);
    assert_true(len >= 200 && len <= 240);
    assert_string_equal(buf + len - 4, ",...");
    assert_memory_equal(buf, arg, len - 4);                  /* a prefix of the list as given */
    assert_true(buf[len - 5] >= '0' && buf[len - 5] <= '9'); /* ends on a whole value */
    assert_true(arg[len - 4] == ',');
    sc_sweep_var_free(&v);
    assert_int_equal(sc_sweep_var_parse("k=1,2.5,-3", &v, err, sizeof err), 0);
    sc_sweep_describe_var(&v, buf, sizeof buf);
    assert_string_equal(buf, "k=1,2.5,-3");
    sc_sweep_var_free(&v);
}

/* The temporary is created with O_EXCL (never an existing file): when every name it tries
 * exists, sc_atomic_open fails with "PATH: File exists" and leaves the files it met alone. */
static void atomic_open_never_reuses_an_existing_temporary(void **state)
{
    (void)state;
    char dir[] = "/tmp/sc-limits-XXXXXX", path[128], temp[160], err[256];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/out.csv", dir);
    enum { TAKEN = 400 };
    for (unsigned n = 0; n < TAKEN; n++) {
        snprintf(temp, sizeof temp, "%s/.out.csv.%ld.%u.tmp", dir, (long)getpid(), n);
        FILE *f = fopen(temp, "wx");
        assert_non_null(f);
        fputs("someone else's", f);
        assert_int_equal(fclose(f), 0);
    }
    assert_null(sc_atomic_open(path, err, sizeof err));
    char want[192];
    snprintf(want, sizeof want, "%s: %s", path, strerror(EEXIST));
    assert_string_equal(err, want);
    for (unsigned n = 0; n < TAKEN; n++) {
        snprintf(temp, sizeof temp, "%s/.out.csv.%ld.%u.tmp", dir, (long)getpid(), n);
        char text[32] = "";
        FILE *f = fopen(temp, "r");
        assert_non_null(f);
        assert_non_null(fgets(text, sizeof text, f));
        fclose(f);
        assert_string_equal(text, "someone else's");
        assert_int_equal(unlink(temp), 0);
    }
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(rmdir(dir), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(big_arrays_are_zeroed_and_released),
        cmocka_unit_test(image_size_overflow_is_refused),
        cmocka_unit_test(sweep_image_past_the_exr_limit_is_refused),
        cmocka_unit_test(long_lists_are_shortened),
        cmocka_unit_test(atomic_open_never_reuses_an_existing_temporary),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
