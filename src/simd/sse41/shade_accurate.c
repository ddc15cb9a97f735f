/* The shading kernel, tier accurate, for SSE4.1 (src/simd/kernel_group.h). */
#include "simd/sse41/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_ACCURATE
#include "simd/kernel_group.h"
