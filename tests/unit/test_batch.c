/* The batch kernels (shadecalc/batch.h): every stated bound of the table on >= 10^6 inputs per
 * kernel × tier (special values plus domain-covering random inputs) against the double
 * reference; every SIMD kernel against the scalar one on the same inputs, with test values in
 * random lanes among random data, every tail length, unaligned pointers and the special-value
 * table; identical bits where the algorithm is the same (SSE4.1, which has no FMA, against the
 * scalar kernels). Under the sanitizers the counts are smaller: that run checks memory. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/accuracy.h"
#include "shadecalc/batch.h"
#include "shadecalc/precision.h"

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifdef SANITIZED
enum { BOUND_INPUTS = 20000 };
#else
enum { BOUND_INPUTS = 1000000 };
#endif

static const float specials[] = {0.0f, -0.0f, 0x1p-149f, -0x1p-149f, FLT_MIN, -FLT_MIN, 0.5f,
                                 1.0f, 2.0f,  -1.0f,     FLT_MAX,   -FLT_MAX, INFINITY, -INFINITY,
                                 NAN,  0.25f, 3.0f,      100.0f};
enum { N_SPECIALS = (int)(sizeof specials / sizeof specials[0]) };

static uint64_t rng = 88172645463325252ULL;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

/* A random input of argument j of e, in its domain: magnitude-biased or uniform. */
static float input(const sc_batch_entry *e, int j)
{
    double lo = e->lo[j], hi = e->hi[j];
    if (j >= e->n_in)
        return 0.0f;
    if (next() & 1)
        return (float)(lo + (hi - lo) * ((double)(next() >> 11) * 0x1p-53));
    return sc_accuracy_sample(&rng, lo, hi);
}

/* Error of got against the reference, in the entry's unit: ULPs, or relative error (with the
 * absolute allowance), each against its bound; returns the ratio error/bound. */
static double bound_ratio(const sc_batch_entry *e, float got, double ref)
{
    if (isnan(ref) && isnan(got))
        return 0.0;
    if (isinf((float)ref) && got == (float)ref)
        return 0.0;
    if (e->bound_ulp > 0)
        return sc_ulp_error(SC_HIGHP, (double)got, ref) / e->bound_ulp;
    double err = fabs((double)got - ref);
    return err / (e->bound_rel * fabs(ref) + e->bound_abs + 1e-300);
}

/* The scalar built-ins' domain rule for pow u1: only normal-float results count. */
static int counts(const sc_batch_entry *e, double ref)
{
    return !(strcmp(e->kernel, "pow") == 0 && strcmp(e->tier, "u1") == 0) ||
           (fabs(ref) >= FLT_MIN && fabs(ref) <= FLT_MAX);
}

static void check_bound(const sc_batch_entry *e, long n)
{
    float *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
    float *out = malloc((size_t)n * sizeof *out);
    assert_non_null(x);
    assert_non_null(y);
    assert_non_null(out);
    for (long i = 0; i < n; i++) {
        x[i] = input(e, 0);
        y[i] = e->n_in > 1 ? input(e, 1) : 0.0f;
    }
    sc_batch_args a = {{x, y}, {out}, (size_t)n, NULL};
    e->fn(&a);
    double worst = 0.0;
    long worst_i = 0;
    for (long i = 0; i < n; i++) {
        double ref;
        e->ref(&a, (size_t)i, &ref);
        if (!counts(e, ref))
            continue;
        double r = bound_ratio(e, out[i], ref);
        if (r > worst) {
            worst = r;
            worst_i = i;
        }
    }
    if (worst > 1.0)
        fail_msg("%s %s %s: error %.3g× the stated bound at x=%a y=%a (got %a)", e->kernel,
                 e->tier, sc_isa_name(e->isa), worst, (double)x[worst_i], (double)y[worst_i],
                 (double)out[worst_i]);
    free(x);
    free(y);
    free(out);
}

/* Every bound of the table: 10^6 inputs on the best instruction set for each kernel × tier,
 * fewer on the others (which are also compared with scalar below). */
static void every_stated_bound_holds(void **state)
{
    (void)state;
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        if (!sc_isa_supported(e->isa))
            continue;
        int best = sc_batch_find(e->kernel, e->tier, sc_isa_active()) == e;
        check_bound(e, best ? BOUND_INPUTS : BOUND_INPUTS / 20);
    }
}

/* 1 if the SIMD kernel runs the scalar kernel's algorithm with the same roundings. */
static int same_bits_expected(const sc_batch_entry *e)
{
    return e->isa == SC_ISA_SSE41 && strcmp(e->kernel, "inversesqrt") != 0;
}

static int same_value(float a, float b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* Runs e and its scalar twin on n elements starting `offset` floats into the buffers, the
 * test value v placed at `lane`, random data elsewhere, and compares. */
static void compare_with_scalar(const sc_batch_entry *e, const sc_batch_entry *s, size_t n,
                                size_t offset, size_t lane, float v0, float v1)
{
    enum { CAP = 80 };
    float x[CAP], y[CAP], o1[CAP + 1], o2[CAP + 1];
    for (size_t i = 0; i < n + offset; i++) {
        x[i] = input(e, 0);
        y[i] = e->n_in > 1 ? input(e, 1) : 0.0f;
    }
    if (lane < n) {
        x[offset + lane] = v0;
        y[offset + lane] = v1;
    }
    o1[offset + n] = o2[offset + n] = 12345.0f; /* guard: nothing written past n */
    sc_batch_args a = {{x + offset, y + offset}, {o1 + offset}, n, NULL};
    sc_batch_args b = {{x + offset, y + offset}, {o2 + offset}, n, NULL};
    e->fn(&a);
    s->fn(&b);
    assert_true(o1[offset + n] == 12345.0f);
    for (size_t i = 0; i < n; i++) {
        float g = o1[offset + i], w = o2[offset + i];
        if (same_bits_expected(e) ? !same_value(g, w) : 0)
            fail_msg("%s %s %s: lane %zu of %zu: %a, scalar %a (x=%a)", e->kernel, e->tier,
                     sc_isa_name(e->isa), i, n, (double)g, (double)w, (double)x[offset + i]);
        double ref;
        e->ref(&a, i, &ref);
        int in_domain = x[offset + i] >= e->lo[0] && x[offset + i] <= e->hi[0] &&
                        (e->n_in < 2 || (y[offset + i] >= e->lo[1] && y[offset + i] <= e->hi[1]));
        if (in_domain && counts(e, ref) && bound_ratio(e, g, ref) > 1.0)
            fail_msg("%s %s %s: lane %zu out of bound (x=%a y=%a got %a)", e->kernel, e->tier,
                     sc_isa_name(e->isa), i, (double)x[offset + i], (double)y[offset + i],
                     (double)g);
    }
}

static void simd_matches_scalar(void **state)
{
    (void)state;
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        if (e->isa == SC_ISA_SCALAR || !sc_isa_supported(e->isa))
            continue;
        const sc_batch_entry *s = sc_batch_find(e->kernel, e->tier, SC_ISA_SCALAR);
        assert_non_null(s);
        for (size_t n = 0; n <= 19; n++) /* every tail length for widths 4 and 8 */
            for (size_t offset = 0; offset < 2; offset++) /* aligned and not */
                compare_with_scalar(e, s, n, offset, next() % (n + 1), input(e, 0), input(e, 1));
        for (int a = 0; a < N_SPECIALS; a++) /* specials in random lanes of 37 elements */
            for (int b = 0; b < (e->n_in > 1 ? N_SPECIALS : 1); b++)
                compare_with_scalar(e, s, 37, next() & 1, next() % 37, specials[a], specials[b]);
        for (int k = 0; k < 2000; k++)
            compare_with_scalar(e, s, 64, 0, next() % 64, input(e, 0), input(e, 1));
    }
}

/* Every kernel named in the table exists for every instruction set compiled in. */
static void table_is_complete(void **state)
{
    (void)state;
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        assert_non_null(e->fn);
        assert_non_null(e->ref);
        assert_true(e->bound_ulp > 0 || e->bound_rel > 0);
        assert_non_null(sc_batch_find(e->kernel, e->tier, SC_ISA_SCALAR));
    }
    float x[3] = {1, 2, 3}, out[3];
    sc_batch_args a = {{x}, {out}, 3, NULL};
    assert_int_equal(sc_batch_run("exp2", "u1", &a), 0);
    assert_true(out[2] == 8.0f);
    assert_int_equal(sc_batch_run("exp2", "u7", &a), -1);
}

static void isa_selection(void **state)
{
    (void)state;
    sc_isa isa;
    assert_int_equal(sc_isa_parse("avx2", &isa), 0);
    assert_int_equal(isa, SC_ISA_AVX2);
    assert_int_equal(sc_isa_parse("neon", &isa), -1);
    assert_true(sc_isa_supported(SC_ISA_SCALAR));
    sc_isa before = sc_isa_active();
    assert_int_equal(sc_isa_set(SC_ISA_SCALAR), 0);
    assert_int_equal(sc_isa_active(), SC_ISA_SCALAR);
    assert_int_equal(sc_isa_set(before), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(table_is_complete),
        cmocka_unit_test(isa_selection),
        cmocka_unit_test(simd_matches_scalar),
        cmocka_unit_test(every_stated_bound_holds),
    };
    return cmocka_run_group_tests_name("batch", tests, NULL, NULL);
}
