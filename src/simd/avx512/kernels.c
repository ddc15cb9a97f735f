/* The batch kernels for AVX-512 F and DQ (src/simd/kernels_impl.h over avx512/vec.h). */
#include "simd/avx512/vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"
