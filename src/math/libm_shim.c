/* TEMPORARY: binary32 built-ins through double libm, so the tree links while the accurate
 * kernels are written. Each function moves to its own file under src/math/ and leaves here. */
#include <math.h>

#include "shadecalc/glsl.h"

#define SHIM1(name, fn)                                                                           \
    float name(float x) { return (float)fn((double)x); }
SHIM1(sc_sinf, sin)
SHIM1(sc_cosf, cos)
SHIM1(sc_tanf, tan)
SHIM1(sc_asinf, asin)
SHIM1(sc_acosf, acos)
SHIM1(sc_atanf, atan)
SHIM1(sc_expf, exp)
SHIM1(sc_logf, log)
SHIM1(sc_exp2f, exp2)
SHIM1(sc_log2f, log2)
SHIM1(sc_sqrtf, sqrt)
float sc_inversesqrtf(float x) { return (float)(1.0 / sqrt((double)x)); }
float sc_powf(float x, float y) { return (float)pow((double)x, (double)y); }
float sc_atan2f(float y, float x) { return (float)atan2((double)y, (double)x); }
