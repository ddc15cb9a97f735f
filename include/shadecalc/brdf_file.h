/*
 * shadecalc/brdf_file.h — BRDFs written in GLSL: the `.brdf` files of Disney's BRDF Explorer
 * (the man page's BRDF FILES).
 *
 *   sc_brdf_file_parse      text -> parameters and compiled shader, or an error naming the line
 *   sc_brdf_file_load       the same from a path, once per process: later loads of the path
 *                           share the first one's compiled program
 *   sc_brdf_file_free       (not for a loaded file, which lives until the process ends)
 *   sc_brdf_file_params     the parameters, in file order
 *   sc_brdf_file_defaults   their default values, as sc_brdf.file_values
 *   sc_brdf_file_set        NAME=VALUE from a spec: checked against its type and range
 *   sc_brdf_file_eval       BRDF(L, V, N, X, Y) at one point (sc_brdf_eval calls it)
 *   sc_brdf_file_eval_many  the same at many points, in blocks (sc_brdf_eval_many calls it)
 *   sc_brdf_file_error      the first run-time error of a file's shader (loop bound)
 *   sc_brdf_export          a built-in model written as a .brdf file of the same math
 *
 * A file is: the first line `analytic`; blank lines and lines whose first non-blank character
 * is `#` anywhere (comments, as BRDF Explorer drops them; `//` also starts a comment line in
 * the parameters); `::begin parameters` ... `::end parameters` with one parameter a line,
 *     float NAME MIN MAX DEFAULT     bool NAME 0|1     color NAME R G B
 * and `::begin shader` ... `::end shader` with GLSL defining
 *     vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
 * (L toward the light, V toward the viewer, N the normal, X and Y the tangent frame). The
 * parameters are read-only globals of types float, bool and vec3. The shader is compiled in the
 * desktop-GLSL dialect of shadecalc/lang.h (implicit int to float, user functions named as
 * built-ins).
 */
#ifndef SHADECALC_BRDF_FILE_H
#define SHADECALC_BRDF_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "shadecalc/api.h"
#include "shadecalc/brdf.h"

SC_BEGIN_DECLS

typedef enum { SC_BRDF_PARAM_FLOAT, SC_BRDF_PARAM_BOOL, SC_BRDF_PARAM_COLOR } sc_brdf_param_type;

typedef struct {
    char name[64];
    sc_brdf_param_type type;
    double min, max; /* float: the file's range (BRDF Explorer's slider) */
    double def[3];   /* the default (bool: 0 or 1; float: def[0]) */
    int line;        /* where the file declares it */
    int offset;      /* its first value in sc_brdf.file_values */
} sc_brdf_param;

/* Loop iterations one evaluation may execute before the error (a runaway loop). */
enum { SC_BRDF_FILE_MAX_ITERATIONS = 100000 };

/* Parses and compiles `text` (named `name` in messages); NULL with "NAME:LINE: what is wrong"
 * (NAME:LINE:COLUMN for the GLSL) in err. */
sc_brdf_file *sc_brdf_file_parse(const char *text, const char *name, char *err, size_t size);
/* Reads the file at path (at most 1 MiB) and parses it; a path loaded before gives the same
 * file. Thread-safe. NULL with the error in err. */
const sc_brdf_file *sc_brdf_file_load(const char *path, char *err, size_t size);
void sc_brdf_file_free(sc_brdf_file *f);

const char *sc_brdf_file_name(const sc_brdf_file *f);
int sc_brdf_file_params(const sc_brdf_file *f, const sc_brdf_param **out);

/* b becomes the file's BRDF with every parameter at its default. */
void sc_brdf_file_defaults(const sc_brdf_file *f, sc_brdf *b);
/* Sets parameter `name` of b's file from text: a number in MIN..MAX (float), 0|1|true|false
 * (bool), one number or R,G,B (color). -1 with the error (and a "did you mean" for an unknown
 * name) in err. */
int sc_brdf_file_set(sc_brdf *b, const char *name, const char *value, char *err, size_t size);

/* f = BRDF(L, V, N, X, Y) in precision p, with X, Y the frame's t and b. On a run-time error f
 * is NaN and the error is kept (sc_brdf_file_error); once it is, every evaluation gives NaN. */
void sc_brdf_file_eval(sc_prec p, const sc_brdf *b, const sc_frame *frame, const double l[3],
                       const double v[3], double f[3]);
/* f[i] = BRDF(pts[i].l, pts[i].v, ...) for i < n, the same values as n calls of
 * sc_brdf_file_eval (bit for bit), computed by the block execution of shadecalc/lang.h: the
 * shader's dispatch is paid once per block of points. Returns n, or the index of the first point
 * whose evaluation failed (0 if the shader had failed before): that point and the later ones
 * are NaN, and the error is kept as sc_brdf_file_eval keeps it. */
int sc_brdf_file_eval_many(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                           double (*f)[3]);
/* The first run-time error ("NAME:LINE:COLUMN: message") or NULL. */
const char *sc_brdf_file_error(const sc_brdf_file *f);

/* Writes b (a built-in model) as a .brdf file whose shader computes the same f in the same
 * order of operations; its parameters are b's, with these values as defaults. 0, or -1 on a
 * write error. */
int sc_brdf_export(FILE *out, const sc_brdf *b);

SC_END_DECLS

#endif
