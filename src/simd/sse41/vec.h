/* The vector helpers of the batch kernels for SSE4.1: 4 float lanes, 2 double lanes, no FMA
 * (a·b + c rounds twice, as in the scalar kernels). Compiled with -msse4.1. */
#ifndef SHADECALC_SIMD_SSE41_VEC_H
#define SHADECALC_SIMD_SSE41_VEC_H

#include <smmintrin.h>

#define VW 4
#define VD_PER_VF 2
#define ISA_SUFFIX sse41

typedef __m128 vf;
typedef __m128 vm;
typedef __m128i vi;
typedef __m128d vd;
typedef __m128d vdm;
typedef __m128i vl;

static inline vf vf_loadu(const float *p) { return _mm_loadu_ps(p); }
static inline void vf_storeu(float *p, vf x) { _mm_storeu_ps(p, x); }
/* a non-temporal store (p aligned to 16 bytes), and the fence after a run of them */
static inline void vf_stream(float *p, vf x) { _mm_stream_ps(p, x); }
static inline void vf_stream_fence(void) { _mm_sfence(); }
static inline vf vf_set1(float x) { return _mm_set1_ps(x); }
static inline vf vf_add(vf a, vf b) { return _mm_add_ps(a, b); }
static inline vf vf_sub(vf a, vf b) { return _mm_sub_ps(a, b); }
static inline vf vf_mul(vf a, vf b) { return _mm_mul_ps(a, b); }
static inline vf vf_div(vf a, vf b) { return _mm_div_ps(a, b); }
static inline vf vf_fma(vf a, vf b, vf c) { return _mm_add_ps(_mm_mul_ps(a, b), c); }
static inline vf vf_sqrt(vf a) { return _mm_sqrt_ps(a); }
static inline vf vf_rsqrt_est(vf a) { return _mm_rsqrt_ps(a); }
static inline vf vf_rcp_est(vf a) { return _mm_rcp_ps(a); }
static inline vf vf_min(vf a, vf b) { return _mm_min_ps(a, b); }
static inline vf vf_max(vf a, vf b) { return _mm_max_ps(a, b); }
static inline vm vf_lt(vf a, vf b) { return _mm_cmplt_ps(a, b); }
static inline vm vf_le(vf a, vf b) { return _mm_cmple_ps(a, b); }
static inline vm vf_eq(vf a, vf b) { return _mm_cmpeq_ps(a, b); }
static inline vm vf_isnan(vf a) { return _mm_cmpunord_ps(a, a); }
static inline vm vf_nlt(vf a, vf b) { return _mm_cmpnlt_ps(a, b); } /* !(a < b) */
static inline vm vm_or(vm a, vm b) { return _mm_or_ps(a, b); }
static inline vm vm_and(vm a, vm b) { return _mm_and_ps(a, b); }
static inline int vm_any(vm a) { return _mm_movemask_ps(a) != 0; }
static inline int vm_lane(vm a, int i) { return (_mm_movemask_ps(a) >> i) & 1; }
static inline vf vf_select(vm m, vf a, vf b) { return _mm_blendv_ps(b, a, m); }
static inline vf vf_keep(vm m, vf a) { return _mm_and_ps(m, a); } /* a where m, else +0 */
static inline vi vf_as_vi(vf x) { return _mm_castps_si128(x); }
static inline vf vi_as_vf(vi x) { return _mm_castsi128_ps(x); }
static inline vi vi_round(vf x) { return _mm_cvtps_epi32(x); }
static inline vf vi_to_vf(vi x) { return _mm_cvtepi32_ps(x); }
static inline vi vi_set1(int x) { return _mm_set1_epi32(x); }
static inline vi vi_add(vi a, vi b) { return _mm_add_epi32(a, b); }
static inline vi vi_sub(vi a, vi b) { return _mm_sub_epi32(a, b); }
static inline vi vi_and(vi a, vi b) { return _mm_and_si128(a, b); }
static inline vi vi_shl23(vi a) { return _mm_slli_epi32(a, 23); }
static inline vi vi_shl31(vi a) { return _mm_slli_epi32(a, 31); }
static inline vi vi_sra23(vi a) { return _mm_srai_epi32(a, 23); }
static inline vm vi_eq(vi a, vi b) { return _mm_castsi128_ps(_mm_cmpeq_epi32(a, b)); }
static inline vf vf_abs(vf a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }

static inline vd vd_from_lo(vf x) { return _mm_cvtps_pd(x); }
static inline vd vd_from_hi(vf x) { return _mm_cvtps_pd(_mm_movehl_ps(x, x)); }
/* VW/2 floats at p, as doubles */
static inline vd vd_load_floats(const float *p)
{
    return _mm_cvtps_pd(_mm_castpd_ps(_mm_load_sd((const double *)(const void *)p)));
}
static inline vf vf_from_vd(vd lo, vd hi)
{
    return _mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi));
}
static inline vd vd_set1(double x) { return _mm_set1_pd(x); }
static inline vd vd_add(vd a, vd b) { return _mm_add_pd(a, b); }
static inline vd vd_sub(vd a, vd b) { return _mm_sub_pd(a, b); }
static inline vd vd_mul(vd a, vd b) { return _mm_mul_pd(a, b); }
static inline vd vd_div(vd a, vd b) { return _mm_div_pd(a, b); }
static inline vd vd_fma(vd a, vd b, vd c) { return _mm_add_pd(_mm_mul_pd(a, b), c); }
static inline vd vd_sqrt(vd a) { return _mm_sqrt_pd(a); }
static inline vd vd_min(vd a, vd b) { return _mm_min_pd(a, b); }
static inline vd vd_max(vd a, vd b) { return _mm_max_pd(a, b); }
static inline vdm vd_lt(vd a, vd b) { return _mm_cmplt_pd(a, b); }
static inline vd vd_select(vdm m, vd a, vd b) { return _mm_blendv_pd(b, a, m); }
static inline vl vd_as_vl(vd x) { return _mm_castpd_si128(x); }
static inline vd vl_as_vd(vl x) { return _mm_castsi128_pd(x); }
static inline vl vl_set1(long long x) { return _mm_set1_epi64x(x); }
static inline vl vl_add(vl a, vl b) { return _mm_add_epi64(a, b); }
static inline vl vl_sub(vl a, vl b) { return _mm_sub_epi64(a, b); }
static inline vl vl_and(vl a, vl b) { return _mm_and_si128(a, b); }
static inline vl vl_or(vl a, vl b) { return _mm_or_si128(a, b); }
static inline vl vl_shl52(vl a) { return _mm_slli_epi64(a, 52); }
static inline vl vl_shr52(vl a) { return _mm_srli_epi64(a, 52); }
static inline vdm vl_eq(vl a, vl b) { return _mm_castsi128_pd(_mm_cmpeq_epi64(a, b)); }

#endif
