/* The checker of the shortest decimals (shortest_check.h). */
#include "shortest_check.h"
#include "shortest_exact.h"

#include <fenv.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TEXT = 64 };

/* A decimal m·10^scale. */
typedef struct {
    uint64_t m;
    int scale;
} decimal;

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The decimal text s correctly rounded to p, once: strtod for binary64, glibc's strtof for
 * binary32. For binary16 and lowp, whose values and midpoints are all binary64 values: the
 * decimal lies in [lo, hi], its binary64 neighbours (strtod rounding downward and upward, which
 * glibc honours). Either it is lo itself, or it lies strictly between lo and hi, where no
 * midpoint of p is; then when lo and hi round to different values of p, the end nearer zero or
 * the other is their midpoint, and the decimal lies on the other side of it. (The end nearer
 * zero: its rounding is finite whenever the two differ, so the midpoint test is exact.) */
static double correctly_rounded(const char *s, sc_prec p)
{
    if (p == SC_DOUBLE)
        return strtod(s, NULL);
    if (p == SC_HIGHP)
        return strtof(s, NULL);
    int mode = fegetround();
    fesetround(FE_DOWNWARD);
    double lo = strtod(s, NULL);
    fesetround(FE_UPWARD);
    double hi = strtod(s, NULL);
    fesetround(mode);
    double near = fabs(lo) < fabs(hi) ? lo : hi, far = near == lo ? hi : lo;
    double n = sc_round(p, near), f = sc_round(p, far);
    return n == f || near != n / 2 + f / 2 ? n : f;
}

/* Whether the text s reads back to x in p: its single correct rounding to p is x (lowp: without
 * relying on its saturation, the decimal at most SC_LOWP_MAX + 2^-9). */
int shortest_reads_back(const char *s, double x, sc_prec p)
{
    if (!same_bits(correctly_rounded(s, p), x))
        return 0;
    if (p != SC_LOWP)
        return 1;
    int mode = fegetround();
    fesetround(x < 0 ? FE_DOWNWARD : FE_UPWARD);
    double outward = strtod(s, NULL);
    fesetround(mode);
    return fabs(outward) <= SC_LOWP_MAX + 0x1p-9;
}

static int decimal_reads_back(decimal d, double x, sc_prec p)
{
    char s[TEXT];
    snprintf(s, sizeof s, "%s%llue%d", signbit(x) ? "-" : "", (unsigned long long)d.m, d.scale);
    return shortest_reads_back(s, x, p);
}

static decimal normalized(decimal d)
{
    while (d.m && d.m % 10 == 0) {
        d.m /= 10;
        d.scale++;
    }
    return d;
}

static int equal(decimal a, decimal b)
{
    a = normalized(a);
    b = normalized(b);
    return a.m == b.m && a.scale == b.scale;
}

static int digit_count(uint64_t m)
{
    int n = 1;
    while (m >= 10) {
        m /= 10;
        n++;
    }
    return n;
}

/* The value of a decimal text ("-0.0125", "1.5e-07", "30") as digits and a scale, exactly. */
static decimal value_of(const char *s)
{
    decimal d = {0, 0};
    int after_point = 0;
    for (s += *s == '-'; *s && *s != 'e'; s++) {
        if (*s == '.') {
            after_point = 1;
            continue;
        }
        d.m = d.m * 10 + (uint64_t)(*s - '0');
        d.scale -= after_point;
    }
    if (*s == 'e')
        d.scale += atoi(s + 1);
    return d;
}

/* |x| correctly rounded to n significant digits (n >= 1). */
static decimal rounded(double x, int n)
{
    char s[TEXT];
    snprintf(s, sizeof s, "%.*e", n - 1, fabs(x));
    return value_of(s);
}

/* The n-digit decimals next to r (an n-digit rounding of x) on either side: r ± one unit, and
 * below a power of ten the finer neighbour 10·r − 1 one scale down. */
static int neighbours(decimal r, int n, decimal out[3])
{
    int k = 0;
    out[k++] = (decimal){r.m + 1, r.scale};
    if (r.m > 1)
        out[k++] = (decimal){r.m - 1, r.scale};
    uint64_t power = 1;
    for (int i = 1; i < n; i++)
        power *= 10;
    if (r.m == power)
        out[k++] = (decimal){10 * r.m - 1, r.scale - 1};
    return k;
}

static int fail(char *why, size_t size, double x, const char *s, const char *what, decimal d)
{
    snprintf(why, size, "%a printed %s: %s %llue%d", x, s, what, (unsigned long long)d.m, d.scale);
    return -1;
}

/* Whether s is laid out as shortest_g_text lays out its value with its digit count n. The value
 * is read as a long double, whose 64 bits hold any decimal of at most 17 digits closely enough
 * that %.{n}Lg gives back its digits. */
static int laid_out_as_g(const char *s, int n)
{
    char g[TEXT];
    shortest_g_text(g, sizeof g, strtold(s, NULL), n);
    return strcmp(s, g) == 0;
}

void shortest_g_text(char *out, size_t size, long double v, int n)
{
    snprintf(out, size, "%.*Lg", n, v);
    const char *e = strchr(out, 'e');
    if (e && atoi(e + 1) >= 0 && atoi(e + 1) < 6)
        snprintf(out, size, "%.0Lf", v);
}

int shortest_check(double x, sc_prec p, char *why, size_t why_size)
{
    char s[TEXT];
    sc_format_shortest(s, sizeof s, x, p);
    return shortest_check_text(x, p, s, why, why_size);
}

int shortest_check_text(double x, sc_prec p, const char *s, char *why, size_t why_size)
{
    decimal got = normalized(value_of(s));
    if (!shortest_reads_back(s, x, p) || (s[0] == '-') != (signbit(x) != 0))
        return fail(why, why_size, x, s, "does not read back as", got);
    int n = digit_count(got.m);
    if (!laid_out_as_g(s, n))
        return fail(why, why_size, x, s, "not laid out as %g would write", got);
    if (n > 1) {
        decimal shorter[4] = {rounded(x, n - 1)};
        int count = 1 + neighbours(shorter[0], n - 1, shorter + 1);
        for (int i = 0; i < count; i++)
            if (decimal_reads_back(shorter[i], x, p))
                return fail(why, why_size, x, s, "a shorter decimal reads back:", shorter[i]);
    }
    decimal closest = rounded(x, n);
    if (decimal_reads_back(closest, x, p))
        return equal(got, closest) ? 0 : fail(why, why_size, x, s, "the closer is", closest);
    decimal other[3];
    int count = neighbours(closest, n, other);
    for (int i = 0; i < count; i++)
        if (equal(got, other[i]))
            return 0;
    return fail(why, why_size, x, s, "not next to x; the closest is", closest);
}

typedef struct {
    uint64_t first, count, stride, failures;
    int worker, threads;
    char why[256];
} binary32_share;

/* 0 if sc_format_shortest passes for f: by the exact checker, and by the one above too on
 * every bit pattern divisible by CROSS_CHECK; else -1 with the reason. */
enum { CROSS_CHECK = 4099 };
static int check_binary32(float f, uint32_t bits, char *why, size_t why_size)
{
    char s[TEXT];
    sc_format_shortest(s, sizeof s, f, SC_HIGHP);
    int exact = shortest_exact_check(f, s, why, why_size);
    if (bits % CROSS_CHECK != 0)
        return exact;
    char libc_why[256], exact_why[256];
    int libc = shortest_check_text(f, SC_HIGHP, s, libc_why, sizeof libc_why);
    if (libc == exact)
        return exact;
    snprintf(exact_why, sizeof exact_why, "%s", exact ? why : "passed");
    snprintf(why, why_size, "the checkers disagree: exact %.100s; libc %.100s", exact_why,
             libc ? libc_why : "passed");
    return -1;
}

static void *check_share(void *arg)
{
    binary32_share *w = arg;
    for (uint64_t i = (uint64_t)w->worker; i < w->count; i += (uint64_t)w->threads) {
        uint32_t bits = (uint32_t)(w->first + i * w->stride);
        float f;
        memcpy(&f, &bits, sizeof f);
        char why[256];
        if (f != 0.0f && isfinite(f) && check_binary32(f, bits, why, sizeof why) != 0 &&
            w->failures++ == 0)
            memcpy(w->why, why, sizeof why);
    }
    return NULL;
}

uint64_t shortest_check_binary32(uint64_t first, uint64_t count, uint64_t stride, int threads,
                                 char *why, size_t why_size)
{
    binary32_share *shares = calloc((size_t)threads, sizeof *shares);
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    uint64_t failures = 0;
    snprintf(why, why_size, "%s", shares && ids ? "" : "out of memory");
    int started = 0;
    for (; shares && ids && started < threads; started++) {
        shares[started] = (binary32_share){first, count, stride, 0, started, threads, ""};
        if (pthread_create(&ids[started], NULL, check_share, &shares[started]) != 0)
            break;
    }
    for (int i = 0; i < started; i++) {
        pthread_join(ids[i], NULL);
        if (shares[i].failures && failures == 0)
            snprintf(why, why_size, "%s", shares[i].why);
        failures += shares[i].failures;
    }
    if (started < threads && why[0] == '\0')
        snprintf(why, why_size, "cannot start thread %d", started + 1);
    free(shares);
    free(ids);
    return started < threads ? failures + 1 : failures;
}
