/* What the commands share about BRDFs written in GLSL (shadecalc/brdf_file.h): the parameter
 * list of --explain, and the report of a shader's run-time error. */
#ifndef SHADECALC_CLI_BRDF_FILE_H
#define SHADECALC_CLI_BRDF_FILE_H

#include <stdio.h>

#include "shadecalc/brdf_file.h"
#include "shadecalc/shade.h"

/* The file and each parameter with its value, type and range, as text lines or as the members
 * "brdf_file" and "parameters" of a JSON object (after a comma); nothing unless m is a file's
 * BRDF. */
void brdf_file_explain(FILE *out, const sc_model *m, sc_prec p, int json);

/* The run-time error of m's shader ("FILE:LINE:COLUMN: message"), or NULL. */
const char *brdf_file_failure(const sc_model *m);

/* After a command computed with m: SC_EXIT_RUNTIME after printing the error if the file's
 * shader failed at run time (its loop bound), else SC_EXIT_OK. */
int brdf_file_status(const sc_model *m, const char *cmd);

#endif
