/* Deterministic random inputs for the tests: splitmix64 (Steele, Lea and Flood 2014). */
#ifndef SHADECALC_TESTS_SPLITMIX_H
#define SHADECALC_TESTS_SPLITMIX_H

#include <stdint.h>

/* The next 64 random bits of the sequence in *state (any seed) */
uint64_t splitmix_next(uint64_t *state);

/* Uniform in [lo, hi), 53 random bits */
double splitmix_uniform(uint64_t *state, double lo, double hi);

#endif
