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
 *   sc_program_values       the number of top-level expression statements (the values a run
 *                           emits), sc_program_value_type the type of one
 *   sc_program_run_block    runs the top-level code for n elements at once (structure of
 *                           arrays: each input component a column of n doubles), one value's
 *                           components written as columns
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

/* ---- block execution ----
 *
 * sc_program_run_block runs the program for n sets of inputs and gives the value of one of its
 * top-level expression statements for each, bit for bit what sc_program_run gives for each set
 * alone (the same rounding of every operation in every precision, the same domain reports per
 * element, the same runtime errors). Inside, the elements run in blocks: every register is a
 * column of up to a few hundred elements, each instruction is dispatched once per block and
 * loops over the elements. Control flow that differs between elements (if/else, loops whose trip
 * count depends on the element, an early return) runs under an execution mask: each element has
 * its own instruction address, the elements at the lowest address run the next instruction
 * together, and elements that waited (after a branch or a loop) join again at the same address;
 * the block runs unmasked (all elements at one address) whenever it can. */

int sc_program_values(const sc_program *prog);
sc_ltype sc_program_value_type(const sc_program *prog, int value);

/* A domain error or undefined integer operation of element `element` (0..n-1). */
typedef void (*sc_lang_block_domain_fn)(void *user, long element, int line, int column,
                                        const char *func, const char *rule);

typedef struct {
    sc_prec prec;
    long n; /* elements */
    /* One column of n values per component of each input, in the order of the inputs given to
     * sc_program_compile (input 0's components, then input 1's, ...): element e's value of that
     * component is inputs[c][e], rounded or wrapped as sc_program_run rounds its inputs. */
    const double *const *inputs;
    int value;          /* which top-level expression statement, 0 .. sc_program_values() - 1 */
    double *const *out; /* one column of n per component of that value's type */
    sc_lang_block_domain_fn on_domain; /* may be NULL */
    void *user;
} sc_lang_block;

/* Runs the elements; returns n when every one ran, else the lowest index of an element that
 * stopped with a runtime error (*err filled for it; line 0 for out of memory). The outputs of
 * the elements that ran are written, also after a failing one. */
long sc_program_run_block(const sc_program *prog, const sc_lang_block *block, sc_lang_error *err);

SC_END_DECLS

#endif
