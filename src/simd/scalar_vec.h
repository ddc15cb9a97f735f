/* The vector helpers of the batch kernels for plain C: one lane, the readable specification of
 * every fast tier (src/simd/kernels_impl.h). The rsqrt estimate is the bit-trick guess with two
 * Newton steps (relative error below 2^-17), where the SIMD ones use rsqrtps; the reciprocal
 * estimate is a division, where they use rcpps. */
#ifndef SHADECALC_SIMD_SCALAR_VEC_H
#define SHADECALC_SIMD_SCALAR_VEC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#define VW 1
#define ISA_SUFFIX scalar

typedef float vf;
typedef int vm;
typedef int32_t vi;

static inline vf vf_loadu(const float *p) { return *p; }
static inline void vf_storeu(float *p, vf x) { *p = x; }
/* one lane has no non-temporal store: an ordinary one */
static inline void vf_stream(float *p, vf x) { *p = x; }
static inline void vf_stream_fence(void) {}
static inline vf vf_set1(float x) { return x; }
static inline vf vf_add(vf a, vf b) { return a + b; }
static inline vf vf_sub(vf a, vf b) { return a - b; }
static inline vf vf_mul(vf a, vf b) { return a * b; }
static inline vf vf_div(vf a, vf b) { return a / b; }
static inline vf vf_fma(vf a, vf b, vf c) { return a * b + c; }
static inline vf vf_sqrt(vf a) { return sqrtf(a); }
/* as minps and maxps: a < b ? a : b, so a NaN in either operand gives b */
static inline vf vf_min(vf a, vf b) { return a < b ? a : b; }
static inline vf vf_max(vf a, vf b) { return a > b ? a : b; }
static inline vm vf_lt(vf a, vf b) { return a < b; }
static inline vm vf_le(vf a, vf b) { return a <= b; }
static inline vm vf_eq(vf a, vf b) { return a == b; }
static inline vm vf_isnan(vf a) { return a != a; }
static inline vm vm_or(vm a, vm b) { return a | b; }
static inline vm vm_and(vm a, vm b) { return a & b; }
static inline int vm_any(vm a) { return a != 0; }
static inline int vm_lane(vm a, int i) { return i == 0 && a; }
static inline vf vf_select(vm m, vf a, vf b) { return m ? a : b; }
static inline vi vf_as_vi(vf x)
{
    vi i;
    memcpy(&i, &x, sizeof i);
    return i;
}
static inline vf vi_as_vf(vi x)
{
    vf f;
    memcpy(&f, &x, sizeof f);
    return f;
}
static inline vi vi_round(vf x) { return (vi)lrintf(x); }
static inline vf vi_to_vf(vi x) { return (vf)x; }
static inline vi vi_set1(int x) { return x; }
static inline vi vi_add(vi a, vi b) { return (vi)((uint32_t)a + (uint32_t)b); }
static inline vi vi_sub(vi a, vi b) { return (vi)((uint32_t)a - (uint32_t)b); }
static inline vi vi_and(vi a, vi b) { return a & b; }
static inline vi vi_shl23(vi a) { return (vi)((uint32_t)a << 23); }
static inline vi vi_sra23(vi a) { return a >= 0 ? a >> 23 : -1 - ((-1 - a) >> 23); }
static inline vm vi_eq(vi a, vi b) { return a == b; }
static inline vf vf_abs(vf a) { return fabsf(a); }

static inline vf vf_rsqrt_est(vf x)
{
    uint32_t bits = (uint32_t)vf_as_vi(x); /* Lomont's constant; negative x gives NaN below */
    vf y = vi_as_vf((vi)(0x5f375a86u - (bits >> 1)));
    y = y * (1.5f - 0.5f * x * y * y);
    return y * (1.5f - 0.5f * x * y * y);
}

/* the reciprocal: rcpps's 2^-12 estimate is a hardware detail; one lane divides */
static inline vf vf_rcp_est(vf x) { return 1.0f / x; }

#endif
