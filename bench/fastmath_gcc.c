/* The plain loops as gcc builds them with -O3 -march=native -ffast-math: rows "gcc-fast", the
 * peers of the tiers of this CPU's best instruction set (bench/harness.c). */
#if defined(__GNUC__) && !defined(__clang__)
#define BENCH_FAST_COMPILER 1
#endif
#define BENCH_LOOPS_LOOKUP bench_fast_gcc_loop
#include "bench/fastmath.h"
