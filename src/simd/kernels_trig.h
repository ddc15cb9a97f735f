/* The kernel_tier names of the sin, cos, acos, atan2 batch kernels (src/simd/trig_impl.h). */
#ifndef SHADECALC_SIMD_KERNELS_TRIG_H
#define SHADECALC_SIMD_KERNELS_TRIG_H

#define SC_BATCH_KERNELS_TRIG(X)

#endif
