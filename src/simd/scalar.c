/* The batch kernels in portable C: every tier of src/simd/kernels_impl.h over the four float
 * and two double lanes of src/simd/scalar_vec.h, the SSE4.1 kernels' operations in GNU C. */
#include "simd/scalar_vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"

