/*
 * shadecalc/accuracy.h — the stated accuracy of each highp built-in, and its measurement.
 *
 *   sc_accuracy_table, sc_accuracy_count   one row per function: its binary32 kernel, the double
 *                                          reference, the stated domain and bound in ULP
 *   sc_accuracy_sample                     a binary32 input with magnitude-biased exponent
 *   sc_accuracy_random                     its random bits
 *   sc_accuracy_measure                    max and mean ULP error over the special values
 *                                          crossed over all arguments, then random inputs
 *
 * One table drives the unit test (tests/unit/test_math_accuracy.c), `make accuracy` and the
 * README's accuracy table, so the three never disagree. Errors are in ULPs of binary32 at the
 * double result (shadecalc/precision.h sc_ulp_error); a result the reference puts beyond the
 * binary32 range counts as exact when the kernel returns that infinity.
 */
#ifndef SHADECALC_ACCURACY_H
#define SHADECALC_ACCURACY_H

#include <stdint.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef struct {
    const char *name;
    int arity;
    float (*f1)(float);
    float (*f2)(float, float);
    double (*ref1)(double);
    double (*ref2)(double, double);
    double lo[2], hi[2]; /* the domain of each argument for random inputs */
    int normal_result;   /* 1: only inputs whose reference result is a normal float count */
    const char *domain;  /* the domain, as the README states it */
    double bound_ulp;    /* the stated bound */
} sc_accuracy_row;

extern const sc_accuracy_row sc_accuracy_table[];
extern const int sc_accuracy_count;

typedef struct {
    long inputs; /* inputs measured inside the domain */
    double max_ulp;
    double mean_ulp;
    float worst[2];          /* the arguments of the largest error */
    long special_mismatches; /* special values whose result is not the reference's (NaN = NaN) */
} sc_accuracy_stats;

/* Uniform exponent and mantissa, random sign allowed when lo < 0, within [lo, hi]. */
float sc_accuracy_sample(uint64_t *state, double lo, double hi);
/* The generator behind it (xorshift64*): the next 64 random bits of *state. */
uint64_t sc_accuracy_random(uint64_t *state);

/* Measures row r on the special-value table (all combinations) and n_random random inputs:
 * half magnitude-biased, a quarter uniform in value over the domain, a quarter in [0.5, 2]
 * (where the logarithms and powers round hardest). Deterministic for a given seed. */
void sc_accuracy_measure(const sc_accuracy_row *r, long n_random, uint64_t seed,
                         sc_accuracy_stats *out);

SC_END_DECLS

#endif
