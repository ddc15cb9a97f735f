/* Every batch kernel but the shading one, in portable C (src/simd/kernel_group.h); the u1 tier of
 * exp2, exp, log2, log, pow and inversesqrt as loops over the scalar highp built-ins (src/math/),
 * the accurate reference the SIMD u1 kernels reproduce. */
#include "simd/scalar/vec.h"
#define SC_KERNEL_GROUP SC_GROUP_KERNELS
#include "simd/kernel_group.h"

BATCH1_LANES(exp2_u1, sc_exp2f)
BATCH1_LANES(exp_u1, sc_expf)
BATCH1_LANES(log2_u1, sc_log2f)
BATCH1_LANES(log_u1, sc_logf)
BATCH2_LANES(pow_u1, sc_powf)
BATCH1_LANES(inversesqrt_u1, sc_inversesqrtf)
