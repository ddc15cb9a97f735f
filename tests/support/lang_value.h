/* Test helpers around the language's runs (shadecalc/lang.h), shared by the unit tests and the
 * fuzz harnesses: one value of a program, and the comparison of two results bit for bit. */
#ifndef SHADECALC_TESTS_LANG_VALUE_H
#define SHADECALC_TESTS_LANG_VALUE_H

#include "shadecalc/lang.h"

/* Which of the values a run prints to keep, and where its components go. */
typedef struct {
    int value;   /* its index among the values printed (sc_program_values) */
    int seen;    /* values printed so far: 0 before the run */
    double *out; /* its components, up to 16 */
} lang_value_pick;

/* The emit callback of sc_program_run that keeps the picked value; user is a lang_value_pick,
 * or a structure whose first member is one. */
int lang_value_keep(void *user, const char *text, int len, int line, const sc_lvalue *v);

/* a and b the same double to the bit, or both NaN */
int lang_same_bits(double a, double b);

#endif
