/* The plain loops as gcc builds them with -O3 -mavx2 -mfma -ffast-math: rows "gcc-fast-avx2",
 * the peers of the AVX2 tiers on any CPU (bench/fastmath_gcc.c: -march=native). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__AVX2__)
#define BENCH_FAST_COMPILER 1
#endif
#define BENCH_LOOPS_LOOKUP bench_fast_gcc_avx2_loop
#include "bench/fastmath.h"
