/* Every batch kernel but the shading one, for AVX-512 F and DQ (src/simd/kernel_group.h). */
#include "simd/avx512/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_KERNELS
#include "simd/kernel_group.h"
