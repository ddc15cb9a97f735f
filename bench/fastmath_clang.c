/* The plain loops of bench/libm_loops.c as clang compiles them with -O3 -march=native
 * -ffast-math (the Makefile compiles this file with clang and those flags when clang is
 * installed): peer rows "clang-fast" of `shadecalc bench`. Without clang it has no loops. */
#include "bench/bench.h"

#if defined(__clang__) && defined(__FAST_MATH__)
#define BENCH_LOOPS_LOOKUP bench_fast_clang_loop
#include "bench/libm_loops.c"
#else
sc_batch_fn bench_fast_clang_loop(const char *kernel)
{
    (void)kernel;
    return NULL;
}
#endif
