/* image/adopt.h — an image around an array it takes over (private to the library).
 *
 * For arrays from sc_big_calloc (util/bigalloc.h) only, which sc_image_free releases: a
 * renderer's colour plane becomes an image's pixels without a copy (sc_render_image_take). */
#ifndef SHADECALC_IMAGE_ADOPT_H
#define SHADECALC_IMAGE_ADOPT_H

#include "shadecalc/image.h"

/* As sc_image_init, with `data` (width × height × n_channels floats, non-NULL) as the pixels
 * instead of a new array: 0, or -1 as sc_image_init (data not taken: still the caller's). */
int image_adopt(sc_image *img, int width, int height, int n_channels, const char *const *names,
                float *data);

#endif
