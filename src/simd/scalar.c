/* The batch kernels in portable C: the fast tiers of src/simd/kernels_impl.h over the lanes of
 * src/simd/scalar_vec.h, and the u1 tier as loops over the scalar highp built-ins (src/math/),
 * the accurate reference the SIMD u1 kernels reproduce. */
#include "simd/scalar_vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"

BATCH1_LANES(exp2_u1, sc_exp2f)
BATCH1_LANES(exp_u1, sc_expf)
BATCH1_LANES(log2_u1, sc_log2f)
BATCH1_LANES(log_u1, sc_logf)
BATCH2_LANES(pow_u1, sc_powf)
BATCH1_LANES(inversesqrt_u1, sc_inversesqrtf)
