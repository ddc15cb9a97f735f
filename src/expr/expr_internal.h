/* The compiled form of a shadecalc expression (shadecalc/expr.h), shared by the parser, the
 * built-in table and the evaluators. A program is a flat register program: its typed nodes in
 * post-order (each node after its children, children left to right, statements first), so
 * one loop over the array evaluates it without recursion, however deep the tree. Every node
 * reads its `count` operands from values[base .. base + count) and writes its result to
 * values[base]; statement s leaves its value in values[s] (read by NODE_SLOT s), and the final
 * expression's in values[n_stmts]. The parser assigns the bases as a stack would. */
#ifndef SHADECALC_EXPR_INTERNAL_H
#define SHADECALC_EXPR_INTERNAL_H

#include <stddef.h>

#include "shadecalc/expr.h"

typedef enum {
    NODE_NUMBER,    /* num */
    NODE_INPUT,     /* op = input index */
    NODE_SLOT,      /* op = statement index (its value is values[op]) */
    NODE_NEGATE,    /* one child */
    NODE_BINARY,    /* op = '+' '-' '*' '/'; two children */
    NODE_CALL,      /* op = built-in index; children are the arguments */
    NODE_CONSTRUCT, /* type = the constructed type; children are the arguments */
    NODE_SWIZZLE,   /* one child; count2 components in swz */
    NODE_INDEX      /* one child; op = the literal index */
} node_kind;

typedef struct {
    node_kind kind;
    sc_type type;
    int column;
    int op;
    int base, count; /* operands in values[base .. base + count), result in values[base] */
    double num;
    signed char tie; /* NODE_NUMBER: the side of num its decimal lies on (sc_literal) */
    unsigned char swz[4];
    int swz_len;
} expr_node;

struct sc_expr {
    expr_node *nodes; /* in evaluation order */
    int n_nodes, cap_nodes;
    int n_stmts;
    int n_values; /* size of the values array an evaluation needs */
    int root;     /* the last node; its value is values[n_stmts] */
    int n_inputs;
};

/* Largest number of statements (and so of slots) in one program. */
#define SC_EXPR_MAX_STATEMENTS 64

/* ---- parsing helpers (parse.c), shared with the language of src/lang/ ---- */

/* Grows *buf (of *cap elements of elem bytes) to hold need; 0, or -1 if out of memory. */
int sc_expr_grow(void **buf, int *cap, int need, size_t elem);
/* Component index of swizzle letter c in its set (xyzw, rgba, stpq), the set in *set; or -1. */
int sc_swizzle_component(char c, int *set);

/* ---- evaluation (eval.c), shared with the dual-number evaluator (dual.c) ---- */

/* The values array of one evaluation of e with elements of `size` bytes: `local` (of
 * local_size bytes) if large enough, else allocated (NULL if out of memory). */
void *sc_expr_values(const sc_expr *e, size_t size, void *local, size_t local_size);
/* A value of type t with every component NaN (the result when out of memory). */
sc_value sc_expr_nan(sc_type t);

/* `a op b` (op '+' '-' '*' '/') with GLSL's rules, the result of type `type`, in precision p. */
sc_value sc_expr_binary(sc_prec p, int op, sc_type type, const sc_value *a, const sc_value *b);
/* The components a swizzle or index node `n` selects from `base`. */
sc_value sc_expr_select(const expr_node *n, const sc_value *base);

/* ---- built-ins (builtins.c) ---- */

/* What an evaluator needs to report a domain error. */
typedef struct {
    sc_prec p;
    int column;
    const char *name;
    sc_expr_domain_fn on_domain;
    void *user;
} call_context;

/* Looks up the built-in `name` for the argument types; returns its index, or -1 with a message
 * in msg (size msg_size) saying what is wrong ("pow: expects 2 arguments, got 1"). */
int sc_builtin_resolve(const char *name, int name_len, const sc_type *args, int n_args,
                       sc_type *result, char *msg, int msg_size);
/* 1 if `name` is a built-in function's name (so not usable as a variable). */
int sc_builtin_exists(const char *name, int name_len);
sc_value sc_builtin_eval(int index, const call_context *ctx, const sc_value *args, int n_args);
const char *sc_builtin_name(int index);

/* The scalar form of a component-wise built-in (sin, pow, clamp ...: component k of the result
 * from component k of each argument, a float argument broadcast): exactly one of f1 f2 f3 set,
 * and its GLSL ES domain (NULL if it has none: else the rule the arguments a[] break, or NULL).
 * Returns 0, or -1 for the other built-ins (dot, normalize, inverse ...). */
typedef struct {
    double (*f1)(sc_prec, double);
    double (*f2)(sc_prec, double, double);
    double (*f3)(sc_prec, double, double, double);
    const char *(*domain)(const double *a);
} sc_builtin_scalar;
int sc_builtin_componentwise(int index, sc_builtin_scalar *out);

/* ---- constructors (construct.c) ---- */

/* Type check of `type(args...)`: 0, or -1 with a message in msg. */
int sc_construct_check(sc_type type, const sc_type *args, int n_args, char *msg, int msg_size);
sc_value sc_construct(sc_type type, const sc_value *args, int n_args);

#endif
