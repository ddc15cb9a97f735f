/* Text helpers for messages (util/text.h). */
#include "util/text.h"

#include <stdio.h>
#include <string.h>

enum { WORD_MAX = 64 };

size_t sc_edit_distance(const char *a, const char *b)
{
    size_t n = strlen(a), m = strlen(b);
    if (n >= WORD_MAX || m >= WORD_MAX)
        return (size_t)-1;
    /* d[i][j]: distance between the first i bytes of a and the first j of b. */
    size_t d[WORD_MAX][WORD_MAX];
    for (size_t i = 0; i <= n; i++)
        d[i][0] = i;
    for (size_t j = 0; j <= m; j++)
        d[0][j] = j;
    for (size_t i = 1; i <= n; i++)
        for (size_t j = 1; j <= m; j++) {
            size_t cost = a[i - 1] != b[j - 1];
            size_t best = d[i - 1][j - 1] + cost;
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1; /* adjacent transposition */
            d[i][j] = best;
        }
    return d[n][m];
}

void sc_suggest_init(sc_suggestion *s, const char *word)
{
    s->word = word;
    s->best = NULL;
    s->distance = (size_t)-1;
}

void sc_suggest_consider(sc_suggestion *s, const char *candidate)
{
    size_t d = sc_edit_distance(s->word, candidate);
    if (d > 0 && d < s->distance) {
        s->distance = d;
        s->best = candidate;
    }
}

const char *sc_suggest_best(const sc_suggestion *s)
{
    size_t limit = strlen(s->word) / 3;
    limit = limit < 1 ? 1 : limit > 3 ? 3 : limit;
    return s->best && s->distance <= limit ? s->best : NULL;
}

const char *sc_suggest_among(const char *word, const char *const *names)
{
    sc_suggestion s;
    sc_suggest_init(&s, word);
    for (; *names; names++)
        sc_suggest_consider(&s, *names);
    return sc_suggest_best(&s);
}

/* The length of the valid UTF-8 sequence at s (at most len bytes), or 0 if it is not one. */
static size_t utf8_length(const unsigned char *s, size_t len)
{
    unsigned char c = s[0];
    size_t n = c >= 0xc2 && c <= 0xdf   ? 2
               : c >= 0xe0 && c <= 0xef ? 3
               : c >= 0xf0 && c <= 0xf4 ? 4
                                        : 0;
    if (n == 0 || n > len)
        return 0;
    /* The second byte's range excludes overlong forms, surrogates and code points > U+10FFFF. */
    unsigned char lo = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80;
    unsigned char hi = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
    if (s[1] < lo || s[1] > hi)
        return 0;
    for (size_t i = 2; i < n; i++)
        if (s[i] < 0x80 || s[i] > 0xbf)
            return 0;
    return n;
}

/* The printable form of the character at s[i] (of len bytes) into piece; sets *used to the
 * bytes it takes and returns the piece's length. */
static size_t piece_at(const unsigned char *s, size_t len, size_t i, char piece[8], size_t *used)
{
    size_t n = s[i] < 0x80 ? (s[i] >= 0x20 && s[i] != 0x7f) : utf8_length(s + i, len - i);
    if (n == 0) {
        *used = 1;
        return (size_t)snprintf(piece, 8, "\\x%02x", s[i]);
    }
    memcpy(piece, s + i, n);
    *used = n;
    return n;
}

const char *sc_escape_n(const char *s, size_t len, char *buf, size_t size)
{
    const unsigned char *u = (const unsigned char *)s;
    char piece[8];
    size_t total = 0, out = 0, used;
    if (size == 0)
        return buf;
    for (size_t i = 0; i < len; i += used)
        total += piece_at(u, len, i, piece, &used);
    /* When it does not all fit, keep room for "..." after the last whole piece. */
    size_t room = total < size ? size - 1 : size < 4 ? 0 : size - 4;
    for (size_t i = 0; i < len; i += used) {
        size_t n = piece_at(u, len, i, piece, &used);
        if (out + n > room)
            break;
        memcpy(buf + out, piece, n);
        out += n;
    }
    if (total >= size && size >= 4) {
        memcpy(buf + out, "...", 3);
        out += 3;
    }
    buf[out] = '\0';
    return buf;
}

const char *sc_escape(const char *s, char *buf, size_t size)
{
    return sc_escape_n(s, strlen(s), buf, size);
}
