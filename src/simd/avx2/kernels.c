/* The batch kernels for AVX2 + FMA (src/simd/kernels_impl.h over avx2/vec.h). */
#include "simd/avx2/vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"
