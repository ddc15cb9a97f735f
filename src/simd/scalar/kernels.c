/* Every batch kernel but the shading one, in portable C (src/simd/kernel_group.h): every tier over
 * the four float and two double lanes of src/simd/scalar/vec.h, the SSE4.1 kernels' operations in
 * GNU C. */
#include "simd/scalar/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_KERNELS
#include "simd/kernel_group.h"
