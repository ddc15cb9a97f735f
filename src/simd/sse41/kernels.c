/* Every batch kernel but the shading one, for SSE4.1 (src/simd/kernel_group.h). */
#include "simd/sse41/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_KERNELS
#include "simd/kernel_group.h"
