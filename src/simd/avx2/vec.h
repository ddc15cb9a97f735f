/* The vector helpers of the batch kernels for AVX2 + FMA: 8 float lanes, 4 double lanes
 * (src/simd/kernels_impl.h uses only these). Compiled with -mavx2 -mfma -mf16c. */
#ifndef SHADECALC_SIMD_AVX2_VEC_H
#define SHADECALC_SIMD_AVX2_VEC_H

#include <immintrin.h>

#define VW 8
#define VD_PER_VF 2
#define ISA_SUFFIX avx2
#define SIMD_HAS_FMA 1 /* vf_fma and vd_fma round once */

typedef __m256 vf;
typedef __m256 vm; /* lane masks: all bits set or clear */
typedef __m256i vi;
typedef __m256d vd;
typedef __m256d vdm;
typedef __m256i vl;

static inline vf vf_loadu(const float *p) { return _mm256_loadu_ps(p); }
static inline void vf_storeu(float *p, vf x) { _mm256_storeu_ps(p, x); }
/* a non-temporal store (p aligned to 32 bytes), and the fence after a run of them */
static inline void vf_stream(float *p, vf x) { _mm256_stream_ps(p, x); }
static inline void vf_stream_fence(void) { _mm_sfence(); }
static inline vf vf_set1(float x) { return _mm256_set1_ps(x); }
static inline vf vf_add(vf a, vf b) { return _mm256_add_ps(a, b); }
static inline vf vf_sub(vf a, vf b) { return _mm256_sub_ps(a, b); }
static inline vf vf_mul(vf a, vf b) { return _mm256_mul_ps(a, b); }
static inline vf vf_div(vf a, vf b) { return _mm256_div_ps(a, b); }
static inline vf vf_fma(vf a, vf b, vf c) { return _mm256_fmadd_ps(a, b, c); }
static inline vf vf_sqrt(vf a) { return _mm256_sqrt_ps(a); }
static inline vf vf_rsqrt_est(vf a) { return _mm256_rsqrt_ps(a); }
static inline vf vf_rcp_est(vf a) { return _mm256_rcp_ps(a); }
static inline vf vf_min(vf a, vf b) { return _mm256_min_ps(a, b); }
static inline vf vf_max(vf a, vf b) { return _mm256_max_ps(a, b); }
static inline vm vf_lt(vf a, vf b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
static inline vm vf_le(vf a, vf b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
static inline vm vf_eq(vf a, vf b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
static inline vm vf_isnan(vf a) { return _mm256_cmp_ps(a, a, _CMP_UNORD_Q); }
static inline vm vf_nlt(vf a, vf b) { return _mm256_cmp_ps(a, b, _CMP_NLT_UQ); } /* !(a < b) */
static inline vm vm_or(vm a, vm b) { return _mm256_or_ps(a, b); }
static inline vm vm_and(vm a, vm b) { return _mm256_and_ps(a, b); }
static inline int vm_any(vm a) { return _mm256_movemask_ps(a) != 0; }
static inline int vm_lane(vm a, int i) { return (_mm256_movemask_ps(a) >> i) & 1; }
static inline vf vf_select(vm m, vf a, vf b) { return _mm256_blendv_ps(b, a, m); }
/* a where m, else +0: one AND, where a blend with zero costs the compiler a sign spread of m too
 * (it cannot know that a comparison's lanes are all bits set or clear) */
static inline vf vf_keep(vm m, vf a) { return _mm256_and_ps(m, a); }
static inline vi vf_as_vi(vf x) { return _mm256_castps_si256(x); }
static inline vf vi_as_vf(vi x) { return _mm256_castsi256_ps(x); }
static inline vi vi_round(vf x) { return _mm256_cvtps_epi32(x); } /* to nearest, ties even */
static inline vf vi_to_vf(vi x) { return _mm256_cvtepi32_ps(x); }
static inline vi vi_set1(int x) { return _mm256_set1_epi32(x); }
static inline vi vi_add(vi a, vi b) { return _mm256_add_epi32(a, b); }
static inline vi vi_sub(vi a, vi b) { return _mm256_sub_epi32(a, b); }
static inline vi vi_and(vi a, vi b) { return _mm256_and_si256(a, b); }
static inline vi vi_shl23(vi a) { return _mm256_slli_epi32(a, 23); }
static inline vi vi_shl31(vi a) { return _mm256_slli_epi32(a, 31); }
static inline vi vi_sra23(vi a) { return _mm256_srai_epi32(a, 23); }
static inline vm vi_eq(vi a, vi b) { return _mm256_castsi256_ps(_mm256_cmpeq_epi32(a, b)); }
static inline vf vf_abs(vf a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }

/* doubles: the low and high halves of a vf */
static inline vd vd_from_lo(vf x) { return _mm256_cvtps_pd(_mm256_castps256_ps128(x)); }
static inline vd vd_from_hi(vf x) { return _mm256_cvtps_pd(_mm256_extractf128_ps(x, 1)); }
/* VW/2 floats at p, as doubles: a load folded into the conversion */
static inline vd vd_load_floats(const float *p) { return _mm256_cvtps_pd(_mm_loadu_ps(p)); }
static inline vf vf_from_vd(vd lo, vd hi)
{
    return _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo));
}
static inline vd vd_set1(double x) { return _mm256_set1_pd(x); }
static inline vd vd_add(vd a, vd b) { return _mm256_add_pd(a, b); }
static inline vd vd_sub(vd a, vd b) { return _mm256_sub_pd(a, b); }
static inline vd vd_mul(vd a, vd b) { return _mm256_mul_pd(a, b); }
static inline vd vd_div(vd a, vd b) { return _mm256_div_pd(a, b); }
static inline vd vd_fma(vd a, vd b, vd c) { return _mm256_fmadd_pd(a, b, c); }
static inline vd vd_sqrt(vd a) { return _mm256_sqrt_pd(a); }
static inline vd vd_min(vd a, vd b) { return _mm256_min_pd(a, b); }
static inline vd vd_max(vd a, vd b) { return _mm256_max_pd(a, b); }
static inline vdm vd_lt(vd a, vd b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
static inline vd vd_select(vdm m, vd a, vd b) { return _mm256_blendv_pd(b, a, m); }
static inline vl vd_as_vl(vd x) { return _mm256_castpd_si256(x); }
static inline vd vl_as_vd(vl x) { return _mm256_castsi256_pd(x); }
static inline vl vl_set1(long long x) { return _mm256_set1_epi64x(x); }
static inline vl vl_add(vl a, vl b) { return _mm256_add_epi64(a, b); }
static inline vl vl_sub(vl a, vl b) { return _mm256_sub_epi64(a, b); }
static inline vl vl_and(vl a, vl b) { return _mm256_and_si256(a, b); }
static inline vl vl_or(vl a, vl b) { return _mm256_or_si256(a, b); }
static inline vl vl_shl52(vl a) { return _mm256_slli_epi64(a, 52); }
static inline vl vl_shr52(vl a) { return _mm256_srli_epi64(a, 52); }
static inline vdm vl_eq(vl a, vl b) { return _mm256_castsi256_pd(_mm256_cmpeq_epi64(a, b)); }

#endif
