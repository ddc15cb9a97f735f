/* Zeroed arrays of many megabytes, on transparent huge pages where the kernel offers them. */
#ifndef SHADECALC_UTIL_BIGALLOC_H
#define SHADECALC_UTIL_BIGALLOC_H

#include <stddef.h>

/* calloc(count, size), 0 on overflow or failure; released with free(). Arrays of 2 MiB or more
 * are aligned to 2 MiB and advised as huge pages (Linux madvise MADV_HUGEPAGE), then zeroed:
 * one page fault per 2 MiB instead of one per 4 KiB. */
void *sc_big_calloc(size_t count, size_t size);

#endif
