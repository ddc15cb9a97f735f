/* The shading kernel, tier bits8, for SSE4.1 (src/simd/kernel_group.h). */
#include "simd/sse41/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_BITS8
#include "simd/kernel_group.h"
