/*
 * shadecalc/image.h — float images with named channels, and OpenEXR files.
 *
 *   SC_IMAGE_MAX_CHANNELS   16
 *   sc_pixel_type           SC_PIXEL_HALF, SC_PIXEL_FLOAT (how channels are stored in a file)
 *   sc_image                width × height pixels of n_channels floats, interleaved, y = 0 the top
 *   sc_image_attr           a string attribute {name, value}
 *   sc_image_init           allocate a zeroed image with channel names
 *   sc_image_free           release an image (safe on a zeroed or failed one)
 *   sc_image_pixel          pointer to a pixel's first channel
 *   sc_image_channel_index  a channel's index by name, -1 if absent
 *   sc_exr_write            write a scanline EXR (ZIP), atomically (shadecalc/file.h)
 *   sc_exr_read             read a scanline or tiled EXR into a float image, with its string
 *                           attributes (all but "type", the part's storage kind)
 *   sc_exr_read_memory      the same from bytes in memory (name is used in messages only)
 *   sc_image_attrs_free     release the attributes sc_exr_read returned
 *
 * Files: EXR stores channels sorted by name; the writer also stores the image's own channel
 * order as the string-vector attribute "shadecalc:channel_order", and the reader uses it when
 * it names exactly the file's channels (otherwise the file's order), so a round trip returns
 * the same names in the same order. Half channels are rounded to nearest even by
 * sc_half_from_double (shadecalc/precision.h); NaN stays NaN, beyond ±65504 becomes ±Inf.
 * The reader converts half, float and uint channels to float (uint above 2^24 rounds to
 * nearest), takes part 0 of a multi-part file and level (0,0) of a tiled mip/rip-map, and
 * refuses deep data, subsampled channels, more than SC_IMAGE_MAX_CHANNELS channels and images
 * of more than SC_EXR_MAX_VALUES values (width × height × channels).
 */
#ifndef SHADECALC_IMAGE_H
#define SHADECALC_IMAGE_H

#include <stddef.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

enum { SC_IMAGE_MAX_CHANNELS = 16 };
#define SC_EXR_MAX_VALUES ((size_t)1 << 28)

typedef enum { SC_PIXEL_HALF, SC_PIXEL_FLOAT } sc_pixel_type;

typedef struct {
    char *name;
    char *value;
} sc_image_attr; /* string attributes */

typedef struct {
    int width, height, n_channels;
    char *channel[SC_IMAGE_MAX_CHANNELS]; /* "R","G","B","A","Y","Z","N.X",... (owned) */
    float *data; /* interleaved: data[((size_t)y * width + x) * n_channels + c]; y = 0 the top */
} sc_image;

/* Allocates a zeroed image; 0, or -1 (width or height < 1, n_channels not in
 * 1..SC_IMAGE_MAX_CHANNELS, a NULL, empty or repeated name, size overflow, out of memory).
 * On failure *img is left zeroed (sc_image_free is safe). */
int sc_image_init(sc_image *img, int width, int height, int n_channels, const char *const *names);
void sc_image_free(sc_image *img);

static inline float *sc_image_pixel(const sc_image *img, int x, int y)
{
    return img->data + ((size_t)y * (size_t)img->width + (size_t)x) * (size_t)img->n_channels;
}

int sc_image_channel_index(const sc_image *img, const char *name); /* -1 if absent */

/* Writes img as a scanline EXR, ZIP compression, channels stored as `type`, with the string
 * attributes given (e.g. "shadecalc:command", "shadecalc:x_range"), atomically (file.h); "-"
 * writes to stdout. 0, or -1 with err "PATH: reason". */
int sc_exr_write(const char *path, const sc_image *img, sc_pixel_type type,
                 const sc_image_attr *attrs, int n_attrs, char *err, size_t errsize);

/* Reads any scanline or tiled EXR of half/float/uint channels into a float image, and its
 * string attributes (caller frees with sc_image_attrs_free; attrs may be NULL if not wanted).
 * 0, or -1 with err "PATH: reason" and *out zeroed, *attrs NULL, *n_attrs 0. */
int sc_exr_read(const char *path, sc_image *out, sc_image_attr **attrs, int *n_attrs, char *err,
                size_t errsize);
int sc_exr_read_memory(const void *bytes, size_t size, const char *name, sc_image *out,
                       sc_image_attr **attrs, int *n_attrs, char *err, size_t errsize);

void sc_image_attrs_free(sc_image_attr *attrs, int n);

SC_END_DECLS

#endif
