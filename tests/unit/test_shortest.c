/* Shortest round-trip decimals (src/util/shortest.c, the Schubfach algorithm): its table of
 * powers of ten and its floor logarithms against exact big-integer arithmetic, then the printed
 * decimals against the independent checker of tests/exhaustive/shortest_check.h: every binary16
 * and lowp value, 10^6 random binary32 and binary64 values, and binary64's hard cases. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "tests/exhaustive/shortest_check.h"
#include "tests/unit/scale.h"
#include "util/shortest.h"

/* ---- a small unsigned big integer: enough for 2^1100 · 10^330 · 2^126 ---- */

enum { LIMBS = 96 };
typedef struct {
    uint32_t limb[LIMBS]; /* little endian */
} big;

static big big_of(uint64_t hi, uint64_t lo) /* hi·2^64 + lo */
{
    big b = {{0}};
    b.limb[0] = (uint32_t)lo;
    b.limb[1] = (uint32_t)(lo >> 32);
    b.limb[2] = (uint32_t)hi;
    b.limb[3] = (uint32_t)(hi >> 32);
    return b;
}

static void big_mul_small(big *b, uint32_t m)
{
    uint64_t carry = 0;
    for (int i = 0; i < LIMBS; i++) {
        uint64_t t = (uint64_t)b->limb[i] * m + carry;
        b->limb[i] = (uint32_t)t;
        carry = t >> 32;
    }
    assert_true(carry == 0);
}

static void big_shift_left(big *b, int bits)
{
    for (; bits >= 16; bits -= 16)
        big_mul_small(b, 1u << 16);
    big_mul_small(b, 1u << bits);
}

static int big_cmp(const big *a, const big *b)
{
    for (int i = LIMBS - 1; i >= 0; i--)
        if (a->limb[i] != b->limb[i])
            return a->limb[i] < b->limb[i] ? -1 : 1;
    return 0;
}

/* The sign of x·2^twos·10^tens − 1, exactly. */
static int cmp_one(big x, int twos, int tens)
{
    big one = big_of(0, 1);
    big_shift_left(twos >= 0 ? &x : &one, abs(twos));
    big *scaled = tens >= 0 ? &x : &one;
    for (int left = abs(tens); left > 0; left -= left >= 9 ? 9 : 1) /* 10^9 at a time */
        big_mul_small(scaled, left >= 9 ? 1000000000u : 10u);
    return big_cmp(&x, &one);
}

/* g = g1·2^63 + g0 as a big integer, minus `minus` (0 or 1). */
static big table_g(int k, uint64_t minus)
{
    const uint64_t *g = sc_shortest_g[k - SC_SHORTEST_K_MIN];
    uint64_t lo = (g[0] << 63 | g[1]) - minus, hi = g[0] >> 1;
    assert_true(g[1] < UINT64_C(1) << 63);
    return big_of(hi - (minus && lo == UINT64_MAX), lo);
}

/* [S] §9.8: (g − 1)·2^r <= 10^-k < g·2^r with r = flog2pow10(-k) − 125 and 2^125 <= g − 1 <
 * 2^126, so g − 1 = floor(10^-k / 2^r). */
static void every_power_of_ten_in_the_table_is_exact(void **state)
{
    (void)state;
    big lowest = big_of(UINT64_C(1) << 61, 0), highest = big_of(UINT64_C(1) << 62, 0);
    for (int k = SC_SHORTEST_K_MIN; k <= SC_SHORTEST_K_MAX; k++) {
        int r = sc_flog2_pow10(-k) - 125;
        big below = table_g(k, 1), above = table_g(k, 0);
        if (big_cmp(&below, &lowest) < 0 || big_cmp(&below, &highest) >= 0 ||
            cmp_one(below, r, k) > 0 || cmp_one(above, r, k) <= 0)
            fail_msg("g(%d) is not floor(10^%d / 2^%d) + 1", k, -k, r);
    }
}

/* 10^k <= 2^e < 10^(k+1) for k = flog10pow2(e), the same with 3/4·2^e, and 2^k <= 10^e <
 * 2^(k+1) for k = flog2pow10(e), over the exponents the three formats use. */
static void the_floor_logarithms_are_exact(void **state)
{
    (void)state;
    big one = big_of(0, 1), three = big_of(0, 3);
    for (int e = -1100; e <= 1100; e++) {
        int k = sc_flog10_pow2(e), k34 = sc_flog10_three_quarters_pow2(e);
        if (cmp_one(one, e, -k) < 0 || cmp_one(one, e, -k - 1) >= 0)
            fail_msg("flog10pow2(%d) = %d", e, k);
        if (cmp_one(three, e - 2, -k34) < 0 || cmp_one(three, e - 2, -k34 - 1) >= 0)
            fail_msg("flog10threeQuartersPow2(%d) = %d", e, k34);
    }
    for (int e = -340; e <= 340; e++) {
        int k = sc_flog2_pow10(e);
        if (cmp_one(one, -k, e) < 0 || cmp_one(one, -k - 1, e) >= 0)
            fail_msg("flog2pow10(%d) = %d", e, k);
    }
}

/* ---- the printed decimals ---- */

static void check(double x, sc_prec p)
{
    char why[256];
    if (shortest_check(x, p, why, sizeof why) != 0)
        fail_msg("%s: %s", sc_prec_name(p), why);
}

static void every_binary16_value_prints_shortest(void **state)
{
    (void)state;
    for (unsigned h = 0; h < 0x10000; h++) {
        double x = sc_half_to_double((uint16_t)h);
        if (x != 0.0 && isfinite(x))
            check(x, SC_MEDIUMP);
    }
}

static void every_lowp_value_prints_shortest(void **state)
{
    (void)state;
    for (int k = -511; k <= 511; k++)
        if (k)
            check(k / 256.0, SC_LOWP);
}

static uint64_t xorshift(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* 10^6 random bit patterns of binary32 (highp) or binary64 (double), a sample of them under the
 * sanitizers (tests/unit/scale.h); zeros, infinities and NaNs skipped. */
static void check_random_values(sc_prec p, uint64_t seed)
{
    size_t samples = sc_test_inputs(1000000);
    for (size_t i = 0; i < samples; i++) {
        uint64_t bits = xorshift(&seed);
        uint32_t high = (uint32_t)(bits >> 32);
        float f;
        double x;
        memcpy(&f, &high, sizeof f);
        memcpy(&x, &bits, sizeof x);
        x = p == SC_HIGHP ? f : x;
        if (x != 0.0 && isfinite(x))
            check(x, p);
    }
}

static void random_binary32_values_print_shortest(void **state)
{
    (void)state;
    check_random_values(SC_HIGHP, 0x9e3779b97f4a7c15u);
}

static void random_binary64_values_print_shortest(void **state)
{
    (void)state;
    check_random_values(SC_DOUBLE, 0x2545f4914f6cdd1du);
}

/* Powers of two (the irregular intervals), subnormals, the extremes, and the neighbours of
 * short decimals and of their midpoints (where the closest decimal is a near tie). */
static void hard_binary64_values_print_shortest(void **state)
{
    (void)state;
    for (int e = -1074; e <= 1023; e++)
        check(ldexp(1.0, e), SC_DOUBLE);
    for (uint64_t c = 1; c < 5000; c++) {
        check(ldexp((double)c, -1074), SC_DOUBLE);
        check(DBL_MIN - ldexp((double)c, -1074), SC_DOUBLE);
    }
    const double extremes[] = {DBL_MAX, DBL_MIN, DBL_TRUE_MIN, -DBL_MAX, 1.0, 0.1, 1e23, 9e15};
    for (size_t i = 0; i < sizeof extremes / sizeof *extremes; i++)
        check(extremes[i], SC_DOUBLE);
    uint64_t seed = 0x0123456789abcdefu;
    for (int i = 0; i < 50000; i++) {
        char text[64];
        int digits = 1 + (int)(xorshift(&seed) % 17), exponent = (int)(xorshift(&seed) % 600) - 300;
        uint64_t m = xorshift(&seed) % 100000000000000000u;
        snprintf(text, sizeof text, "%.*llu%se%d", digits, (unsigned long long)m, i & 1 ? "5" : "",
                 exponent); /* odd i: a midpoint of the decimals one digit shorter */
        double x = strtod(text, NULL);
        if (x == 0.0 || !isfinite(x))
            continue;
        check(x, SC_DOUBLE);
        check(nextafter(x, 0.0), SC_DOUBLE);
        check(nextafter(x, INFINITY), SC_DOUBLE);
    }
}

/* ---- the text ---- */

static void special_values_and_the_g_layout(void **state)
{
    (void)state;
    const struct {
        double x;
        sc_prec p;
        const char *text;
    } cases[] = {
        {0.0, SC_HIGHP, "0"},
        {-0.0, SC_DOUBLE, "-0"},
        {INFINITY, SC_MEDIUMP, "inf"},
        {-INFINITY, SC_HIGHP, "-inf"},
        {NAN, SC_LOWP, "nan"},
        {30.0, SC_HIGHP, "30"},
        {123456.0, SC_DOUBLE, "123456"},
        {1e6, SC_DOUBLE, "1e+06"},
        {1234567.0, SC_DOUBLE, "1234567"},
        {1e-4, SC_DOUBLE, "0.0001"},
        {1e-5, SC_DOUBLE, "1e-05"},
        {5e-324, SC_DOUBLE, "5e-324"},
        {-1.5, SC_LOWP, "-1.5"},
        {(double)0.1f, SC_HIGHP, "0.1"},
        {0x1p-6, SC_MEDIUMP, "0.01563"}, /* 0.015625's interval reaches further up than down */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char buf[64];
        int len = sc_format_shortest(buf, sizeof buf, cases[i].x, cases[i].p);
        assert_string_equal(buf, cases[i].text);
        assert_int_equal(len, (int)strlen(cases[i].text));
    }
}

/* A value that is not one of the precision's prints as the double it is. */
static void a_value_outside_the_precision_prints_its_double(void **state)
{
    (void)state;
    char buf[64];
    sc_format_shortest(buf, sizeof buf, 0.1, SC_HIGHP);
    assert_string_equal(buf, "0.1");
    sc_format_shortest(buf, sizeof buf, 1.0 / 3.0, SC_MEDIUMP);
    assert_true(strtod(buf, NULL) == 1.0 / 3.0);
}

/* As snprintf: the whole length returned, the text cut to the buffer and terminated. */
static void a_short_buffer_gets_a_terminated_prefix(void **state)
{
    (void)state;
    char buf[4] = "xyz";
    assert_int_equal(sc_format_shortest(buf, sizeof buf, -0.125, SC_DOUBLE), 6);
    assert_string_equal(buf, "-0.");
    assert_int_equal(sc_format_shortest(buf, 0, -0.125, SC_DOUBLE), 6);
    assert_string_equal(buf, "-0.");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_power_of_ten_in_the_table_is_exact),
        cmocka_unit_test(the_floor_logarithms_are_exact),
        cmocka_unit_test(every_binary16_value_prints_shortest),
        cmocka_unit_test(every_lowp_value_prints_shortest),
        cmocka_unit_test(random_binary32_values_print_shortest),
        cmocka_unit_test(random_binary64_values_print_shortest),
        cmocka_unit_test(hard_binary64_values_print_shortest),
        cmocka_unit_test(special_values_and_the_g_layout),
        cmocka_unit_test(a_value_outside_the_precision_prints_its_double),
        cmocka_unit_test(a_short_buffer_gets_a_terminated_prefix),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
