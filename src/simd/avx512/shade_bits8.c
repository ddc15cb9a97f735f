/* The shading kernel, tier bits8, for AVX-512 F and DQ (src/simd/kernel_group.h). */
#include "simd/avx512/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_BITS8
#include "simd/kernel_group.h"
