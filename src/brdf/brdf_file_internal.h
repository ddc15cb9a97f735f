/* A compiled .brdf file (shadecalc/brdf_file.h), shared by the format's parser (brdf_file.c)
 * and the compiler, evaluator and cache (brdf_file_run.c). */
#ifndef SHADECALC_BRDF_FILE_INTERNAL_H
#define SHADECALC_BRDF_FILE_INTERNAL_H

#include <pthread.h>
#include <stdatomic.h>

#include "shadecalc/brdf_file.h"
#include "shadecalc/lang.h"

/* What runs change: the first run-time error, kept for the caller to report. */
typedef struct {
    atomic_int failed;
    pthread_mutex_t lock;
    char message[256];
} brdf_file_status;

struct sc_brdf_file {
    char *name;
    sc_brdf_param params[SC_BRDF_FILE_MAX_PARAMS];
    int n_params, n_values;
    sc_program *prog;
    brdf_file_status *status;
};

/* The parts of a file's text: its parameters (into f) and its GLSL, with every line outside
 * the shader section blanked so that the GLSL's line numbers are the file's; *shader_line is
 * the line of `::begin shader`. 0, or -1 with "NAME:LINE: what is wrong" in err. */
int sc_brdf_file_split(const char *text, sc_brdf_file *f, char **glsl, int *shader_line, char *err,
                       size_t size);

/* Compiles the GLSL into f->prog; 0 or -1 with the error in err. */
int sc_brdf_file_compile(sc_brdf_file *f, const char *glsl, int shader_line, char *err,
                         size_t size);

#endif
