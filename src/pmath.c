/* Built-ins and arithmetic in a chosen precision: libm for the double reference, the accurate
 * binary32 built-ins for highp, rounded further for mediump and lowp (shadecalc/pmath.h). */
#include "shadecalc/pmath.h"

#include <math.h>

#include "shadecalc/glsl.h"

double sc_p_add(sc_prec p, double a, double b) { return sc_round(p, a + b); }
double sc_p_sub(sc_prec p, double a, double b) { return sc_round(p, a - b); }
double sc_p_mul(sc_prec p, double a, double b) { return sc_round(p, a * b); }
double sc_p_div(sc_prec p, double a, double b) { return sc_round(p, a / b); }
double sc_p_neg(sc_prec p, double a) { return sc_round(p, -a); }

/* The binary32 result, rounded further to p (a no-op for highp). */
#define SC_P_FN1(name, ref, f32)                                                                  \
    double sc_p_##name(sc_prec p, double x)                                                       \
    {                                                                                             \
        return p == SC_DOUBLE ? ref(x) : sc_round(p, (double)f32((float)x));                      \
    }
#define SC_P_FN2(name, ref, f32)                                                                  \
    double sc_p_##name(sc_prec p, double x, double y)                                             \
    {                                                                                             \
        return p == SC_DOUBLE ? ref(x, y) : sc_round(p, (double)f32((float)x, (float)y));         \
    }

static double inversesqrt(double x) { return 1.0 / sqrt(x); }

SC_P_FN1(sin, sin, sc_sinf)
SC_P_FN1(cos, cos, sc_cosf)
SC_P_FN1(tan, tan, sc_tanf)
SC_P_FN1(asin, asin, sc_asinf)
SC_P_FN1(acos, acos, sc_acosf)
SC_P_FN1(atan, atan, sc_atanf)
SC_P_FN1(exp, exp, sc_expf)
SC_P_FN1(log, log, sc_logf)
SC_P_FN1(exp2, exp2, sc_exp2f)
SC_P_FN1(log2, log2, sc_log2f)
SC_P_FN1(sqrt, sqrt, sc_sqrtf)
SC_P_FN1(inversesqrt, inversesqrt, sc_inversesqrtf)
SC_P_FN2(pow, pow, sc_powf)
SC_P_FN2(atan2, atan2, sc_atan2f)
