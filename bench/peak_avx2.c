/* The floating-point peak of the roofline: independent chains of AVX2 fused multiply-adds and of
 * additions, 10 of each (more than latency times issue rate for both: 4 cycles × 2 FMA pipes and
 * 3 cycles × 2 add pipes on Zen 3), so that the loop runs at the throughput of all the FP pipes
 * a kernel's mix of multiplies and additions can use. Compiled with -mavx2 -mfma (Makefile). */
#include "bench/bench.h"
#include "bench/timer.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>

double bench_peak_avx2(void)
{
    if (!(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")))
        return 0.0;
    enum { ITER = 4000000, CHAINS = 10 };
    const __m256 m = _mm256_set1_ps(0.999999f), c = _mm256_set1_ps(1e-7f);
    double best = 0.0;
    for (int r = 0; r < 3; r++) {
        __m256 acc[CHAINS], sum[CHAINS];
        for (int k = 0; k < CHAINS; k++)
            acc[k] = sum[k] = _mm256_set1_ps(1.0f + (float)k);
        double t0 = bench_now_ns();
        for (int i = 0; i < ITER; i++)
            for (int k = 0; k < CHAINS; k++) {
                acc[k] = _mm256_fmadd_ps(acc[k], m, c);
                sum[k] = _mm256_add_ps(sum[k], c);
            }
        double t = bench_now_ns() - t0;
        float lanes[8];
        for (int k = 1; k < CHAINS; k++)
            acc[0] = _mm256_add_ps(acc[0], _mm256_add_ps(acc[k], sum[k]));
        _mm256_storeu_ps(lanes, acc[0]);
        bench_keep(lanes[0]);
        if (t > 0 && 16.0 * CHAINS * ITER / t > best)
            best = 16.0 * CHAINS * ITER / t;
    }
    return best;
}
#else
double bench_peak_avx2(void) { return 0.0; }
#endif
