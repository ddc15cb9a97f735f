/* Text helpers shared by the library's and the command line's messages: "did you mean" from
 * the edit distance, and user input quoted safely. */
#ifndef SHADECALC_UTIL_TEXT_H
#define SHADECALC_UTIL_TEXT_H

#include <stddef.h>

/* The closest candidate to a mistyped word, among candidates offered one at a time:
 *     sc_suggestion s; sc_suggest_init(&s, word);
 *     for (...) sc_suggest_consider(&s, name);
 *     const char *best = sc_suggest_best(&s);   // NULL when nothing is close */
typedef struct {
    const char *word;
    const char *best;
    size_t distance;
} sc_suggestion;

void sc_suggest_init(sc_suggestion *s, const char *word);
void sc_suggest_consider(sc_suggestion *s, const char *candidate);
/* The candidate at the least edit distance, if that distance is at most a third of the word's
 * length (at least 1, at most 3) and the candidate is not the word itself; else NULL. */
const char *sc_suggest_best(const sc_suggestion *s);

/* The same over a NULL-terminated list of names. */
const char *sc_suggest_among(const char *word, const char *const *names);

/* Optimal-string-alignment distance: insertions, deletions, substitutions and transpositions
 * of adjacent characters each count 1 (bytes; words longer than 63 bytes count as far). */
size_t sc_edit_distance(const char *a, const char *b);

/* s as printable text into buf: control characters, DEL and bytes that are not valid UTF-8
 * become \xNN (so escaping twice changes nothing); cut with "..." to fit. Returns buf. */
const char *sc_escape(const char *s, char *buf, size_t size);
/* The same for the first len bytes of s (which may hold NUL bytes). */
const char *sc_escape_n(const char *s, size_t len, char *buf, size_t size);

#endif
