/* The floating-point peak of the roofline: independent chains of AVX2 fused multiply-adds and of
 * additions, 7 of each (as many as the 16 ymm registers hold beside the two constants; about
 * latency times issue rate: 4 cycles × 2 FMA pipes, 3 cycles × 2 add pipes on Zen 3), so that
 * the loop runs near the throughput of all the FP pipes a kernel's mix of multiplies and
 * additions can use; and the memory side, a stream loop over as many arrays as a kernel reads
 * and writes. Compiled with -mavx2 -mfma (Makefile). */
#include "bench/bench.h"
#include "bench/timer.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>

/* One step of every chain: named variables, not an array, so that they live in registers. */
#define CHAINS(X) X(0) X(1) X(2) X(3) X(4) X(5) X(6)
#define DECLARE(k) __m256 f##k = _mm256_set1_ps(1.0f + k), s##k = f##k;
#define STEP(k)                                                                                    \
    f##k = _mm256_fmadd_ps(f##k, m, c);                                                            \
    s##k = _mm256_add_ps(s##k, c);
#define SUM(k) total = _mm256_add_ps(total, _mm256_add_ps(f##k, s##k));

static double one_run(int iterations)
{
    const __m256 m = _mm256_set1_ps(0.999999f), c = _mm256_set1_ps(1e-7f);
    CHAINS(DECLARE)
    double t0 = bench_now_ns();
    for (int i = 0; i < iterations; i++) {
        CHAINS(STEP)
    }
    double t = bench_now_ns() - t0;
    __m256 total = _mm256_setzero_ps();
    CHAINS(SUM)
    float lanes[8];
    _mm256_storeu_ps(lanes, total);
    bench_keep(lanes[0]);
    return t > 0 ? 8.0 * 14 * iterations / t : 0.0;
}

double bench_peak_avx2(void)
{
    if (!(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")))
        return 0.0;
    /* The best of many short runs (20000 steps: about 0.1 ms), as the kernels' samples are
     * short: on a loaded machine a long run is shared with other processes and reads a
     * fraction of the peak, which put kernels above 100% of their compute bound. */
    double best = 0.0;
    for (int r = 0; r < 300; r++) {
        double v = one_run(20000);
        best = v > best ? v : best;
    }
    return best;
}

int bench_stream_avx2_supported(void) { return __builtin_cpu_supports("avx2"); }

double bench_stream_pass_avx2(float *const *arrays, int k, int m, size_t n)
{
    double t0 = bench_now_ns();
    for (size_t i = 0; i + 8 <= n; i += 8) {
        __m256 sum = _mm256_load_ps(arrays[0] + i);
        for (int j = 1; j < k; j++)
            sum = _mm256_add_ps(sum, _mm256_load_ps(arrays[j] + i));
        for (int j = 0; j < m; j++)
            _mm256_stream_ps(arrays[k + j] + i, sum);
    }
    _mm_sfence();
    double t = bench_now_ns() - t0;
    bench_keep(arrays[k][n / 2]);
    return t;
}
#else
double bench_peak_avx2(void) { return 0.0; }
int bench_stream_avx2_supported(void) { return 0; }
double bench_stream_pass_avx2(float *const *arrays, int k, int m, size_t n)
{
    (void)arrays, (void)k, (void)m, (void)n;
    return 0.0;
}
#endif
