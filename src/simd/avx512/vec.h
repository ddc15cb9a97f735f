/* The vector helpers of the batch kernels for AVX-512 (F and DQ): 16 float lanes, 8 double
 * lanes, lane masks in mask registers (src/simd/kernels_impl.h uses only these). Compiled with
 * -mavx512f -mavx512dq. The estimates are rsqrt14 and rcp14 (relative error <= 2^-14, tighter
 * than AVX2's 1.5·2^-12, so every bound derived for those holds). */
#ifndef SHADECALC_SIMD_AVX512_VEC_H
#define SHADECALC_SIMD_AVX512_VEC_H

#include <immintrin.h>

#define VW 16
#define VD_PER_VF 2
#define ISA_SUFFIX avx512
#define SIMD_HAS_FMA 1        /* vf_fma and vd_fma round once */
#define SIMD_FINE_ESTIMATES 1 /* rsqrt14 and rcp14: relative error <= 2^-14 */

typedef __m512 vf;
typedef __mmask16 vm; /* one bit per lane */
typedef __m512i vi;
typedef __m512d vd;
typedef __mmask8 vdm;
typedef __m512i vl;

static inline vf vf_loadu(const float *p) { return _mm512_loadu_ps(p); }
static inline void vf_storeu(float *p, vf x) { _mm512_storeu_ps(p, x); }
/* a non-temporal store (p aligned to 64 bytes), and the fence after a run of them */
static inline void vf_stream(float *p, vf x) { _mm512_stream_ps(p, x); }
static inline void vf_stream_fence(void) { _mm_sfence(); }
static inline vf vf_set1(float x) { return _mm512_set1_ps(x); }
static inline vf vf_add(vf a, vf b) { return _mm512_add_ps(a, b); }
static inline vf vf_sub(vf a, vf b) { return _mm512_sub_ps(a, b); }
static inline vf vf_mul(vf a, vf b) { return _mm512_mul_ps(a, b); }
static inline vf vf_div(vf a, vf b) { return _mm512_div_ps(a, b); }
static inline vf vf_fma(vf a, vf b, vf c) { return _mm512_fmadd_ps(a, b, c); }
static inline vf vf_fms(vf a, vf b, vf c) { return _mm512_fmsub_ps(a, b, c); }   /* a b − c */
static inline vf vf_fnma(vf a, vf b, vf c) { return _mm512_fnmadd_ps(a, b, c); } /* c − a b */
static inline vf vf_sqrt(vf a) { return _mm512_sqrt_ps(a); }
static inline vf vf_rsqrt_est(vf a) { return _mm512_rsqrt14_ps(a); }
static inline vf vf_rcp_est(vf a) { return _mm512_rcp14_ps(a); }
static inline vf vf_min(vf a, vf b) { return _mm512_min_ps(a, b); }
static inline vf vf_max(vf a, vf b) { return _mm512_max_ps(a, b); }
static inline vm vf_lt(vf a, vf b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
static inline vm vf_le(vf a, vf b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
static inline vm vf_eq(vf a, vf b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
static inline vm vf_isnan(vf a) { return _mm512_cmp_ps_mask(a, a, _CMP_UNORD_Q); }
static inline vm vf_nlt(vf a, vf b) { return _mm512_cmp_ps_mask(a, b, _CMP_NLT_UQ); }
static inline vm vm_or(vm a, vm b) { return (vm)(a | b); }
static inline vm vm_and(vm a, vm b) { return (vm)(a & b); }
static inline int vm_any(vm a) { return a != 0; }
static inline int vm_lane(vm a, int i) { return (a >> i) & 1; }
static inline vf vf_select(vm m, vf a, vf b) { return _mm512_mask_blend_ps(m, b, a); }
static inline vf vf_keep(vm m, vf a) { return _mm512_maskz_mov_ps(m, a); } /* a where m, else +0 */
static inline vi vf_as_vi(vf x) { return _mm512_castps_si512(x); }
static inline vf vi_as_vf(vi x) { return _mm512_castsi512_ps(x); }
static inline vi vi_round(vf x) { return _mm512_cvtps_epi32(x); } /* to nearest, ties even */
static inline vf vi_to_vf(vi x) { return _mm512_cvtepi32_ps(x); }
static inline vi vi_set1(int x) { return _mm512_set1_epi32(x); }
static inline vi vi_add(vi a, vi b) { return _mm512_add_epi32(a, b); }
static inline vi vi_sub(vi a, vi b) { return _mm512_sub_epi32(a, b); }
static inline vi vi_and(vi a, vi b) { return _mm512_and_si512(a, b); }
static inline vi vi_shl23(vi a) { return _mm512_slli_epi32(a, 23); }
static inline vi vi_shl31(vi a) { return _mm512_slli_epi32(a, 31); }
static inline vi vi_sra23(vi a) { return _mm512_srai_epi32(a, 23); }
static inline vm vi_eq(vi a, vi b) { return _mm512_cmpeq_epi32_mask(a, b); }
static inline vf vf_abs(vf a) { return _mm512_abs_ps(a); }

/* doubles: the low and high halves of a vf */
static inline vd vd_from_lo(vf x) { return _mm512_cvtps_pd(_mm512_castps512_ps256(x)); }
static inline vd vd_from_hi(vf x)
{
    return _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(x), 1)));
}
/* VW/2 floats at p, as doubles: a load folded into the conversion */
static inline vd vd_load_floats(const float *p) { return _mm512_cvtps_pd(_mm256_loadu_ps(p)); }
static inline vf vf_from_vd(vd lo, vd hi)
{
    __m256 l = _mm512_cvtpd_ps(lo), h = _mm512_cvtpd_ps(hi);
    return _mm512_castpd_ps(
        _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(l)), _mm256_castps_pd(h), 1));
}
static inline vd vd_set1(double x) { return _mm512_set1_pd(x); }
static inline vd vd_add(vd a, vd b) { return _mm512_add_pd(a, b); }
static inline vd vd_sub(vd a, vd b) { return _mm512_sub_pd(a, b); }
static inline vd vd_mul(vd a, vd b) { return _mm512_mul_pd(a, b); }
static inline vd vd_div(vd a, vd b) { return _mm512_div_pd(a, b); }
static inline vd vd_fma(vd a, vd b, vd c) { return _mm512_fmadd_pd(a, b, c); }
static inline vd vd_sqrt(vd a) { return _mm512_sqrt_pd(a); }
static inline vd vd_min(vd a, vd b) { return _mm512_min_pd(a, b); }
static inline vd vd_max(vd a, vd b) { return _mm512_max_pd(a, b); }
static inline vdm vd_lt(vd a, vd b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
static inline vd vd_select(vdm m, vd a, vd b) { return _mm512_mask_blend_pd(m, b, a); }
static inline vl vd_as_vl(vd x) { return _mm512_castpd_si512(x); }
static inline vd vl_as_vd(vl x) { return _mm512_castsi512_pd(x); }
static inline vl vl_set1(long long x) { return _mm512_set1_epi64(x); }
static inline vl vl_add(vl a, vl b) { return _mm512_add_epi64(a, b); }
static inline vl vl_sub(vl a, vl b) { return _mm512_sub_epi64(a, b); }
static inline vl vl_and(vl a, vl b) { return _mm512_and_si512(a, b); }
static inline vl vl_or(vl a, vl b) { return _mm512_or_si512(a, b); }
static inline vl vl_shl52(vl a) { return _mm512_slli_epi64(a, 52); }
static inline vl vl_shr52(vl a) { return _mm512_srli_epi64(a, 52); }
static inline vdm vl_eq(vl a, vl b) { return _mm512_cmpeq_epi64_mask(a, b); }

#endif
