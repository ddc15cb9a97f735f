/* The subjects of make exhaustive (subjects.h). */
#include "subjects.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"
#include "shadecalc/pmath.h"

/* ---- the stated binary64 bounds of the highp cores (each derived in its src/math/ file) ---- */

static double rel(double eps, double a) { return eps * fabs(a); }

static double bound_exp2(float x, float y, double a)
{
    (void)x, (void)y;
    return rel(0x1p-47, a);
}
/* exp.c: the exponent's error grows with |x| up to the clamp of |x log2 e| at 1000 (|x| < 694);
 * beyond, the core is 2^±1000 within the exp2 bound, and the exact value rounds the same. */
static double bound_exp(float x, float y, double a)
{
    (void)y;
    double ax = fabs((double)x);
    return rel(ax < 694.0 ? 0x1p-47 + 0x1p-51 * ax : 0x1p-47, a);
}
/* sinh.c: sinh and cosh within (2^-46 + 2^-50 |x|) for |x| < 694; beyond, the core is 2^999 and
 * the exact value is beyond binary32's range too. */
static double bound_hyperbolic(float x, float y, double a)
{
    (void)y;
    double ax = fabs((double)x);
    return rel(ax < 694.0 ? 0x1p-46 + 0x1p-50 * ax : 0x1p-46, a);
}
/* A bound that is one relative error for every input. */
#define CONSTANT_BOUND(name, e)                                                                    \
    static double name(float x, float y, double a)                                                 \
    {                                                                                              \
        (void)x, (void)y;                                                                          \
        return rel(e, a);                                                                          \
    }
CONSTANT_BOUND(bound_log, 0x1p-48)
CONSTANT_BOUND(bound_47, 0x1p-47)
CONSTANT_BOUND(bound_46, 0x1p-46)
CONSTANT_BOUND(bound_sqrt, 0x1p-53)
CONSTANT_BOUND(bound_51, 0x1p-51)

/* sincos.c: the reduction is exact for |x| < 0.78 (k = 0), else r carries 2^-99.7 absolute. */
static double reduction_error(float x) { return fabsf(x) < 0.78f ? 0.0 : 0x1p-99; }
static double bound_sincos(float x, float y, double a)
{
    (void)y;
    return rel(0x1p-47, a) + reduction_error(x);
}
static double bound_tan(float x, float y, double a)
{
    (void)y;
    return rel(0x1p-46, a) + reduction_error(x) * (1.0 + a * a);
}

/* pow.c: (2^-47 + 2^-48 |t|)|core| with t = y log2|x| (here by libm: the factor of 1.45
 * between 21u and 2^-48 covers its error); infinite for the special inputs, which MPFR
 * settles. */
static double bound_pow(float x, float y, double a)
{
    double t = (double)y * log2(fabs((double)x));
    return rel(0x1p-47 + 0x1p-48 * fabs(t), a);
}

/* inversesqrt of ±0 is ±Inf (sqrt.c; MPFR's rec_sqrt gives +Inf for both). */
static int rec_sqrt_glsl(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd)
{
    if (mpfr_zero_p(x)) {
        mpfr_set_inf(r, mpfr_signbit(x) ? -1 : 1);
        return 0;
    }
    return mpfr_rec_sqrt(r, x, rnd);
}

#define HIGHP1(name, bound, mpfr)                                                                  \
    {#name, 1, sc_##name##f, NULL, NULL,       sc_k_##name##_core, NULL,                           \
     bound, 1, mpfr,         NULL, sc_p_##name},
#define HIGHP2(name, bound, mpfr)                                                                  \
    {#name, 2, NULL, sc_##name##f, NULL, NULL, sc_k_##name##_core, bound, 1, NULL, mpfr, NULL},

const exh_subject exh_highp[] = {
    /* clang-format off */
    HIGHP1(exp, bound_exp, mpfr_exp) HIGHP1(exp2, bound_exp2, mpfr_exp2)
    HIGHP1(log, bound_log, mpfr_log) HIGHP1(log2, bound_log, mpfr_log2)
    HIGHP1(sin, bound_sincos, mpfr_sin) HIGHP1(cos, bound_sincos, mpfr_cos)
    HIGHP1(tan, bound_tan, mpfr_tan) HIGHP1(asin, bound_46, mpfr_asin)
    HIGHP1(acos, bound_46, mpfr_acos) HIGHP1(atan, bound_47, mpfr_atan)
    HIGHP1(sqrt, bound_sqrt, mpfr_sqrt) HIGHP1(inversesqrt, bound_51, rec_sqrt_glsl)
    HIGHP1(sinh, bound_hyperbolic, mpfr_sinh) HIGHP1(cosh, bound_hyperbolic, mpfr_cosh)
    HIGHP1(tanh, bound_47, mpfr_tanh) HIGHP1(asinh, bound_47, mpfr_asinh)
    HIGHP1(acosh, bound_47, mpfr_acosh) HIGHP1(atanh, bound_47, mpfr_atanh)
    HIGHP2(pow, bound_pow, mpfr_pow) HIGHP2(atan2, bound_46, mpfr_atan2)
    /* clang-format on */
};
const int exh_highp_count = (int)(sizeof exh_highp / sizeof exh_highp[0]);

/* ---- the u1 batch kernels against glibc's binary64 functions ---- */

/* glibc documents at most 1 ULP of binary64 (<= 2^-52 relative) for exp exp2 log log2 sin cos
 * acos on x86-64 (the GNU C Library manual, "Known Maximum Errors in Math Functions"); the
 * checker allows twice that. sqrt is IEEE (u); 1/sqrt two roundings (2.01u). */
static double libm_exp(float x) { return exp((double)x); }
static double libm_exp2(float x) { return exp2((double)x); }
static double libm_log(float x) { return log((double)x); }
static double libm_log2(float x) { return log2((double)x); }
static double libm_sin(float x) { return sin((double)x); }
static double libm_cos(float x) { return cos((double)x); }
static double libm_acos(float x) { return acos((double)x); }
static double libm_sqrt(float x) { return sqrt((double)x); }
static double libm_inversesqrt(float x) { return 1.0 / sqrt((double)x); }

typedef struct {
    const char *kernel;
    double (*approx)(float);
    double (*bound)(float, float, double);
    exh_mpfr1_fn mpfr;
} libm_reference;

static const libm_reference references[] = {
    {"exp", libm_exp, bound_51, mpfr_exp},
    {"exp2", libm_exp2, bound_51, mpfr_exp2},
    {"log", libm_log, bound_51, mpfr_log},
    {"log2", libm_log2, bound_51, mpfr_log2},
    {"sin", libm_sin, bound_51, mpfr_sin},
    {"cos", libm_cos, bound_51, mpfr_cos},
    {"acos", libm_acos, bound_51, mpfr_acos},
    {"sqrt", libm_sqrt, bound_sqrt, mpfr_sqrt},
    {"inversesqrt", libm_inversesqrt, bound_51, rec_sqrt_glsl},
};

static const libm_reference *reference_of(const char *kernel)
{
    for (size_t i = 0; i < sizeof references / sizeof references[0]; i++)
        if (strcmp(references[i].kernel, kernel) == 0)
            return &references[i];
    return NULL;
}

int exh_batch_subjects(exh_subject *out, char (*names)[EXH_NAME_MAX], int max)
{
    int n = 0;
    for (int i = 0; i < sc_batch_count && n < max; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        const libm_reference *ref = reference_of(e->kernel);
        if (strcmp(e->tier, "u1") != 0 || e->n_in != 1 || !ref || !sc_isa_supported(e->isa))
            continue;
        snprintf(names[n], EXH_NAME_MAX, "%s u1 %s", e->kernel, sc_isa_name(e->isa));
        out[n] = (exh_subject){names[n], 1,          NULL, NULL,      e,    ref->approx,
                               NULL,     ref->bound, 0,    ref->mpfr, NULL, NULL};
        n++;
    }
    return n;
}

/* ---- biased pairs for pow and atan2 ---- */

static uint64_t next(uint64_t *s) /* xorshift64* */
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545F4914F6CDD1DULL;
}

static double unit(uint64_t *s) { return (double)(next(s) >> 11) * 0x1p-53; }

static float any_float(uint64_t *s)
{
    uint32_t u = (uint32_t)(next(s) >> 32);
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* A positive float with its exponent uniform in [lo, hi] and a random significand. */
static float magnitude(uint64_t *s, int lo, int hi)
{
    int e = lo + (int)(next(s) % (uint64_t)(hi - lo + 1));
    return (float)ldexp(1.0 + unit(s), e);
}

static float random_sign(uint64_t *s, float x) { return next(s) & 1 ? -x : x; }

/* x within 2^20 ULPs of 1 (above or below), y such that |y log2 x| is up to 150 */
static void pow_near_one(uint64_t *s, float *x, float *y)
{
    double k = (double)(1 + next(s) % (1u << (next(s) % 21)));
    *x = (float)(next(s) & 1 ? 1.0 + k * 0x1p-23 : 1.0 - k * 0x1p-24);
    double t = ldexp(1.0 + unit(s), -(int)(next(s) % 24)) * 75.0;
    *y = random_sign(s, (float)(t / log2((double)*x)));
}

/* results near overflow (2^124 .. 2^128.5) and underflow (2^-151 .. 2^-120) */
static void pow_near_limits(uint64_t *s, float *x, float *y)
{
    *x = magnitude(s, -149, 127);
    if (*x == 1.0f)
        *x = 2.0f;
    double t = next(s) & 1 ? 124.0 + 4.5 * unit(s) : -151.0 + 31.0 * unit(s);
    *y = (float)(t / log2((double)*x));
}

/* |y| from 2^8 to 2^40, x = 2^(t/y) rounded (near 1) */
static void pow_large_y(uint64_t *s, float *x, float *y)
{
    *y = random_sign(s, magnitude(s, 8, 40));
    *x = (float)exp2((-150.0 + 278.0 * unit(s)) / (double)*y);
}

/* exact and midpoint results: integer x^2, x^3, x^(3/2), (m²)^(1/2) ... and negative bases */
static void pow_exact(uint64_t *s, float *x, float *y)
{
    static const float ys[] = {2.0f, 3.0f, 4.0f, 0.5f, 1.5f, -1.0f, -2.0f, 2.5f, 0.25f, 5.0f};
    float m = (float)(1 + next(s) % 8192);
    *y = ys[next(s) % (sizeof ys / sizeof ys[0])];
    *x = (next(s) & 3) == 0 ? m * m : m;
    *x = ldexpf(*x, (int)(next(s) % 41) - 20);
    if ((next(s) & 3) == 0 && *y == floorf(*y))
        *x = -*x;
}

static void pow_pair(uint64_t *s, float *x, float *y)
{
    switch (next(s) % 8) {
    case 0:
    case 1: pow_near_one(s, x, y); break;
    case 2: pow_near_limits(s, x, y); break;
    case 3: pow_large_y(s, x, y); break;
    case 4: pow_exact(s, x, y); break;
    case 5: /* negative x, integer y */
        *x = -magnitude(s, -12, 12);
        *y = (float)((int)(next(s) % 301) - 150);
        break;
    case 6: /* any bits: the special values, NaN, infinities, subnormals */
        *x = any_float(s);
        *y = any_float(s);
        break;
    default: *x = magnitude(s, -149, 127); *y = random_sign(s, magnitude(s, -24, 8));
    }
}

/* (y, x) with |y/x| = 2^-k·m, k up to 280 (then swapped for the steep side) */
static void atan2_ratio(uint64_t *s, float *y, float *x, int steep)
{
    float a = magnitude(s, -149, 127);
    float b = (float)ldexp((double)a * (1.0 + unit(s)), -(int)(next(s) % 281));
    *y = random_sign(s, steep ? a : b);
    *x = random_sign(s, steep ? b : a);
}

/* |y/x| near a constant c of the reductions (1, tan(π/12), 1/tan(π/12)) */
static void atan2_near(uint64_t *s, float *y, float *x)
{
    static const double cs[] = {1.0, 0.26794919243112270647, 3.7320508075688772935};
    double c = cs[next(s) % 3] * (1.0 + ldexp(unit(s) - 0.5, -(int)(next(s) % 30)));
    *x = random_sign(s, magnitude(s, -100, 100));
    *y = random_sign(s, (float)((double)fabsf(*x) * c));
}

static void atan2_pair(uint64_t *s, float *y, float *x)
{
    switch (next(s) % 6) {
    case 0:
        *y = any_float(s);
        *x = any_float(s);
        break;
    case 1: atan2_ratio(s, y, x, 0); break;
    case 2: atan2_ratio(s, y, x, 1); break;
    case 3: atan2_near(s, y, x); break;
    case 4: /* subnormal against anything */
        *y = random_sign(s, magnitude(s, -149, -127));
        *x = random_sign(s, magnitude(s, -149, 127));
        break;
    default:
        *y = random_sign(s, magnitude(s, -149, 127));
        *x = random_sign(s, magnitude(s, -149, 127));
    }
}

exh_pair_gen exh_pair_generator(const char *name)
{
    if (strcmp(name, "pow") == 0)
        return pow_pair;
    if (strcmp(name, "atan2") == 0)
        return atan2_pair;
    return NULL;
}
