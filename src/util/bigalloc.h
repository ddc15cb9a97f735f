/* Zeroed arrays of many megabytes, on transparent huge pages where the kernel offers them. */
#ifndef SHADECALC_UTIL_BIGALLOC_H
#define SHADECALC_UTIL_BIGALLOC_H

#include <stddef.h>

/* A zeroed array of count elements of size bytes, 0 on overflow or failure; released with
 * sc_big_free only (a header before the array says how). Arrays of 2 MiB or more are
 * anonymous mappings aligned to 2 MiB and advised as huge pages (Linux madvise MADV_HUGEPAGE):
 * one page fault per 2 MiB instead of one per 4 KiB, taken by the thread that first touches
 * the page. Others, and all under AddressSanitizer or where mmap fails, come from calloc. */
void *sc_big_calloc(size_t count, size_t size);

/* Releases an array from sc_big_calloc; nothing for 0. */
void sc_big_free(void *array);

#endif
