/* The kernel_tier names of the attenuation, spot and BRDF batch kernels
 * (src/simd/light_impl.h). */
#ifndef SHADECALC_SIMD_KERNELS_LIGHT_H
#define SHADECALC_SIMD_KERNELS_LIGHT_H

#define SC_BATCH_KERNELS_LIGHT(X)

#endif
