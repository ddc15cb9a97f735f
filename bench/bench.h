/* The benchmark harness behind `shadecalc bench` (src/cli/cmd_bench.c): cases, timing,
 * accuracy, the machine's measured bounds, the report. */
#ifndef SHADECALC_BENCH_H
#define SHADECALC_BENCH_H

#include <stddef.h>
#include <stdio.h>

#include "shadecalc/batch.h"

/* ---- the plain loops a user would write with libm (bench/libm_loops.c) ---- */

/* The loop for a kernel, with the project's ordinary flags; NULL if none. */
sc_batch_fn bench_libm_loop(const char *kernel);
/* The same loops compiled with -O3 -march=native -ffast-math by gcc and by clang
 * (bench/fastmath_*.c); NULL if none, or if that compiler was not installed at build time. */
sc_batch_fn bench_fast_gcc_loop(const char *kernel);
sc_batch_fn bench_fast_clang_loop(const char *kernel);
/* The same built with -O3 -mavx2 -mfma -ffast-math (rows "gcc-fast-avx2", "clang-fast-avx2"). */
sc_batch_fn bench_fast_gcc_avx2_loop(const char *kernel);
sc_batch_fn bench_fast_clang_avx2_loop(const char *kernel);

/* ---- SLEEF's AVX2 functions (bench/sleef_avx2.c; optional, built when SLEEF is found) ---- */

typedef struct {
    const char *kernel, *tier; /* "pow", "u10" */
    sc_batch_fn fn;
} bench_sleef;

/* 1 if the binary has SLEEF and the CPU runs its AVX2 functions. */
int bench_sleef_available(void);
/* Why there are no SLEEF rows ("" when there are), and SLEEF's version ("" without it). */
const char *bench_sleef_absence(void);
const char *bench_sleef_version(void);
/* The SLEEF loops for a kernel: *out points at the first of the returned count. */
int bench_sleef_loops(const char *kernel, const bench_sleef **out);

/* ---- the machine (bench/machine.c) ---- */

typedef struct {
    char cpu[128];
    char date[32];      /* UTC, ISO 8601, when the run started */
    double load[3];     /* load averages over 1, 5, 15 minutes at the start; -1 if unknown */
    double bandwidth;   /* bytes per ns, measured: read + written by a stream loop */
    double lane_ops_ns; /* peak float lane operations per ns at 8 lanes (an FMA counts one):
                         * AVX2 FMA chains, or scalar chains times 8 without AVX2 */
} bench_machine;

void bench_machine_measure(bench_machine *m);
int bench_isa_width(sc_isa isa);
/* AVX2 FMA lane operations per ns (bench/peak_avx2.c); 0 without AVX2. */
double bench_peak_avx2(void);
/* One pass of a stream loop over n floats of k input arrays, arrays[0..k), and m output arrays
 * after them, 32-byte aligned: AVX2 loads, the inputs' sum stored with non-temporal stores, as
 * the batch kernels move their data at streaming sizes. Its ns; only where
 * bench_stream_avx2_supported (1 if the CPU has AVX2). */
int bench_stream_avx2_supported(void);
double bench_stream_pass_avx2(float *const *arrays, int k, int m, size_t n);

/* ---- cases: kernel × isa × tier (× scene for shade) × size ---- */

typedef struct bench_row {
    const char *kernel, *isa, *tier; /* isa "libm", "gcc-fast", "clang-fast" and tier "loop" for
                                        the plain loops */
    const char *scene;               /* "lambert 1d", …; "" for non-shading kernels */
    size_t n;
    double ns_per_elem, ns_min, ns_max; /* the median of the repeats, their minimum, maximum */
    double ns_mad; /* median absolute deviation of the repeats from the median */
    double cv;     /* robust coefficient of variation: 1.4826 MAD / median */
    int noisy;     /* cv > BENCH_NOISY_CV or max > 2 × median: rerun with more repeats */
    double speedup_vs_scalar, speedup_vs_libm;
    sc_batch_error err;
    size_t not_rounded; /* normal results that differ from the reference rounded to float */
    const sc_batch_entry *entry; /* the table row measured (its bounds); NULL: a peer row */
    double roofline_ns;          /* max(compute bound, memory bound) per element */
    double roofline_fraction;    /* roofline_ns / ns_per_elem */
    int pareto;                  /* not beaten in both error and speed among the kernel's rows */
    const struct bench_row *dominated_by; /* a tier's first peer row (libm, gcc-fast,
                                            clang-fast, SLEEF) no slower and no less accurate,
                                            built for the tier's instruction set or below */
    sc_isa peer_isa; /* a peer row: the instruction set it is built for (libm: scalar) */
} bench_row;

typedef struct {
    const char *kernels[32];
    int n_kernels; /* 0: all */
    int isa_mask;  /* bit per sc_isa; 0: all supported */
    const char *tiers[16];
    int n_tiers; /* 0: all */
    size_t sizes[4];
    int n_sizes;
    int repeat;
    int warmup; /* untimed calls before the repeats (at least 1: it calibrates their length) */
} bench_options;

#define BENCH_NOISY_CV 0.05

/* Runs every selected case; *rows is malloc'ed. Returns 0, or -1 out of memory. */
int bench_run(const bench_options *o, const bench_machine *m, bench_row **rows, int *n_rows);

/* ---- report (bench/report.c) ---- */
enum { BENCH_TABLE, BENCH_CSV, BENCH_JSON, BENCH_MARKDOWN };
void bench_report(FILE *out, int format, const bench_machine *m, const bench_row *rows, int n);
/* The table's kernels (those named; all when n_kernels is 0) as text, CSV or JSON */
void bench_list(FILE *out, int format, const char *const *kernels, int n_kernels);
/* A row's name in the reports: "isa tier" ("avx2 u1", "sleef-avx2 u10"), the isa alone for the
 * plain loops ("libm") */
const char *bench_row_name(const bench_row *r, char *buf, size_t size);
/* The Pareto plot of `bench --plot` as SVG; 0, or -1 if out of memory or writing failed. */
int bench_plot_write(FILE *out, const bench_row *rows, int n);
/* s as the body of a JSON string: quotes, backslashes and control characters escaped */
void bench_json_text(FILE *out, const char *s);
/* Whether name is in list (an empty list selects everything). */
int bench_selected(const char *name, const char *const *list, int n);

/* ---- --compare (bench/compare.c) ---- */

typedef struct {
    const char *kernel, *scene, *isa, *tier; /* the key, with n; pointing into the document */
    size_t n;
    double ns, mad; /* ns_per_elem (the median) and ns_mad; NaN where the report has null */
} bench_cmp_row;

typedef struct {
    struct sc_json *doc;
    bench_cmp_row *rows;
    int n;
} bench_report_file;

/* Reads a JSON report of `bench -o FILE.json`. SC_EXIT_OK; SC_EXIT_RUNTIME if the file cannot
 * be read; SC_EXIT_USAGE if it is not such a report (the error, with the file and the line and
 * column or the row, printed). */
int bench_report_read(const char *path, bench_report_file *rep);
void bench_report_free(bench_report_file *rep);
/* The rows of a and b matched by kernel, scene, isa, tier and n: the ratio B/A of the median
 * ns per element and its significance, then the rows only in one report; table, CSV or JSON
 * (Markdown prints the table). 0, or -1 out of memory. */
int bench_compare(FILE *out, int format, const char *path_a, const bench_report_file *a,
                  const char *path_b, const bench_report_file *b);

#endif
