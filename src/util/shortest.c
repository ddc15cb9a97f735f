/* Shortest round-trip decimals (util/shortest.h): the Schubfach algorithm of R. Giulietti,
 * "The Schubfach way to render doubles" (2020), cited as [S], for binary64, binary32 and
 * binary16; a direct search for lowp; the %g-style text of sc_format_shortest. */
#include "util/shortest.h"

#include <math.h>
#include <string.h>

/* ---- 128-bit products by the table's g ---- */

/* floor(a·b / 2^64), from 32-bit halves (portable C11). */
static uint64_t mul_high(uint64_t a, uint64_t b)
{
    uint64_t a_lo = (uint32_t)a, a_hi = a >> 32, b_lo = (uint32_t)b, b_hi = b >> 32;
    uint64_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi;
    /* at most (2^32 - 1) + (2^32 - 1) + (2^32 - 1)^2 = 2^64 - 1: no overflow */
    uint64_t middle = (lo_lo >> 32) + (uint32_t)hi_lo + lo_hi;
    return a_hi * b_hi + (hi_lo >> 32) + (middle >> 32);
}

/* r_o(cp·g·2^-127), rounded to odd: the floor, with its lowest bit set when the product has a
 * fraction ([S] §9.9, figure 8). g·2^-127 exceeds the power of ten by less than 2^-63 of a unit
 * of the result for cp < 2^64, so an exact integer stays exact, and [S] §9.9 proves that no
 * other product of the binary64 range comes closer to an integer than that. */
static uint64_t round_to_odd(const uint64_t g[2], uint64_t cp)
{
    uint64_t x1 = mul_high(g[1], cp);
    uint64_t y0 = g[0] * cp, y1 = mul_high(g[0], cp);
    uint64_t z = (y0 >> 1) + x1; /* the fraction, in units of 2^-63, and a carry in bit 63 */
    uint64_t floor = y1 + (z >> 63);
    uint64_t fraction = z & ((UINT64_C(1) << 63) - 1);
    return floor | (fraction != 0);
}

/* ---- Schubfach: the skeleton of [S] figure 7, with the computations of figure 9 ---- */

typedef struct {
    int precision; /* significand bits, the implicit one included */
    int q_min;     /* exponent of the smallest subnormal step */
} binary_format;

static const binary_format binary64 = {53, -1074}, binary32 = {24, -149}, binary16 = {11, -24};

/* 4·x·10^-k, rounded to odd, for x = v and Rv's bounds: v̄, v̄l and v̄r of [S] figure 9. */
typedef struct {
    uint64_t vb, vbl, vbr;
} scaled_interval;

/* Whether 4·d (d = u·10^k, a candidate) is inside Rv; `open` when Rv excludes its bounds (an odd
 * c: a decimal on the bound reads back, by ties to even, as the even neighbour). [S] §9.3. */
static int above_left(const scaled_interval *r, uint64_t d, int open)
{
    return r->vbl + (uint64_t)open <= d << 2;
}
static int below_right(const scaled_interval *r, uint64_t d, int open)
{
    return (d << 2) + (uint64_t)open <= r->vbr;
}

/* Between s·10^k and (s + 1)·10^k, the one inside Rv, or the closer to v when both are (ties:
 * the even one). [S] §9.3 proves that at least one of them is inside. */
static uint64_t closest_of_two(const scaled_interval *r, uint64_t s, int open)
{
    uint64_t t = s + 1;
    int u_in = above_left(r, s, open), w_in = below_right(r, t, open);
    if (u_in != w_in)
        return u_in ? s : t;
    int64_t cmp = (int64_t)(r->vb - ((s + t) << 1)); /* 4v·10^-k against 4·(s + t)/2 */
    return cmp < 0 || (cmp == 0 && (s & 1) == 0) ? s : t;
}

/* v = c·2^q, c < 2^precision (a subnormal has q = q_min and c < 2^(precision - 1)). */
static sc_decimal schubfach(const binary_format *f, uint64_t c, int q)
{
    int open = (int)(c & 1);
    /* At a power of two (but the smallest normal) the step below v is half the step above:
     * Rv is [v - 2^(q-2), v + 2^(q-1)], the irregular spacing of [S] figure 7. */
    int irregular = c == UINT64_C(1) << (f->precision - 1) && q > f->q_min;
    uint64_t cb = c << 2, cbr = cb + 2, cbl = irregular ? cb - 1 : cb - 2;
    /* k as [S] figure 7 chooses it: 10^k <= the width of Rv < 10^(k+1), so Rv holds at most one
     * multiple of 10^(k+1) and at least one multiple of 10^k. */
    int k = irregular ? sc_flog10_three_quarters_pow2(q) : sc_flog10_pow2(q);
    int h = q + sc_flog2_pow10(-k) + 2; /* 2 <= h <= 5: cb << h < 2^60 */
    const uint64_t *g = sc_shortest_g[k - SC_SHORTEST_K_MIN];
    scaled_interval r = {round_to_odd(g, cb << h), round_to_odd(g, cbl << h),
                         round_to_odd(g, cbr << h)};
    uint64_t s = r.vb >> 2; /* floor(v·10^-k) >= 1 */
    if (s >= 10) {
        /* u' = 10·floor(s/10)·10^k or w' = u' + 10^(k+1) ([S] §9.3): a multiple of 10^(k+1)
         * inside Rv has fewer digits than any other candidate and is the only one. With s < 10
         * both kinds have one digit, and the closest must be chosen among s and s + 1: skip. */
        uint64_t sp10 = s / 10 * 10, tp10 = sp10 + 10;
        int up_in = above_left(&r, sp10, open), wp_in = below_right(&r, tp10, open);
        if (up_in != wp_in)
            return (sc_decimal){up_in ? sp10 : tp10, k};
    }
    return (sc_decimal){closest_of_two(&r, s, open), k};
}

/* x (positive, a value of the format) as c·2^q: binary64's significand and exponent, shifted
 * to the format's precision, or to its smallest exponent for a subnormal (exact: x is one of
 * the format's values). */
static sc_decimal shortest_binary(const binary_format *f, double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int biased = (int)(bits >> 52);
    uint64_t c = bits & ((UINT64_C(1) << 52) - 1);
    int q = biased ? biased - 1075 : -1074;
    if (biased)
        c |= UINT64_C(1) << 52;
    int shift = q + 53 - f->precision < f->q_min ? f->q_min - q : 53 - f->precision;
    return schubfach(f, c >> shift, q + shift);
}

/* ---- lowp: k/256, |k| <= 511 ---- */

/* The fewest decimal places n whose nearest multiple of 10^-n (ties to even) lies in k/256's
 * interval: (2k - 1)/512 .. (2k + 1)/512, bounds included for an even k, and for k = 511 the
 * upper one (sc_round_lowp saturates there). Rv is 2^-8 wide, so n <= 3. */
static sc_decimal shortest_lowp(double x)
{
    uint64_t k = (uint64_t)fabs(x * 256.0), scale = 1;
    int closed = (k & 1) == 0;
    for (int n = 0;; n++, scale *= 10) {
        uint64_t d = k * scale / 256, rest = k * scale % 256;
        d += rest > 128 || (rest == 128 && (d & 1));
        uint64_t lo = (2 * k - 1) * scale, hi = (2 * k + 1) * scale, d512 = d * 512;
        if ((closed ? lo <= d512 : lo < d512) && (closed || k == 511 ? d512 <= hi : d512 < hi))
            return (sc_decimal){d, -n};
    }
}

static sc_decimal without_trailing_zeros(sc_decimal d)
{
    while (d.digits % 10 == 0) {
        d.digits /= 10;
        d.exponent++;
    }
    return d;
}

sc_decimal sc_shortest_decimal(double x, sc_prec p)
{
    double a = fabs(x);
    switch (p) {
    case SC_HIGHP: return without_trailing_zeros(shortest_binary(&binary32, a));
    case SC_MEDIUMP: return without_trailing_zeros(shortest_binary(&binary16, a));
    case SC_LOWP: return without_trailing_zeros(shortest_lowp(a));
    case SC_DOUBLE: break;
    }
    return without_trailing_zeros(shortest_binary(&binary64, a));
}

/* ---- text, as %g writes it ---- */

enum { TEXT_MAX = 32 }; /* "-1.2345678901234567e-308" */

static const uint64_t power_of_ten[20] = {1,
                                          10,
                                          100,
                                          1000,
                                          10000,
                                          100000,
                                          1000000,
                                          10000000,
                                          100000000,
                                          1000000000,
                                          10000000000,
                                          100000000000,
                                          1000000000000,
                                          10000000000000,
                                          100000000000000,
                                          1000000000000000,
                                          10000000000000000,
                                          100000000000000000,
                                          1000000000000000000,
                                          10000000000000000000u};

/* The number of decimal digits of d, by a binary search over the powers of ten. */
static int digit_count(uint64_t d)
{
    int n = 1; /* d >= 10^(n-1) throughout */
    for (int step = 16; step; step /= 2)
        if (n + step <= 20 && d >= power_of_ten[n + step - 1])
            n += step;
    return n;
}

/* Writes the n decimal digits of d at out, two at a time from the right. */
static void write_digits(char *out, uint64_t d, int n)
{
    static const char pairs[] = "00010203040506070809101112131415161718192021222324252627282930"
                                "31323334353637383940414243444546474849505152535455565758596061"
                                "6263646566676869707172737475767778798081828384858687888990919293"
                                "949596979899";
    char *p = out + n;
    for (; d >= 100; d /= 100)
        memcpy(p -= 2, pairs + 2 * (d % 100), 2);
    if (d >= 10)
        memcpy(p - 2, pairs + 2 * d, 2);
    else
        p[-1] = (char)('0' + d);
}

/* d1[.d2...]e±XX, the exponent with at least two digits. */
static int scientific(char *out, const char *digits, int n, int exponent)
{
    int len = 0;
    out[len++] = digits[0];
    if (n > 1) {
        out[len++] = '.';
        memcpy(out + len, digits + 1, (size_t)n - 1);
        len += n - 1;
    }
    out[len++] = 'e';
    out[len++] = exponent < 0 ? '-' : '+';
    int magnitude = exponent < 0 ? -exponent : exponent;
    if (magnitude < 10)
        out[len++] = '0';
    int width = digit_count((uint64_t)magnitude);
    write_digits(out + len, (uint64_t)magnitude, width);
    return len + width;
}

/* The digits with the point placed, padded with zeros on either side (the decimal is
 * digits·10^(exponent - n + 1)). */
static int positional(char *out, const char *digits, int n, int exponent)
{
    if (exponent < 0) { /* 0.000ddd */
        int zeros = -exponent - 1;
        memcpy(out, "0.", 2);
        memset(out + 2, '0', (size_t)zeros);
        memcpy(out + 2 + zeros, digits, (size_t)n);
        return 2 + zeros + n;
    }
    if (exponent >= n - 1) { /* ddd000 */
        memcpy(out, digits, (size_t)n);
        memset(out + n, '0', (size_t)(exponent + 1 - n));
        return exponent + 1;
    }
    memcpy(out, digits, (size_t)exponent + 1); /* dd.ddd */
    out[exponent + 1] = '.';
    memcpy(out + exponent + 2, digits + exponent + 1, (size_t)(n - exponent - 1));
    return n + 1;
}

/* %g's choice ("%.Pg" with P the digit count), except that integers below 10^6 are written out
 * ("30", not "3e+01"), as %g writes them with its default six digits. */
static int decimal_text(char *out, int negative, sc_decimal d)
{
    char digits[20];
    int n = digit_count(d.digits), exponent = d.exponent + n - 1, len = 0;
    write_digits(digits, d.digits, n);
    if (negative)
        out[len++] = '-';
    int exponential = exponent < -4 || exponent >= (n > 6 ? n : 6);
    return len + (exponential ? scientific : positional)(out + len, digits, n, exponent);
}

static int special_text(char *out, double x)
{
    const char *text = isnan(x)   ? "nan"
                       : isinf(x) ? (x < 0 ? "-inf" : "inf")
                                  : (signbit(x) ? "-0" : "0");
    size_t len = strlen(text);
    memcpy(out, text, len);
    return (int)len;
}

int sc_format_shortest(char *buf, size_t size, double x, sc_prec p)
{
    char text[TEXT_MAX];
    int len;
    if (x == 0.0 || !isfinite(x))
        len = special_text(text, x);
    else /* a value that is not one of p's has no decimal reading back to it: its own digits */
        len = decimal_text(
            text, signbit(x) != 0,
            sc_shortest_decimal(x, p == SC_DOUBLE || sc_round(p, x) == x ? p : SC_DOUBLE));
    if (size > 0) {
        size_t copied = (size_t)len < size ? (size_t)len : size - 1;
        memcpy(buf, text, copied);
        buf[copied] = '\0';
    }
    return len;
}
