/* The batch kernels in plain C: the fast tiers of src/simd/kernels_impl.h over one lane, and
 * the u1 tier as loops over the scalar highp built-ins (src/math/), the accurate reference the
 * SIMD u1 kernels reproduce. */
#include "simd/scalar_vec.h"
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#include "simd/scene_impl.h"
#include "simd/area_impl.h"

BATCH1(exp2_u1, sc_exp2f)
BATCH1(exp_u1, sc_expf)
BATCH1(log2_u1, sc_log2f)
BATCH1(log_u1, sc_logf)
BATCH2(pow_u1, sc_powf)
BATCH1(inversesqrt_u1, sc_inversesqrtf)
