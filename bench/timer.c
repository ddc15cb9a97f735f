/* Monotonic time in ns, and a volatile sink so that the optimizer keeps measured work. */
#include <time.h>

#include "bench/timer.h"

double bench_now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static volatile float sink;
void bench_keep(float x) { sink = x; }
