/* The exact checker of sc_format_shortest for binary32: the rules of shortest_check.h, decided
 * with exact arithmetic instead of glibc's conversions (about 15 times faster: `--groups print`
 * checks every binary32 with it, and with shortest_check.h's checker too on a sample).
 *
 * x = m·2^e (m < 2^24) reads back from the decimals of an interval I around x, as
 * shortest_reads_back decides (strtof(s) is x: one correct rounding to binary32, as shadecalc
 * reads a highp literal): the bounds are the midpoints (2m ± 1)·2^(e-1) to x's neighbours, the
 * lower one (4m - 1)·2^(e-2) at a power of two above the smallest normal; included for an even
 * m (ties to even), excluded for an odd m.
 * A decimal c·10^g is compared with a bound b·2^t exactly: in double when they differ by more
 * than 2^-40 of b (both are within 2^-49 there), otherwise as c·5^g·2^g against b·2^t with the
 * common powers of 2 and 5 cancelled, in 256-bit integers. Then, with n the printed digits and
 * 10^P <= |x| < 10^(P+1), s = floor(|x| / 10^(P-n+1)):
 *   - no decimal of n - 1 digits is in I: I contains |x|, so it holds one if and only if it holds
 *     (s/10)·10^(P-n+2) or the next multiple of that step;
 *   - the printed one is the closest of s·10^(P-n+1) and (s + 1)·10^(P-n+1) among those in I
 *     (ties: the even one), which is the closest of n digits in I;
 *   - the text is the layout of shortest_g_text (shortest_check.h) for its digits. */
#ifndef SHADECALC_EXHAUSTIVE_SHORTEST_EXACT_H
#define SHADECALC_EXHAUSTIVE_SHORTEST_EXACT_H

#include <stddef.h>

/* 0 if s is the text sc_format_shortest must write for x (binary32, finite, nonzero); else -1
 * with the reason in why (also for a zero or non-finite x). */
int shortest_exact_check(float x, const char *s, char *why, size_t why_size);

/* 1 if the decimal text s ("-1.25e-07", at most 19 significant digits) reads back to x as
 * above, 0 if not, -1 if s is no such text or x is zero or not finite. */
int shortest_exact_reads_back(float x, const char *s);

#endif
