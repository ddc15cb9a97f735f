/* SLEEF's AVX2 functions in loops over the arrays, as a user of SLEEF writes them: comparison
 * rows of `shadecalc bench` (isa "sleef-avx2", tiers u10/u35 as SLEEF names them). Built with
 * SLEEF only when the Makefile finds it (libsleef-dev, optional); otherwise bench_sleef_loops
 * finds nothing and the report's header says so. */
#include <string.h>

#include "bench/bench.h"

#if defined(SC_HAVE_SLEEF) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#include <sleef.h>

/* 8 lanes at a time, calling SLEEF's function directly in the loop (no pointer, no wrapper);
 * the tail through a buffer padded with 1. `expr` computes the vector r from x (and y). */
/* clang-format off */
#define SLEEF_LOOP(name, expr)                                                                    \
    static void name(const sc_batch_args *a)                                                      \
    {                                                                                             \
        const float *in0 = a->in[0], *in1 = a->in[1] ? a->in[1] : a->in[0];                      \
        float *out = a->out[0];                                                                   \
        size_t i = 0, n = a->n;                                                                   \
        for (; i + 8 <= n; i += 8) {                                                              \
            __m256 x = _mm256_loadu_ps(in0 + i), y = _mm256_loadu_ps(in1 + i);                   \
            (void)y;                                                                              \
            _mm256_storeu_ps(out + i, expr);                                                      \
        }                                                                                         \
        if (i == n)                                                                               \
            return;                                                                               \
        float bx[8], by[8], br[8];                                                                \
        pad_tail(in0 + i, bx, n - i);                                                             \
        pad_tail(in1 + i, by, n - i);                                                             \
        __m256 x = _mm256_loadu_ps(bx), y = _mm256_loadu_ps(by);                                  \
        (void)y;                                                                                  \
        _mm256_storeu_ps(br, expr);                                                               \
        memcpy(out + i, br, (n - i) * sizeof(float));                                             \
    }
/* clang-format on */

/* the first count < 8 elements of p, padded with 1 */
static void pad_tail(const float *p, float *b, size_t count)
{
    for (size_t k = 0; k < 8; k++)
        b[k] = k < count ? p[k] : 1.0f;
}

/* kernel, SLEEF's tier, the vector expression */
/* clang-format off */
#define SLEEF_FUNCTIONS(X)                                                                        \
    X(pow, u10, Sleef_powf8_u10avx2(x, y))                                                        \
    X(exp, u10, Sleef_expf8_u10avx2(x))                                                           \
    X(exp2, u10, Sleef_exp2f8_u10avx2(x)) X(exp2, u35, Sleef_exp2f8_u35avx2(x))                   \
    X(log, u10, Sleef_logf8_u10avx2(x)) X(log, u35, Sleef_logf8_u35avx2(x))                       \
    X(log2, u10, Sleef_log2f8_u10avx2(x)) X(log2, u35, Sleef_log2f8_u35avx2(x))                   \
    X(sin, u10, Sleef_sinf8_u10avx2(x)) X(sin, u35, Sleef_sinf8_u35avx2(x))                       \
    X(cos, u10, Sleef_cosf8_u10avx2(x)) X(cos, u35, Sleef_cosf8_u35avx2(x))                       \
    X(acos, u10, Sleef_acosf8_u10avx2(x)) X(acos, u35, Sleef_acosf8_u35avx2(x))                   \
    X(atan2, u10, Sleef_atan2f8_u10avx2(x, y)) X(atan2, u35, Sleef_atan2f8_u35avx2(x, y))         \
    X(sqrt, u05, Sleef_sqrtf8_u05avx2(x))

#define SLEEF_DEFINE(kernel, tier, expr) SLEEF_LOOP(kernel##_##tier, expr)
SLEEF_FUNCTIONS(SLEEF_DEFINE)
/* clang-format on */

#define SLEEF_ROW(kernel, tier, expr) {#kernel, #tier, kernel##_##tier},
static const bench_sleef sleef_loops[] = {SLEEF_FUNCTIONS(SLEEF_ROW)};

int bench_sleef_available(void)
{
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

const char *bench_sleef_absence(void)
{
    return bench_sleef_available() ? "" : "this CPU lacks AVX2 or FMA: no sleef-avx2 rows";
}

#define SLEEF_STR2(x) #x
#define SLEEF_STR(x) SLEEF_STR2(x)
const char *bench_sleef_version(void)
{
    return SLEEF_STR(SLEEF_VERSION_MAJOR) "." SLEEF_STR(SLEEF_VERSION_MINOR) "." SLEEF_STR(
        SLEEF_VERSION_PATCHLEVEL);
}

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

const char *bench_sleef_absence(void)
{
    return "SLEEF not found at build time: no sleef-avx2 rows (install libsleef-dev and rebuild)";
}

const char *bench_sleef_version(void) { return ""; }

int bench_sleef_loops(const char *kernel, const bench_sleef **out)
{
    (void)kernel;
    (void)out;
    return 0;
}
#endif
