/* SLEEF's AVX2 functions as batch loops: comparison rows of `shadecalc bench` (isa "sleef-avx2",
 * tiers u10/u35 as SLEEF names them). Built with SLEEF only when the Makefile finds it
 * (libsleef-dev, optional); otherwise bench_sleef_loop finds nothing and bench says so. */
#include <string.h>

#include "bench/bench.h"

#if defined(SC_HAVE_SLEEF) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#include <sleef.h>

typedef __m256 (*sleef1)(__m256);
typedef __m256 (*sleef2)(__m256, __m256);

/* 8 lanes at a time; the tail through a buffer padded with 1 */
static void run_sleef(const sc_batch_args *a, sleef1 f1, sleef2 f2)
{
    size_t i = 0;
    for (; i + 8 <= a->n; i += 8) {
        __m256 x = _mm256_loadu_ps(a->in[0] + i);
        _mm256_storeu_ps(a->out[0] + i, f1 ? f1(x) : f2(x, _mm256_loadu_ps(a->in[1] + i)));
    }
    if (i == a->n)
        return;
    float x[8], y[8], r[8];
    for (size_t k = 0; k < 8; k++) {
        x[k] = i + k < a->n ? a->in[0][i + k] : 1.0f;
        y[k] = f2 && i + k < a->n ? a->in[1][i + k] : 1.0f;
    }
    _mm256_storeu_ps(r, f1 ? f1(_mm256_loadu_ps(x)) : f2(_mm256_loadu_ps(x), _mm256_loadu_ps(y)));
    for (size_t k = 0; i + k < a->n; k++)
        a->out[0][i + k] = r[k];
}

/* wrappers: SLEEF declares its functions as returning const __m256, a type clang will not
 * convert to sleef1/sleef2 */
#define LOOP1(name, fn)                                                                           \
    static __m256 lane_##name(__m256 x) { return fn(x); }                                        \
    static void name(const sc_batch_args *a) { run_sleef(a, lane_##name, NULL); }
#define LOOP2(name, fn)                                                                           \
    static __m256 lane_##name(__m256 x, __m256 y) { return fn(x, y); }                           \
    static void name(const sc_batch_args *a) { run_sleef(a, NULL, lane_##name); }
LOOP2(pow_u10, Sleef_powf8_u10avx2)
LOOP1(exp_u10, Sleef_expf8_u10avx2)
LOOP1(exp2_u10, Sleef_exp2f8_u10avx2)
LOOP1(exp2_u35, Sleef_exp2f8_u35avx2)
LOOP1(log_u10, Sleef_logf8_u10avx2)
LOOP1(log_u35, Sleef_logf8_u35avx2)
LOOP1(log2_u10, Sleef_log2f8_u10avx2)
LOOP1(log2_u35, Sleef_log2f8_u35avx2)
LOOP1(sin_u10, Sleef_sinf8_u10avx2)
LOOP1(sin_u35, Sleef_sinf8_u35avx2)
LOOP1(cos_u10, Sleef_cosf8_u10avx2)
LOOP1(cos_u35, Sleef_cosf8_u35avx2)
LOOP1(acos_u10, Sleef_acosf8_u10avx2)
LOOP1(acos_u35, Sleef_acosf8_u35avx2)
LOOP2(atan2_u10, Sleef_atan2f8_u10avx2)
LOOP2(atan2_u35, Sleef_atan2f8_u35avx2)
LOOP1(sqrt_u05, Sleef_sqrtf8_u05avx2)

static const bench_sleef sleef_loops[] = {
    {"pow", "u10", pow_u10},     {"exp", "u10", exp_u10},     {"exp2", "u10", exp2_u10},
    {"exp2", "u35", exp2_u35},   {"log", "u10", log_u10},     {"log", "u35", log_u35},
    {"log2", "u10", log2_u10},   {"log2", "u35", log2_u35},   {"sin", "u10", sin_u10},
    {"sin", "u35", sin_u35},     {"cos", "u10", cos_u10},     {"cos", "u35", cos_u35},
    {"acos", "u10", acos_u10},   {"acos", "u35", acos_u35},   {"atan2", "u10", atan2_u10},
    {"atan2", "u35", atan2_u35}, {"sqrt", "u05", sqrt_u05},
};

int bench_sleef_available(void) { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

int bench_sleef_loops(const char *kernel, const bench_sleef **out)
{
    int n = 0;
    for (size_t i = 0; i < sizeof sleef_loops / sizeof sleef_loops[0]; i++)
        if (strcmp(sleef_loops[i].kernel, kernel) == 0) {
            if (n == 0)
                *out = &sleef_loops[i];
            n++;
        }
    return n;
}
#else
int bench_sleef_available(void) { return 0; }

int bench_sleef_loops(const char *kernel, const bench_sleef **out)
{
    (void)kernel;
    (void)out;
    return 0;
}
#endif
