/* Declarations of every batch kernel for every instruction set (src/simd/). */
#ifndef SHADECALC_SIMD_KERNELS_H
#define SHADECALC_SIMD_KERNELS_H

#include "shadecalc/batch.h"
#include "simd/kernels_light.h"
#include "simd/kernels_trig.h"

#if defined(__x86_64__) || defined(__i386__)
#define SC_HAVE_X86 1
#endif

/* kernel_tier names, each defined once per instruction set */
/* clang-format off */
#define SC_BATCH_KERNELS(X)                                                                       \
    X(exp2_u1) X(exp2_u4) X(exp2_bits12) X(exp2_bits8) X(exp_u1) X(exp_u4) X(exp_bits12)         \
    X(exp_bits8) X(log2_u1) X(log2_u4) X(log2_bits12) X(log2_bits8) X(log_u1) X(log_u4)          \
    X(log_bits12) X(log_bits8) X(pow_u1) X(pow_bits12) X(pow_bits8) X(inversesqrt_u1)            \
    X(inversesqrt_u4) X(inversesqrt_bits11) X(sqrt_u1) X(dot_bits22) X(reflect_bits22)           \
    X(normalize_u3) X(length_u2) X(shade_accurate) X(shade_bits12)

#define SC_DECLARE_SCALAR(name) void sc_batch_##name##_scalar(const sc_batch_args *a);
#define SC_DECLARE_SSE41(name) void sc_batch_##name##_sse41(const sc_batch_args *a);
#define SC_DECLARE_AVX2(name) void sc_batch_##name##_avx2(const sc_batch_args *a);
#define SC_DECLARE_AVX512(name) void sc_batch_##name##_avx512(const sc_batch_args *a);
#define SC_BATCH_ALL_KERNELS(X) SC_BATCH_KERNELS(X) SC_BATCH_KERNELS_TRIG(X) SC_BATCH_KERNELS_LIGHT(X)
/* clang-format on */
SC_BATCH_ALL_KERNELS(SC_DECLARE_SCALAR)
#ifdef SC_HAVE_X86
SC_BATCH_ALL_KERNELS(SC_DECLARE_SSE41)
SC_BATCH_ALL_KERNELS(SC_DECLARE_AVX2)
SC_BATCH_ALL_KERNELS(SC_DECLARE_AVX512)
#endif

#endif
