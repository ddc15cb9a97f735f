/* Float images with named channels (shadecalc/image.h): allocation, lookup, attribute lists. */
#include "shadecalc/image.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "image/adopt.h"
#include "util/bigalloc.h"

static int names_are_valid(int n, const char *const *names)
{
    for (int c = 0; c < n; c++) {
        if (!names[c] || !names[c][0])
            return 0;
        for (int d = 0; d < c; d++)
            if (strcmp(names[c], names[d]) == 0)
                return 0;
    }
    return 1;
}

static int copy_names(sc_image *img, int n, const char *const *names)
{
    for (int c = 0; c < n; c++) {
        size_t len = strlen(names[c]) + 1;
        if (!(img->channel[c] = malloc(len)))
            return -1;
        memcpy(img->channel[c], names[c], len);
    }
    return 0;
}

/* The image's size and names, and `data` (0: a zeroed array of its own) as its pixels. */
static int image_with(sc_image *img, int width, int height, int n_channels,
                      const char *const *names, float *data)
{
    memset(img, 0, sizeof *img);
    if (width < 1 || height < 1 || n_channels < 1 || n_channels > SC_IMAGE_MAX_CHANNELS || !names ||
        !names_are_valid(n_channels, names))
        return -1;
    if ((size_t)height > SIZE_MAX / sizeof(float) / (size_t)n_channels / (size_t)width)
        return -1;
    size_t pixels = (size_t)width * (size_t)height;
    if (copy_names(img, n_channels, names) != 0 ||
        !(data = data ? data : sc_big_calloc(pixels * (size_t)n_channels, sizeof(float)))) {
        sc_image_free(img);
        return -1;
    }
    img->width = width;
    img->height = height;
    img->n_channels = n_channels;
    img->data = data;
    return 0;
}

int sc_image_init(sc_image *img, int width, int height, int n_channels, const char *const *names)
{
    return image_with(img, width, height, n_channels, names, NULL);
}

int image_adopt(sc_image *img, int width, int height, int n_channels, const char *const *names,
                float *data)
{
    return data ? image_with(img, width, height, n_channels, names, data) : -1;
}

void sc_image_free(sc_image *img)
{
    for (int c = 0; c < SC_IMAGE_MAX_CHANNELS; c++)
        free(img->channel[c]);
    sc_big_free(img->data);
    memset(img, 0, sizeof *img);
}

int sc_image_channel_index(const sc_image *img, const char *name)
{
    for (int c = 0; c < img->n_channels; c++)
        if (strcmp(img->channel[c], name) == 0)
            return c;
    return -1;
}

void sc_image_attrs_free(sc_image_attr *attrs, int n)
{
    if (!attrs)
        return;
    for (int i = 0; i < n; i++) {
        free(attrs[i].name);
        free(attrs[i].value);
    }
    free(attrs);
}
