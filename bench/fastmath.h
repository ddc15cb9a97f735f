/* The plain loops of bench/libm_loops.c as one compiler builds them with -O3 (-march=native, or
 * -mavx2 -mfma) -ffast-math (peer rows of `shadecalc bench`), included by bench/fastmath_*.c,
 * which the Makefile compiles with that compiler and those flags.
 * Each defines BENCH_LOOPS_LOOKUP (its lookup's name) and, when the compiler is the one it is
 * named after, BENCH_FAST_COMPILER; otherwise (that compiler not installed) it has no loops. */
#include "bench/bench.h"

#if defined(BENCH_FAST_COMPILER) && defined(__FAST_MATH__)
#include "bench/libm_loops.c"
#else
sc_batch_fn BENCH_LOOPS_LOOKUP(const char *kernel)
{
    (void)kernel;
    return NULL;
}
#endif
