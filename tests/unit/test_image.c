/* Images, EXR files and atomic writing (shadecalc/image.h, file.h). References: pixel values
 * from closed forms of (x, y, c); binary16 rounding at its ties from the IEEE 754 definition;
 * files written and inspected with OpenEXR's own Core API, independently of sc_exr_*. */
#include <dirent.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include <OpenEXR/openexr.h>

#include "image/half.h"
#include "shadecalc/file.h"
#include "shadecalc/image.h"
#include "shadecalc/precision.h"

static char dir[64]; /* a fresh directory for the files of one test */
static char path_buf[4][160];

static const char *in_dir(int slot, const char *name)
{
    snprintf(path_buf[slot], sizeof path_buf[slot], "%s/%s", dir, name);
    return path_buf[slot];
}

static int entries_in_dir(void)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static void remove_tree(const char *top)
{
    DIR *d = opendir(top);
    if (!d)
        return;
    char p[512];
    for (struct dirent *e; (e = readdir(d));) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(p, sizeof p, "%s/%s", top, e->d_name);
        struct stat st;
        if (lstat(p, &st) == 0 && S_ISDIR(st.st_mode))
            remove_tree(p);
        else
            unlink(p);
    }
    closedir(d);
    rmdir(top);
}

static int make_dir(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/sc_test_image.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
    (void)state;
    remove_tree(dir);
    return 0;
}

/* Exactly representable in binary16 and binary32 for the sizes used here: multiples of 1/2
 * below 1024 in magnitude. */
static float pattern(int x, int y, int c) { return 0.5f * (float)(x + 40 * y + 7 * c - 300); }

static void fill_pattern(sc_image *img)
{
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            for (int c = 0; c < img->n_channels; c++)
                sc_image_pixel(img, x, y)[c] = pattern(x, y, c);
}

static void assert_same_names(const sc_image *got, const char *const *names, int n)
{
    assert_int_equal(got->n_channels, n);
    for (int c = 0; c < n; c++)
        assert_string_equal(got->channel[c], names[c]);
}

static void read_back(const char *path, sc_image *out, sc_image_attr **attrs, int *n)
{
    char err[256] = "";
    if (sc_exr_read(path, out, attrs, n, err, sizeof err) != 0)
        fail_msg("reading %s: %s", path, err);
}

static void write_ok(const char *path, const sc_image *img, sc_pixel_type type,
                     const sc_image_attr *attrs, int n)
{
    char err[256] = "";
    if (sc_exr_write(path, img, type, attrs, n, err, sizeof err) != 0)
        fail_msg("writing %s: %s", path, err);
}

/* ---- sc_image ---------------------------------------------------------------------------- */

static void image_init_rejects_bad_arguments(void **state)
{
    (void)state;
    const char *names[SC_IMAGE_MAX_CHANNELS + 1] = {"R", "G", "B"};
    const char *dup[] = {"R", "G", "R"}, *empty[] = {"R", ""}, *null[] = {"R", NULL};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 0, 1, 1, names), -1);
    assert_int_equal(sc_image_init(&img, 1, -5, 1, names), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, 0, names), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, SC_IMAGE_MAX_CHANNELS + 1, names), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, 3, dup), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, 2, empty), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, 2, null), -1);
    assert_int_equal(sc_image_init(&img, 1, 1, 1, NULL), -1);
    assert_int_equal(sc_image_init(&img, 1 << 30, 1 << 30, 16, names), -1); /* 2^66 bytes */
    assert_null(img.data);
    sc_image_free(&img); /* safe after a failure */
}

static void image_is_zeroed_interleaved_and_finds_channels(void **state)
{
    (void)state;
    const char *names[] = {"N.X", "N.Y", "N.Z"};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 5, 4, 3, names), 0);
    for (size_t i = 0; i < 5 * 4 * 3; i++)
        assert_true(img.data[i] == 0.0f);
    /* data[((size_t)y * width + x) * n_channels + c] */
    assert_ptr_equal(sc_image_pixel(&img, 2, 3), img.data + (3 * 5 + 2) * 3);
    assert_ptr_equal(sc_image_pixel(&img, 4, 3) + 2, img.data + 5 * 4 * 3 - 1);
    assert_int_equal(sc_image_channel_index(&img, "N.Z"), 2);
    assert_int_equal(sc_image_channel_index(&img, "N.X"), 0);
    assert_int_equal(sc_image_channel_index(&img, "N"), -1);
    assert_true(img.channel[0] != names[0]); /* owned copies */
    sc_image_free(&img);
    assert_null(img.data);
}

/* ---- round trips ------------------------------------------------------------------------- */

static void round_trip_sizes_and_channels(sc_pixel_type type)
{
    static const int sizes[][2] = {{1, 1}, {7, 3}, {33, 17}, {5, 32}, {2, 49}};
    static const char *const sets[][6] = {
        {"Y"}, {"R", "G", "B"}, {"R", "G", "B", "A"}, {"Z", "A", "N.X", "N.Y", "N.Z", "B"}};
    static const int counts[] = {1, 3, 4, 6};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++) {
            sc_image img, back;
            assert_int_equal(sc_image_init(&img, sizes[s][0], sizes[s][1], counts[k], sets[k]), 0);
            fill_pattern(&img);
            write_ok(in_dir(0, "trip.exr"), &img, type, NULL, 0);
            read_back(in_dir(0, "trip.exr"), &back, NULL, NULL);
            assert_int_equal(back.width, sizes[s][0]);
            assert_int_equal(back.height, sizes[s][1]);
            assert_same_names(&back, sets[k], counts[k]); /* the image's order, not EXR's */
            for (int y = 0; y < back.height; y++)
                for (int x = 0; x < back.width; x++)
                    for (int c = 0; c < back.n_channels; c++)
                        if (sc_image_pixel(&back, x, y)[c] != pattern(x, y, c))
                            fail_msg("%dx%d %s at (%d,%d): %g, want %g", back.width, back.height,
                                     back.channel[c], x, y, sc_image_pixel(&back, x, y)[c],
                                     pattern(x, y, c));
            sc_image_free(&img);
            sc_image_free(&back);
        }
}

static void half_round_trip_odd_sizes_and_channels(void **state)
{
    (void)state;
    round_trip_sizes_and_channels(SC_PIXEL_HALF);
}

static void float_round_trip_odd_sizes_and_channels(void **state)
{
    (void)state;
    round_trip_sizes_and_channels(SC_PIXEL_FLOAT);
}

static int same_value(float a, float b)
{
    return (isnan(a) && isnan(b)) || (a == b && signbit(a) == signbit(b));
}

/* Writes the n values as one row of a one-channel image stored as type; they must read back
 * as want (same sign of zero, NaN as NaN). */
static void assert_row_comes_back_as(const float *values, const float *want, int n,
                                     sc_pixel_type type)
{
    const char *names[] = {"V"};
    sc_image img, back;
    assert_int_equal(sc_image_init(&img, n, 1, 1, names), 0);
    memcpy(img.data, values, (size_t)n * sizeof *values);
    write_ok(in_dir(0, "row.exr"), &img, type, NULL, 0);
    read_back(in_dir(0, "row.exr"), &back, NULL, NULL);
    for (int i = 0; i < n; i++)
        if (!same_value(back.data[i], want[i]))
            fail_msg("value %d (%a): %a, want %a", i, values[i], back.data[i], want[i]);
    sc_image_free(&img);
    sc_image_free(&back);
}

static void float_keeps_every_bit_pattern_class(void **state)
{
    (void)state;
    const float values[] = {0.0f,      -0.0f,      1.0f / 3.0f, -0x1.fffffep127f,
                            0x1p-149f, -0x1p-126f, INFINITY,    -INFINITY,
                            NAN,       65520.0f,   3.14159265f, 1e-30f};
    assert_row_comes_back_as(values, values, (int)(sizeof values / sizeof values[0]),
                             SC_PIXEL_FLOAT);
}

/* Binary16 has 11 significant bits, exponents -14..15, subnormal step 2^-24 (IEEE 754-2008);
 * ties go to the even significand. */
static void half_rounds_to_nearest_even(void **state)
{
    (void)state;
    const float in[] = {1.0f + 0x1p-11f,            /* tie between 1 and 1+2^-10: even 1 */
                        1.0f + 3 * 0x1p-11f,        /* tie: up to the even 1+2^-9 */
                        1.0f + 0x1p-11f + 0x1p-20f, /* above the tie: 1+2^-10 */
                        -(2048.0f + 1.0f),          /* tie between 2048 and 2050: even 2048 */
                        2.5f * 0x1p-24f,            /* subnormal tie: 2·2^-24 */
                        3.5f * 0x1p-24f,            /* subnormal tie: 4·2^-24 */
                        0x1p-25f,                   /* half the smallest subnormal: +0 */
                        -0x1p-26f,                  /* -0 */
                        65504.0f,                   /* the largest half */
                        65519.0f,                   /* below the overflow tie: 65504 */
                        65520.0f,                   /* the tie 65504|65536: even is 2^16, Inf */
                        -1e30f,
                        NAN,
                        0.1f};
    const float want[] = {
        1.0f,  1.0f + 0x1p-9f, 1.0f + 0x1p-10f, -2048.0f, 2 * 0x1p-24f, 4 * 0x1p-24f, 0.0f,
        -0.0f, 65504.0f,       65504.0f,        INFINITY, -INFINITY,    NAN,          0x1.998p-4f};
    assert_row_comes_back_as(in, want, (int)(sizeof in / sizeof in[0]), SC_PIXEL_HALF);
}

/* Every binary16 value comes back as itself, and random floats as the project's rounding. */
static void half_agrees_with_the_project_rounding(void **state)
{
    (void)state;
    const int w = 256, h = 257; /* 2^16 values + a row of random ones */
    const char *names[] = {"Y"};
    sc_image img, back;
    assert_int_equal(sc_image_init(&img, w, h, 1, names), 0);
    uint32_t seed = 12345;
    for (int i = 0; i < w * h; i++) {
        seed = seed * 1664525u + 1013904223u;
        float r;
        uint32_t bits = seed;
        memcpy(&r, &bits, sizeof r);
        img.data[i] = i < 0x10000 ? (float)sc_half_to_double((uint16_t)i) : r;
    }
    write_ok(in_dir(0, "all.exr"), &img, SC_PIXEL_HALF, NULL, 0);
    read_back(in_dir(0, "all.exr"), &back, NULL, NULL);
    for (int i = 0; i < w * h; i++) {
        float want = (float)sc_round_half(img.data[i]);
        if (!same_value(back.data[i], want))
            fail_msg("value %d (%a): %a, want %a", i, img.data[i], back.data[i], want);
    }
    sc_image_free(&img);
    sc_image_free(&back);
}

/* ---- attributes ---------------------------------------------------------------------------- */

static void attributes_round_trip(void **state)
{
    (void)state;
    char long_value[5000];
    memset(long_value, 'x', sizeof long_value - 1);
    long_value[sizeof long_value - 1] = '\0';
    const sc_image_attr attrs[] = {
        {"shadecalc:command", "shadecalc sweep --var 'x=0:1:101' 'pow(x, 32.0)'"},
        {"shadecalc:x_range", "0:1:101"},
        {"shadecalc:a_name_longer_than_31_characters", "long names need the long-name flag"},
        {"owner", ""},
        {"notes", long_value},
    };
    const int n = (int)(sizeof attrs / sizeof attrs[0]);
    const char *names[] = {"R", "G", "B"};
    sc_image img, back;
    assert_int_equal(sc_image_init(&img, 3, 2, 3, names), 0);
    write_ok(in_dir(0, "attrs.exr"), &img, SC_PIXEL_HALF, attrs, n);
    sc_image_attr *got = NULL;
    int n_got = -1;
    read_back(in_dir(0, "attrs.exr"), &back, &got, &n_got);
    assert_int_equal(n_got, n);
    for (int i = 0; i < n; i++) { /* the file's order is the order written */
        assert_string_equal(got[i].name, attrs[i].name);
        assert_string_equal(got[i].value, attrs[i].value);
    }
    sc_image_attrs_free(got, n_got);
    sc_image_free(&img);
    sc_image_free(&back);
}

static void bad_attributes_are_refused_naming_the_path(void **state)
{
    (void)state;
    const char *names[] = {"Y"};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 1, 1, 1, names), 0);
    const sc_image_attr reserved[] = {{"shadecalc:channel_order", "Y"}};
    const sc_image_attr twice[] = {{"a", "1"}, {"a", "2"}};
    const sc_image_attr no_value[] = {{"a", NULL}};
    const sc_image_attr *lists[] = {reserved, twice, no_value};
    const int counts[] = {1, 2, 1};
    const char *path = in_dir(0, "bad.exr");
    for (int i = 0; i < 3; i++) {
        char err[256] = "";
        assert_int_equal(
            sc_exr_write(path, &img, SC_PIXEL_FLOAT, lists[i], counts[i], err, sizeof err), -1);
        assert_ptr_equal(strstr(err, path), err);
    }
    assert_int_equal(entries_in_dir(), 0);
    sc_image_free(&img);
}

/* ---- files written by OpenEXR itself ------------------------------------------------------ */

/* Channels of the test files, given unsorted; EXR stores them as A, B, C. */
static const char *const foreign_names[] = {"C", "A", "B"};
static const exr_pixel_type_t foreign_types[] = {EXR_PIXEL_FLOAT, EXR_PIXEL_UINT, EXR_PIXEL_HALF};

/* The value of a channel at data-window pixel (x, y): float C holds a non-dyadic fraction, uint A
 * integers beyond 2^24 (the reader rounds them to float), half B multiples of 1/2. */
static double foreign_value(const char *name, int x, int y)
{
    switch (name[0]) {
    case 'C': return (float)(x - 0.1 * y);
    case 'A': return 16777217.0 + 65.0 * (x + 100) + y;
    default: return 0.5 * (x + 3 * y);
    }
}

static exr_attr_box2i_t box(int x0, int y0, int x1, int y1)
{
    exr_attr_box2i_t b = {.min = {.x = x0, .y = y0}, .max = {.x = x1, .y = y1}};
    return b;
}

static int element_size(exr_pixel_type_t t) { return t == EXR_PIXEL_HALF ? 2 : 4; }

static void pack_value(unsigned char *to, exr_pixel_type_t t, double v)
{
    if (t == EXR_PIXEL_HALF) {
        uint16_t h = sc_half_from_double(v);
        memcpy(to, &h, 2);
    } else if (t == EXR_PIXEL_UINT) {
        uint32_t u = (uint32_t)v;
        memcpy(to, &u, 4);
    } else {
        float f = (float)v;
        memcpy(to, &f, 4);
    }
}

/* Fills one planar buffer per channel for the chunk whose top-left pixel is (x0, y0), and points
 * the encoder at them. */
static void fill_chunk(exr_encode_pipeline_t *enc, unsigned char **planes, int x0, int y0)
{
    for (int i = 0; i < enc->channel_count; i++) {
        exr_coding_channel_info_t *ch = &enc->channels[i];
        int size = element_size((exr_pixel_type_t)ch->data_type);
        free(planes[i]);
        planes[i] = malloc((size_t)(ch->width * ch->height * size));
        for (int y = 0; y < ch->height; y++)
            for (int x = 0; x < ch->width; x++)
                pack_value(planes[i] + (y * ch->width + x) * size, (exr_pixel_type_t)ch->data_type,
                           foreign_value(ch->channel_name, x0 + x, y0 + y));
        ch->user_bytes_per_element = (int16_t)size;
        ch->user_data_type = ch->data_type;
        ch->user_pixel_stride = size;
        ch->user_line_stride = size * ch->width;
        ch->encode_from_ptr = planes[i];
    }
}

static void encode_foreign_chunk(exr_context_t ctx, exr_encode_pipeline_t *enc,
                                 const exr_chunk_info_t *chunk, int first, int x0, int y0)
{
    unsigned char *planes[3] = {NULL, NULL, NULL};
    assert_int_equal(first ? exr_encoding_initialize(ctx, 0, chunk, enc)
                           : exr_encoding_update(ctx, 0, chunk, enc),
                     EXR_ERR_SUCCESS);
    fill_chunk(enc, planes, x0, y0);
    assert_int_equal(exr_encoding_choose_default_routines(ctx, 0, enc), EXR_ERR_SUCCESS);
    assert_int_equal(exr_encoding_run(ctx, 0, enc), EXR_ERR_SUCCESS);
    for (int i = 0; i < 3; i++)
        free(planes[i]);
}

/* A file written by OpenEXR's Core API alone: scanlines, or tiles of tile × tile pixels. */
static void write_foreign(const char *path, exr_attr_box2i_t window, exr_compression_t comp,
                          int tile)
{
    exr_context_t ctx = NULL;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_attr_v2f_t center = {.x = 0.0f, .y = 0.0f};
    int part = 0;
    assert_int_equal(exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init), 0);
    assert_int_equal(
        exr_add_part(ctx, NULL, tile ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part), 0);
    assert_int_equal(exr_initialize_required_attr(ctx, part, &window, &window, 1.0f, &center, 1.0f,
                                                  EXR_LINEORDER_INCREASING_Y, comp),
                     0);
    if (tile)
        assert_int_equal(exr_set_tile_descriptor(ctx, part, (uint32_t)tile, (uint32_t)tile,
                                                 EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN),
                         0);
    for (int c = 0; c < 3; c++)
        assert_int_equal(exr_add_channel(ctx, part, foreign_names[c], foreign_types[c],
                                         EXR_PERCEPTUALLY_LINEAR, 1, 1),
                         0);
    assert_int_equal(exr_attr_set_string(ctx, part, "comment", "written by the test"), 0);
    assert_int_equal(exr_write_header(ctx), 0);
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    exr_chunk_info_t chunk;
    int first = 1, w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    if (tile) {
        for (int ty = 0; ty * tile < h; ty++)
            for (int tx = 0; tx * tile < w; tx++, first = 0) {
                assert_int_equal(exr_write_tile_chunk_info(ctx, part, tx, ty, 0, 0, &chunk), 0);
                encode_foreign_chunk(ctx, &enc, &chunk, first, window.min.x + tx * tile,
                                     window.min.y + ty * tile);
            }
    } else {
        int32_t lines = 0;
        assert_int_equal(exr_get_scanlines_per_chunk(ctx, part, &lines), 0);
        for (int y = window.min.y; y <= window.max.y; y += lines, first = 0) {
            assert_int_equal(exr_write_scanline_chunk_info(ctx, part, y, &chunk), 0);
            encode_foreign_chunk(ctx, &enc, &chunk, first, window.min.x, y);
        }
    }
    exr_encoding_destroy(ctx, &enc);
    assert_int_equal(exr_finish(&ctx), 0);
}

static void assert_foreign_pixels(const sc_image *img, exr_attr_box2i_t window)
{
    const char *sorted[] = {"A", "B", "C"}; /* no channel-order attribute: the file's order */
    assert_same_names(img, sorted, 3);
    assert_int_equal(img->width, window.max.x - window.min.x + 1);
    assert_int_equal(img->height, window.max.y - window.min.y + 1);
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            for (int c = 0; c < 3; c++) {
                float want = (float)foreign_value(sorted[c], window.min.x + x, window.min.y + y);
                if (sc_image_pixel(img, x, y)[c] != want)
                    fail_msg("%s at (%d,%d): %.9g, want %.9g", sorted[c], x, y,
                             sc_image_pixel(img, x, y)[c], want);
            }
}

static void reads_scanline_files_of_every_lossless_compression(void **state)
{
    (void)state;
    const exr_compression_t comps[] = {EXR_COMPRESSION_NONE, EXR_COMPRESSION_RLE,
                                       EXR_COMPRESSION_ZIPS, EXR_COMPRESSION_ZIP,
                                       EXR_COMPRESSION_PIZ};
    const exr_attr_box2i_t window = box(-3, 5, 9, 40); /* 13 × 36, not at the origin */
    for (size_t i = 0; i < sizeof comps / sizeof comps[0]; i++) {
        sc_image img;
        sc_image_attr *attrs = NULL;
        int n = 0;
        write_foreign(in_dir(0, "scan.exr"), window, comps[i], 0);
        read_back(in_dir(0, "scan.exr"), &img, &attrs, &n);
        assert_foreign_pixels(&img, window);
        assert_int_equal(n, 1);
        assert_string_equal(attrs[0].name, "comment");
        assert_string_equal(attrs[0].value, "written by the test");
        sc_image_attrs_free(attrs, n);
        sc_image_free(&img);
    }
}

static void reads_tiled_files_with_partial_tiles(void **state)
{
    (void)state;
    const exr_attr_box2i_t window = box(0, 0, 18, 10); /* 19 × 11 in 8 × 8 tiles */
    sc_image img;
    write_foreign(in_dir(0, "tiled.exr"), window, EXR_COMPRESSION_ZIP, 8);
    read_back(in_dir(0, "tiled.exr"), &img, NULL, NULL);
    assert_foreign_pixels(&img, window);
    sc_image_free(&img);
}

/* Our file, opened with OpenEXR's reader: ZIP, sorted channels of the requested type, the
 * data window, the attributes. */
static void written_file_is_zip_with_typed_sorted_channels(void **state)
{
    (void)state;
    const char *names[] = {"R", "G", "B", "A"};
    const sc_image_attr attrs[] = {{"shadecalc:command", "render --size 7x3"}};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 7, 3, 4, names), 0);
    for (int t = 0; t < 2; t++) {
        sc_pixel_type type = t ? SC_PIXEL_FLOAT : SC_PIXEL_HALF;
        write_ok(in_dir(0, "ours.exr"), &img, type, attrs, 1);
        exr_context_t ctx = NULL;
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        assert_int_equal(exr_start_read(&ctx, in_dir(0, "ours.exr"), &init), 0);
        exr_compression_t comp;
        exr_storage_t storage;
        exr_attr_box2i_t dw;
        const exr_attr_chlist_t *chl = NULL;
        assert_int_equal(exr_get_compression(ctx, 0, &comp), 0);
        assert_int_equal(comp, EXR_COMPRESSION_ZIP);
        assert_int_equal(exr_get_storage(ctx, 0, &storage), 0);
        assert_int_equal(storage, EXR_STORAGE_SCANLINE);
        assert_int_equal(exr_get_data_window(ctx, 0, &dw), 0);
        assert_true(dw.min.x == 0 && dw.min.y == 0 && dw.max.x == 6 && dw.max.y == 2);
        assert_int_equal(exr_get_channels(ctx, 0, &chl), 0);
        assert_int_equal(chl->num_channels, 4);
        const char *sorted[] = {"A", "B", "G", "R"};
        for (int c = 0; c < 4; c++) {
            assert_string_equal(chl->entries[c].name.str, sorted[c]);
            assert_int_equal(chl->entries[c].pixel_type, t ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF);
        }
        int32_t len = 0;
        const char *value = NULL;
        assert_int_equal(exr_attr_get_string(ctx, 0, "shadecalc:command", &len, &value), 0);
        assert_string_equal(value, "render --size 7x3");
        assert_int_equal(exr_finish(&ctx), 0);
    }
    sc_image_free(&img);
}

/* ---- failures leave nothing behind --------------------------------------------------------- */

static void write_into_a_missing_directory_fails_with_the_path(void **state)
{
    (void)state;
    const char *names[] = {"Y"};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 2, 2, 1, names), 0);
    const char *path = in_dir(0, "no/such/dir/out.exr");
    char err[256] = "";
    assert_int_equal(sc_exr_write(path, &img, SC_PIXEL_HALF, NULL, 0, err, sizeof err), -1);
    assert_ptr_equal(strstr(err, path), err);
    assert_non_null(strstr(err, "No such file or directory"));
    assert_int_equal(entries_in_dir(), 0);
    sc_image_free(&img);
}

static void failed_write_keeps_the_previous_file(void **state)
{
    (void)state;
    const char *names[] = {"R", "G"};
    char too_long[300]; /* EXR names have at most 255 bytes */
    memset(too_long, 'n', sizeof too_long - 1);
    too_long[sizeof too_long - 1] = '\0';
    const char *bad_names[] = {"R", too_long};
    sc_image good, bad, back;
    assert_int_equal(sc_image_init(&good, 9, 20, 2, names), 0);
    assert_int_equal(sc_image_init(&bad, 9, 20, 2, bad_names), 0);
    fill_pattern(&good);
    const char *path = in_dir(0, "keep.exr");
    write_ok(path, &good, SC_PIXEL_FLOAT, NULL, 0);
    char err[256] = "";
    assert_int_equal(sc_exr_write(path, &bad, SC_PIXEL_FLOAT, NULL, 0, err, sizeof err), -1);
    assert_ptr_equal(strstr(err, path), err);
    assert_int_equal(entries_in_dir(), 1); /* no temporary left */
    read_back(path, &back, NULL, NULL);
    assert_int_equal(back.height, 20);
    assert_memory_equal(back.data, good.data, 9 * 20 * 2 * sizeof(float));
    sc_image_free(&good);
    sc_image_free(&bad);
    sc_image_free(&back);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void assert_file_holds(const char *path, const char *text)
{
    char buf[64] = "";
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    assert_string_equal(buf, text);
}

static void atomic_abort_keeps_the_target(void **state)
{
    (void)state;
    const char *path = in_dir(0, "a.txt");
    write_text(path, "old");
    char err[256] = "";
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    assert_non_null(f);
    fputs("new and longer", sc_atomic_stream(f));
    fflush(sc_atomic_stream(f));
    assert_int_equal(entries_in_dir(), 2);
    assert_file_holds(path, "old"); /* untouched until the commit */
    sc_atomic_abort(f);
    assert_int_equal(entries_in_dir(), 1);
    assert_file_holds(path, "old");
}

static void atomic_commit_replaces_and_keeps_the_mode(void **state)
{
    (void)state;
    const char *path = in_dir(0, "b.txt");
    write_text(path, "old");
    assert_int_equal(chmod(path, 0640), 0);
    char err[256] = "";
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    assert_non_null(f);
    const char *temp = sc_atomic_temp_path(f);
    assert_non_null(temp);
    assert_memory_equal(temp, dir, strlen(dir)); /* same directory: rename is atomic */
    assert_null(strchr(temp + strlen(dir) + 1, '/'));
    fputs("new", sc_atomic_stream(f));
    assert_int_equal(sc_atomic_commit(f, err, sizeof err), 0);
    assert_file_holds(path, "new");
    assert_int_equal(entries_in_dir(), 1);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 07777, 0640);
}

static void atomic_commit_failure_removes_the_temporary(void **state)
{
    (void)state;
    const char *path = in_dir(0, "c");
    char err[256] = "";
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    assert_non_null(f);
    fputs("data", sc_atomic_stream(f));
    assert_int_equal(mkdir(path, 0755), 0); /* the target became a directory: rename fails */
    write_text(in_dir(1, "c/inside"), "x");
    assert_int_equal(sc_atomic_commit(f, err, sizeof err), -1);
    assert_ptr_equal(strstr(err, path), err);
    assert_int_equal(entries_in_dir(), 1);
    assert_file_holds(in_dir(1, "c/inside"), "x");
}

static void atomic_open_refuses_a_directory_and_allows_stdout(void **state)
{
    (void)state;
    char err[256] = "";
    assert_null(sc_atomic_open(dir, err, sizeof err));
    assert_ptr_equal(strstr(err, dir), err);
    assert_non_null(strstr(err, "Is a directory"));
    assert_int_equal(entries_in_dir(), 0);
    sc_atomic_file *f = sc_atomic_open("-", err, sizeof err);
    assert_non_null(f);
    assert_ptr_equal(sc_atomic_stream(f), stdout);
    assert_null(sc_atomic_temp_path(f));
    assert_int_equal(sc_atomic_commit(f, err, sizeof err), 0);
    sc_atomic_abort(NULL);
}

/* ---- bad input ------------------------------------------------------------------------------ */

static unsigned char *file_bytes(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    unsigned char *bytes = malloc(1 << 16);
    *size = fread(bytes, 1, 1 << 16, f);
    assert_true(feof(f));
    fclose(f);
    return bytes;
}

static void assert_read_fails_cleanly(const unsigned char *bytes, size_t size)
{
    sc_image img;
    sc_image_attr *attrs = (sc_image_attr *)1;
    int n = -1;
    char err[256] = "";
    if (sc_exr_read_memory(bytes, size, "mem.exr", &img, &attrs, &n, err, sizeof err) != -1)
        fail_msg("%zu bytes were accepted", size);
    assert_ptr_equal(strstr(err, "mem.exr: "), err);
    assert_true(strlen(err) > strlen("mem.exr: "));
    assert_null(img.data);
    assert_null(attrs);
    assert_int_equal(n, 0);
}

static void every_truncation_of_a_file_is_refused(void **state)
{
    (void)state;
    const char *names[] = {"R", "G", "B"};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 13, 40, 3, names), 0);
    fill_pattern(&img);
    write_ok(in_dir(0, "whole.exr"), &img, SC_PIXEL_HALF, NULL, 0);
    size_t size = 0;
    unsigned char *bytes = file_bytes(in_dir(0, "whole.exr"), &size);
    for (size_t n = 0; n < size; n++)
        assert_read_fails_cleanly(bytes, n);
    free(bytes);
    sc_image_free(&img);
}

static void garbage_and_missing_files_are_refused(void **state)
{
    (void)state;
    const unsigned char magic_only[] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    unsigned char noise[4096];
    uint32_t seed = 99;
    for (size_t i = 0; i < sizeof noise; i++)
        noise[i] = (unsigned char)((seed = seed * 1664525u + 1013904223u) >> 24);
    assert_read_fails_cleanly(magic_only, sizeof magic_only);
    assert_read_fails_cleanly(noise, sizeof noise);
    memcpy(noise, magic_only, sizeof magic_only);
    assert_read_fails_cleanly(noise, sizeof noise);
    sc_image img;
    char err[256] = "";
    const char *path = in_dir(0, "absent.exr");
    assert_int_equal(sc_exr_read(path, &img, NULL, NULL, err, sizeof err), -1);
    assert_ptr_equal(strstr(err, path), err);
    assert_non_null(strstr(err, "No such file or directory"));
}

/* Flipped bytes anywhere: accepted or refused, never a crash (this test runs under ASan too). */
static void corrupted_bytes_never_crash(void **state)
{
    (void)state;
    const char *names[] = {"Y", "Z"};
    sc_image img, out;
    assert_int_equal(sc_image_init(&img, 20, 35, 2, names), 0);
    fill_pattern(&img);
    write_ok(in_dir(0, "flip.exr"), &img, SC_PIXEL_FLOAT, NULL, 0);
    size_t size = 0;
    unsigned char *bytes = file_bytes(in_dir(0, "flip.exr"), &size);
    for (size_t i = 0; i < size; i++) {
        bytes[i] ^= 0xa5;
        char err[256];
        if (sc_exr_read_memory(bytes, size, "flip.exr", &out, NULL, NULL, err, sizeof err) == 0) {
            assert_true(out.n_channels >= 1 && out.width >= 1 && out.height >= 1);
            sc_image_free(&out);
        }
        bytes[i] ^= 0xa5;
    }
    free(bytes);
    sc_image_free(&img);
}

/* ---- compressions and threads ------------------------------------------------------------ */

static void write_with_ok(const char *path, const sc_image *img, sc_pixel_type type,
                          sc_exr_compression c, int threads)
{
    char err[256] = "";
    sc_exr_options opt = {type, c, threads};
    if (sc_exr_write_with(path, img, &opt, NULL, 0, err, sizeof err) != 0)
        fail_msg("writing %s (%s, %d threads): %s", path, sc_exr_compression_name(c), threads, err);
}

/* Each compression is the one the file's header names (read by OpenEXR itself) and gives the
 * pixels back: exactly, but for pxr24 on float channels, which keeps 24 bits (the float
 * rounded to 15 fraction bits, so within 2^-15 relative). */
static void every_compression_round_trips(void **state)
{
    (void)state;
    static const exr_compression_t named[SC_EXR_COMPRESSION_COUNT] = {
        EXR_COMPRESSION_NONE, EXR_COMPRESSION_RLE, EXR_COMPRESSION_ZIPS,
        EXR_COMPRESSION_ZIP,  EXR_COMPRESSION_PIZ, EXR_COMPRESSION_PXR24};
    const char *names[] = {"R", "G", "B"};
    sc_image img, back;
    assert_int_equal(sc_image_init(&img, 37, 70, 3, names), 0);
    fill_pattern(&img);
    img.data[5] = 1.0f / 3.0f; /* not exact in 24 bits */
    for (int c = 0; c < SC_EXR_COMPRESSION_COUNT; c++)
        for (int t = 0; t < 2; t++) {
            sc_pixel_type type = t ? SC_PIXEL_FLOAT : SC_PIXEL_HALF;
            write_with_ok(in_dir(0, "c.exr"), &img, type, (sc_exr_compression)c, 3);
            exr_context_t ctx = NULL;
            exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
            exr_compression_t comp;
            assert_int_equal(exr_start_read(&ctx, in_dir(0, "c.exr"), &init), 0);
            assert_int_equal(exr_get_compression(ctx, 0, &comp), 0);
            assert_int_equal(comp, named[c]);
            exr_finish(&ctx);
            read_back(in_dir(0, "c.exr"), &back, NULL, NULL);
            int lossy = c == SC_EXR_PXR24 && type == SC_PIXEL_FLOAT;
            for (size_t i = 0; i < 37 * 70 * 3; i++) {
                float want = type == SC_PIXEL_HALF ? (float)sc_round_half(img.data[i])
                                                   : img.data[i];
                double allowed = lossy ? 0x1p-15 * fabs(want) : 0.0;
                if (!(fabs(back.data[i] - want) <= allowed))
                    fail_msg("%s %s value %zu: %a, want %a", sc_exr_compression_name(c),
                             t ? "float" : "half", i, back.data[i], want);
            }
            sc_image_free(&back);
        }
    sc_image_free(&img);
}

/* The bytes of a file do not depend on the number of threads that compressed its chunks (one
 * chunk, fewer chunks than threads, many chunks). */
static void threads_do_not_change_the_file(void **state)
{
    (void)state;
    const char *names[] = {"R", "G", "B", "A"};
    static const int heights[] = {1, 40, 120}; /* files under file_bytes' 64 KB */
    for (int h = 0; h < 3; h++) {
        sc_image img;
        assert_int_equal(sc_image_init(&img, 61, heights[h], 4, names), 0);
        for (size_t i = 0; i < (size_t)61 * (size_t)heights[h] * 4; i++)
            img.data[i] = (float)sin(0.001 * (double)(i * i % 100003));
        for (int c = 0; c < SC_EXR_COMPRESSION_COUNT; c++) {
            write_with_ok(in_dir(0, "one.exr"), &img, SC_PIXEL_HALF, (sc_exr_compression)c, 1);
            write_with_ok(in_dir(1, "many.exr"), &img, SC_PIXEL_HALF, (sc_exr_compression)c, 7);
            size_t n1 = 0, n7 = 0;
            unsigned char *one = file_bytes(in_dir(0, "one.exr"), &n1);
            unsigned char *many = file_bytes(in_dir(1, "many.exr"), &n7);
            assert_int_equal(n1, n7);
            assert_memory_equal(one, many, n1);
            free(one);
            free(many);
        }
        sc_image_free(&img);
    }
}

static void compression_names_and_bad_options(void **state)
{
    (void)state;
    for (int c = 0; c < SC_EXR_COMPRESSION_COUNT; c++) {
        sc_exr_compression back;
        assert_int_equal(
            sc_exr_compression_parse(sc_exr_compression_name((sc_exr_compression)c), &back), 0);
        assert_int_equal(back, c);
    }
    sc_exr_compression c;
    assert_int_equal(sc_exr_compression_parse("dwaa", &c), -1);
    assert_int_equal(sc_exr_compression_parse("ZIP", &c), -1);
    assert_null(sc_exr_compression_name(SC_EXR_COMPRESSION_COUNT));
    const char *names[] = {"Y"};
    sc_image img;
    assert_int_equal(sc_image_init(&img, 2, 2, 1, names), 0);
    const sc_exr_options bad[] = {{SC_PIXEL_HALF, SC_EXR_COMPRESSION_COUNT, 0},
                                  {SC_PIXEL_HALF, SC_EXR_ZIP, -1},
                                  {(sc_pixel_type)7, SC_EXR_ZIP, 0}};
    for (int i = 0; i < 3; i++) {
        char err[256] = "";
        assert_int_equal(
            sc_exr_write_with(in_dir(0, "bad.exr"), &img, &bad[i], NULL, 0, err, sizeof err), -1);
        assert_non_null(strstr(err, "invalid write options"));
    }
    assert_int_equal(entries_in_dir(), 0);
    sc_image_free(&img);
}

/* The array conversion (F16C where present) has the bits of sc_half_from_double for every
 * float of the exponents where the rounding is decided (float subnormals, 2^-26 .. 2^-13, the
 * ones around 1, 2^14 .. 2^17, Inf/NaN), both signs; every float of all exponents when
 * SHADECALC_EXHAUSTIVE is set (2^32 values, a few minutes). */
static void check_halves_of_exponent(int exponent_field)
{
    enum { BLOCK = 1 << 16 };
    static float in[BLOCK];
    static uint16_t fast[BLOCK], slow[BLOCK];
    for (uint32_t sign = 0; sign < 2; sign++)
        for (uint32_t m0 = 0; m0 < (1u << 23); m0 += BLOCK) {
            for (uint32_t i = 0; i < BLOCK; i++) {
                uint32_t bits = sign << 31 | (uint32_t)exponent_field << 23 | (m0 + i);
                memcpy(&in[i], &bits, sizeof bits);
            }
            image_halves_from_floats(in, fast, BLOCK, 0);
            image_halves_from_floats(in, slow, BLOCK, 1);
            if (memcmp(fast, slow, sizeof fast) != 0)
                for (uint32_t i = 0; i < BLOCK; i++)
                    if (fast[i] != slow[i])
                        fail_msg("%a: 0x%04x, software 0x%04x", in[i], fast[i], slow[i]);
        }
}

static void array_halves_match_the_software_rounding(void **state)
{
    (void)state;
    static const int exponents[] = {0,   1,   101, 102, 103, 104, 105, 106, 107, 108, 109, 110,
                                    111, 112, 113, 114, 126, 127, 141, 142, 143, 144, 255};
    int all = getenv("SHADECALC_EXHAUSTIVE") != NULL;
    for (int e = 0; e < (all ? 256 : (int)(sizeof exponents / sizeof exponents[0])); e++)
        check_halves_of_exponent(all ? e : exponents[e]);
    /* odd lengths: the tail after the last full vector */
    float values[13];
    uint16_t fast[13], slow[13];
    for (int i = 0; i < 13; i++)
        values[i] = 0.1f * (float)i - 0.55f;
    for (size_t n = 0; n <= 13; n++) {
        image_halves_from_floats(values, fast, n, 0);
        image_halves_from_floats(values, slow, n, 1);
        assert_memory_equal(fast, slow, n * sizeof *fast);
    }
}

#define FILE_TEST(f) cmocka_unit_test_setup_teardown(f, make_dir, remove_dir)

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(image_init_rejects_bad_arguments),
        cmocka_unit_test(image_is_zeroed_interleaved_and_finds_channels),
        FILE_TEST(half_round_trip_odd_sizes_and_channels),
        FILE_TEST(float_round_trip_odd_sizes_and_channels),
        FILE_TEST(float_keeps_every_bit_pattern_class),
        FILE_TEST(half_rounds_to_nearest_even),
        FILE_TEST(half_agrees_with_the_project_rounding),
        FILE_TEST(attributes_round_trip),
        FILE_TEST(bad_attributes_are_refused_naming_the_path),
        FILE_TEST(reads_scanline_files_of_every_lossless_compression),
        FILE_TEST(reads_tiled_files_with_partial_tiles),
        FILE_TEST(written_file_is_zip_with_typed_sorted_channels),
        FILE_TEST(write_into_a_missing_directory_fails_with_the_path),
        FILE_TEST(failed_write_keeps_the_previous_file),
        FILE_TEST(atomic_abort_keeps_the_target),
        FILE_TEST(atomic_commit_replaces_and_keeps_the_mode),
        FILE_TEST(atomic_commit_failure_removes_the_temporary),
        FILE_TEST(atomic_open_refuses_a_directory_and_allows_stdout),
        FILE_TEST(every_truncation_of_a_file_is_refused),
        FILE_TEST(garbage_and_missing_files_are_refused),
        FILE_TEST(corrupted_bytes_never_crash),
        FILE_TEST(every_compression_round_trips),
        FILE_TEST(threads_do_not_change_the_file),
        FILE_TEST(compression_names_and_bad_options),
        cmocka_unit_test(array_halves_match_the_software_rounding),
    };
    return cmocka_run_group_tests_name("image", tests, NULL, NULL);
}
