/* The operations on one element that the interpreter of one element (lang_run.c) and the
 * interpreter of blocks (lang_block.c) share, so that both compute every value the same way. */
#ifndef SHADECALC_LANG_VM_H
#define SHADECALC_LANG_VM_H

#include "lang/lang_internal.h"

/* The opcode families (contiguous in the opcode enum): a op b component-wise, op a, and the
 * comparisons giving one bool. */
static inline int vm_is_binary(int op) { return op >= OP_ADD && op <= OP_SHR; }
static inline int vm_is_unary(int op) { return op >= OP_NEG && op <= OP_NOT; }
static inline int vm_is_compare(int op) { return op >= OP_LT && op <= OP_NE; }

/* Where domain errors and undefined integer operations of an element go (fn may be NULL). */
typedef struct {
    sc_lang_domain_fn fn;
    void *user;
} vm_report;

/* A constant or input in precision p: a float rounded, an integer wrapped to `bits`, a bool
 * 0 or 1. */
double vm_in_precision(sc_prec p, int bits, sc_kind kind, double x);
/* The same for a constant of the program (a float literal rounded once from its decimal). */
double vm_constant_in_precision(sc_prec p, int bits, const constant *c);
/* `x op y` of an integer instruction (OP_ADD ... OP_SHR of kind int or uint). */
double vm_integer_binary(const insn *in, int bits, double x, double y, const vm_report *r);
/* OP_NEG, OP_BITNOT or OP_NOT of one component. */
double vm_unary(const insn *in, int bits, double a);
/* OP_MATMUL: out (rows x cols) = a (rows x inner) * b (inner x cols), dims = rows, inner, cols;
 * out may not overlap a or b. */
void vm_matmul(sc_prec p, const int *dims, const double *a, const double *b, double *out);
/* OP_BUILTIN: the call's result into dst from its arguments args[i] (each contiguous). */
void vm_builtin(sc_prec p, const builtin_call *call, const insn *in, const double *const *args,
                double *dst, const vm_report *r);

/* Runtime errors, worded alike by both interpreters: *err filled at in's line and column, -1.
 * vm_index checks the index i of OP_LOAD or OP_STORE (0 with the component offset if valid). */
int vm_index(const insn *in, double i, long long *offset, sc_lang_error *err);
int vm_too_many_iterations(const insn *in, long bound, sc_lang_error *err);
int vm_too_deep(const insn *in, int depth, sc_lang_error *err);
int vm_no_return(const insn *in, sc_lang_error *err);

#endif
