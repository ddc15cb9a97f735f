/* Huge-page arrays (bigalloc.h). A 2048² render touched its framebuffer and image, about
 * 260 MiB, in 4 KiB pages: 66 000 page faults and 0.54 s of system time against 0.60 s of
 * computing on one thread of a VM, where faults are dear, and two threads faulting at once
 * contended for the process's memory map (1.3x for two threads). On huge pages: about 2 000
 * faults, 1.9-2.4x for two threads (render --size 2048x2048, Zen 4 VM, THP "madvise").
 * Large arrays are fresh mappings, which the kernel zeroes on first touch: the render's threads
 * take the faults of the tiles they clear, where zeroing everything first took one thread. */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS, MADV_HUGEPAGE */
#include "util/bigalloc.h"

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

enum { HUGE_PAGE = 2 << 20, HEADER = 64 };

/* Stored just before the array: how to release it. */
typedef struct {
    void *base;    /* what calloc or mmap returned */
    size_t mapped; /* the mapping's length; 0: from calloc */
} big_header;

static void *with_header(void *base, size_t mapped, char *array)
{
    big_header *h = (big_header *)(array - HEADER);
    h->base = base;
    h->mapped = mapped;
    return array;
}

#if !defined(MAP_ANONYMOUS) && defined(MAP_ANON)
#define MAP_ANONYMOUS MAP_ANON /* the BSDs' and macOS's older name */
#endif

/* Sanitizers see overflows and leaks of calloc's blocks, not of mappings: their builds take
 * calloc for every size. */
#if defined(__SANITIZE_ADDRESS__)
#define BIG_USE_MMAP 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define BIG_USE_MMAP 0
#endif
#endif
#ifndef BIG_USE_MMAP
#ifdef MAP_ANONYMOUS
#define BIG_USE_MMAP 1
#else
#define BIG_USE_MMAP 0
#endif
#endif

#if BIG_USE_MMAP
static size_t round_up(size_t n, size_t to) { return (n + to - 1) / to * to; }

/* A mapping whose array starts on a 2 MiB boundary and ends on one, with one page before it
 * for the header; the slack before and after is unmapped again. 0 where mmap fails. */
static void *map_huge(size_t bytes)
{
    long page_size = sysconf(_SC_PAGESIZE);
    size_t page = (size_t)page_size, span = round_up(bytes, HUGE_PAGE);
    if (page_size < HEADER || page > HUGE_PAGE || span > SIZE_MAX - (size_t)HUGE_PAGE)
        return NULL; /* span itself cannot wrap: sc_big_calloc refuses bytes that would */
    size_t len = span + HUGE_PAGE; /* the array starts at most a huge page past the base */
    char *base = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED)
        return NULL;
    char *array = (char *)round_up((uintptr_t)base + page, HUGE_PAGE), *start = array - page;
    char *end = array + span;
    if (start > base)
        munmap(base, (size_t)(start - base));
    if (base + len > end)
        munmap(end, (size_t)(base + len - end));
#ifdef MADV_HUGEPAGE
    (void)madvise(array, span, MADV_HUGEPAGE); /* advice only: ordinary pages where refused */
#endif
    return with_header(start, (size_t)(end - start), array);
}
#endif

void *sc_big_calloc(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    size_t bytes = count * size;
    if (bytes > SIZE_MAX - HUGE_PAGE)
        return NULL;
#if BIG_USE_MMAP
    if (bytes >= HUGE_PAGE) {
        void *array = map_huge(bytes);
        if (array)
            return array;
    }
#endif
    char *base = calloc(1, HEADER + (bytes ? bytes : 1));
    return base ? with_header(base, 0, base + HEADER) : NULL;
}

void sc_big_free(void *array)
{
    if (!array)
        return;
    const big_header *h = (const big_header *)((char *)array - HEADER);
    if (h->mapped)
        munmap(h->base, h->mapped);
    else
        free(h->base);
}
