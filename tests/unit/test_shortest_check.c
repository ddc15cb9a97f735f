/* The two checkers of the shortest binary32 decimals against each other: the exact one of
 * tests/exhaustive/shortest_exact.h (integers) and the one of shortest_check.h (glibc's
 * conversions). On printed texts both must pass, on texts one step off (a digit more or less,
 * the last digit ±1, another layout) both must fail, and on decimals of up to 19 digits next to
 * the bounds of the read-back intervals both must say the same. Reading back is one correct
 * rounding, as shadecalc reads a literal, never a rounding to binary64 first: checked for
 * binary32 and, in shortest_check.h's reader of binary16 and lowp, on decimals beside every
 * midpoint of those formats. */
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
#include "tests/exhaustive/shortest_exact.h"
#include "tests/unit/midpoint_text.h"

enum { TEXT = 64 };

static uint64_t xorshift(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

static float float_of(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* The digits (no trailing zero) and power of ten of a text: "-1.250e-07" is 125, -9. */
static uint64_t digits_of(const char *s, int *power)
{
    char plain[TEXT];
    size_t len = 0;
    int after_point = 0;
    *power = 0;
    for (s += *s == '-'; *s && *s != 'e' && len + 1 < sizeof plain; s++) {
        after_point |= *s == '.';
        if (*s != '.') {
            plain[len++] = *s;
            *power -= after_point;
        }
    }
    plain[len] = '\0';
    *power += *s == 'e' ? atoi(s + 1) : 0;
    uint64_t d = strtoull(plain, NULL, 10);
    for (; d && d % 10 == 0; d /= 10)
        ++*power;
    return d;
}

static int digit_count(uint64_t d)
{
    int n = 1;
    for (; d >= 10; d /= 10)
        n++;
    return n;
}

/* ±d·10^power in the layout sc_format_shortest documents (the text shortest_check.h checks). */
static void laid_out(char out[TEXT], int negative, uint64_t d, int power)
{
    char exact[TEXT];
    for (; d && d % 10 == 0; d /= 10)
        power++;
    snprintf(exact, sizeof exact, "%s%llue%d", negative ? "-" : "", (unsigned long long)d, power);
    shortest_g_text(out, TEXT, strtold(exact, NULL), digit_count(d));
}

/* Both checkers on x with the text s: pass when `pass`, fail otherwise. */
static void both_checkers(float x, const char *s, int pass)
{
    char exact_why[256] = "passed", libc_why[256] = "passed";
    int exact = shortest_exact_check(x, s, exact_why, sizeof exact_why);
    int libc = shortest_check_text(x, SC_HIGHP, s, libc_why, sizeof libc_why);
    if ((exact == 0) != pass || (libc == 0) != pass)
        fail_msg("%a, text %s, expected to %s: exact %s; libc %s", (double)x, s,
                 pass ? "pass" : "fail", exact_why, libc_why);
}

/* The text with a zero inserted before its exponent, or ".0" appended to an integer. */
static void with_a_trailing_zero(char out[TEXT], const char *s)
{
    const char *e = strchr(s, 'e');
    size_t head = e ? (size_t)(e - s) : strlen(s);
    snprintf(out, TEXT, "%.*s%s%s", (int)head, s, strchr(s, '.') ? "0" : ".0", s + head);
}

/* The printed text of x passes; its neighbours of one digit more or less, or with the last digit
 * changed by one, fail; so do other layouts of the same digits. */
static void printed_passes_and_mutations_fail(float x)
{
    char s[TEXT], t[TEXT];
    if (x == 0.0f || !isfinite(x))
        return;
    sc_format_shortest(s, sizeof s, x, SC_HIGHP);
    both_checkers(x, s, 1);
    int negative = signbit(x) != 0, power;
    uint64_t d = digits_of(s, &power);
    const struct {
        uint64_t d;
        int power;
    } others[] = {
        {d + 1, power},          {d - 1, power},          {10 * d + 1, power - 1},
        {10 * d - 1, power - 1}, {10 * d + 5, power - 1}, {10 * d - 5, power - 1},
        {d / 10, power + 1},     {d / 10 + 1, power + 1},
    };
    for (size_t i = 0; i < sizeof others / sizeof *others; i++) {
        if (others[i].d == 0)
            continue;
        laid_out(t, negative, others[i].d, others[i].power);
        both_checkers(x, t, 0);
    }
    snprintf(t, sizeof t, "%s%llue%d", negative ? "-" : "", (unsigned long long)d, power);
    both_checkers(x, t, strcmp(s, t) == 0);
    snprintf(t, sizeof t, "%.*e", digit_count(d) - 1, (double)strtold(s, NULL));
    both_checkers(x, t, strcmp(s, t) == 0);
    with_a_trailing_zero(t, s);
    both_checkers(x, t, 0);
    snprintf(t, sizeof t, "+%.60s", s);
    both_checkers(x, t, 0);
}

/* Random bit patterns, then the values where the rules are tight: powers of two (irregular
 * intervals), subnormals, the extremes, neighbours of powers of ten, and m·2^e with m a
 * multiple of a power of five (decimals with few digits, ties between two decimals). */
static void printed_texts_pass_and_mutated_ones_fail(void **state)
{
    (void)state;
    uint64_t seed = 0x243f6a8885a308d3u;
    for (int i = 0; i < 20000; i++)
        printed_passes_and_mutations_fail(float_of((uint32_t)xorshift(&seed)));
    for (int e = -149; e <= 127; e++) {
        printed_passes_and_mutations_fail(ldexpf(1.0f, e));
        printed_passes_and_mutations_fail(nextafterf(ldexpf(1.0f, e), 0.0f));
    }
    for (uint32_t bits = 1; bits < 3000; bits++) {
        printed_passes_and_mutations_fail(float_of(bits));
        printed_passes_and_mutations_fail(-float_of(0x00800000u - bits));
    }
    printed_passes_and_mutations_fail(FLT_MAX);
    printed_passes_and_mutations_fail(FLT_MIN);
    for (int k = -45; k <= 38; k++) {
        float ten = (float)pow(10.0, k);
        printed_passes_and_mutations_fail(ten);
        printed_passes_and_mutations_fail(nextafterf(ten, 0.0f));
        printed_passes_and_mutations_fail(nextafterf(ten, INFINITY));
    }
    for (uint32_t five = 5; five < 1u << 24; five *= 5)
        for (uint32_t m = five; m < 1u << 24 && m < 40 * five; m += 2 * five)
            for (int e = -149; e <= 104; e += 1 + (int)(xorshift(&seed) % 29))
                printed_passes_and_mutations_fail(ldexpf((float)m, e));
}

/* The bounds of x's read-back interval: its midpoints to the neighbours, exact in a long double. */
static void bounds_of(float x, long double bound[2])
{
    float below = nextafterf(x, 0.0f), above = nextafterf(x, INFINITY);
    bound[0] = ((long double)x + below) / 2;
    bound[1] = isfinite(above) ? ((long double)x + above) / 2
                               : (long double)x + ((long double)x - below) / 2;
}

/* Decimals of 17 to 19 digits next to each bound of x's interval, some within half a double's
 * unit of it (where strtod rounds to the bound itself), against both readers. Counts those that
 * a reading through binary64 would round twice to another value than strtof, for the test
 * below to see they were reached. */
static int readers_agree_near_the_bounds(float x)
{
    long double bound[2];
    bounds_of(x, bound);
    int twice = 0;
    for (int side = 0; side < 2; side++)
        for (int digits = 17; digits <= 19; digits++) {
            char text[TEXT];
            snprintf(text, sizeof text, "%.*Le", digits - 1, bound[side]);
            int power;
            uint64_t d = digits_of(text, &power);
            for (; digit_count(d) < digits; d *= 10)
                power--;
            for (int step = -3; step <= 3; step++) {
                snprintf(text, sizeof text, "%llue%d", (unsigned long long)(d + (uint64_t)step),
                         power);
                int libc = shortest_reads_back(text, x, SC_HIGHP);
                int exact = shortest_exact_reads_back(x, text);
                if (exact != libc)
                    fail_msg("%a: %s reads back: exact %d, libc %d", (double)x, text, exact, libc);
                twice += (float)strtod(text, NULL) != strtof(text, NULL);
            }
        }
    return twice;
}

static void both_readers_agree_at_the_interval_bounds(void **state)
{
    (void)state;
    uint64_t seed = 0x13198a2e03707344u;
    int twice = 0;
    for (int i = 0; i < 20000; i++) {
        float x = fabsf(float_of((uint32_t)xorshift(&seed)));
        if (x != 0.0f && isfinite(x))
            twice += readers_agree_near_the_bounds(x);
    }
    for (int e = -149; e <= 127; e++)
        twice += readers_agree_near_the_bounds(ldexpf(1.0f, e));
    twice += readers_agree_near_the_bounds(FLT_MAX) + readers_agree_near_the_bounds(FLT_MIN) +
             readers_agree_near_the_bounds(FLT_TRUE_MIN);
    assert_true(twice > 0);
}

/* Texts that are no decimal, or one the exact reader cannot hold. */
static void the_exact_checker_rejects_what_is_no_decimal(void **state)
{
    (void)state;
    const char *texts[] = {"",
                           "-",
                           ".",
                           "e5",
                           "1e",
                           "1e+",
                           "1.5x",
                           "1..5",
                           "nan",
                           "inf",
                           "12345678901234567890",
                           "1e99999",
                           "0",
                           "-0.0"};
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++) {
        char why[256];
        if (shortest_exact_check(1.0f, texts[i], why, sizeof why) == 0)
            fail_msg("%s passed for 1", texts[i]);
        assert_true(shortest_exact_reads_back(1.0f, texts[i]) != 1);
    }
    assert_int_equal(shortest_exact_reads_back(1.0f, "1.00000000000000000"), 1);
    assert_int_equal(shortest_exact_reads_back(-1.0f, "1"), 0);
    assert_int_equal(shortest_exact_reads_back(1.0f, "1e-300"), 0);
}

/* 0x1.5c87fap-84 is the binary32 nearest 7.038531e-26; binary64 puts that decimal on the
 * midpoint 0x1.5c87fbp-84, which ties to the even 0x1.5c87fcp-84. Both checkers read it once,
 * as strtof does: the 7 digits pass, and the 8 digits a reader through binary64 would need
 * are one too many. */
static void the_checkers_round_a_literal_once(void **state)
{
    (void)state;
    float x = strtof("7.038531e-26", NULL);
    assert_true(strtod("7.038531e-26", NULL) == ((double)x + nextafterf(x, INFINITY)) / 2);
    both_checkers(x, "7.038531e-26", 1);
    both_checkers(-x, "-7.038531e-26", 1);
    both_checkers(x, "7.0385313e-26", 0);
    assert_int_equal(shortest_exact_reads_back(x, "7.038531e-26"), 1);
}

/* Decimals beside a midpoint v of p, which strtod reads as v: the one toward zero reads back to
 * v's neighbour toward zero, the other to the neighbour away from zero (never to both). */
static void reads_beside(sc_prec p, double toward, double away)
{
    double v = toward / 2 + away / 2;
    char text[SC_BESIDE_TEXT];
    for (int side = 0; side < 2; side++) {
        sc_text_beside(text, v, side);
        double want = side ? away : toward, other = side ? toward : away;
        assert_true(strtod(text, NULL) == v);
        if (!shortest_reads_back(text, want, p) || shortest_reads_back(text, other, p))
            fail_msg("%s: %.40s... does not read back as %a alone", sc_prec_name(p), text, want);
    }
}

/* Every midpoint of binary16 (subnormals, normals, the one below the overflow threshold 65520,
 * which rounds down to 65504 from below and up to infinity from above), and of lowp (up to its
 * saturation, where the reader must not count on it: the decimal above 511.5/256 fails). */
static void the_half_and_lowp_reader_rounds_once(void **state)
{
    (void)state;
    for (unsigned h = 0; h < 0x7bff; h++)
        for (int sign = -1; sign <= 1; sign += 2)
            reads_beside(SC_MEDIUMP, sign * sc_half_to_double((uint16_t)h),
                         sign * sc_half_to_double((uint16_t)(h + 1)));
    char text[SC_BESIDE_TEXT];
    sc_text_beside(text, 65520.0, 0);
    assert_true(shortest_reads_back(text, 65504.0, SC_MEDIUMP));
    sc_text_beside(text, 65520.0, 1);
    assert_false(shortest_reads_back(text, 65504.0, SC_MEDIUMP));
    for (int k = 0; k < 511; k++)
        for (int sign = -1; sign <= 1; sign += 2)
            reads_beside(SC_LOWP, sign * (k / 256.0), sign * ((k + 1) / 256.0));
    sc_text_beside(text, 511.5 / 256, 0);
    assert_true(shortest_reads_back(text, SC_LOWP_MAX, SC_LOWP));
    sc_text_beside(text, 511.5 / 256, 1);
    assert_false(shortest_reads_back(text, SC_LOWP_MAX, SC_LOWP));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(printed_texts_pass_and_mutated_ones_fail),
        cmocka_unit_test(both_readers_agree_at_the_interval_bounds),
        cmocka_unit_test(the_exact_checker_rejects_what_is_no_decimal),
        cmocka_unit_test(the_checkers_round_a_literal_once),
        cmocka_unit_test(the_half_and_lowp_reader_rounds_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
