/* Precision emulation: binary16 and lowp rounding, ULP measure, bit patterns (docs/formulas.md §9);
 * the shortest decimals are in util/shortest.c. */
#include "shadecalc/precision.h"

#include <errno.h>
#include <fenv.h>
#include <float.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const prec_names[] = {"double", "highp", "mediump", "lowp"};

int sc_prec_parse(const char *name, sc_prec *out)
{
    for (int i = 0; i < 4; i++) {
        if (strcmp(name, prec_names[i]) == 0) {
            *out = (sc_prec)i;
            return 0;
        }
    }
    return -1;
}

const char *sc_prec_name(sc_prec p) { return prec_names[p]; }

/* binary16: 1 sign, 5 exponent (bias 15), 10 fraction bits; largest finite 65504. */
uint16_t sc_half_from_double(double x)
{
    uint16_t sign = signbit(x) ? 0x8000 : 0;
    double a = fabs(x);
    if (isnan(x))
        return sign | 0x7e00;
    /* 65520 is halfway between 65504 and 2^16: ties to even round it up, to infinity. */
    if (a >= 65520.0)
        return sign | 0x7c00;
    if (a < 0x1p-14) /* subnormal or zero: a multiple of 2^-24, exact scaling then RNE */
        return sign | (uint16_t)rint(a * 0x1p24);
    int e;
    frexp(a, &e);
    e -= 1;                            /* a = m * 2^e with m in [1, 2) */
    double q = rint(ldexp(a, 10 - e)); /* 11-bit significand in [1024, 2048] */
    if (q == 2048.0) {
        q = 1024.0;
        e += 1;
    }
    if (e > 15)
        return sign | 0x7c00;
    return sign | (uint16_t)((e + 15) << 10) | (uint16_t)(q - 1024.0);
}

double sc_half_to_double(uint16_t h)
{
    int e = (h >> 10) & 0x1f;
    int f = h & 0x3ff;
    double v;
    if (e == 0x1f)
        v = f ? NAN : INFINITY;
    else if (e == 0)
        v = ldexp(f, -24);
    else
        v = ldexp(f + 1024, e - 25);
    return (h & 0x8000) ? -v : v;
}

double sc_round_half(double x) { return sc_half_to_double(sc_half_from_double(x)); }

double sc_round_lowp(double x)
{
    if (isnan(x))
        return x;
    double k = rint(fmax(fmin(x, 2.0), -2.0) * 256.0);
    k = fmax(fmin(k, 511.0), -511.0);
    return k / 256.0;
}

double sc_round(sc_prec p, double x)
{
    switch (p) {
    case SC_HIGHP: return (double)(float)x;
    case SC_MEDIUMP: return sc_round_half(x);
    case SC_LOWP: return sc_round_lowp(x);
    case SC_DOUBLE: break;
    }
    return x;
}

/* Mantissa bits (with the implicit one) and the exponent of the smallest subnormal step. */
static void prec_format(sc_prec p, int *digits, int *min_exp)
{
    static const int d[] = {53, 24, 11, 0};
    static const int m[] = {-1074, -149, -24, -8};
    *digits = d[p];
    *min_exp = m[p];
}

/* frexp's exponent of a finite nonzero x (|x| in [2^(e-1), 2^e)), read from the bits when x is
 * normal: frexp and ldexp were half the cost of a ULP measure, which the tests make ~10^9 times */
static int binary_exponent(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int biased = (int)((bits >> 52) & 0x7ff);
    if (biased == 0) {
        int e;
        frexp(x, &e);
        return e;
    }
    return biased - 1022;
}

/* 2^k, built from the bits when it is a normal double */
static double power_of_two(int k)
{
    if (k < DBL_MIN_EXP - 1 || k > DBL_MAX_EXP - 1)
        return ldexp(1.0, k);
    uint64_t bits = (uint64_t)(k + 1023) << 52;
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

double sc_prec_ulp(sc_prec p, double x)
{
    if (!isfinite(x))
        return NAN;
    int digits, min_exp;
    prec_format(p, &digits, &min_exp);
    if (p == SC_LOWP || x == 0.0)
        return power_of_two(min_exp);
    int ue = binary_exponent(x) - digits;
    return power_of_two(ue > min_exp ? ue : min_exp);
}

double sc_ulp_error(sc_prec p, double got, double exact)
{
    if (isnan(got) || isnan(exact))
        return (isnan(got) && isnan(exact)) ? 0.0 : INFINITY;
    if (isinf(got) || isinf(exact))
        return got == exact ? 0.0 : INFINITY;
    return fabs(got - exact) / sc_prec_ulp(p, exact);
}

int sc_format_bits(char *buf, size_t size, double x, sc_prec p)
{
    switch (p) {
    case SC_DOUBLE: {
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        return snprintf(buf, size, "0x%016" PRIx64, bits);
    }
    case SC_HIGHP: {
        float f = (float)x;
        uint32_t bits;
        memcpy(&bits, &f, sizeof bits);
        return snprintf(buf, size, "0x%08" PRIx32, bits);
    }
    case SC_MEDIUMP: return snprintf(buf, size, "0x%04x", (unsigned)sc_half_from_double(x));
    default: {
        double k = isnan(x) ? 0.0 : x * 256.0; /* lowp has no NaN bit pattern: 0 */
        return snprintf(buf, size, "0x%04x", (unsigned)(uint16_t)(int16_t)k);
    }
    }
}

/* ---- decimal literals, rounded once ---- */

/* Whether v has at most 25 significant bits, as every midpoint between two neighbours of
 * binary32 (24 bits), binary16 (11) and lowp (multiples of 2^-8 below 2) has: the low 28 of
 * binary64's 52 fraction bits are zero. (Binary64 subnormals pass too: all round to zero.) */
static int may_be_a_midpoint(double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return isfinite(v) && (bits & ((UINT64_C(1) << 28) - 1)) == 0;
}

/* sign(decimal s - v), v the nearest binary64 to s: s is below v if and only if strtod rounding
 * downward gives less than v, above it if and only if rounding upward gives more. */
static signed char side_of(const char *s, double v)
{
    int mode = fegetround(), saved = errno;
    fesetround(FE_DOWNWARD);
    signed char side = -(strtod(s, NULL) < v);
    if (side == 0) {
        fesetround(FE_UPWARD);
        side = strtod(s, NULL) > v;
    }
    fesetround(mode);
    errno = saved;
    return side;
}

sc_literal sc_literal_read(const char *s, char **end)
{
    sc_literal lit = {strtod(s, end), 0};
    if (may_be_a_midpoint(lit.value))
        lit.tie = side_of(s, lit.value);
    return lit;
}

/* Whether v lies halfway between two neighbours of p: an odd multiple of half of p's ULP there
 * (fmod is exact). Past the largest finite value, the midpoint to the next power of two (65520
 * in binary16) is one too: it rounds to the finite value or to infinity. */
static int is_a_midpoint(sc_prec p, double v)
{
    double ulp = sc_prec_ulp(p, v);
    return fmod(fabs(v), ulp) == ulp / 2;
}

double sc_literal_round(sc_prec p, sc_literal lit)
{
    if (lit.tie == 0 || p == SC_DOUBLE || !is_a_midpoint(p, lit.value))
        return sc_round(p, lit.value);
    /* the next binary64 on the decimal's side lies, like the decimal, strictly between the
     * midpoint and that neighbour: it rounds to the neighbour */
    return sc_round(p, nextafter(lit.value, lit.tie > 0 ? INFINITY : -INFINITY));
}
