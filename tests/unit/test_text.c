/* The message helpers (util/text.h): edit distances against hand-counted ones, the
 * did-you-mean threshold, and the escaping of control characters and invalid UTF-8 against
 * the byte ranges of RFC 3629 §4. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "util/text.h"

static void edit_distance_counts_each_edit_once(void **state)
{
    (void)state;
    assert_int_equal(sc_edit_distance("kitten", "sitting"), 3); /* 2 substitutions, 1 insertion */
    assert_int_equal(sc_edit_distance("", "abc"), 3);
    assert_int_equal(sc_edit_distance("abc", "abc"), 0);
    assert_int_equal(sc_edit_distance("precison", "precision"), 1);
    assert_int_equal(sc_edit_distance("ab", "ba"), 1); /* a transposition */
    assert_int_equal(sc_edit_distance("normalise", "normalize"), 1);
    assert_int_equal(sc_edit_distance("ca", "abc"), 3); /* OSA, not Damerau: 3, not 2 */
}

static void edit_distance_of_long_words_is_far(void **state)
{
    (void)state;
    char a[100];
    memset(a, 'a', sizeof a - 1);
    a[sizeof a - 1] = '\0';
    assert_true(sc_edit_distance(a, a + 1) > 3);
}

static const char *suggest(const char *word, const char *const *names)
{
    return sc_suggest_among(word, names);
}

static void suggestion_is_the_nearest_within_a_third(void **state)
{
    (void)state;
    static const char *const names[] = {"precision", "format", "define", "hex", "ulp", NULL};
    assert_string_equal(suggest("precison", names), "precision");
    assert_string_equal(suggest("fromat", names), "format");
    assert_string_equal(suggest("hx", names), "hex"); /* short words: distance 1 allowed */
    assert_string_equal(suggest("hxx", names), "hex");
    assert_null(suggest("fmt", names)); /* 3 edits from format: more than a third of 3 */
    assert_null(suggest("zzzzzz", names));
    assert_null(suggest("format", names)); /* the word itself is no suggestion */
}

static const char *escaped(const char *s, size_t size)
{
    static char buf[256];
    return sc_escape(s, buf, size);
}

static void escape_keeps_printable_text_and_valid_utf8(void **state)
{
    (void)state;
    assert_string_equal(escaped("light point pos=0,0,1", 256), "light point pos=0,0,1");
    assert_string_equal(escaped("\xce\xb8 \xe2\x82\xac \xf0\x9f\x98\x80", 256),
                        "\xce\xb8 \xe2\x82\xac \xf0\x9f\x98\x80"); /* θ € U+1F600 */
    assert_string_equal(escaped("a\\b", 256), "a\\b");
}

static void escape_writes_control_bytes_and_bad_utf8_as_hex(void **state)
{
    (void)state;
    assert_string_equal(escaped("a\tb\nc\x1b[0m\x7f", 256), "a\\x09b\\x0ac\\x1b[0m\\x7f");
    assert_string_equal(escaped("\xff\xc3", 256), "\\xff\\xc3");          /* bad lead, truncated */
    assert_string_equal(escaped("\xc0\xaf", 256), "\\xc0\\xaf");          /* overlong '/' */
    assert_string_equal(escaped("\xe0\x80\xaf", 256), "\\xe0\\x80\\xaf"); /* overlong, 3 bytes */
    assert_string_equal(escaped("\xed\xa0\x80", 256), "\\xed\\xa0\\x80"); /* a surrogate */
    assert_string_equal(escaped("\xf4\x90\x80\x80", 256), "\\xf4\\x90\\x80\\x80"); /* > U+10FFFF */
    assert_string_equal(escaped("\xe2\x82", 256), "\\xe2\\x82"); /* cut sequence */
}

static void escaping_twice_changes_nothing(void **state)
{
    (void)state;
    char once[64], twice[64];
    sc_escape("x\x01y\xff", once, sizeof once);
    assert_string_equal(sc_escape(once, twice, sizeof twice), once);
}

static void escape_cuts_with_an_ellipsis(void **state)
{
    (void)state;
    assert_string_equal(escaped("abcdefghij", 8), "abcd...");
    assert_string_equal(escaped("\x01\x02\x03", 10), "\\x01...");
    assert_string_equal(escaped("abc", 4), "abc");
    char n[8];
    assert_string_equal(sc_escape_n("a\0b", 3, n, sizeof n), "a\\x00b");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(edit_distance_counts_each_edit_once),
        cmocka_unit_test(edit_distance_of_long_words_is_far),
        cmocka_unit_test(suggestion_is_the_nearest_within_a_third),
        cmocka_unit_test(escape_keeps_printable_text_and_valid_utf8),
        cmocka_unit_test(escape_writes_control_bytes_and_bad_utf8_as_hex),
        cmocka_unit_test(escaping_twice_changes_nothing),
        cmocka_unit_test(escape_cuts_with_an_ellipsis),
    };
    return cmocka_run_group_tests_name("text", tests, NULL, NULL);
}
