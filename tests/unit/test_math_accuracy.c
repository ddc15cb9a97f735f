/* Every stated bound of the highp built-ins (shadecalc/accuracy.h) on more than 10^6 inputs per
 * function against the double-precision libm reference, and the special values. Under the
 * sanitizers the count is a sample (tests/unit/scale.h): the sanitized run checks memory and
 * undefined behaviour, the plain run the bounds; SHADECALC_ACCURACY_INPUTS=N sets it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <fenv.h>
#include <math.h>
#include <stdlib.h>

#include <cmocka.h>

#include "shadecalc/accuracy.h"
#include "shadecalc/glsl.h"
#include "tests/unit/scale.h"

static long input_count(void)
{
    const char *env = getenv("SHADECALC_ACCURACY_INPUTS");
    long n = env ? atol(env) : 0;
    return n > 0 ? n : (long)sc_test_inputs(1100000);
}

static void every_stated_bound_holds(void **state)
{
    (void)state;
    long n = input_count();
    for (int i = 0; i < sc_accuracy_count; i++) {
        const sc_accuracy_row *r = &sc_accuracy_table[i];
        sc_accuracy_stats s;
        sc_accuracy_measure(r, n, 42 + (uint64_t)i, &s);
        printf("%-12s %-30s bound %.1f  max %.4f  mean %.4f  inputs %ld\n", r->name, r->domain,
               r->bound_ulp, s.max_ulp, s.mean_ulp, s.inputs);
        if (s.max_ulp > r->bound_ulp)
            fail_msg("%s: %.4f ULP at (%a, %a) breaks the stated bound %.1f", r->name, s.max_ulp,
                     (double)s.worst[0], (double)s.worst[1], r->bound_ulp);
        if (s.special_mismatches)
            fail_msg("%s: %ld special values differ from the reference", r->name,
                     s.special_mismatches);
        assert_true(s.inputs >= n);
    }
}

/* The measurement itself can fail: a kernel off by 2 ULP must be caught. */
static float sloppy_exp(float x) { return nextafterf(nextafterf(sc_expf(x), INFINITY), INFINITY); }

static void a_broken_kernel_is_caught(void **state)
{
    (void)state;
    sc_accuracy_row r = sc_accuracy_table[0];
    r.f1 = sloppy_exp;
    sc_accuracy_stats s;
    sc_accuracy_measure(&r, 10000, 1, &s);
    assert_true(s.max_ulp > 1.4);
}

static void special_values(void **state)
{
    (void)state;
    assert_true(sc_powf(-8.0f, 1.0f / 3.0f) != sc_powf(-8.0f, 1.0f / 3.0f)); /* NaN */
    assert_true(sc_powf(-2.0f, 3.0f) == -8.0f);
    assert_true(sc_powf(NAN, 0.0f) == 1.0f && sc_powf(1.0f, NAN) == 1.0f);
    assert_true(sc_powf(0.0f, -1.0f) == INFINITY && sc_powf(-0.0f, -1.0f) == -INFINITY);
    assert_true(sc_powf(-1.0f, INFINITY) == 1.0f);
    assert_true(sc_expf(-INFINITY) == 0.0f && sc_expf(INFINITY) == INFINITY);
    assert_true(sc_exp2f(128.0f) == INFINITY && sc_exp2f(-149.0f) == 0x1p-149f);
    assert_true(sc_logf(0.0f) == -INFINITY && sc_logf(-0.0f) == -INFINITY);
    assert_true(sc_logf(-1.0f) != sc_logf(-1.0f));
    assert_true(sc_log2f(0x1p-149f) == -149.0f);
    assert_true(sc_sinf(-0.0f) == 0.0f && signbit(sc_sinf(-0.0f)));
    assert_true(sc_sinf(INFINITY) != sc_sinf(INFINITY));
    assert_true(sc_atan2f(0.0f, -0.0f) == (float)3.14159265358979323846);
    assert_true(sc_atan2f(-0.0f, 0.0f) == 0.0f && signbit(sc_atan2f(-0.0f, 0.0f)));
    assert_true(sc_atan2f(INFINITY, -INFINITY) == (float)(3 * 3.14159265358979323846 / 4));
    assert_true(sc_asinf(1.5f) != sc_asinf(1.5f) &&
                sc_acosf(-1.0f) == (float)3.14159265358979323846);
    assert_true(sc_inversesqrtf(0.0f) == INFINITY && sc_inversesqrtf(-0.0f) == -INFINITY);
    assert_true(sc_inversesqrtf(INFINITY) == 0.0f &&
                sc_inversesqrtf(-1.0f) != sc_inversesqrtf(-1.0f));
    assert_true(sc_sqrtf(-0.0f) == 0.0f && signbit(sc_sqrtf(-0.0f)));
}

/* sinh, tanh, asinh, atanh of a tiny x are x exactly (x³ is far below half an ULP of x): the
 * result is exact, so no underflow is signalled, even for subnormal x (IEEE 754 signals
 * underflow for a tiny inexact result only). */
static void tiny_hyperbolic_arguments_are_exact_without_underflow(void **state)
{
    (void)state;
    static const float tiny[] = {0x1p-149f, 0x1.fffffcp-127f, 0x1p-126f, 1e-30f, 0x1p-13f};
    float (*const odd[])(float) = {sc_sinhf, sc_tanhf, sc_asinhf, sc_atanhf};
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; i++)
        for (size_t f = 0; f < sizeof odd / sizeof odd[0]; f++)
            for (int sign = -1; sign <= 1; sign += 2) {
                float x = (float)sign * tiny[i];
                feclearexcept(FE_ALL_EXCEPT);
                float y = odd[f](x);
                int underflow = fetestexcept(FE_UNDERFLOW);
                if (y != x || underflow)
                    fail_msg("function %zu at %a: %a, underflow %d", f, (double)x, (double)y,
                             underflow != 0);
            }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_stated_bound_holds),
        cmocka_unit_test(a_broken_kernel_is_caught),
        cmocka_unit_test(special_values),
        cmocka_unit_test(tiny_hyperbolic_arguments_are_exact_without_underflow),
    };
    return cmocka_run_group_tests_name("math accuracy", tests, NULL, NULL);
}
