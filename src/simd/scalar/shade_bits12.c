/* The shading kernel, tier bits12, in portable C (src/simd/kernel_group.h). */
#include "simd/scalar/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_SHADE_BITS12
#include "simd/kernel_group.h"
