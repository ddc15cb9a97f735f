/* The batch kernels for SSE4.1 (src/simd/kernels_impl.h over sse41/vec.h). */
#include "simd/sse41/vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"
