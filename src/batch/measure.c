/* Accuracy of a batch kernel's outputs against its double reference (shadecalc/batch.h):
 * the figures of `shadecalc bench` and the check of tests/unit/test_batch.c. */
#include <math.h>
#include <string.h>

#include "shadecalc/batch.h"
#include "shadecalc/precision.h"

/* The pow u1 domain rule of the scalar built-ins: only normal-float results are stated. (The
 * names are compared only off the normal range: the tests measure ~10^9 outputs.) */
static int stated(const sc_batch_entry *e, double ref)
{
    if (fabs(ref) >= 0x1p-126 && fabs(ref) <= 0x1.fffffep127)
        return 1;
    return strcmp(e->kernel, "pow") != 0 || strcmp(e->tier, "u1") != 0;
}

/* fmax for a that is never NaN, without its library call */
static double larger(double a, double b) { return b > a ? b : a; }

/* got against ref as a fraction of e's bound: ULPs (ulp, already measured), or relative error
 * with the absolute allowance times the reference's scale. Both NaN, or the same overflow: 0.
 * A scale of +Inf marks an element outside the stated domain (a discontinuity): 0. */
static double bound_ratio(const sc_batch_entry *e, float got, double ref, double ulp, double scale)
{
    if (isnan(ref) && isnan(got))
        return 0.0;
    if ((isinf((float)ref) && got == (float)ref) || isinf(scale))
        return 0.0;
    if (e->bound_ulp > 0)
        return ulp / e->bound_ulp;
    double err = fabs((double)got - ref);
    if (err == 0.0)
        return 0.0;
    return err / (e->bound_rel * fabs(ref) + e->bound_abs * scale);
}

void sc_batch_error_init(sc_batch_error *acc) { memset(acc, 0, sizeof *acc); }

double sc_batch_error_element(const sc_batch_entry *e, const sc_batch_args *a, size_t i,
                              sc_batch_error *acc)
{
    double ref[4];
    e->ref(a, i, ref);
    return sc_batch_error_against(e, a, i, ref, acc);
}

double sc_batch_error_against(const sc_batch_entry *e, const sc_batch_args *a, size_t i,
                              const double *ref, sc_batch_error *acc)
{
    double worst = 0.0;
    for (int j = 0; j < e->n_out; j++) {
        if (!stated(e, ref[j]))
            continue;
        float got = a->out[j][i];
        double ulp = sc_ulp_error(SC_HIGHP, (double)got, ref[j]);
        double ratio = bound_ratio(e, got, ref[j], ulp, ref[e->n_out]);
        double abs_err = fabs((double)got - ref[j]);
        worst = larger(worst, ratio);
        if (isfinite(ulp)) {
            acc->max_ulp = larger(acc->max_ulp, ulp);
            acc->sum_ulp += ulp;
            acc->count++;
        }
        if (isfinite(abs_err) && ref[j] != 0.0)
            acc->max_rel = larger(acc->max_rel, abs_err / fabs(ref[j]));
        if (isfinite(abs_err))
            acc->max_abs = larger(acc->max_abs, abs_err);
    }
    if (worst > acc->max_ratio) {
        acc->max_ratio = worst;
        acc->worst = i;
    }
    return worst;
}

void sc_batch_error_of(const sc_batch_entry *e, const sc_batch_args *a, sc_batch_error *acc)
{
    for (size_t i = 0; i < a->n; i++)
        sc_batch_error_element(e, a, i, acc);
}
