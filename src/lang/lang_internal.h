/* The compiled form of a shadecalc program (shadecalc/lang.h), shared by the compiler and the
 * interpreter.
 *
 * A program is a register bytecode: one flat array of doubles (the registers) holds every
 * variable, parameter, temporary and constant, each at an offset fixed at compile time, and the
 * instructions name those offsets. GLSL forbids recursion, so each function's registers are
 * allocated statically, once (no frames): a call copies the arguments into the callee's
 * parameter registers, jumps, and RET jumps back to the address the call pushed. The interpreter
 * is one loop over the instructions, without recursion. */
#ifndef SHADECALC_LANG_INTERNAL_H
#define SHADECALC_LANG_INTERNAL_H

#include "expr/expr_internal.h"
#include "shadecalc/lang.h"

typedef enum {
    OP_MOV, /* dst[0..n) = a[0..n) */
    OP_CVT, /* dst[0..n) = a[0..n) converted from kind2 to kind */
    OP_ADD, /* component-wise dst = a op b in kind; flags: BCAST_A, BCAST_B */
    OP_SUB,
    OP_MUL,
    OP_DIV,
    OP_MOD,
    OP_BITAND,
    OP_BITOR,
    OP_BITXOR,
    OP_SHL,
    OP_SHR,
    OP_NEG,    /* dst = -a, n components */
    OP_BITNOT, /* dst = ~a */
    OP_NOT,    /* dst = !a (bool) */
    OP_LT,     /* scalar comparisons in kind: dst = a op b (bool) */
    OP_LE,
    OP_EQ, /* dst = (a[0..n) == b[0..n)) one bool */
    OP_NE,
    OP_MATMUL, /* dst = a (rows x inner) * b (inner x cols): rows, inner, cols in aux[c..c+3) */
    OP_JMP,    /* pc = c */
    OP_JZ,     /* if a[0] == 0: pc = c */
    OP_JNZ,
    OP_LOOP, /* counts an iteration: error past the bound */
    OP_CALL, /* push pc, pc = c */
    OP_RET,
    OP_NORETURN, /* a value-returning function ended without `return`: error */
    OP_BUILTIN,  /* calls[c]: a built-in's result to dst */
    OP_LOAD,     /* dst[0..n) = a[i·n ..] with i = int b[0], error unless 0 <= i < c */
    OP_STORE,    /* dst[i·n ..] = a[0..n) with i = int b[0], error unless 0 <= i < c */
    OP_EMIT,     /* emits[c]: report a[..] */
    OP_HALT
} opcode;

enum { BCAST_A = 1, BCAST_B = 2 };

typedef struct {
    unsigned char op, kind, kind2, flags;
    int n;
    int dst, a, b, c;
    int line, column;
} insn;

/* A built-in call: evaluated through expr/builtins.c (float built-ins) or lang_builtins.c. */
typedef struct {
    int index; /* in expr/builtins.c (float) or lang_builtins.c (is_lang) */
    int is_lang;
    int n_args;
    int args[4]; /* argument registers */
    sc_ltype types[4];
    sc_ltype result;
} builtin_call;

typedef struct {
    int start, len; /* the expression's text in the source */
    sc_ltype type;
} emit_site;

/* A constant: its register and value (a float is rounded to the precision, an integer wrapped
 * to its width, when a run starts; a float literal's decimal is rounded once, with its tie). */
typedef struct {
    int reg;
    sc_kind kind;
    double value;
    signed char tie; /* a float literal's sc_literal tie; 0 for other constants */
} constant;

struct sc_program {
    char *src;
    insn *code;
    int n_code, cap_code;
    builtin_call *calls;
    int n_calls, cap_calls;
    emit_site *emits;
    int n_emits, cap_emits;
    constant *consts;
    int n_consts, cap_consts;
    int *aux; /* OP_MATMUL dimensions */
    int n_aux, cap_aux;
    int n_regs;
    int max_call_depth;
    int n_inputs;
    int input_regs[64];
    sc_ltype input_types[64];
    long max_iterations;
};

/* ---- types (lang_types.c) ---- */

sc_ltype sc_lt(sc_kind kind, int cols, int rows);
int sc_lt_equal(sc_ltype a, sc_ltype b);
int sc_lt_is_scalar(sc_ltype t);
int sc_lt_is_vector(sc_ltype t); /* 2..4 rows, one column */
int sc_lt_is_matrix(sc_ltype t);
int sc_lt_is_integer(sc_ltype t); /* int or uint kind */
/* The expr.h type of a float scalar, vector or square matrix; -1 for others. */
int sc_lt_to_expr(sc_ltype t, sc_type *out);
sc_ltype sc_lt_from_expr(sc_type t);
/* Parses a type name ("float", "ivec3", "mat2x3", "void" gives kind 255); 0 or -1. */
int sc_lt_parse(const char *s, int len, sc_ltype *out);

/* The value of an integer of `kind` (int or uint) wrapped to `bits` bits: the int result is
 * in [-2^(bits-1), 2^(bits-1)), the uint in [0, 2^bits). x is truncated toward zero first;
 * NaN and |x| >= 2^63 give 0. */
double sc_int_wrap(sc_kind kind, int bits, double x);
/* The same for the two's complement bits u (modulo 2^64). */
double sc_int_wrap_bits(sc_kind kind, int bits, unsigned long long u);
/* x (of kind `from`) converted to `to` (GLSL ES §5.4.1): float to int truncates toward zero,
 * saturating out of range, NaN to 0; int <-> uint keeps the bit pattern; bool is x != 0. */
double sc_convert(sc_kind to, sc_kind from, double x, sc_prec p);

/* ---- int, uint and bool built-ins (lang_builtins.c) ---- */

/* The built-in `name` for the argument types: its index and result type; -1 if none matches
 * (msg then says why, if the name is one of these built-ins); -2 if the name is not one. */
int sc_lang_builtin_resolve(const char *name, int len, const sc_ltype *args, int n_args,
                            sc_ltype *result, char *msg, int msg_size);
int sc_lang_builtin_exists(const char *name, int len);
/* Evaluates built-in `index` into out (of type result). */
void sc_lang_builtin_eval(int index, sc_prec p, const double *const *args, const sc_ltype *types,
                          int n_args, sc_ltype result, double *out);
/* Names for the did-you-mean of an unknown function. */
const char *sc_lang_builtin_name(int index);
int sc_lang_builtin_count(void);

#endif
