/* The shading kernel, tier accurate, in portable C (src/simd/kernel_group.h). */
#include "simd/scalar/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_ACCURATE
#include "simd/kernel_group.h"
