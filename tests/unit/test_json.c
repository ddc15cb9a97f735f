/* The strict JSON reader (src/util/json.h): values and escapes decoded as RFC 8259 defines
 * them, every malformed input refused with its line and column, nesting bounded. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "util/json.h"

static sc_json *parse(const char *text, char *err)
{
    return sc_json_parse(text, strlen(text), err, 160);
}

static void values_are_decoded(void **state)
{
    (void)state;
    char err[160];
    sc_json *v = parse(
        " {\"a\": [1, -2.5e3, 0.125, true, false, null], \"s\": \"x\\\"\\\\\\/\\n\\u00e9\"} ", err);
    assert_non_null(v);
    const sc_json *a = sc_json_member(v, "a");
    assert_non_null(a);
    assert_int_equal(a->type, SC_JSON_ARRAY);
    const sc_json *e = a->child;
    assert_true(e->type == SC_JSON_NUMBER && e->number == 1.0);
    e = e->next;
    assert_true(e->type == SC_JSON_NUMBER && e->number == -2500.0);
    e = e->next;
    assert_true(e->number == 0.125);
    e = e->next;
    assert_true(e->type == SC_JSON_BOOL && e->number == 1.0);
    e = e->next;
    assert_true(e->type == SC_JSON_BOOL && e->number == 0.0);
    e = e->next;
    assert_int_equal(e->type, SC_JSON_NULL);
    assert_null(e->next);
    /* U+00E9 is C3 A9 in UTF-8 */
    assert_string_equal(sc_json_member(v, "s")->string, "x\"\\/\n\xc3\xa9");
    assert_null(sc_json_member(v, "missing"));
    sc_json_free(v);
}

static void surrogate_pairs_join(void **state)
{
    (void)state;
    char err[160];
    /* U+1F600 = D83D DE00 in UTF-16, F0 9F 98 80 in UTF-8 */
    sc_json *v = parse("\"\\ud83d\\ude00\"", err);
    assert_non_null(v);
    assert_string_equal(v->string, "\xf0\x9f\x98\x80");
    sc_json_free(v);
}

static void expect_error(const char *text, const char *want)
{
    char err[160] = "";
    sc_json *v = sc_json_parse(text, strlen(text), err, sizeof err);
    if (v || strcmp(err, want) != 0)
        fail_msg("%s: got %s [%s], want [%s]", text, v ? "a value" : "NULL", err, want);
}

static void malformed_input_is_refused_with_its_place(void **state)
{
    (void)state;
    expect_error("", "line 1, column 1: unexpected end of input");
    expect_error("[1,]", "line 1, column 4: unexpected character");
    expect_error("{\"a\" 1}", "line 1, column 6: expected ':'");
    expect_error("{1: 2}", "line 1, column 2: expected a member name in quotes");
    expect_error("[1 2]", "line 1, column 4: expected ',' or ']'");
    expect_error("01", "line 1, column 2: text after the value");
    expect_error("-", "line 1, column 2: expected a digit");
    expect_error("1.", "line 1, column 3: expected a digit after '.'");
    expect_error("1e+", "line 1, column 4: expected a digit in the exponent");
    expect_error("\n\n  tru", "line 3, column 3: expected true");
    expect_error("\"a\\x\"", "line 1, column 4: unknown escape");
    expect_error("\"\\u12\"", "line 1, column 6: expected four hex digits after \\u");
    expect_error("\"\\udc00\"", "line 1, column 8: lone low surrogate");
    expect_error("\"\\u0000\"", "line 1, column 8: \\u0000 is not accepted");
    expect_error("\"abc", "line 1, column 5: unterminated string");
    expect_error("[\"a\tb\"]", "line 1, column 4: control character in a string");
}

static void nesting_and_length_are_bounded(void **state)
{
    (void)state;
    char deep[2 * SC_JSON_MAX_DEPTH + 8];
    /* SC_JSON_MAX_DEPTH + 1 arrays: the innermost is at depth SC_JSON_MAX_DEPTH, accepted */
    size_t n = SC_JSON_MAX_DEPTH + 1;
    memset(deep, '[', n);
    memset(deep + n, ']', n);
    char err[160];
    sc_json *v = sc_json_parse(deep, 2 * n, err, sizeof err);
    assert_non_null(v);
    sc_json_free(v);
    memset(deep, '[', n + 1);
    memset(deep + n + 1, ']', n + 1);
    assert_null(sc_json_parse(deep, 2 * n + 2, err, sizeof err));
    assert_string_equal(err, "line 1, column 66: nested deeper than 64");
    char number[SC_JSON_MAX_NUMBER + 2];
    memset(number, '1', sizeof number - 1);
    number[sizeof number - 1] = '\0';
    expect_error(number, "line 1, column 1: number longer than 64 characters");
    number[sizeof number - 2] = '\0'; /* exactly the limit */
    assert_non_null(v = parse(number, err));
    sc_json_free(v);
}

static void text_need_not_end_in_nul(void **state)
{
    (void)state;
    char err[160];
    const char text[] = {'[', '1', ']', '9'}; /* only the first three bytes are the document */
    sc_json *v = sc_json_parse(text, 3, err, sizeof err);
    assert_non_null(v);
    assert_true(v->child->number == 1.0);
    sc_json_free(v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_are_decoded),
        cmocka_unit_test(surrogate_pairs_join),
        cmocka_unit_test(malformed_input_is_refused_with_its_place),
        cmocka_unit_test(nesting_and_length_are_bounded),
        cmocka_unit_test(text_need_not_end_in_nul),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
