/*
 * The correct-rounding checker of make exhaustive (tests/exhaustive/).
 *
 * A subject is a binary32 function under test (a highp built-in, or a batch kernel of one tier
 * and instruction set) together with a binary64 approximation of its exact value and a proven
 * bound on that approximation's error. For each input the checker decides the correctly
 * rounded binary32 result soundly and fast:
 *   - the approximation a and its bound b: if a − b and a + b round to the same binary32, the
 *     exact value, which lies between them, rounds to it too (rounding is monotone);
 *   - otherwise (rare: the exact value is near a rounding boundary, or a is 0 or infinite) MPFR
 *     computes the correctly rounded binary32 (24 bits, binary32's exponent range, subnormals).
 * A NaN approximation stands for an input outside the function's domain: the result must be
 * NaN; a zero or infinite one is exact (special values: sin ±0, log 0) or beyond binary64's
 * range and so beyond binary32's on the same side (glibc's exp overflowing). The audit checks
 * these against MPFR too.
 * For a highp built-in the approximation is the binary64 value the built-in itself rounds
 * (sc_k_<name>_core, src/math/kernel.h) with the bound its source file states and derives; the
 * checker also requires the built-in's result to be that value rounded. For a batch kernel the
 * approximation is glibc's binary64 function with its documented error allowance.
 *
 * The audit mode sends every input to MPFR as well: it checks that the exact value lies within
 * each approximation's stated bound and that the fast decision agrees with MPFR (the smoke test
 * of make check runs it on a sample, so that a wrong bound is caught).
 */
#ifndef SHADECALC_EXHAUSTIVE_CHECKER_H
#define SHADECALC_EXHAUSTIVE_CHECKER_H

#include <mpfr.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "shadecalc/batch.h"
#include "shadecalc/precision.h"

typedef int (*exh_mpfr1_fn)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
typedef int (*exh_mpfr2_fn)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);

typedef struct exh_subject {
    const char *name; /* "exp" (highp), "exp u1 avx2" (batch) */
    int arity;        /* 1 or 2 */
    /* the function under test: a binary32 function, or a batch kernel (entry->fn) */
    float (*f1)(float);
    float (*f2)(float, float);
    const sc_batch_entry *entry;
    /* the binary64 approximation of the exact value and its bound: |approx − exact| <= bound */
    double (*approx1)(float x);
    double (*approx2)(float x, float y);
    double (*bound)(float x, float y, double approx);
    int approx_is_core; /* 1: the function's result is (float)approx, bit for bit */
    /* the exact function: correctly rounded by MPFR */
    exh_mpfr1_fn mpfr1;
    exh_mpfr2_fn mpfr2;
    /* mediump and lowp of the same built-in (pmath.h), or NULL */
    double (*in_precision)(sc_prec p, double x);
} exh_subject;

/* An input whose result is not correctly rounded, or where the checker's premises failed. */
typedef enum {
    EXH_WRONG,       /* the result is not the correctly rounded binary32 */
    EXH_NOT_CORE,    /* a highp result is not its core value rounded */
    EXH_BOUND_BROKEN /* the exact value lies outside approx ± bound (audit, or an MPFR input) */
} exh_miss_kind;

typedef struct {
    float x, y, got, want;
    double ulp; /* |got − exact| in binary32 ULPs at the exact value */
    exh_miss_kind kind;
} exh_miss;

typedef struct {
    uint64_t inputs, decided, settled; /* settled: sent to MPFR */
    uint64_t wrong, not_core, bound_broken;
    double max_ulp; /* largest error of the results not correctly rounded (0 when all are:
                       their error is at most 0.5 ULP), at (worst_x, worst_y) */
    float worst_x, worst_y;
    exh_miss *misses; /* every miss, sorted by input */
    size_t n_misses, cap_misses;
} exh_stats;

/* The inputs of a run: bit patterns first, first + stride, ... (count of them), or `count`
 * pairs drawn by a generator (deterministic: chunk k of the run seeds its own generator). */
typedef void (*exh_pair_gen)(uint64_t *rng, float *x, float *y);
typedef struct {
    uint64_t first, count, stride; /* one-argument subjects: bits first + k·stride (mod 2^32) */
    exh_pair_gen gen;              /* two-argument subjects */
    int audit;                     /* 1: every input also to MPFR (bounds and decisions) */
    int threads;
} exh_run_spec;

void exh_stats_init(exh_stats *s);
void exh_stats_free(exh_stats *s);

/* Runs subject s on the inputs of spec, on spec->threads threads; out gets the merged counts. */
int exh_run(const exh_subject *s, const exh_run_spec *spec, exh_stats *out);

/* The correctly rounded binary32 of s at (x, y) by MPFR, and the exact value in binary64 (to
 * 2^-60 relative) in *exact. */
float exh_mpfr_round32(const exh_subject *s, float x, float y, double *exact);

/* The same rounded to prec bits with the exponent range [emin, emax] of MPFR (significands in
 * [1/2, 1)) and its subnormals: binary32 is 24, -148, 128; binary16 11, -23, 16. */
float exh_mpfr_round(const exh_subject *s, float x, float y, mpfr_prec_t prec, mpfr_exp_t emin,
                     mpfr_exp_t emax);

/* If approx ± bound (with the slack of its own roundings) rounds to one binary32, writes it
 * and returns 1. */
int exh_rounds_to_one(double approx, double bound, float *out);

/* Same binary32, NaN equal to NaN, +0 not equal to −0. */
int exh_same(float a, float b);

/* Writes every miss of s as one line (input bits and value, result, correct result, ULP error,
 * kind) to path, atomically (a temporary file renamed). Returns 0, or -1 with errno set. */
int exh_write_misses(const char *path, const exh_subject *s, const exh_stats *st);

/* mediump and lowp (pmath.h) round the highp result once more: for each of the 2^16 binary16
 * inputs of a one-argument highp subject, the highp result is correctly rounded (as exh_run
 * decides it), mediump is sc_round_half of it and lowp sc_round_lowp of it; double_rounded
 * counts the inputs where that mediump result differs from the exact value rounded straight to
 * binary16 (the documented double rounding, not an error). */
typedef struct {
    long inputs, highp_wrong, mediump_mismatch, lowp_mismatch, double_rounded;
} exh_half_stats;
void exh_half_check(const exh_subject *s, exh_half_stats *out);

/* Prints one summary line of a finished run. */
void exh_print_summary(FILE *f, const exh_subject *s, const exh_stats *st, double seconds);

#endif
