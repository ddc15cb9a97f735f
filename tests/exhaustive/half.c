/* mediump and lowp as one more rounding of highp, for every binary16 input (checker.h). */
#include <math.h>

#include "checker.h"

/* The correctly rounded binary32 of s at x: the fast decision, else MPFR. */
static float correctly_rounded(const exh_subject *s, float x)
{
    double a = s->approx1(x), exact;
    float want;
    if (isnan(a))
        return NAN;
    if (exh_rounds_to_one(a, s->bound(x, 0.0f, a), &want))
        return want;
    return exh_mpfr_round32(s, x, 0.0f, &exact);
}

static int same_value(double a, double b) { return (isnan(a) && isnan(b)) || a == b; }

void exh_half_check(const exh_subject *s, exh_half_stats *out)
{
    *out = (exh_half_stats){0, 0, 0, 0, 0};
    for (uint32_t h = 0; h < 0x10000; h++) {
        float x = (float)sc_half_to_double((uint16_t)h), hp = s->f1(x);
        out->inputs++;
        out->highp_wrong += !exh_same(hp, correctly_rounded(s, x));
        out->mediump_mismatch += !same_value(s->in_precision(SC_MEDIUMP, (double)x),
                                             sc_round_half((double)hp));
        out->lowp_mismatch += !same_value(s->in_precision(SC_LOWP, (double)x),
                                          sc_round_lowp((double)hp));
        /* binary16 in MPFR's terms: 11 bits, 2^-24 = 2^-23/2, 65504 < 2^16 */
        double direct = (double)exh_mpfr_round(s, x, 0.0f, 11, -23, 16);
        out->double_rounded += !same_value(direct, sc_round_half((double)hp));
    }
}
