/* libFuzzer harness: the EXR reader (shadecalc/image.h, through OpenEXR's Core API) accepts or
 * refuses any bytes without crashing, hanging or leaking; a refusal always says why, and an
 * accepted image has a valid shape whose every value is readable. Seeds: tiny files of
 * sc_exr_write (half, float, attributes), an OpenEXR-written tiled file, truncated copies. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_image(const sc_image *img, const sc_image_attr *attrs, int n_attrs)
{
    if (img->width < 1 || img->height < 1 || img->n_channels < 1 ||
        img->n_channels > SC_IMAGE_MAX_CHANNELS)
        abort();
    for (int c = 0; c < img->n_channels; c++)
        if (sc_image_channel_index(img, img->channel[c]) != c) /* names distinct */
            abort();
    size_t bytes = (size_t)img->width * (size_t)img->height * (size_t)img->n_channels * 4;
    float *copy = malloc(bytes);
    if (copy) /* ASan checks that the buffer is as large as stated */
        memcpy(copy, img->data, bytes);
    free(copy);
    for (int i = 0; i < n_attrs; i++)
        if (strlen(attrs[i].name) == 0 || !attrs[i].value)
            abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sc_image img;
    sc_image_attr *attrs = NULL;
    int n_attrs = 0;
    char err[256] = "";
    if (sc_exr_read_memory(data, size, "fuzz.exr", &img, &attrs, &n_attrs, err, sizeof err) == 0) {
        check_image(&img, attrs, n_attrs);
        sc_image_free(&img);
        sc_image_attrs_free(attrs, n_attrs);
    } else if (strncmp(err, "fuzz.exr: ", 10) != 0 || !err[10] || img.data || attrs) {
        abort();
    }
    return 0;
}
