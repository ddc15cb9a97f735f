/* Shortest round-trip decimals by the Schubfach algorithm: R. Giulietti, "The Schubfach way to
 * render doubles" (2020), cited below as [S] with its section numbers. For a positive binary
 * value v = c·2^q, the rounding interval Rv holds the reals that round back to v; [S] finds
 * the decimal of Rv with the fewest digits, and among those the closest to v, from three
 * products by a 126-bit power of ten, without a loop over digit counts. The same code serves
 * binary64 (as proved in [S]), binary32 and binary16 (checked for every value: the unit and
 * exhaustive tests), and a direct search serves lowp's 1023 fixed-point values.
 *
 * sc_format_shortest (shadecalc/precision.h) is defined in shortest.c. */
#ifndef SHADECALC_UTIL_SHORTEST_H
#define SHADECALC_UTIL_SHORTEST_H

#include <stdint.h>

#include "shadecalc/precision.h"

/* A positive decimal digits·10^exponent; digits has no trailing zero. */
typedef struct {
    uint64_t digits;
    int exponent;
} sc_decimal;

/* The shortest decimal that reads back to x (finite, nonzero, a value of p) in precision p,
 * the closest to x among those (ties to an even last digit). The sign is dropped. */
sc_decimal sc_shortest_decimal(double x, sc_prec p);

/* ---- the pieces of [S], exposed for tests/unit/test_shortest.c ---- */

/* floor(log10(2^e)), floor(log10(3/4·2^e)) and floor(log2(10^e)) by fixed-point products:
 * the constants are floor(log10(2)·2^41), floor(log10(3/4)·2^41) and floor(log2(10)·2^38).
 * tests/unit/test_shortest.c checks them exactly over the exponents of the three formats. */
static inline int sc_flog10_pow2(int e) { return (int)(((int64_t)e * 661971961083LL) >> 41); }
static inline int sc_flog10_three_quarters_pow2(int e)
{
    return (int)(((int64_t)e * 661971961083LL - 274743187321LL) >> 41);
}
static inline int sc_flog2_pow10(int e) { return (int)(((int64_t)e * 913124641741LL) >> 38); }

/* g(k) of [S] §9.8.3: 10^-k = β·2^r with 2^125 <= β < 2^126 and g = floor(β) + 1, stored as
 * {g1, g0} with g = g1·2^63 + g0 (shortest_table.c, written by mk/gen-shortest-table.py). */
enum { SC_SHORTEST_K_MIN = -324, SC_SHORTEST_K_MAX = 292 };
extern const uint64_t sc_shortest_g[SC_SHORTEST_K_MAX - SC_SHORTEST_K_MIN + 1][2];

#endif
