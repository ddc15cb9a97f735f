/* The exact checker of the shortest binary32 decimals (shortest_exact.h). */
#include "shortest_exact.h"

#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* ---- unsigned integers of 256 bits ---- */

/* 256 bits hold every product below: a bound b < 2^78 (in units of 2^(e-54)) times 5^66, or a
 * decimal's digits c < 2^64 times 2^158 (see set_up). */
__extension__ typedef unsigned __int128 u128; /* GCC and Clang; __extension__: no -Wpedantic */
enum { LIMBS = 4 };
typedef struct {
    uint64_t limb[LIMBS]; /* little endian */
} big;

/* a·v; *overflow set when it needs more than 256 bits. */
static big big_mul(const big *a, uint64_t v, int *overflow)
{
    big r;
    uint64_t carry = 0;
    for (int i = 0; i < LIMBS; i++) {
        u128 t = (u128)a->limb[i] * v + carry;
        r.limb[i] = (uint64_t)t;
        carry = (uint64_t)(t >> 64);
    }
    *overflow |= carry != 0;
    return r;
}

static big big_shift_left(const big *a, int bits, int *overflow)
{
    big r = {{0}};
    int words = bits / 64, rest = bits % 64;
    for (int i = LIMBS - 1; i >= words; i--) {
        uint64_t below = rest && i > words ? a->limb[i - words - 1] >> (64 - rest) : 0;
        r.limb[i] = a->limb[i - words] << rest | below;
    }
    for (int i = LIMBS - words; i < LIMBS; i++) /* limbs shifted out whole */
        *overflow |= i >= 0 && a->limb[i] != 0;
    if (rest && words < LIMBS) /* the bits shifted out of the top limb */
        *overflow |= a->limb[LIMBS - 1 - words] >> (64 - rest) != 0;
    return r;
}

static int big_cmp(const big *a, const big *b)
{
    for (int i = LIMBS - 1; i >= 0; i--)
        if (a->limb[i] != b->limb[i])
            return a->limb[i] < b->limb[i] ? -1 : 1;
    return 0;
}

/* 5^k, 27 factors of 5 at a time (5^27 < 2^64). */
static big power_of_five(int k, int *overflow)
{
    big r = {{1}};
    for (; k > 0; k -= 27) {
        uint64_t factor = 1;
        for (int i = 0; i < k && i < 27; i++)
            factor *= 5;
        r = big_mul(&r, factor, overflow);
    }
    return r;
}

static int bit_length(uint64_t v)
{
    int n = 0;
    for (int step = 32; step; step /= 2)
        if (v >> step) {
            v >>= step;
            n += step;
        }
    return n + (v != 0);
}

/* ---- 10^k in double, within 2^-50 of it ---- */

enum { TEN_MIN = -80, TEN_MAX = 45 };
static double ten_to_the[TEN_MAX - TEN_MIN + 1];

/* Within 4·2^-53 of a (each of 4 steps rounds once). */
static double big_to_double(const big *a)
{
    double v = 0;
    for (int i = LIMBS - 1; i >= 0; i--)
        v = ldexp(v, 64) + (double)a->limb[i];
    return v;
}

/* 10^k = 5^k·2^k: 5^|k| within 2^-51, its inverse within 2^-51 + 2^-53, times 2^k exactly. */
static void fill_powers_of_ten(void)
{
    for (int k = TEN_MIN; k <= TEN_MAX; k++) {
        int overflow = 0;
        big five = power_of_five(abs(k), &overflow);
        double v = big_to_double(&five);
        ten_to_the[k - TEN_MIN] = ldexp(k < 0 ? 1 / v : v, k);
    }
}

/* ---- x's read-back interval, scaled for decimals c·10^g ---- */

typedef struct {
    uint32_t m; /* |x| = m·2^e, m < 2^24 */
    int e;
} binary32;

static binary32 parts_of(float x)
{
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    uint32_t biased = bits >> 23 & 0xff, fraction = bits & 0x7fffff;
    binary32 b = {fraction, -149};
    if (biased) {
        b.m |= UINT32_C(1) << 23;
        b.e = (int)biased - 150;
    }
    return b;
}

/* A decimal c·10^g is compared with I's bounds and x in double first: c·10^g within 2^-50 of
 * it (the table and the product), each binary quantity within 2^-53. A difference beyond 2^-40
 * of the quantity decides; otherwise (a decimal on a bound or on x, or very near) the exact
 * comparison: c·10^g against v·2^shift units of 2^(e-54), with the common factors
 * 2^min(g, e-54) and 5^min(g, 0) cancelled, c·decimal_factor against v·5^max(-g, 0)·
 * 2^(shift + max(e-54-g, 0)). */
enum { LOW, X, HIGH };
typedef struct {
    uint64_t v[3]; /* I's bounds and |x|: v·2^shift units of 2^(e-54), v < 2^64 */
    int shift[3];
    double approx[3]; /* the same in double */
    double unit;      /* 2^(e-54) */
    double ten;       /* 10^g in double; 0 outside the table: exact comparisons only */
    int closed;       /* I includes its bounds */
    int e, g;
    int exact;   /* the big integers below are set up */
    big side[3]; /* the binary sides */
    big decimal_factor;
    int overflow; /* some product did not fit in 256 bits */
} interval;

static void set_bound(interval *r, int i, uint64_t v, int shift)
{
    r->v[i] = v;
    r->shift[i] = shift;
    r->approx[i] = (double)v * (double)(UINT64_C(1) << shift) * r->unit; /* powers of 2: exact */
}

/* In units of 2^(e-54), I is (2m ± 1)·2^53 around m·2^54 ((4m - 1)·2^52 below a power of two). */
static void set_up(interval *r, binary32 b, int g)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, fill_powers_of_ten);
    r->closed = b.m % 2 == 0; /* the big integers are left for set_up_exact */
    r->e = b.e;
    r->g = g;
    r->unit = ldexp(1.0, b.e - 54);
    r->exact = r->overflow = 0;
    r->ten = g >= TEN_MIN && g <= TEN_MAX ? ten_to_the[g - TEN_MIN] : 0;
    uint64_t m = b.m;
    set_bound(r, X, m, 54);
    if (m == UINT64_C(1) << 23 && b.e > -149)
        set_bound(r, LOW, 4 * m - 1, 52);
    else
        set_bound(r, LOW, 2 * m - 1, 53);
    set_bound(r, HIGH, 2 * m + 1, 53);
}

static void set_up_exact(interval *r)
{
    int t = r->e - 54, g = r->g, twos = t > g ? t - g : 0;
    big five = power_of_five(g < 0 ? -g : 0, &r->overflow);
    for (int i = 0; i < 3; i++) {
        big product = big_mul(&five, r->v[i], &r->overflow);
        r->side[i] = big_shift_left(&product, r->shift[i] + twos, &r->overflow);
    }
    big decimal_five = power_of_five(g > 0 ? g : 0, &r->overflow);
    r->decimal_factor = big_shift_left(&decimal_five, g > t ? g - t : 0, &r->overflow);
    r->exact = 1;
}

/* The sign of c·10^g - the quantity `which` ((double)c is within 2^-53 of c). */
static int compare(interval *r, uint64_t c, int which)
{
    double d = (double)c * r->ten, q = r->approx[which];
    if (d > q * (1 + 0x1p-40))
        return 1;
    if (d < q * (1 - 0x1p-40) && r->ten > 0)
        return -1;
    if (!r->exact)
        set_up_exact(r);
    big product = big_mul(&r->decimal_factor, c, &r->overflow);
    return big_cmp(&product, &r->side[which]);
}

static int above_low(interval *r, uint64_t c) { return compare(r, c, LOW) >= !r->closed; }
static int below_high(interval *r, uint64_t c) { return compare(r, c, HIGH) <= -!r->closed; }
static int inside(interval *r, uint64_t c) { return above_low(r, c) && below_high(r, c); }

/* ---- the text ---- */

enum { TEXT = 64 };

/* ±digits·10^exponent, digits without trailing zeros, count of them. */
typedef struct {
    int negative, count, exponent;
    uint64_t digits;
} decimal_text;

static const char *exponent_of(const char *s, int *exponent)
{
    int sign = *s == '-' ? -1 : 1, value = 0;
    s += *s == '-' || *s == '+';
    if (*s < '0' || *s > '9')
        return NULL;
    for (; *s >= '0' && *s <= '9'; s++)
        if ((value = value * 10 + (*s - '0')) > 9999)
            return NULL;
    *exponent += sign * value;
    return s;
}

/* Reads [-]d*[.d*][e[±]d+]: 0, or -1 for other text, no digit, more than 19 significant
 * digits or an exponent beyond ±9999. */
static int parse(const char *s, decimal_text *t)
{
    *t = (decimal_text){.negative = *s == '-'};
    s += t->negative;
    int point = 0, any = 0, significant = 0;
    for (;; s++) {
        if (*s == '.' && !point) {
            point = 1;
            continue;
        }
        if (*s < '0' || *s > '9')
            break;
        any = 1;
        t->exponent -= point;
        if (significant == 0 && *s == '0')
            continue;
        if (++significant > 19)
            return -1;
        t->digits = t->digits * 10 + (uint64_t)(*s - '0');
    }
    if (*s == 'e' && (s = exponent_of(s + 1, &t->exponent)) == NULL)
        return -1;
    if (!any || *s != '\0')
        return -1;
    for (; t->digits && t->digits % 10 == 0; t->digits /= 10)
        t->exponent++;
    for (uint64_t d = t->digits; d; d /= 10)
        t->count++;
    return 0;
}

/* Writes v with at least `width` digits; returns their number. */
static int write_number(char *out, int v, int width)
{
    int n = 0;
    for (int rest = v; rest || n < width; rest /= 10)
        n++;
    for (int i = n - 1; i >= 0; i--, v /= 10)
        out[i] = (char)('0' + v % 10);
    return n;
}

/* How printf("%.{n}g") writes the decimal (n its digit count), except that an integer below
 * 10^6 is written out: d.ddde±XX when the exponent of its leading digit is below -4 or at least
 * max(n, 6), otherwise its digits at their powers of ten, zeros around them, the point between
 * the powers 0 and -1. */
static void g_layout(const decimal_text *t, char out[TEXT])
{
    char digits[20];
    uint64_t d = t->digits;
    for (int i = t->count - 1; i >= 0; i--, d /= 10)
        digits[i] = (char)('0' + d % 10);
    int n = t->count, lead = t->exponent + n - 1, last = t->exponent, len = 0;
    if (t->negative)
        out[len++] = '-';
    if (lead < -4 || lead >= (n > 6 ? n : 6)) {
        out[len++] = digits[0];
        if (n > 1)
            out[len++] = '.';
        memcpy(out + len, digits + 1, (size_t)n - 1);
        len += n - 1;
        out[len++] = 'e';
        out[len++] = lead < 0 ? '-' : '+';
        len += write_number(out + len, lead < 0 ? -lead : lead, 2);
    } else {
        for (int power = lead > 0 ? lead : 0; power >= 0 || power >= last; power--) {
            if (power == -1)
                out[len++] = '.';
            out[len++] = power <= lead && power >= last ? digits[lead - power] : '0';
        }
    }
    out[len] = '\0';
}

/* ---- the check ---- */

static const uint64_t ten_to[11] = {1,       10,       100,       1000,       10000,      100000,
                                    1000000, 10000000, 100000000, 1000000000, 10000000000};

static int fail(char *why, size_t size, float x, const char *s, const char *what, uint64_t c,
                int scale)
{
    snprintf(why, size, "%a printed %s: %s %llue%d", (double)x, s, what, (unsigned long long)c,
             scale);
    return -1;
}

/* Moves s to floor(|x| / 10^(g+1)) in at most `steps` steps: 0, or -1 if more are needed. */
static int floor_of_tenth(interval *r, uint64_t *s, int steps)
{
    for (; steps >= 0; steps--) {
        if (*s > 0 && compare(r, 10 * *s, X) > 0)
            --*s;
        else if (compare(r, 10 * (*s + 1), X) <= 0)
            ++*s;
        else
            return 0;
    }
    return -1;
}

/* floor(log10(|x|)) or one less or more: log10(2)·floor(log2(|x|)). */
static int lead_estimate(binary32 b) { return (int)floor((b.e + bit_length(b.m) - 1) * 0.30103); }

/* Sets I up for the grid 10^(P - digits) with 10^P <= |x| < 10^(P+1); returns floor(|x| /
 * 10^(P - digits + 1)), a number of `digits` digits. lead and s are estimates of P and of the
 * result: the comparisons decide, and a floating-point quotient (within 1 of the floor) replaces
 * an estimate of s that is more than two off. */
static uint64_t set_up_at_x(interval *r, binary32 b, int digits, int lead, uint64_t s)
{
    for (;;) {
        int g = lead - digits;
        set_up(r, b, g);
        if (floor_of_tenth(r, &s, 2) != 0) {
            /* s < 2^40: within 1 of the floor (outside the table, which no binary32 needs, 0) */
            s = r->ten > 0 ? (uint64_t)(r->approx[X] / (10 * r->ten)) : 0;
            floor_of_tenth(r, &s, INT_MAX);
        }
        if (s >= ten_to[digits - 1] && s < ten_to[digits])
            return s;
        lead += s < ten_to[digits - 1] ? -1 : 1;
    }
}

/* Of s·10^(g+1) and (s + 1)·10^(g+1) around |x|, the closest in I (ties: the even s); 0 if
 * neither is in I. As c·10^g. */
static uint64_t closest_in(interval *r, uint64_t s)
{
    uint64_t below = 10 * s, above = below + 10;
    int below_in = above_low(r, below), above_in = below_high(r, above);
    if (!below_in || !above_in)
        return below_in ? below : above_in ? above : 0;
    int side = compare(r, below + 5, X); /* the midpoint against |x| */
    return side > 0 || (side == 0 && s % 2 == 0) ? below : above;
}

/* A text of more than 9 digits: the shorter decimal of 9 digits that reads back (there always is
 * one: the step 10^(P-8) is below the width of I). */
static int check_long(float x, const char *s, binary32 b, char *why, size_t why_size)
{
    interval r;
    uint64_t t = set_up_at_x(&r, b, 9, lead_estimate(b), 0);
    uint64_t shorter = above_low(&r, 10 * t)         ? 10 * t
                       : below_high(&r, 10 * t + 10) ? 10 * t + 10
                                                     : 0;
    if (shorter)
        return fail(why, why_size, x, s, "a shorter decimal reads back:", shorter, r.g);
    return fail(why, why_size, x, s, "more than 9 digits, none fewer reads back near", t, r.g + 1);
}

int shortest_exact_check(float x, const char *s, char *why, size_t why_size)
{
    decimal_text t;
    if (x == 0.0f || !isfinite(x)) {
        snprintf(why, why_size, "%a is not a finite nonzero binary32", (double)x);
        return -1;
    }
    if (parse(s, &t) != 0) {
        snprintf(why, why_size, "%a printed %s: not a decimal text", (double)x, s);
        return -1;
    }
    binary32 b = parts_of(x);
    if (t.count > 9)
        return check_long(x, s, b, why, why_size);
    interval r;
    int n = t.count > 0 ? t.count : 1, lead = lead_estimate(b), text_lead = t.exponent + n - 1;
    int near = text_lead >= lead - 1 && text_lead <= lead + 1; /* then P is text_lead or next */
    uint64_t at_x = set_up_at_x(&r, b, n, near ? text_lead : lead, near ? t.digits : 0);
    int shift = t.exponent - r.g; /* the printed decimal is digits·10^shift·10^g */
    uint64_t printed = t.digits * (shift >= 0 && shift <= 2 ? ten_to[shift] : 0);
    if (t.negative != (signbit(x) != 0) || printed == 0 || !inside(&r, printed))
        return fail(why, why_size, x, s, "does not read back as", t.digits, t.exponent);
    char layout[TEXT];
    g_layout(&t, layout);
    if (strcmp(s, layout) != 0)
        return fail(why, why_size, x, s, "not laid out as %g would write", t.digits, t.exponent);
    uint64_t shorter = at_x / 10 * 100;
    if (n > 1 && (above_low(&r, shorter) || below_high(&r, shorter + 100)))
        return fail(why, why_size, x, s, "a shorter decimal reads back:",
                    above_low(&r, shorter) ? shorter : shorter + 100, r.g);
    uint64_t closest = closest_in(&r, at_x);
    if (closest != printed)
        return fail(why, why_size, x, s, "the closer is", closest, r.g);
    if (r.overflow)
        return fail(why, why_size, x, s, "beyond the checker's 256 bits:", t.digits, t.exponent);
    return 0;
}

int shortest_exact_reads_back(float x, const char *s)
{
    decimal_text t;
    if (x == 0.0f || !isfinite(x) || parse(s, &t) != 0)
        return -1;
    binary32 b = parts_of(x);
    int lead = lead_estimate(b), text_lead = t.exponent + t.count - 1; /* P: lead ± 1 */
    if (t.negative != (signbit(x) != 0) || t.digits == 0 || text_lead < lead - 2 ||
        text_lead > lead + 2)
        return 0; /* I lies within |x|·(1 ± 2^-24) */
    interval r;
    set_up(&r, b, t.exponent);
    int in = inside(&r, t.digits);
    return r.overflow ? -1 : in;
}
