/* tests/support/batch_buffers.h */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tests/support/batch_buffers.h"

static void *allocate(size_t size)
{
    void *p = malloc(size);
    if (!p) {
        fprintf(stderr, "batch_buffers: out of memory (%zu bytes)\n", size);
        abort();
    }
    return p;
}

void batch_buffers_alloc(batch_buffers *b, size_t n, const void *params)
{
    memset(b, 0, sizeof *b);
    for (int j = 0; j < 9; j++)
        b->args.in[j] = b->in[j] = allocate(n * sizeof(float));
    for (int j = 0; j < 3; j++)
        b->args.out[j] = b->out[j] = allocate(n * sizeof(float));
    b->ref = allocate(n * 4 * sizeof(double));
    b->args.n = n;
    b->args.params = params;
}

void batch_buffers_release(batch_buffers *b)
{
    for (int j = 0; j < 9; j++)
        free(b->in[j]);
    for (int j = 0; j < 3; j++)
        free(b->out[j]);
    free(b->ref);
}
