/* The checker of make exhaustive (tests/exhaustive/checker.h) on samples: the highp built-ins
 * and the u1 batch kernels are checked with every input also sent to MPFR (the audit: each
 * stated binary64 bound holds), and the checker itself is shown to catch a function rounded
 * wrongly, a bound stated too tight, and a mediump result that is not highp rounded once more. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include <cmocka.h>

#include "math/kernel.h"
#include "shadecalc/glsl.h"
#include "tests/exhaustive/subjects.h"

/* About 4300 inputs spread over all 2^32 bit patterns (a prime stride). */
static const exh_run_spec sample = {0, (1ULL << 32) / 1000003 + 1, 1000003, NULL, 1, 2};

static const exh_subject *highp(const char *name)
{
    for (int i = 0; i < exh_highp_count; i++)
        if (strcmp(exh_highp[i].name, name) == 0)
            return &exh_highp[i];
    fail_msg("no subject %s", name);
    return NULL;
}

static void run(const exh_subject *s, const exh_run_spec *spec, exh_stats *st)
{
    assert_int_equal(exh_run(s, spec, st), 0);
    assert_true(st->inputs == spec->count);
}

static void every_highp_function_rounds_correctly_on_a_sample(void **state)
{
    (void)state;
    exh_run_spec pairs = {0, 20000, 1, NULL, 1, 2};
    for (int i = 0; i < exh_highp_count; i++) {
        const exh_subject *s = &exh_highp[i];
        exh_stats st;
        pairs.gen = exh_pair_generator(s->name);
        run(s, s->arity == 1 ? &sample : &pairs, &st);
        if (st.wrong || st.not_core || st.bound_broken)
            fail_msg("%s: %llu not correctly rounded, %llu not the core, %llu outside the bound",
                     s->name, (unsigned long long)st.wrong, (unsigned long long)st.not_core,
                     (unsigned long long)st.bound_broken);
        assert_true(st.max_ulp <= 0.5);
        exh_stats_free(&st);
    }
}

static void every_u1_batch_kernel_keeps_its_bound_on_a_sample(void **state)
{
    (void)state;
    exh_subject subjects[64];
    char names[64][EXH_NAME_MAX];
    int n = exh_batch_subjects(subjects, names, 64);
    assert_true(n >= 9);
    for (int i = 0; i < n; i++) {
        exh_stats st;
        run(&subjects[i], &sample, &st);
        if (st.bound_broken || st.max_ulp > subjects[i].entry->bound_ulp)
            fail_msg("%s: %llu outside glibc's allowance, max %.6f ULP", subjects[i].name,
                     (unsigned long long)st.bound_broken, st.max_ulp);
        exh_stats_free(&st);
    }
}

/* exp, one ULP up on every input whose bits are a multiple of 3 */
static int nudged_input(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u % 3 == 0;
}
static float nudged_exp(float x)
{
    float r = sc_expf(x);
    return nudged_input(x) ? nextafterf(r, INFINITY) : r;
}

static void a_wrongly_rounded_function_is_caught(void **state)
{
    (void)state;
    exh_subject s = *highp("exp");
    s.f1 = nudged_exp;
    s.approx_is_core = 0;
    exh_run_spec spec = sample;
    spec.audit = 0;
    uint64_t expected = 0; /* the nudged inputs whose result moved (not NaN, not +Inf) */
    for (uint64_t k = 0; k < spec.count; k++) {
        uint32_t u = (uint32_t)(k * spec.stride);
        float x;
        memcpy(&x, &u, sizeof x);
        expected += nudged_input(x) && !exh_same(nudged_exp(x), sc_expf(x));
    }
    exh_stats st;
    run(&s, &spec, &st);
    assert_true(expected > 1000);
    assert_true(st.wrong == expected && st.n_misses == expected);
    /* one binary32 step up: < 1.5 ULP, < 2.5 ULP of the binade below just under a power of 2 */
    assert_true(st.max_ulp > 0.5 && st.max_ulp < 2.5);
    exh_stats_free(&st);

    s.approx_is_core = 1; /* and as a highp function: its result is not its core rounded */
    run(&s, &spec, &st);
    assert_true(st.not_core == expected);
    exh_stats_free(&st);
}

/* exp through a core 2^-30 off: wrong only near rounding boundaries, where MPFR decides */
static double sloppy_exp_core(float x) { return sc_k_exp_core(x) * (1.0 + 0x1p-30); }
static float sloppy_exp(float x) { return (float)sloppy_exp_core(x); }
static double bound_29(float x, float y, double a)
{
    (void)x, (void)y;
    return 0x1p-29 * fabs(a);
}

static void a_bound_stated_too_tight_is_caught(void **state)
{
    (void)state;
    exh_subject s = *highp("exp");
    s.f1 = sloppy_exp;
    s.approx1 = sloppy_exp_core;
    exh_run_spec spec = {0x3f800000, 1 << 20, 1, NULL, 1, 2}; /* [1, 1.125) */
    exh_stats st;
    run(&s, &spec, &st); /* claims exp's 2^-47 */
    assert_true(st.bound_broken > 0);
    exh_stats_free(&st);

    s.bound = bound_29; /* the true bound: every wrong result is found by MPFR */
    spec.audit = 0;
    run(&s, &spec, &st);
    uint64_t expected = 0;
    for (uint32_t k = 0; k < spec.count; k++) {
        uint32_t u = (uint32_t)spec.first + k;
        float x;
        memcpy(&x, &u, sizeof x);
        expected += sloppy_exp(x) != sc_expf(x); /* sc_expf: correctly rounded (above) */
    }
    assert_true(expected > 0);
    assert_true(st.bound_broken == 0 && st.wrong == expected && st.settled >= expected);
    exh_stats_free(&st);
}

static void mediump_and_lowp_round_highp_once_more(void **state)
{
    (void)state;
    for (int i = 0; i < exh_highp_count; i++) {
        const exh_subject *s = &exh_highp[i];
        if (s->arity != 1)
            continue;
        exh_half_stats h;
        exh_half_check(s, &h);
        print_message("%-12s double-rounded in mediump: %ld of %ld\n", s->name, h.double_rounded,
                      h.inputs);
        if (h.highp_wrong || h.mediump_mismatch || h.lowp_mismatch)
            fail_msg("%s: %ld highp not correctly rounded, %ld mediump and %ld lowp not highp "
                     "rounded",
                     s->name, h.highp_wrong, h.mediump_mismatch, h.lowp_mismatch);
    }
}

/* mediump rounded from binary64 directly: it differs where the double rounding matters */
static double exp_rounded_from_double(sc_prec p, double x) { return sc_round(p, exp(x)); }

static void a_mediump_not_from_highp_is_caught(void **state)
{
    (void)state;
    exh_subject s = *highp("exp");
    s.in_precision = exp_rounded_from_double;
    exh_half_stats h;
    exh_half_check(&s, &h);
    assert_true(h.mediump_mismatch > 0 && h.mediump_mismatch <= h.double_rounded);
}

/* x^y exactly halfway between two binary32 (25 significant bits) rounds to even: the exact
 * product in binary64 rounded once is the reference. */
static void pow_rounds_exact_midpoints(void **state)
{
    (void)state;
    for (double m = 2049; m < 8192; m += 2) /* m² has 23 to 26 bits */
        assert_true(sc_powf((float)m, 2.0f) == (float)(m * m));
    for (double m = 257; m < 323; m += 2) { /* m³ and (m²)^(3/2) */
        assert_true(sc_powf((float)m, 3.0f) == (float)(m * m * m));
        assert_true(sc_powf((float)(m * m), 1.5f) == (float)(m * m * m));
    }
    assert_true(sc_powf(3 * 0x1p-75f, 2.0f) == 4 * 0x1p-149f); /* 9·2^-150 in the subnormals */
    assert_true(sc_powf(-4097.0f, 3.0f) == (float)(-4097.0 * 4097.0 * 4097.0));
}

/* The inputs of exp, exp2, log, sin, cos, acos, atan, asinh and acosh that make exhaustive
 * found rounded the wrong way (their tables of hard cases): MPFR's correctly rounded binary32 is the
 * reference. */
static void check_hard_case(const char *name, uint32_t bits, double bound)
{
    const exh_subject *s = highp(name);
    float x, want;
    double exact;
    memcpy(&x, &bits, sizeof x);
    want = exh_mpfr_round32(s, x, 0.0f, &exact);
    assert_true(s->f1(x) == want);
    assert_true(fabs(s->approx1(x) - exact) <= bound * fabs(exact));
}

static void hard_cases_round_correctly(void **state)
{
    (void)state;
    check_hard_case("exp", 0xc2b2e798, 0x1p-47 + 0x1p-51 * 89.46); /* x = -89.4523315 */
    check_hard_case("exp2", 0x3b429d37, 0x1p-47);
    check_hard_case("exp2", 0xbcf3a937, 0x1p-47);
    check_hard_case("log", 0x4c5d65a5, 0x1p-48);
    check_hard_case("log", 0x65d890d3, 0x1p-48);
    check_hard_case("log", 0x6f31a8ec, 0x1p-48);
    check_hard_case("sin", 0x46199998, 0x1p-47 + 0x1p-99 / 0.34); /* x = 9830.39844 */
    check_hard_case("sin", 0xc6199998, 0x1p-47 + 0x1p-99 / 0.34);
    check_hard_case("cos", 0x5f18b878, 0x1p-47 + 0x1p-99); /* x = 1.10046776e19 */
    check_hard_case("cos", 0xdf18b878, 0x1p-47 + 0x1p-99);
    check_hard_case("cos", 0x6115cb11, 0x1p-47 + 0x1p-99); /* x = 1.72699834e20 */
    check_hard_case("cos", 0xe115cb11, 0x1p-47 + 0x1p-99);
    check_hard_case("acos", 0x328885a3, 0x1p-46); /* x = 1.58932547e-8 */
    check_hard_case("acos", 0x39826222, 0x1p-46); /* x = 0.000248686469 */
    check_hard_case("atan", 0x3d8d6b23, 0x1p-47);
    check_hard_case("atan", 0xbd8d6b23, 0x1p-47);
    check_hard_case("asinh", 0x4bdd65a5, 0x1p-47);
    check_hard_case("asinh", 0xcbdd65a5, 0x1p-47);
    check_hard_case("asinh", 0x655890d3, 0x1p-47);
    check_hard_case("asinh", 0x6eb1a8ec, 0x1p-47);
    check_hard_case("acosh", 0x655890d3, 0x1p-47);
    check_hard_case("acosh", 0x6eb1a8ec, 0x1p-47);
}

/* The pairs of pow and atan2 that make exhaustive found rounded the wrong way in 10^9 biased pairs (its
 * table of hard cases), against MPFR; the core stays within its stated bound. */
static void check_hard_pair(const char *name, uint32_t xbits, uint32_t ybits)
{
    const exh_subject *s = highp(name);
    float x, y;
    double exact;
    memcpy(&x, &xbits, sizeof x);
    memcpy(&y, &ybits, sizeof y);
    float want = exh_mpfr_round32(s, x, y, &exact);
    assert_true(s->f2(x, y) == want);
    double approx = s->approx2(x, y);
    assert_true(fabs(approx - exact) <= s->bound(x, y, approx));
}

static void hard_pairs_round_correctly(void **state)
{
    (void)state;
    static const uint32_t pairs[][2] = {
        {0x1a0a1b50, 0x3fd4b2b2}, {0x3f7ffffd, 0x43008060}, {0x3f800002, 0x4d89596d},
        {0x3f800029, 0xcb662369}, {0x3f80098c, 0x48664977}, {0xbea63a2a, 0xc21c0000},
        {0xbfeb0088, 0x42dc0000}, {0xc531235c, 0xc0e00000},
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        check_hard_pair("pow", pairs[i][0], pairs[i][1]);
    check_hard_pair("atan2", 0xa6f82f9c, 0xaf24ffc0); /* atan2(-1.72213614e-15, -1.50065738e-10) */
}

/* The sin and acos u1 batch kernels of every instruction set round their cores' hard cases as
 * MPFR does, in every lane: each input sits at each position of a run of 67 ordinary inputs. */
static void check_batch_hard_cases(const exh_subject *s, const sc_k_hard_case *table, int n)
{
    enum { RUN = 67 };
    for (int t = 0; t < n; t++)
        for (int at = 0; at < RUN; at++) {
            float in[RUN], out[RUN], x, want;
            double exact;
            for (int i = 0; i < RUN; i++)
                in[i] = 0.25f + 0.01f * (float)i;
            memcpy(&x, &table[t].bits, sizeof x);
            in[at] = x;
            sc_batch_args a = {{in}, {out}, RUN, s->entry->params};
            s->entry->fn(&a);
            want = exh_mpfr_round32(s, x, 0.0f, &exact);
            if (!exh_same(out[at], want))
                fail_msg("%s(%a) = %a in lane %d, correctly rounded %a", s->name, (double)x,
                         (double)out[at], at, (double)want);
        }
}

static void batch_kernels_round_the_hard_cases(void **state)
{
    (void)state;
    exh_subject subjects[64];
    char names[64][EXH_NAME_MAX];
    int n = exh_batch_subjects(subjects, names, 64), checked = 0;
    for (int i = 0; i < n; i++) {
        const char *kernel = subjects[i].entry->kernel;
        if (strcmp(kernel, "sin") == 0)
            check_batch_hard_cases(&subjects[i], sc_k_sin_hard_cases,
                                   SC_K_TABLE_LEN(sc_k_sin_hard_cases));
        else if (strcmp(kernel, "acos") == 0)
            check_batch_hard_cases(&subjects[i], sc_k_acos_hard_cases,
                                   SC_K_TABLE_LEN(sc_k_acos_hard_cases));
        else
            continue;
        checked++;
    }
    assert_true(checked >= 2);
}

/* The hyperbolic functions at their extremes and around every switch point of their methods
 * (sinh.c, asinh.c) and of binary32 (overflow of sinh and cosh, saturation of tanh): each result
 * is MPFR's correctly rounded binary32 (±0 and NaN included). */
static void hyperbolic_extremes_round_correctly(void **state)
{
    (void)state;
    static const char *const names[] = {"sinh", "cosh", "tanh", "asinh", "acosh", "atanh"};
    static const float points[] = {
        0.0f,  0x1p-149f, 0x1.fffffcp-127f, 0x1p-126f, 0x1p-12f, 0.17f,   0.35f,   1.0f,
        1.06f, 9.011f,    89.4159f,         694.0f,    1e10f,    FLT_MAX, INFINITY};
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++) {
        const exh_subject *s = highp(names[n]);
        for (size_t i = 0; i < sizeof points / sizeof points[0]; i++)
            for (int sign = -1; sign <= 1; sign += 2) {
                float x = (float)sign * points[i];
                for (int k = 0; k < 64; k++, x = nextafterf(x, (float)sign * INFINITY)) {
                    double exact;
                    float want = exh_mpfr_round32(s, x, 0.0f, &exact), got = s->f1(x);
                    if (!exh_same(got, want))
                        fail_msg("%s(%a) = %a, correctly rounded %a", s->name, (double)x,
                                 (double)got, (double)want);
                }
            }
        assert_true(exh_same(s->f1(NAN), NAN));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_highp_function_rounds_correctly_on_a_sample),
        cmocka_unit_test(every_u1_batch_kernel_keeps_its_bound_on_a_sample),
        cmocka_unit_test(a_wrongly_rounded_function_is_caught),
        cmocka_unit_test(a_bound_stated_too_tight_is_caught),
        cmocka_unit_test(mediump_and_lowp_round_highp_once_more),
        cmocka_unit_test(a_mediump_not_from_highp_is_caught),
        cmocka_unit_test(pow_rounds_exact_midpoints),
        cmocka_unit_test(hard_pairs_round_correctly),
        cmocka_unit_test(hard_cases_round_correctly),
        cmocka_unit_test(batch_kernels_round_the_hard_cases),
        cmocka_unit_test(hyperbolic_extremes_round_correctly),
    };
    return cmocka_run_group_tests_name("exhaustive checker", tests, NULL, NULL);
}
