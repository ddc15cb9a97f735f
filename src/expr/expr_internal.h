/* The compiled form of a shadecalc expression (shadecalc/expr.h), shared by the parser, the
 * built-in table and the evaluator. A program is a tree of typed nodes in one array; a node's
 * children are kids[first .. first + count). */
#ifndef SHADECALC_EXPR_INTERNAL_H
#define SHADECALC_EXPR_INTERNAL_H

#include "shadecalc/expr.h"

typedef enum {
    NODE_NUMBER,  /* num */
    NODE_INPUT,   /* op = input index */
    NODE_SLOT,    /* op = statement slot index */
    NODE_NEGATE,  /* one child */
    NODE_BINARY,  /* op = '+' '-' '*' '/'; two children */
    NODE_CALL,    /* op = built-in index; children are the arguments */
    NODE_CONSTRUCT, /* type = the constructed type; children are the arguments */
    NODE_SWIZZLE, /* one child; count2 components in swz */
    NODE_INDEX    /* one child; op = the literal index */
} node_kind;

typedef struct {
    node_kind kind;
    sc_type type;
    int column;
    int op;
    int first, count;
    double num;
    unsigned char swz[4];
    int swz_len;
} expr_node;

typedef struct {
    int slot; /* the value goes to slots[slot] */
    int root;
} expr_statement;

struct sc_expr {
    expr_node *nodes;
    int n_nodes, cap_nodes;
    int *kids;
    int n_kids, cap_kids;
    expr_statement *stmts;
    int n_stmts, cap_stmts;
    int root;
    int n_inputs;
};

/* Largest number of statements (and so of slots) in one program. */
#define SC_EXPR_MAX_STATEMENTS 64

/* ---- evaluation (eval.c), shared with the dual-number evaluator (dual.c) ---- */

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

/* ---- constructors (construct.c) ---- */

/* Type check of `type(args...)`: 0, or -1 with a message in msg. */
int sc_construct_check(sc_type type, const sc_type *args, int n_args, char *msg, int msg_size);
sc_value sc_construct(sc_type type, const sc_value *args, int n_args);

#endif
