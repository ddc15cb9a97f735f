/* The arrays of a batch kernel call (shadecalc/batch.h) and their double references, for the
 * unit tests of the light, BRDF, shading and area kernels. */
#ifndef SHADECALC_TESTS_BATCH_BUFFERS_H
#define SHADECALC_TESTS_BATCH_BUFFERS_H

#include <stddef.h>

#include "shadecalc/batch.h"

typedef struct {
    float *in[9], *out[3];
    double *ref; /* 4 per element */
    sc_batch_args args;
} batch_buffers;

/* Every array for n elements (aborts when out of memory); args reads and writes them, with
 * params. */
void batch_buffers_alloc(batch_buffers *b, size_t n, const void *params);
void batch_buffers_release(batch_buffers *b);

#endif
