/* The shading kernel, tier bits8, in portable C (src/simd/kernel_group.h). */
#include "simd/scalar/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_BITS8
#include "simd/kernel_group.h"
