/* Decimal literals rounded once to a precision (sc_literal_read, sc_literal_round): on decimals
 * that binary64 puts exactly on a midpoint of binary32, binary16 or lowp while they lie beside it
 * (tests/unit/midpoint_text.h), the result is the neighbour on the decimal's side. References:
 * glibc's strtof (correctly rounded) for binary32; for binary16 and lowp the construction
 * itself, which says on which side of the midpoint the decimal lies. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <errno.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/precision.h"
#include "tests/unit/midpoint_text.h"

static double read_rounded(sc_prec p, const char *text)
{
    return sc_literal_round(p, sc_literal_read(text, NULL));
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The decimals beside v (which strtod must read as v) round in p to `toward` (the one toward
 * zero) and `away` (the other). */
static void beside_rounds_to(sc_prec p, double v, double toward, double away)
{
    char text[SC_BESIDE_TEXT];
    for (int side = 0; side < 2; side++) {
        sc_text_beside(text, v, side);
        double want = side ? away : toward, got = read_rounded(p, text);
        if (strtod(text, NULL) != v || !same_bits(got, want))
            fail_msg("%s: %.50s...: %a, not %a", sc_prec_name(p), text, got, want);
    }
}

/* Both decimals beside the midpoint of binary32 neighbours a < b (|a| < |b|) and beside the
 * binary64 values next to the midpoint, against strtof; the decimals beside the midpoint must
 * reach both neighbours (the construction's own check). */
static void binary32_beside(float a, float b)
{
    double m = (double)a / 2 + (double)b / 2;
    beside_rounds_to(SC_HIGHP, m, a, b);
    const double near[] = {m, nextafter(m, 0.0), nextafter(m, 2 * m)};
    for (size_t i = 0; i < sizeof near / sizeof *near; i++)
        for (int side = 0; side < 2; side++) {
            char text[SC_BESIDE_TEXT];
            sc_text_beside(text, near[i], side);
            double want = strtof(text, NULL), got = read_rounded(SC_HIGHP, text);
            if (!same_bits(got, want))
                fail_msg("highp: %.50s...: %a, strtof %a", text, got, want);
        }
}

static float float_of(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

static uint64_t xorshift(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* Random normal binary32 values, the subnormals around the smallest normal, powers of two (where
 * the step changes), both signs; the largest finite value and the midpoint past it, at which
 * strtof goes to infinity from above and stays finite from below. */
static void highp_rounds_a_decimal_once(void **state)
{
    (void)state;
    uint64_t seed = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < 20000; i++) {
        float a = float_of((uint32_t)xorshift(&seed) & 0xfeffffffu); /* |a| < 2^127 */
        if (a != 0.0f && isfinite(a) && fabsf(a) >= 0x1p-120f)
            binary32_beside(a, nextafterf(a, 2 * a));
    }
    for (uint32_t bits = 0; bits < 3000; bits++) {
        binary32_beside(float_of(bits), float_of(bits + 1));
        binary32_beside(-float_of(0x00800000u - bits - 1), -float_of(0x00800000u - bits));
    }
    for (int e = -125; e <= 127; e++) {
        float power = ldexpf(1.0f, e);
        binary32_beside(power, nextafterf(power, INFINITY));
        binary32_beside(-nextafterf(power, 0.0f), -power);
    }
    beside_rounds_to(SC_HIGHP, (double)FLT_MAX + 0x1p103, FLT_MAX, INFINITY);
    beside_rounds_to(SC_HIGHP, -(double)FLT_MAX - 0x1p103, -FLT_MAX, -INFINITY);
    assert_true(read_rounded(SC_HIGHP, "7.038531e-26") == strtof("7.038531e-26", NULL));
    assert_true(read_rounded(SC_HIGHP, "7.038531e-26") != (float)strtod("7.038531e-26", NULL));
}

/* Every pair of binary16 neighbours (subnormals from zero on, normals, both signs), the midpoint
 * 65520 past the largest finite value (65504 from below, infinity from above), and the binary64
 * values next to each midpoint, whose decimals round as those values do. */
static void mediump_rounds_a_decimal_once(void **state)
{
    (void)state;
    for (unsigned h = 0; h < 0x7bff; h++)
        for (int sign = -1; sign <= 1; sign += 2) {
            double a = sign * sc_half_to_double((uint16_t)h);
            double b = sign * sc_half_to_double((uint16_t)(h + 1)), m = a / 2 + b / 2;
            beside_rounds_to(SC_MEDIUMP, m, a, b);
            beside_rounds_to(SC_MEDIUMP, nextafter(m, 0.0), a, a);
            beside_rounds_to(SC_MEDIUMP, nextafter(m, 2 * m), b, b);
        }
    beside_rounds_to(SC_MEDIUMP, 65520.0, 65504.0, INFINITY);
    beside_rounds_to(SC_MEDIUMP, -65520.0, -65504.0, -INFINITY);
}

/* Every pair of lowp neighbours k/256 and (k + 1)/256, and its saturation: the midpoint past
 * the largest value 511/256 and anything beyond it read as 511/256. */
static void lowp_rounds_a_decimal_once(void **state)
{
    (void)state;
    for (int k = 0; k < 511; k++)
        for (int sign = -1; sign <= 1; sign += 2) {
            double a = sign * (k / 256.0), b = sign * ((k + 1) / 256.0), m = a / 2 + b / 2;
            beside_rounds_to(SC_LOWP, m, a, b);
            beside_rounds_to(SC_LOWP, nextafter(m, 0.0), a, a);
            beside_rounds_to(SC_LOWP, nextafter(m, 2 * m), b, b);
        }
    beside_rounds_to(SC_LOWP, 511.5 / 256, SC_LOWP_MAX, SC_LOWP_MAX);
    beside_rounds_to(SC_LOWP, -511.5 / 256, -SC_LOWP_MAX, -SC_LOWP_MAX);
    beside_rounds_to(SC_LOWP, 2.5, SC_LOWP_MAX, SC_LOWP_MAX);
}

/* Double precision is strtod's value, whatever the side. */
static void double_precision_is_strtod(void **state)
{
    (void)state;
    const double values[] = {0.5 + 0x1p-25, 65520.0, 7.038531e-26, 1.0 / 3.0};
    for (size_t i = 0; i < sizeof values / sizeof *values; i++)
        for (int side = 0; side < 2; side++) {
            char text[SC_BESIDE_TEXT];
            sc_text_beside(text, values[i], side);
            assert_true(same_bits(read_rounded(SC_DOUBLE, text), strtod(text, NULL)));
        }
}

/* The syntax, *end and errno of strtod; tie 0 on an exact decimal, and on a value of more than
 * 25 significant bits (no midpoint of any precision), whose side is not computed. */
static void it_reads_what_strtod_reads(void **state)
{
    (void)state;
    const char *texts[] = {"1.5x",
                           "abc",
                           "",
                           " 2",
                           "-0",
                           "1e400",
                           "-1e400",
                           "1e-400",
                           "0x1p-3",
                           "inf",
                           "nan",
                           "0.1",
                           "3.0517578125e-05f",
                           "65520",
                           "2.5e+0,"};
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++) {
        char *want_end, *end;
        errno = 0;
        double want = strtod(texts[i], &want_end);
        int want_errno = errno;
        errno = 0;
        sc_literal lit = sc_literal_read(texts[i], &end);
        if (!(same_bits(lit.value, want) || (isnan(want) && isnan(lit.value))) || end != want_end ||
            errno != want_errno)
            fail_msg("'%s': %a end +%d errno %d, strtod %a +%d %d", texts[i], lit.value,
                     (int)(end - texts[i]), errno, want, (int)(want_end - texts[i]), want_errno);
    }
    assert_int_equal(sc_literal_read("0.5", NULL).tie, 0);
    assert_int_equal(sc_literal_read("0.1", NULL).tie, 0);
    assert_int_equal(sc_literal_read("0.50000000000000000000000000001", NULL).tie, 1);
    assert_int_equal(sc_literal_read("-0.50000000000000000000000000001", NULL).tie, -1);
    assert_int_equal(sc_literal_read("0.49999999999999999999999999999", NULL).tie, -1);
}

/* The caller's rounding mode is kept ("0.5" is read in every mode as 0.5, whose side is then
 * looked up under the other modes). */
static void the_rounding_mode_is_restored(void **state)
{
    (void)state;
    const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    for (size_t i = 0; i < sizeof modes / sizeof *modes; i++) {
        fesetround(modes[i]);
        sc_literal lit = sc_literal_read("0.5", NULL);
        int mode = fegetround();
        fesetround(FE_TONEAREST);
        assert_int_equal(mode, modes[i]);
        assert_true(lit.value == 0.5 && lit.tie == 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(highp_rounds_a_decimal_once),
        cmocka_unit_test(mediump_rounds_a_decimal_once),
        cmocka_unit_test(lowp_rounds_a_decimal_once),
        cmocka_unit_test(double_precision_is_strtod),
        cmocka_unit_test(it_reads_what_strtod_reads),
        cmocka_unit_test(the_rounding_mode_is_restored),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
