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
#define SC_P_FN1(name, ref, f32)                                                                   \
    double sc_p_##name(sc_prec p, double x)                                                        \
    {                                                                                              \
        return p == SC_DOUBLE ? ref(x) : sc_round(p, (double)f32((float)x));                       \
    }
#define SC_P_FN2(name, ref, f32)                                                                   \
    double sc_p_##name(sc_prec p, double x, double y)                                              \
    {                                                                                              \
        return p == SC_DOUBLE ? ref(x, y) : sc_round(p, (double)f32((float)x, (float)y));          \
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
SC_P_FN1(sinh, sinh, sc_sinhf)
SC_P_FN1(cosh, cosh, sc_coshf)
SC_P_FN1(tanh, tanh, sc_tanhf)
SC_P_FN1(asinh, asinh, sc_asinhf)
SC_P_FN1(acosh, acosh, sc_acoshf)
SC_P_FN1(atanh, atanh, sc_atanhf)
SC_P_FN2(pow, pow, sc_powf)
SC_P_FN2(atan2, atan2, sc_atan2f)

/* The common functions: the double reference is the GLSL ES §8.3 defining formula evaluated in
 * binary64; the other precisions round the binary32 built-in (exact for abs sign floor ceil min
 * max step, whose results are one of their inputs or an integer). */
#define SC_P_FN3(name, ref, f32)                                                                   \
    double sc_p_##name(sc_prec p, double x, double y, double z)                                    \
    {                                                                                              \
        return p == SC_DOUBLE ? ref(x, y, z)                                                       \
                              : sc_round(p, (double)f32((float)x, (float)y, (float)z));            \
    }

static const double pi = 3.14159265358979323846;
static double radians(double x) { return x * (pi / 180.0); }
static double degrees(double x) { return x * (180.0 / pi); }
static double sign(double x) { return x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0 * x; }
static double fract(double x) { return x - floor(x); }
static double mod(double x, double y) { return x - y * floor(x / y); }
static double min(double x, double y) { return y < x ? y : x; }
static double max(double x, double y) { return x < y ? y : x; }
static double step(double edge, double x) { return x < edge ? 0.0 : 1.0; }
static double clamp(double x, double lo, double hi) { return min(max(x, lo), hi); }
static double mix(double x, double y, double a) { return x * (1.0 - a) + y * a; }
static double smoothstep(double e0, double e1, double x)
{
    double t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

SC_P_FN1(radians, radians, sc_radiansf)
SC_P_FN1(degrees, degrees, sc_degreesf)
SC_P_FN1(abs, fabs, sc_absf)
SC_P_FN1(sign, sign, sc_signf)
SC_P_FN1(floor, floor, sc_floorf)
SC_P_FN1(ceil, ceil, sc_ceilf)
SC_P_FN1(trunc, trunc, sc_truncf)
SC_P_FN1(round, nearbyint, sc_roundf) /* halves to even in the default rounding mode */
SC_P_FN1(roundeven, nearbyint, sc_roundevenf)
SC_P_FN1(fract, fract, sc_fractf)
SC_P_FN2(mod, mod, sc_modf)
SC_P_FN2(min, min, sc_minf)
SC_P_FN2(max, max, sc_maxf)
SC_P_FN2(step, step, sc_stepf)
SC_P_FN3(clamp, clamp, sc_clampf)
SC_P_FN3(mix, mix, sc_mixf)
SC_P_FN3(smoothstep, smoothstep, sc_smoothstepf)

double sc_p_modf(sc_prec p, double x, double *whole)
{
    if (p == SC_DOUBLE)
        return modf(x, whole);
    float w, fraction = sc_modff((float)x, &w);
    *whole = sc_round(p, (double)w);
    return sc_round(p, (double)fraction);
}
