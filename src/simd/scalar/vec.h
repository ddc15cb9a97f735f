/* The vector helpers of the batch kernels in portable C: four float lanes and two double lanes
 * as GNU C vector types (gcc and clang), which the compiler maps to the target's vector
 * registers (SSE2 on x86-64, NEON on AArch64) or splits into scalar code where there are none.
 * Each lane runs the operations of the readable one-lane specification of every tier
 * (src/simd/kernels_impl.h), rounding for rounding, so that the SSE4.1 kernels, which run them
 * too, give the same bits.
 * One lane at a time left the polynomial chains latency-bound: pow bits12 took 30.7 TSC
 * cycles per element against 13.7 for glibc's powf at -O2, with 91 against 76 instructions
 * per element (callgrind); four lanes per operation, 9.0 cycles. The u1 tiers were loops over
 * the scalar built-ins, the same latency-bound chains (log2 u1: 25 ns per element against 8.4
 * for glibc's log2f at -O2, 117 instructions per element); in the double lanes, 3.6 ns.
 * The rsqrt estimate is the bit-trick guess with two Newton steps (relative error below
 * 2^-17), where the SIMD ones use rsqrtps; the reciprocal estimate is a division, where they
 * use rcpps. */
#ifndef SHADECALC_SIMD_SCALAR_VEC_H
#define SHADECALC_SIMD_SCALAR_VEC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#define VW 4
#define ISA_SUFFIX scalar
#define SIMD_NO_ESTIMATES 1 /* vf_rsqrt_est and vf_rcp_est are not the hardware's */

typedef float vf __attribute__((vector_size(VW * sizeof(float))));
typedef int32_t vi __attribute__((vector_size(VW * sizeof(int32_t))));
typedef uint32_t vu __attribute__((vector_size(VW * sizeof(uint32_t))));
typedef vi vm; /* lane masks: all bits set or clear, as a comparison gives them */
typedef double vd __attribute__((vector_size(2 * sizeof(double))));
typedef int64_t vl __attribute__((vector_size(2 * sizeof(int64_t))));
typedef uint64_t vul __attribute__((vector_size(2 * sizeof(uint64_t))));
typedef vl vdm; /* double lane masks */

static inline vf vf_loadu(const float *p)
{
    vf r;
    memcpy(&r, p, sizeof r);
    return r;
}
static inline void vf_storeu(float *p, vf x) { memcpy(p, &x, sizeof x); }
/* no non-temporal store in portable C: an ordinary one */
static inline void vf_stream(float *p, vf x) { vf_storeu(p, x); }
static inline void vf_stream_fence(void) {}
static inline vf vf_set1(float x) { return (vf){x, x, x, x}; }
static inline vf vf_add(vf a, vf b) { return a + b; }
static inline vf vf_sub(vf a, vf b) { return a - b; }
static inline vf vf_mul(vf a, vf b) { return a * b; }
static inline vf vf_div(vf a, vf b) { return a / b; }
static inline vf vf_fma(vf a, vf b, vf c) { return a * b + c; } /* two roundings */
static inline vm vf_lt(vf a, vf b) { return a < b; }
static inline vm vf_le(vf a, vf b) { return a <= b; }
static inline vm vf_eq(vf a, vf b) { return a == b; }
static inline vm vf_isnan(vf a) { return a != a; }
static inline vm vf_nlt(vf a, vf b) { return ~(a < b); } /* !(a < b): true where either is NaN */
static inline vm vm_or(vm a, vm b) { return a | b; }
static inline vm vm_and(vm a, vm b) { return a & b; }
/* as two 64-bit halves: four instructions on SSE2, where the four lanes took ten */
static inline int vm_any(vm a)
{
    uint64_t h[2];
    memcpy(h, &a, sizeof h);
    return (h[0] | h[1]) != 0;
}
static inline int vm_lane(vm a, int i) { return a[i] != 0; }
static inline vi vf_as_vi(vf x) { return (vi)x; }
static inline vf vi_as_vf(vi x) { return (vf)x; }
static inline vf vf_select(vm m, vf a, vf b) { return (vf)((m & (vi)a) | (~m & (vi)b)); }
static inline vf vf_keep(vm m, vf a) { return (vf)(m & (vi)a); } /* a where m, else +0 */
/* as minps and maxps: a < b ? a : b, so a NaN in either operand gives b */
static inline vf vf_min(vf a, vf b) { return vf_select(a < b, a, b); }
static inline vf vf_max(vf a, vf b) { return vf_select(a > b, a, b); }
static inline vf vf_sqrt(vf a) { return (vf){sqrtf(a[0]), sqrtf(a[1]), sqrtf(a[2]), sqrtf(a[3])}; }
/* rint, ties to even as cvtps2dq, for |x| <= 2^22 (every caller clamps its argument well
 * inside): x + 1.5·2^23 has a unit ULP, so the sum rounds x to an integer, which the
 * subtraction recovers exactly (lrintf is a libm call at -O2) */
static inline vi vi_round(vf x)
{
    const vf shifter = vf_set1(0x1.8p23f);
    return __builtin_convertvector((x + shifter) - shifter, vi);
}
static inline vf vi_to_vf(vi x) { return __builtin_convertvector(x, vf); }
static inline vi vi_set1(int x) { return (vi){x, x, x, x}; }
static inline vi vi_add(vi a, vi b) { return (vi)((vu)a + (vu)b); }
static inline vi vi_sub(vi a, vi b) { return (vi)((vu)a - (vu)b); }
static inline vi vi_and(vi a, vi b) { return a & b; }
static inline vi vi_shl23(vi a) { return (vi)((vu)a << 23); }
static inline vi vi_shl31(vi a) { return (vi)((vu)a << 31); }
static inline vi vi_sra23(vi a) { return a >> 23; } /* arithmetic, as gcc and clang shift */
static inline vm vi_eq(vi a, vi b) { return a == b; }
static inline vf vf_abs(vf a) { return (vf)((vi)a & vi_set1(0x7fffffff)); }

/* ---- two double lanes, as SSE2's: the u1 tiers (double lanes of src/simd/kernels_impl.h) ---- */

static inline vd vd_from_lo(vf x) { return (vd){x[0], x[1]}; }
static inline vd vd_from_hi(vf x) { return (vd){x[2], x[3]}; }
/* VW/2 floats at p, as doubles */
static inline vd vd_load_floats(const float *p) { return (vd){p[0], p[1]}; }
/* each lane rounded once to float, as cvtpd2ps */
static inline vf vf_from_vd(vd lo, vd hi)
{
    return (vf){(float)lo[0], (float)lo[1], (float)hi[0], (float)hi[1]};
}
static inline vd vd_set1(double x) { return (vd){x, x}; }
static inline vd vd_add(vd a, vd b) { return a + b; }
static inline vd vd_sub(vd a, vd b) { return a - b; }
static inline vd vd_mul(vd a, vd b) { return a * b; }
static inline vd vd_div(vd a, vd b) { return a / b; }
static inline vd vd_fma(vd a, vd b, vd c) { return a * b + c; } /* two roundings */
static inline vd vd_sqrt(vd a) { return (vd){sqrt(a[0]), sqrt(a[1])}; }
static inline vdm vd_lt(vd a, vd b) { return a < b; }
static inline vl vd_as_vl(vd x) { return (vl)x; }
static inline vd vl_as_vd(vl x) { return (vd)x; }
static inline vd vd_select(vdm m, vd a, vd b) { return (vd)((m & (vl)a) | (~m & (vl)b)); }
/* as minpd and maxpd: a NaN in either operand gives b */
static inline vd vd_min(vd a, vd b) { return vd_select(a < b, a, b); }
static inline vd vd_max(vd a, vd b) { return vd_select(a > b, a, b); }
static inline vl vl_set1(long long x) { return (vl){x, x}; }
static inline vl vl_add(vl a, vl b) { return (vl)((vul)a + (vul)b); }
static inline vl vl_and(vl a, vl b) { return a & b; }
static inline vl vl_or(vl a, vl b) { return a | b; }
static inline vl vl_shl52(vl a) { return (vl)((vul)a << 52); }
static inline vdm vl_eq(vl a, vl b) { return a == b; }

/* Lomont's constant, then two Newton steps; negative x gives NaN */
static inline vf vf_rsqrt_est(vf x)
{
    vf y = (vf)((vu){0x5f375a86u, 0x5f375a86u, 0x5f375a86u, 0x5f375a86u} - ((vu)x >> 1));
    const vf half = vf_set1(0.5f), three_halves = vf_set1(1.5f);
    y = y * (three_halves - half * x * y * y);
    return y * (three_halves - half * x * y * y);
}

/* the reciprocal: rcpps's 2^-12 estimate is a hardware detail; the portable lanes divide */
static inline vf vf_rcp_est(vf x) { return vf_set1(1.0f) / x; }

#endif
