/* Every batch kernel but the shading one, for AVX2 + FMA (src/simd/kernel_group.h). */
#include "simd/avx2/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_KERNELS
#include "simd/kernel_group.h"
