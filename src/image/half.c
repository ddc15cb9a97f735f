/* Float to binary16 over arrays (image/half.h). */
#include "image/half.h"

#include <stdatomic.h>

#include "shadecalc/precision.h"

static void software_halves(const float *in, uint16_t *out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = sc_half_from_double(in[i]);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>

/* VCVTPS2PH rounds to nearest even like the software path, but keeps a NaN's payload: each NaN
 * becomes the quiet NaN of its sign first, which converts to sign | 0x7e00. */
__attribute__((target("avx,f16c"))) static size_t f16c_halves(const float *in, uint16_t *out,
                                                              size_t n)
{
    const __m256 sign_bit = _mm256_set1_ps(-0.0f);
    const __m256 quiet_nan = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fc00000));
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        __m256 x = _mm256_loadu_ps(in + i);
        __m256 nan = _mm256_cmp_ps(x, x, _CMP_UNORD_Q);
        __m256 canonical = _mm256_or_ps(_mm256_and_ps(x, sign_bit), quiet_nan);
        x = _mm256_blendv_ps(x, canonical, nan);
        __m128i h = _mm256_cvtps_ph(x, _MM_FROUND_TO_NEAREST_INT);
        _mm_storeu_si128((__m128i *)(out + i), h);
    }
    return i;
}

/* F16C from CPUID leaf 1 (ECX bit 29; clang's __builtin_cpu_supports does not know "f16c"),
 * with AVX enabled by the OS. Asked once: CPUID traps to the hypervisor in a virtual machine,
 * and asking for every row of a 2048x2048 EXR took a tenth of the render's time there. */
static int have_f16c(void)
{
    static atomic_int known = -1; /* -1 until asked; any thread may ask first, all agree */
    int have = atomic_load_explicit(&known, memory_order_relaxed);
    if (have < 0) {
        unsigned a, b, c, d;
        have = __builtin_cpu_supports("avx") && __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C);
        atomic_store_explicit(&known, have, memory_order_relaxed);
    }
    return have;
}
#else
static size_t f16c_halves(const float *in, uint16_t *out, size_t n)
{
    (void)in;
    (void)out;
    (void)n;
    return 0;
}

static int have_f16c(void) { return 0; }
#endif

void image_halves_from_floats(const float *in, uint16_t *out, size_t n, int force_software)
{
    size_t done = !force_software && have_f16c() ? f16c_halves(in, out, n) : 0;
    software_halves(in + done, out + done, n - done);
}
