/* shadecalc eval --file: a program of the language of shadecalc/lang.h, its top-level
 * expressions printed as `eval` prints expressions. */
#ifndef SHADECALC_CLI_EVAL_FILE_H
#define SHADECALC_CLI_EVAL_FILE_H

#include <stdio.h>

#include "shadecalc/expr.h"
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
int sc_eval_file(const char *path, const sc_expr_input *defines, const sc_value *values,
                 int n_defines, const eval_file_options *o);

/* Shared with cmd_eval.c: a component in precision p (the shortest decimal, or its bits with
 * hex; NaN, Inf and bits quoted in JSON) and an RFC 4180 CSV field (a JSON string:
 * sc_print_json_string, cli/cli.h). */
void sc_print_float(FILE *out, double x, sc_prec p, int hex, int json);
void sc_print_csv_field(FILE *out, const char *s);

#endif
