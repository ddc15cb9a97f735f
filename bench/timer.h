/* Wall-clock time for the benchmark, and a sink that keeps results alive. */
#ifndef SHADECALC_BENCH_TIMER_H
#define SHADECALC_BENCH_TIMER_H

double bench_now_ns(void);
void bench_keep(float x);

#endif
