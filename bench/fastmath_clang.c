/* The plain loops as clang builds them with -O3 -march=native -ffast-math: rows "clang-fast". */
#if defined(__clang__)
#define BENCH_FAST_COMPILER 1
#endif
#define BENCH_LOOPS_LOOKUP bench_fast_clang_loop
#include "bench/fastmath.h"
