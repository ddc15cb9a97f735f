/* Decimal texts that binary64 cannot tell from a value v: v's exact decimal moved by far less
 * than half a binary64 unit, so that strtod returns v itself while the decimal lies strictly
 * above or below it. At a midpoint v of a narrower format, the decimal then rounds (once,
 * correctly) to v's upper or lower neighbour, whichever way ties to even would go: the cases on
 * which a reading through binary64 rounds twice and can land on the wrong side. */
#ifndef SC_TEST_MIDPOINT_TEXT_H
#define SC_TEST_MIDPOINT_TEXT_H

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { SC_BESIDE_TEXT = 512 };

/* Writes v's exact decimal (every binary64 of at least 2^-247 has one of at most 300 places) and
 * moves it in magnitude by 10^-(its places + 30): away from zero by appending zeros and a one,
 * toward zero by lowering its last digit by one (with borrows) and appending nines. v: finite,
 * nonzero, at least 2^-247 in magnitude. */
static inline void sc_text_beside(char out[SC_BESIDE_TEXT], double v, int away_from_zero)
{
    int n = snprintf(out, SC_BESIDE_TEXT, "%.300f", v);
    while (out[n - 1] == '0')
        n--;
    out[n] = '\0'; /* "0.5", "65520." */
    if (!away_from_zero) {
        int i = out[n - 1] == '.' ? n - 2 : n - 1;
        for (; out[i] == '0' || out[i] == '.'; i--)
            out[i] = out[i] == '.' ? '.' : '9';
        out[i]--;
    }
    strcat(out,
           away_from_zero ? "000000000000000000000000000001" : "999999999999999999999999999999");
}

#endif
