/* The checker of the shortest decimals (sc_format_shortest, src/util/shortest.c), independent of
 * the algorithm: glibc's correctly rounded printf("%.*e") and strtod/strtof decide.
 *
 * A decimal of L significant digits passes for x in precision p when
 *   - it reads back: s rounded once, correctly, to p is x, bit for bit (the way shadecalc reads
 *     a literal: strtod for double, strtof for highp, for mediump and lowp the decimal's two
 *     binary64 neighbours from strtod rounding down and up, see shortest_reads_back);
 *   - no decimal of L - 1 digits reads back. Any shorter decimal can be written with L - 1
 *     digits, and the only candidates are the two (L - 1)-digit decimals around x: %.{L-2}e
 *     gives one, its neighbours the other (below a power of ten the grid is ten times finer);
 *   - it is the closest of its length: %.{L-1}e of x (ties to even, as the printed one) if
 *     that reads back, otherwise the L-digit neighbour on the other side of x.
 * make check runs it over every binary16 and samples of binary32 and binary64
 * (tests/unit/test_shortest.c). make exhaustive (--groups print) checks every binary32 with the
 * faster exact checker of shortest_exact.h, and with this one too on a sample of them
 * (tests/unit/test_shortest_check.c checks that both agree). */
#ifndef SHADECALC_EXHAUSTIVE_SHORTEST_CHECK_H
#define SHADECALC_EXHAUSTIVE_SHORTEST_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "shadecalc/precision.h"

/* 0 if sc_format_shortest(x, p) passes; else -1 with the reason in why. x: a finite, nonzero
 * value of p. */
int shortest_check(double x, sc_prec p, char *why, size_t why_size);

/* The same for the text s instead of sc_format_shortest's. */
int shortest_check_text(double x, sc_prec p, const char *s, char *why, size_t why_size);

/* Whether s reads back to x in p: s correctly rounded to p (once, not through a binary64) is x;
 * for lowp without relying on its saturation (s at most SC_LOWP_MAX + 2^-9 in magnitude). */
int shortest_reads_back(const char *s, double x, sc_prec p);

/* The text of v as %.{n}Lg writes it, except that an integer below 10^6 is written out (%.0Lf)
 * where %g would switch to an exponent: the layout sc_format_shortest documents. */
void shortest_g_text(char *out, size_t size, long double v, int n);

/* Checks every `stride`-th binary32 bit pattern from `first` (count of them) on `threads`
 * threads, by shortest_exact.h and, on every bit pattern divisible by 4099, by both checkers;
 * returns the number of failures and keeps the first one's reason in why. */
uint64_t shortest_check_binary32(uint64_t first, uint64_t count, uint64_t stride, int threads,
                                 char *why, size_t why_size);

#endif
