/* The plain loops of bench/libm_loops.c as gcc compiles them with -O3 -march=native
 * -ffast-math (the Makefile compiles this file with gcc and those flags): peer rows
 * "gcc-fast" of `shadecalc bench`. Without gcc the file is built by another compiler and has
 * no loops. */
#include "bench/bench.h"

#if defined(__GNUC__) && !defined(__clang__) && defined(__FAST_MATH__)
#define BENCH_LOOPS_LOOKUP bench_fast_gcc_loop
#include "bench/libm_loops.c"
#else
sc_batch_fn bench_fast_gcc_loop(const char *kernel)
{
    (void)kernel;
    return NULL;
}
#endif
