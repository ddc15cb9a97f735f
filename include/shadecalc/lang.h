/*
 * shadecalc/lang.h — programs in a subset of GLSL ES 3.00 (chapters 4–8), compiled once to a
 * register bytecode and run in any precision.
 *
 *   sc_ltype, sc_lvalue     bool int uint float, their vectors, and matrices matCxR (C columns of
 *                           R rows, column-major: element (r, c) is v[c·R + r]); every
 *                           component a double (an int or uint holds its exact integer value, a
 *                           bool 0 or 1)
 *   sc_ltype_name           "ivec3", "mat2x3", "mat3" ...
 *   sc_ltype_size           number of components
 *   sc_program_compile      source -> program, or an error with its line and column
 *   sc_program_run          runs the top-level code in source order; each top-level expression
 *                           statement's value goes to a callback
 *   sc_program_free
 *
 * The language is described in the man page (EVAL FILES): declarations, `const`, blocks,
 * if/else, for/while/do with break/continue, switch, functions with in/out/inout parameters,
 * overloading and prototypes, every operator of GLSL ES 3.00 §5, one-dimensional arrays of any
 * other type and structures (§4.1.8, §4.1.9). Types are checked as GLSL ES checks them: no
 * implicit conversions (`1 + 2.0` is an error). Integers are two's complement of the
 * precision's width (32 bits in double and highp, 16 in mediump, 9 in lowp): every result wraps
 * to that width. Recursion is an error, as GLSL ES says; loops stop with an error past
 * max_iterations executed iterations.
 */
#ifndef SHADECALC_LANG_H
#define SHADECALC_LANG_H

#include "shadecalc/api.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

typedef enum { SC_KIND_FLOAT, SC_KIND_INT, SC_KIND_UINT, SC_KIND_BOOL } sc_kind;

/* A scalar has cols = rows = 1, a vector cols = 1 and rows = N, a matrix cols, rows >= 2. */
typedef struct {
    unsigned char kind, cols, rows;
} sc_ltype;

typedef struct {
    sc_ltype type;
    double v[16];
} sc_lvalue;

/* The GLSL name of t ("bvec2", "mat4x2", "mat3"), written in buf (16 bytes suffice). */
const char *sc_ltype_name(sc_ltype t, char *buf, int size);
int sc_ltype_size(sc_ltype t);

/* The integer width a precision emulates: 32 (double, highp), 16 (mediump) or 9 (lowp). */
int sc_int_bits(sc_prec p);

/* An error: 1-based line and column in the source (0 if it has none) and the message. */
typedef struct {
    int line, column;
    char message[200];
} sc_lang_error;

/* A value the caller provides (a -D definition): a read-only global named `name`. */
typedef struct {
    const char *name;
    sc_ltype type;
} sc_lang_input;

typedef struct {
    long max_iterations; /* loop iterations executed in one run before the error (<= 0: 10^7) */
    /* Desktop GLSL's implicit conversion (GLSL 1.30 §4.1.10), for code written for it: an int or
     * uint scalar or vector where a float one is expected (an operand beside a float, an
     * initializer, an assigned or returned value, a function argument) converts to float. */
    int implicit_int_to_float;
    /* Desktop GLSL's built-in redefinition (GLSL 1.10 to 4.60, unlike GLSL ES): a program may
     * define functions named as built-ins; a call whose arguments fit one of them calls it,
     * other calls of the name still call the built-in. */
    int desktop_builtins;
} sc_lang_options;

enum { SC_LANG_DEFAULT_MAX_ITERATIONS = 10000000 };

typedef struct sc_program sc_program;

/* Compiles `src` with the inputs; NULL with *err filled on a syntax or type error (or out of
 * memory: line 0). `options` may be NULL. */
sc_program *sc_program_compile(const char *src, const sc_lang_input *inputs, int n_inputs,
                               const sc_lang_options *options, sc_lang_error *err);
void sc_program_free(sc_program *prog);

/* Receives each top-level expression statement's value: its source text (not terminated,
 * `len` bytes), its line, and the value. An array or structure comes one element or member
 * (recursively) at a time, its text the expression's followed by the path: `a[0]`, `s.pos`,
 * `s.w[1]`. Returns 0 to go on, nonzero to stop the run. */
typedef int (*sc_lang_emit_fn)(void *user, const char *text, int len, int line,
                               const sc_lvalue *value);
/* Called for an argument outside a built-in's GLSL ES domain, an integer division by zero or a
 * shift count outside 0..31, at line:column of the operation. */
typedef void (*sc_lang_domain_fn)(void *user, int line, int column, const char *func,
                                  const char *rule);

/* Runs the program in precision p (float inputs rounded to p; int and uint inputs truncated
 * toward zero and wrapped to the precision's width, NaN or beyond 2^63 giving 0; bool inputs
 * true unless 0). Returns 0; -1 on a runtime error (too
 * many loop iterations, an index out of range, a function ending without `return`, out of
 * memory) with *err filled; 1 if emit asked to stop. */
int sc_program_run(const sc_program *prog, sc_prec p, const sc_lvalue *inputs, sc_lang_emit_fn emit,
                   sc_lang_domain_fn on_domain, void *user, sc_lang_error *err);

SC_END_DECLS

#endif
