/*
 * shadecalc/sweep.h — parameter sweeps (`shadecalc sweep`, issue 5): a grid of variables,
 * `$name` substitution into spec strings, rows formatted as CSV/TSV/JSON lines, and an ordered
 * multi-threaded runner that streams any number of rows in constant memory.
 *
 *   sc_sweep_var              one variable: a linear or geometric range, or a list of values
 *   sc_sweep_var_parse        "NAME=START:STOP:COUNT" (inclusive) | "NAME=V1,V2,..."
 *   sc_sweep_var_set_log      geometric spacing for a range
 *   sc_sweep_var_value        the i-th value
 *   sc_sweep_var_free
 *   sc_sweep_grid             the cartesian product of the variables, the first varying fastest
 *   sc_sweep_grid_add         a parsed variable (names are unique)
 *   sc_sweep_grid_find        a variable's index by name, -1 if absent
 *   sc_sweep_grid_rows        the number of rows (0 if above SC_SWEEP_MAX_ROWS)
 *   sc_sweep_grid_point       row index -> the value of every variable
 *   sc_sweep_grid_free
 *   sc_sweep_substitute       `$NAME` and `${NAME}` in a text -> the variable's value
 *   sc_sweep_format_parse     "csv|tsv|jsonl" -> sc_sweep_format
 *   sc_sweep_table            the columns of the output: variables then results
 *   sc_sweep_write_header     the header line (csv, tsv; jsonl has none)
 *   sc_sweep_format_row       one row as text
 *   sc_sweep_row_max          an upper bound of the length of a formatted row
 *   sc_sweep_run              evaluates every row on N threads, output in row order
 *   sc_sweep_describe_var     "name=start:stop:count", "... log" or "name=v1,v2,..."
 *   sc_sweep_image_init       an image of a two-variable sweep (width = first, height = second)
 *   sc_sweep_image_store      one row's results into its pixel
 *   sc_sweep_image_write      the image as EXR, with the command line and both ranges
 *
 * Values of the variables are doubles; they print (and substitute) as the shortest decimal that
 * reads back to the same double, and the result columns as the shortest decimal that reads back
 * to the same value of the table's precision (sc_format_shortest).
 */
#ifndef SHADECALC_SWEEP_H
#define SHADECALC_SWEEP_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "shadecalc/api.h"
#include "shadecalc/image.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

enum { SC_SWEEP_NAME_MAX = 32, SC_SWEEP_MAX_VARS = 8 };
#define SC_SWEEP_MAX_ROWS 4503599627370496.0 /* 2^52 */

typedef enum { SC_SPACING_LINEAR, SC_SPACING_LOG, SC_SPACING_LIST } sc_spacing;

typedef struct {
    char name[SC_SWEEP_NAME_MAX]; /* an identifier: [A-Za-z_][A-Za-z0-9_]* */
    sc_spacing spacing;
    double start, stop; /* ranges: the first and last values (inclusive) */
    long count;         /* number of values, >= 1 */
    double *list;       /* SC_SPACING_LIST: the count values (owned) */
} sc_sweep_var;

/* Parses "NAME=START:STOP:COUNT" or "NAME=V1,V2,..." (a single value is a list of one).
 * Returns 0, or -1 with a message naming the argument in err. */
int sc_sweep_var_parse(const char *arg, sc_sweep_var *out, char *err, size_t errsize);
/* Makes a range geometric: START·(STOP/START)^(i/(COUNT−1)). -1 with err for a list, or for
 * ends that are zero or of opposite signs. */
int sc_sweep_var_set_log(sc_sweep_var *v, char *err, size_t errsize);
/* The i-th value (0 <= i < count); a range ends exactly on START and STOP. */
double sc_sweep_var_value(const sc_sweep_var *v, long i);
void sc_sweep_var_free(sc_sweep_var *v);

typedef struct {
    sc_sweep_var var[SC_SWEEP_MAX_VARS];
    int n;
} sc_sweep_grid;

/* Takes ownership of *v (also on failure: it is freed). -1 with err on a duplicate name or too
 * many variables. */
int sc_sweep_grid_add(sc_sweep_grid *g, sc_sweep_var *v, char *err, size_t errsize);
int sc_sweep_grid_find(const sc_sweep_grid *g, const char *name);
/* The product of the counts (1 for no variables); 0 if it exceeds SC_SWEEP_MAX_ROWS. */
uint64_t sc_sweep_grid_rows(const sc_sweep_grid *g);
/* values[k] = the value of variable k at `row`; variable 0 varies fastest. */
void sc_sweep_grid_point(const sc_sweep_grid *g, uint64_t row, double *values);
void sc_sweep_grid_free(sc_sweep_grid *g);

/* Copies text to out, replacing each $NAME (the longest identifier after the $) and ${NAME} by
 * the value of that variable in `values` (shortest round-trip decimal). Returns 0, or -1 with
 * err: an unknown variable, a $ not followed by a name, or out too small. */
int sc_sweep_substitute(const char *text, const sc_sweep_grid *g, const double *values, char *out,
                        size_t size, char *err, size_t errsize);

typedef enum { SC_SWEEP_CSV, SC_SWEEP_TSV, SC_SWEEP_JSONL } sc_sweep_format;

/* 0, or -1 for a name that is not csv, tsv or jsonl. */
int sc_sweep_format_parse(const char *name, sc_sweep_format *out);

typedef struct {
    sc_sweep_format format;
    sc_prec prec;             /* of the result columns */
    const char *const *names; /* n_vars + n_results column names */
    int n_vars, n_results;
} sc_sweep_table;

/* Writes the header line (csv, tsv; nothing for jsonl). 0, or -1 on a write error. */
int sc_sweep_write_header(FILE *out, const sc_sweep_table *t);
/* Formats one row, newline included (jsonl: {"name": value, ...}, NaN and infinities as the
 * strings "nan", "inf", "-inf"). Returns its length, or -1 if it does not fit in size. */
int sc_sweep_format_row(char *buf, size_t size, const sc_sweep_table *t, const double *vars,
                        const double *results);
size_t sc_sweep_row_max(const sc_sweep_table *t);

/* A sweep to run. eval is called concurrently from `threads` workers (worker = 0..threads−1,
 * for per-worker state); consume, the text output and progress are called from the calling
 * thread, in row order. */
typedef struct {
    const sc_sweep_grid *grid;
    int n_results;
    /* results[0..n_results) of one row; 0, or with a message in err -1 (it failed at run
     * time) or SC_SWEEP_ROW_INVALID (the row's input is invalid: a spec its values make so) */
    int (*eval)(void *user, int worker, const double *vars, double *results, char *err,
                size_t errsize);
    void *user;
    /* optional: sees every row; 0, or -1 or SC_SWEEP_ROW_INVALID with err to stop (as eval) */
    int (*consume)(void *user, uint64_t row, const double *vars, const double *results, char *err,
                   size_t errsize);
    const sc_sweep_table *table; /* optional: rows written to out as text */
    FILE *out;
    /* optional: rows done so far, after each block */
    void (*progress)(void *user, uint64_t done, uint64_t total);
    int threads; /* >= 1 */
    /* optional, used instead of eval (which may then be NULL): `count` rows at once, their variables in vars (row after
     * row, grid->n each) and their results in results (n_results each); returns count, or the
     * index in the block of the first row that failed, with a message in err and that row's
     * code as eval returns it (-1 or SC_SWEEP_ROW_INVALID) in *failure (the rows before it are
     * written) */
    int (*eval_block)(void *user, int worker, int count, const double *vars, double *results,
                      int *failure, char *err, size_t errsize);
} sc_sweep_job;

/* What eval or consume returns for a row whose input is invalid (not a run-time failure). */
enum { SC_SWEEP_ROW_INVALID = -2 };

typedef enum {
    SC_SWEEP_OK = 0,
    SC_SWEEP_FAILED = -1,      /* eval or consume failed: err holds "row N: message" */
    SC_SWEEP_WRITE_ERROR = -2, /* writing to out failed: errno is the reason */
    SC_SWEEP_NO_MEMORY = -3,
    SC_SWEEP_INVALID = -4 /* eval or consume returned SC_SWEEP_ROW_INVALID: err as FAILED */
} sc_sweep_status;

/* Evaluates every row of the grid; rows before a failing one are still written and consumed.
 * The header is the caller's (sc_sweep_write_header). The output does not depend on threads. */
sc_sweep_status sc_sweep_run(const sc_sweep_job *job, char *err, size_t errsize);

/* ---- images (src/sweep/image.c) ---- */

/* Writes a description of v into buf (lists shortened to about 200 characters). */
void sc_sweep_describe_var(const sc_sweep_var *v, char *buf, size_t size);

/* Allocates img (shadecalc/image.h) for a grid of exactly two variables: width = the first's
 * count, height = the second's, the second variable growing upward (its first value on the
 * bottom row, as a plot's y axis and BRDF Explorer's θ_h × θ_d slice with θ_d = 0 at the
 * bottom); channels
 * Y for one result, R,G for two, R,G,B for three, R,G,B,A for four. 0; -1 with err when the
 * grid does not fit an image (not two variables, more than SC_EXR_MAX_VALUES values); -2 with
 * err when the allocation failed (out of memory). */
int sc_sweep_image_init(sc_image *img, const sc_sweep_grid *g, int n_results, char *err,
                        size_t errsize);
/* Stores the results of `row` (any order) in their pixel, rounded to float. */
void sc_sweep_image_store(sc_image *img, uint64_t row, const double *results);
/* Writes img as EXR (ZIP, channels as `type`) with the string attributes shadecalc:command,
 * shadecalc:x_range and shadecalc:y_range (sc_sweep_describe_var of the two variables),
 * atomically. 0, or -1 with err "PATH: reason". */
int sc_sweep_image_write(const char *path, const sc_image *img, sc_pixel_type type,
                         const sc_sweep_grid *g, const char *command, char *err, size_t errsize);

SC_END_DECLS

#endif
