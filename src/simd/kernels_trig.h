/* The kernel_tier names of the sin, cos, acos, atan2 batch kernels (src/simd/trig_impl.h). */
#ifndef SHADECALC_SIMD_KERNELS_TRIG_H
#define SHADECALC_SIMD_KERNELS_TRIG_H

/* clang-format off */
#define SC_BATCH_KERNELS_TRIG(X)                                                                  \
    X(sin_u1) X(sin_bits22) X(sin_bits12) X(cos_u1) X(cos_bits22) X(cos_bits12) X(acos_u1)         \
    X(acos_bits22) X(acos_bits12) X(atan2_u1) X(atan2_bits22)
/* clang-format on */

#endif
