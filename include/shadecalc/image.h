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
 *   sc_exr_write_with       the same with a compression and a number of threads
 *   sc_exr_compression_name, sc_exr_compression_parse   none|rle|zips|zip|piz|pxr24
 *   sc_exr_read             read a scanline or tiled EXR into a float image, with its string
 *                           attributes (all but "type", the part's storage kind)
 *   sc_exr_read_memory      the same from bytes in memory (name is used in messages only)
 *   sc_image_attrs_free     release the attributes sc_exr_read returned
 *
 * Files: EXR stores channels sorted by name; the writer also stores the image's own channel
 * order as the string-vector attribute "shadecalc:channel_order", and the reader uses it when
 * it names exactly the file's channels (otherwise the file's order), so a round trip returns
 * the same names in the same order. Half channels are rounded to nearest even by
 * sc_half_from_double (shadecalc/precision.h), with F16C where the CPU has it (the same bits);
 * NaN stays NaN, beyond ±65504 becomes ±Inf. Chunks are compressed on several threads; the
 * file's bytes do not depend on how many.
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
 * On failure *img is left zeroed (sc_image_free is safe). The names and data belong to the
 * library: released by sc_image_free only (data is not a malloc block: never free() or
 * realloc() it, nor give sc_image_free an image whose arrays came from elsewhere). */
int sc_image_init(sc_image *img, int width, int height, int n_channels, const char *const *names);
void sc_image_free(sc_image *img);

static inline float *sc_image_pixel(const sc_image *img, int x, int y)
{
    return img->data + ((size_t)y * (size_t)img->width + (size_t)x) * (size_t)img->n_channels;
}

int sc_image_channel_index(const sc_image *img, const char *name); /* -1 if absent */

/* The compressions of OpenEXR 3.1's Core writer. All are lossless but pxr24, which rounds float
 * channels to 24 bits (half channels stay exact). */
typedef enum {
    SC_EXR_NONE,
    SC_EXR_RLE,
    SC_EXR_ZIPS, /* zlib per scanline */
    SC_EXR_ZIP,  /* zlib per 16 scanlines */
    SC_EXR_PIZ,  /* wavelet + Huffman per 32 scanlines */
    SC_EXR_PXR24,
    SC_EXR_COMPRESSION_COUNT
} sc_exr_compression;

const char *sc_exr_compression_name(sc_exr_compression c);               /* NULL out of range */
int sc_exr_compression_parse(const char *name, sc_exr_compression *out); /* 0, or -1 */

typedef struct {
    sc_pixel_type type; /* how channels are stored */
    sc_exr_compression compression;
    int threads; /* chunks compressed on this many threads; 0: one per core */
} sc_exr_options;

/* Writes img as a scanline EXR, ZIP compression, channels stored as `type`, with the string
 * attributes given (e.g. "shadecalc:command", "shadecalc:x_range"), atomically (file.h); "-"
 * writes to stdout. 0, or -1 with err "PATH: reason". */
int sc_exr_write(const char *path, const sc_image *img, sc_pixel_type type,
                 const sc_image_attr *attrs, int n_attrs, char *err, size_t errsize);
/* The same with opt's type, compression and threads (invalid options: -1, "invalid write
 * options"). */
int sc_exr_write_with(const char *path, const sc_image *img, const sc_exr_options *opt,
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
