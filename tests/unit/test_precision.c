/* Precision emulation (docs/formulas.md §9): binary16 and lowp rounding at ties, subnormal edges, overflow;
 * the ULP measure; shortest decimals that read back. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/precision.h"

static void half_exact_values_round_trip(void **state)
{
    (void)state;
    assert_int_equal(sc_half_from_double(1.0), 0x3c00);
    assert_int_equal(sc_half_from_double(-2.0), 0xc000);
    assert_int_equal(sc_half_from_double(65504.0), 0x7bff);
    assert_int_equal(sc_half_from_double(0x1p-14), 0x0400);   /* smallest normal */
    assert_int_equal(sc_half_from_double(0x1p-24), 0x0001);   /* smallest subnormal */
    assert_int_equal(sc_half_from_double(0x3ffp-24), 0x03ff); /* largest subnormal */
    assert_int_equal(sc_half_from_double(-0.0), 0x8000);
    for (uint32_t h = 0; h < 0x10000; h++) {
        double v = sc_half_to_double((uint16_t)h);
        if (isnan(v))
            continue;
        assert_int_equal(sc_half_from_double(v), h);
    }
}

static void half_ties_round_to_even(void **state)
{
    (void)state;
    /* 1 + 2^-11 is halfway between 1 and 1 + 2^-10: even is 1. */
    assert_int_equal(sc_half_from_double(1.0 + 0x1p-11), 0x3c00);
    /* 1 + 3*2^-11 is halfway between 1 + 2^-10 (odd) and 1 + 2^-9 (even). */
    assert_int_equal(sc_half_from_double(1.0 + 3 * 0x1p-11), 0x3c02);
    /* just above the tie rounds up */
    assert_int_equal(sc_half_from_double(1.0 + 0x1p-11 + 0x1p-30), 0x3c01);
    /* subnormal tie: 2.5 * 2^-24 -> 2 * 2^-24 (even), 3.5 * 2^-24 -> 4 * 2^-24 */
    assert_int_equal(sc_half_from_double(2.5 * 0x1p-24), 0x0002);
    assert_int_equal(sc_half_from_double(3.5 * 0x1p-24), 0x0004);
    /* half the smallest subnormal ties to zero, a hair more rounds up */
    assert_int_equal(sc_half_from_double(0x1p-25), 0x0000);
    assert_int_equal(sc_half_from_double(0x1p-25 + 0x1p-40), 0x0001);
    /* the largest subnormal + half a step rounds up into the smallest normal */
    assert_int_equal(sc_half_from_double(0x3ffp-24 + 0x1p-25), 0x0400);
}

static void half_overflows_to_infinity_at_65520(void **state)
{
    (void)state;
    assert_int_equal(sc_half_from_double(65519.99), 0x7bff);
    assert_int_equal(sc_half_from_double(65520.0), 0x7c00);
    assert_int_equal(sc_half_from_double(-1e300), 0xfc00);
    assert_int_equal(sc_half_from_double(INFINITY), 0x7c00);
    assert_true(isnan(sc_round_half(NAN)));
}

static void lowp_is_fixed_point_with_saturation(void **state)
{
    (void)state;
    assert_true(sc_round_lowp(0.5) == 0.5);
    assert_true(sc_round_lowp(1.0 / 512.0) == 0.0);         /* tie to even: 0 */
    assert_true(sc_round_lowp(3.0 / 512.0) == 4.0 / 512.0); /* tie to even: 2/256 */
    assert_true(sc_round_lowp(0.3) == 77.0 / 256.0);
    assert_true(sc_round_lowp(5.0) == SC_LOWP_MAX);
    assert_true(sc_round_lowp(-INFINITY) == -SC_LOWP_MAX);
    assert_true(isnan(sc_round_lowp(NAN)));
}

static void round_dispatches_by_precision(void **state)
{
    (void)state;
    assert_true(sc_round(SC_DOUBLE, 0.1) == 0.1);
    assert_true(sc_round(SC_HIGHP, 0.1) == (double)0.1f);
    assert_true(sc_round(SC_MEDIUMP, 0.1) == sc_round_half(0.1));
    assert_true(sc_round(SC_HIGHP, 1e-46) == 0.0);
    assert_true(sc_round(SC_HIGHP, 1e39) == INFINITY);
}

static void ulp_error_is_measured_in_the_format(void **state)
{
    (void)state;
    assert_true(sc_prec_ulp(SC_HIGHP, 1.0) == 0x1p-23);
    assert_true(sc_prec_ulp(SC_HIGHP, 0.75) == 0x1p-24);
    assert_true(sc_prec_ulp(SC_HIGHP, 0.0) == 0x1p-149);
    assert_true(sc_prec_ulp(SC_HIGHP, 1e-40) == 0x1p-149);
    assert_true(sc_prec_ulp(SC_MEDIUMP, 1.0) == 0x1p-10);
    assert_true(sc_prec_ulp(SC_LOWP, 1.5) == 0x1p-8);
    /* negative, the ends of binary64 (the ULP subnormal, the argument subnormal), its largest */
    assert_true(sc_prec_ulp(SC_HIGHP, -3.0) == 0x1p-22);
    assert_true(sc_prec_ulp(SC_MEDIUMP, 65504.0) == 0x1p5);
    assert_true(sc_prec_ulp(SC_DOUBLE, 1.0) == 0x1p-52);
    assert_true(sc_prec_ulp(SC_DOUBLE, 0x1p-1000) == 0x1p-1052);
    assert_true(sc_prec_ulp(SC_DOUBLE, -0x1p-1060) == 0x1p-1074);
    assert_true(sc_prec_ulp(SC_DOUBLE, DBL_MAX) == 0x1p971);
    assert_true(sc_ulp_error(SC_HIGHP, 1.0 + 0x1p-23, 1.0) == 1.0);
    assert_true(sc_ulp_error(SC_HIGHP, NAN, NAN) == 0.0);
    assert_true(isinf(sc_ulp_error(SC_HIGHP, INFINITY, 3.0)));
}

static void shortest_decimal_reads_back(void **state)
{
    (void)state;
    char buf[64];
    sc_format_shortest(buf, sizeof buf, (double)0.6f, SC_HIGHP);
    assert_string_equal(buf, "0.6");
    sc_format_shortest(buf, sizeof buf, 0.6, SC_DOUBLE);
    assert_string_equal(buf, "0.6");
    sc_format_shortest(buf, sizeof buf, (double)0.1f, SC_DOUBLE);
    assert_string_equal(buf, "0.10000000149011612");
    sc_format_shortest(buf, sizeof buf, sc_round_half(0.1), SC_MEDIUMP);
    assert_string_equal(buf, "0.1");
    sc_format_shortest(buf, sizeof buf, -0.0, SC_HIGHP);
    assert_string_equal(buf, "-0");
    sc_format_shortest(buf, sizeof buf, -INFINITY, SC_HIGHP);
    assert_string_equal(buf, "-inf");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(half_exact_values_round_trip),
        cmocka_unit_test(half_ties_round_to_even),
        cmocka_unit_test(half_overflows_to_infinity_at_65520),
        cmocka_unit_test(lowp_is_fixed_point_with_saturation),
        cmocka_unit_test(round_dispatches_by_precision),
        cmocka_unit_test(ulp_error_is_measured_in_the_format),
        cmocka_unit_test(shortest_decimal_reads_back),
    };
    return cmocka_run_group_tests_name("precision", tests, NULL, NULL);
}
