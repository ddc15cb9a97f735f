/* The subjects of make exhaustive (checker.h): the highp built-ins with their cores and stated
 * binary64 bounds, the u1 batch kernels against glibc, and the biased pair generators of pow and
 * atan2. */
#ifndef SHADECALC_EXHAUSTIVE_SUBJECTS_H
#define SHADECALC_EXHAUSTIVE_SUBJECTS_H

#include "checker.h"

/* exp exp2 log log2 sin cos tan asin acos atan sqrt inversesqrt sinh cosh tanh asinh acosh atanh,
 * then pow and atan2 */
extern const exh_subject exh_highp[];
extern const int exh_highp_count;

/* Fills out with the one-input u1 batch kernels on every instruction set this CPU supports
 * (at most max) and returns how many; names[k] holds the name "exp u1 avx2" of out[k]. */
enum { EXH_NAME_MAX = 40 };
int exh_batch_subjects(exh_subject *out, char (*names)[EXH_NAME_MAX], int max);

/* The pair generator of a two-argument subject (by its name), or NULL. */
exh_pair_gen exh_pair_generator(const char *name);

#endif
