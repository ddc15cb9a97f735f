/* The stated accuracy of the highp built-ins and its measurement (shadecalc/accuracy.h). */
#include "shadecalc/accuracy.h"

#include <float.h>
#include <math.h>

#include "shadecalc/glsl.h"
#include "shadecalc/precision.h"

static double inversesqrt(double x) { return 1.0 / sqrt(x); }

/* clang-format off */
const sc_accuracy_row sc_accuracy_table[] = {
    {"exp",  1, sc_expf,  0, exp,  0, {-104, 0}, {89, 0},    0, "all x", 1.0},
    {"exp2", 1, sc_exp2f, 0, exp2, 0, {-150, 0}, {128, 0},   0, "all x", 1.0},
    {"log",  1, sc_logf,  0, log,  0, {0, 0},    {FLT_MAX, 0}, 0, "x > 0", 1.0},
    {"log2", 1, sc_log2f, 0, log2, 0, {0, 0},    {FLT_MAX, 0}, 0, "x > 0", 1.0},
    {"pow",  2, 0, sc_powf, 0, pow, {0, -160},   {FLT_MAX, 160}, 1,
     "x > 0, result a normal float", 1.0},
    {"sin",  1, sc_sinf,  0, sin,  0, {-1e4, 0}, {1e4, 0},   0, "-1e4 <= x <= 1e4", 1.0},
    {"cos",  1, sc_cosf,  0, cos,  0, {-1e4, 0}, {1e4, 0},   0, "-1e4 <= x <= 1e4", 1.0},
    {"tan",  1, sc_tanf,  0, tan,  0, {-1e4, 0}, {1e4, 0},   0, "-1e4 <= x <= 1e4", 1.0},
    {"asin", 1, sc_asinf, 0, asin, 0, {-1, 0},   {1, 0},     0, "-1 <= x <= 1", 1.0},
    {"acos", 1, sc_acosf, 0, acos, 0, {-1, 0},   {1, 0},     0, "-1 <= x <= 1", 1.0},
    {"atan", 1, sc_atanf, 0, atan, 0, {-FLT_MAX, 0}, {FLT_MAX, 0}, 0, "all x", 1.0},
    {"atan2", 2, 0, sc_atan2f, 0, atan2, {-FLT_MAX, -FLT_MAX}, {FLT_MAX, FLT_MAX}, 0,
     "all x, y", 1.0},
    {"sqrt", 1, sc_sqrtf, 0, sqrt, 0, {0, 0},    {FLT_MAX, 0}, 0, "x >= 0", 0.5},
    {"inversesqrt", 1, sc_inversesqrtf, 0, inversesqrt, 0, {0, 0}, {FLT_MAX, 0}, 0, "x > 0",
     1.0},
    {"sinh",  1, sc_sinhf,  0, sinh,  0, {-FLT_MAX, 0}, {FLT_MAX, 0}, 0, "all x", 1.0},
    {"cosh",  1, sc_coshf,  0, cosh,  0, {-FLT_MAX, 0}, {FLT_MAX, 0}, 0, "all x", 1.0},
    {"tanh",  1, sc_tanhf,  0, tanh,  0, {-FLT_MAX, 0}, {FLT_MAX, 0}, 0, "all x", 1.0},
    {"asinh", 1, sc_asinhf, 0, asinh, 0, {-FLT_MAX, 0}, {FLT_MAX, 0}, 0, "all x", 1.0},
    {"acosh", 1, sc_acoshf, 0, acosh, 0, {1, 0},   {FLT_MAX, 0}, 0, "x >= 1", 1.0},
    {"atanh", 1, sc_atanhf, 0, atanh, 0, {-1, 0},  {1, 0},     0, "-1 <= x <= 1", 1.0},
};
/* clang-format on */
const int sc_accuracy_count = (int)(sizeof sc_accuracy_table / sizeof sc_accuracy_table[0]);

/* The special-value table of the issue: ±0, ±subnormal min/max, ±FLT_MIN, 0.5, 1, 2, ±FLT_MAX,
 * ±Inf, NaN, and −1, −0.5, −2. */
static const float specials[] = {
    0.0f,
    -0.0f,
    0x1p-149f,
    -0x1p-149f,
    0x1.fffffcp-127f,
    -0x1.fffffcp-127f,
    FLT_MIN,
    -FLT_MIN,
    0.5f,
    -0.5f,
    1.0f,
    -1.0f,
    2.0f,
    -2.0f,
    FLT_MAX,
    -FLT_MAX,
    INFINITY,
    -INFINITY,
    NAN,
};
enum { N_SPECIALS = (int)(sizeof specials / sizeof specials[0]) };

/* xorshift64*: a small deterministic generator. */
uint64_t sc_accuracy_random(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545F4914F6CDD1DULL;
}

float sc_accuracy_sample(uint64_t *state, double lo, double hi)
{
    double top = fmax(fabs(lo), fabs(hi));
    if (!(lo < hi) || top < 0x1p-149) /* an empty or single-point range */
        return (float)lo;
    int max_exp = ilogb(top) + 1, min_exp = -149;
    for (;;) {
        uint64_t r = sc_accuracy_random(state);
        int e = min_exp + (int)((r >> 40) % (uint64_t)(max_exp - min_exp + 1));
        double mant = 1.0 + (double)(r & 0x7fffff) / 0x800000;
        double x = ldexp(mant, e - 1);
        if (lo < 0.0 && (r >> 39 & 1))
            x = -x;
        float f = (float)x;
        if (f >= lo && f <= hi)
            return f;
    }
}

static int in_range(const sc_accuracy_row *r, const float *a)
{
    for (int i = 0; i < r->arity; i++)
        if (!(a[i] >= r->lo[i] && a[i] <= r->hi[i]))
            return 0;
    return 1;
}

static void evaluate(const sc_accuracy_row *r, const float *a, float *got, double *ref)
{
    if (r->arity == 1) {
        *got = r->f1(a[0]);
        *ref = r->ref1((double)a[0]);
    } else {
        *got = r->f2(a[0], a[1]);
        *ref = r->ref2((double)a[0], (double)a[1]);
    }
}

/* ULP error, with an overflowed or underflowed reference exact when matched. */
static double error_of(float got, double ref)
{
    if (isinf((float)ref) && got == (float)ref)
        return 0.0;
    return sc_ulp_error(SC_HIGHP, (double)got, ref);
}

static void record(const sc_accuracy_row *r, const float *a, sc_accuracy_stats *out, double *sum)
{
    float got;
    double ref;
    evaluate(r, a, &got, &ref);
    if (r->normal_result && !(fabs(ref) >= FLT_MIN && fabs(ref) <= FLT_MAX))
        return;
    double e = error_of(got, ref);
    out->inputs++;
    *sum += e;
    if (e > out->max_ulp || out->inputs == 1) {
        out->max_ulp = e;
        out->worst[0] = a[0];
        out->worst[1] = r->arity == 2 ? a[1] : 0.0f;
    }
}

/* Special values must give the reference's result rounded to binary32, NaN for NaN. */
static void check_special(const sc_accuracy_row *r, const float *a, sc_accuracy_stats *out)
{
    float got;
    double ref;
    evaluate(r, a, &got, &ref);
    float want = (float)ref;
    int same = (isnan(got) && isnan(want)) || error_of(got, ref) <= r->bound_ulp ||
               (got == want && signbit(got) == signbit(want));
    if (!same)
        out->special_mismatches++;
}

void sc_accuracy_measure(const sc_accuracy_row *r, long n_random, uint64_t seed,
                         sc_accuracy_stats *out)
{
    *out = (sc_accuracy_stats){0, 0.0, 0.0, {0, 0}, 0};
    double sum = 0.0;
    uint64_t state = seed ? seed : 0x9E3779B97F4A7C15ULL;
    int n2 = r->arity == 2 ? N_SPECIALS : 1;
    for (int i = 0; i < N_SPECIALS; i++)
        for (int j = 0; j < n2; j++) {
            float a[2] = {specials[i], specials[j]};
            check_special(r, a, out);
            if (in_range(r, a))
                record(r, a, out, &sum);
        }
    /* rows that count only normal results draw until n_random inputs counted (at most 4×) */
    long target = out->inputs + n_random;
    for (long k = 0; out->inputs < target && k < 4 * n_random; k++) {
        float a[2];
        for (int i = 0; i < r->arity; i++) {
            int focus = (k & 3) == 0 && r->lo[i] <= 0.5 && r->hi[i] >= 2.0;
            if (focus)
                a[i] = sc_accuracy_sample(&state, 0.5, 2.0);
            else if ((k & 3) == 1) /* uniform in value: the large arguments of trig */
                a[i] = (float)(r->lo[i] +
                               (r->hi[i] - r->lo[i]) *
                                   ((double)(sc_accuracy_random(&state) >> 11) * 0x1p-53));
            else
                a[i] = sc_accuracy_sample(&state, r->lo[i], r->hi[i]);
        }
        record(r, a, out, &sum);
    }
    out->mean_ulp = out->inputs ? sum / (double)out->inputs : 0.0;
}
