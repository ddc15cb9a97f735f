/* shadecalc eval --file: a program of the language of shadecalc/lang.h, its top-level
 * expressions printed as `eval` prints expressions. */
#ifndef SHADECALC_CLI_EVAL_FILE_H
#define SHADECALC_CLI_EVAL_FILE_H

#include <stdio.h>

#include "shadecalc/lang.h"

enum { FMT_GLSL, FMT_CSV, FMT_JSON };

typedef struct {
    sc_prec prec;
    int format;
    int hex, strict;
    long max_iterations;
} eval_file_options;

/* Runs the program in file `path` ("-": standard input) with the -D definitions (names, types
 * and values in the precision); returns the command's exit status. */
int sc_eval_file(const char *path, const sc_lang_input *defines, const sc_lvalue *values,
                 int n_defines, const eval_file_options *o);

/* Shared with cmd_eval.c: a component in precision p (the shortest decimal, or its bits with
 * hex; NaN, Inf and bits quoted in JSON) and an RFC 4180 CSV field (a JSON string:
 * sc_print_json_string, cli/cli.h). */
void sc_print_float(FILE *out, double x, sc_prec p, int hex, int json);
/* A component of a value of kind `kind`: a float as sc_print_float prints it, an int or uint as
 * an integer (hex: its two's complement bits of the precision's width), a bool true or false. */
void sc_print_component(FILE *out, double x, sc_kind kind, sc_prec p, int hex, int json);
/* The csv column of component k of a value of type t: value | x y z w | c0r0 c0r1 ...
 * (column-major). */
void sc_value_column_name(char *buf, size_t size, sc_ltype t, int k);
void sc_print_csv_field(FILE *out, const char *s);
/* A domain error or undefined operation at `at` ("F:LINE:COLUMN", "column C"): an error with
 * --strict, else a warning. */
void sc_report_domain_hit(const char *at, const char *func, const char *rule, int strict);

enum { DOMAIN_MAX_HITS = 8 };

/* The domain errors of a run, each (line, column, rule) once, the first DOMAIN_MAX_HITS. */
typedef struct {
    struct {
        int line, column;
        const char *func, *rule;
    } hit[DOMAIN_MAX_HITS];
    int n;
} domain_hits;

/* Adds a domain error to h unless it holds it already (or is full). */
void domain_hits_record(domain_hits *h, int line, int column, const char *func, const char *rule);

#endif
