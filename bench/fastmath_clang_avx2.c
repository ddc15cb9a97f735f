/* The plain loops as clang builds them with -O3 -mavx2 -mfma -ffast-math: rows
 * "clang-fast-avx2", the peers of the AVX2 tiers on any CPU (bench/fastmath_clang.c: native). */
#if defined(__clang__) && defined(__AVX2__)
#define BENCH_FAST_COMPILER 1
#endif
#define BENCH_LOOPS_LOOKUP bench_fast_clang_avx2_loop
#include "bench/fastmath.h"
