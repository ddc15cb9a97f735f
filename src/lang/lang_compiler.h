/* The compiler's shared state (shadecalc/lang.h): lexer (lang_lex.c), expressions
 * (lang_expr.c), statements, functions and the program (lang_stmt.c). One pass: the parser
 * checks types and emits the bytecode of lang_internal.h as it reads. */
#ifndef SHADECALC_LANG_COMPILER_H
#define SHADECALC_LANG_COMPILER_H

#include "lang/lang_internal.h"

/* MAX_DEPTH bounds the recursion of the parser (nested parentheses, calls, unary operators,
 * conditionals, assignments and blocks), so that no input overflows the C stack. */
enum { MAX_DEPTH = 256, MAX_NAME = 64, MAX_PARAMS = 8, MAX_CALL_ARGS = 16, MAX_REGS = 1 << 22 };

typedef enum { T_END, T_INT, T_UINT, T_FLOAT, T_IDENT, T_PUNCT, T_BAD } tkind;

/* Multi-character operators (single characters are their own code). */
enum {
    P_SHL = 256,
    P_SHR,
    P_LE,
    P_GE,
    P_EQ,
    P_NE,
    P_AND,
    P_OR,
    P_XOR,
    P_INC,
    P_DEC,
    P_ADD_ASSIGN,
    P_SUB_ASSIGN,
    P_MUL_ASSIGN,
    P_DIV_ASSIGN,
    P_MOD_ASSIGN,
    P_SHL_ASSIGN,
    P_SHR_ASSIGN,
    P_AND_ASSIGN,
    P_OR_ASSIGN,
    P_XOR_ASSIGN
};

typedef struct {
    tkind kind;
    const char *start;
    int len;
    int line, column;
    int punct;       /* T_PUNCT: the character or P_ code */
    double num;      /* T_INT, T_UINT (exact), T_FLOAT */
    const char *msg; /* T_BAD: what is wrong */
} ltoken;

typedef struct {
    const char *pos;
    int line;
    const char *line_start;
} lexer;

typedef struct {
    char name[MAX_NAME];
    sc_ltype type;
    int reg;
    int is_const;
    int scope;
} variable;

enum { Q_IN = 1, Q_OUT = 2, Q_INOUT = 3 };

typedef struct {
    char name[MAX_NAME];
    sc_ltype ret;
    int n_params;
    sc_ltype params[MAX_PARAMS];
    int qual[MAX_PARAMS];
    int param_regs[MAX_PARAMS];
    int ret_reg;
    int entry;
} function;

/* A value the parser has computed: its type and registers, and, when it can be assigned, where
 * it lives: register lv_reg (+ int register lv_index × lv_stride when indexed at run time, with
 * lv_count elements) + lv_comp[k] for component k. */
typedef struct {
    sc_ltype type;
    int reg;
    int lv;          /* 1 assignable, 0 not */
    const char *why; /* !lv: why not ("a constant", ...) */
    int lv_reg, lv_index, lv_stride, lv_count;
    unsigned char lv_comp[16];
    int is_literal; /* an integer literal (an index known at compile time) */
    double literal;
    int is_assignment; /* the top operator stores (not printed at top level) */
} operand;

/* A loop being compiled: the chains of its break and continue jumps (each jump's target field
 * holds the previous jump of the chain, -1 ends it, until patched). */
typedef struct {
    int break_chain, continue_chain;
} loop_ctx;

typedef struct {
    sc_program *prog;
    const char *src;
    lexer lx;
    ltoken tok;
    const char *prev_end; /* the end of the token before tok */
    sc_lang_error *err;
    int failed;
    int depth;
    variable *vars;
    int n_vars, cap_vars;
    int scope;
    function *funcs;
    int n_funcs, cap_funcs;
    int cur_func; /* -1 at top level */
    int implicit; /* sc_lang_options.implicit_int_to_float */
    int desktop_builtins;
    loop_ctx *loop;
} compiler;

/* ---- lang_lex.c ---- */
void lex_init(lexer *lx, const char *src);
void lex_next(lexer *lx, ltoken *t);
void next(compiler *cs);
/* The token after the current one (the lexer does not move). */
ltoken peek(const compiler *cs);
int is_punct(const compiler *cs, int p);
int is_word(const compiler *cs, const char *word);
int token_is_word(const ltoken *t, const char *word);

/* ---- errors (lang_expr.c) ---- */
int fail_at(compiler *cs, const ltoken *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
int fail_expected(compiler *cs, const char *what);
int expect(compiler *cs, int p, const char *what);
const char *type_str(sc_ltype t, char *buf);

/* ---- emitting (lang_expr.c) ---- */
int alloc_regs(compiler *cs, int n);
/* A register holding a constant (rounded or wrapped to the precision when a run starts). */
int const_reg(compiler *cs, sc_kind kind, double value);
int emit(compiler *cs, insn in);
int emit_at(compiler *cs, const ltoken *t, int op, int dst, int a, int b, int c, int n);
void patch_chain(compiler *cs, int chain, int target);
int here(const compiler *cs);

/* ---- expressions (lang_expr.c) ---- */
int parse_expression(compiler *cs, operand *out); /* with the comma operator */
int parse_assignment(compiler *cs, operand *out);
/* Converts a value to a bool condition register (errors unless it is a bool scalar). */
int parse_condition(compiler *cs, int *reg);
/* Stores the value in register src into the lvalue. */
int store(compiler *cs, const operand *lv, int src, const ltoken *at);
const variable *find_variable(const compiler *cs, const char *s, int len);
/* With implicit conversions: v converted to `target` if it is the integer form of that float
 * type (else unchanged). 0, or -1 on error. */
int widen_to(compiler *cs, const ltoken *at, sc_ltype target, operand *v);
/* 1 if a value of type `from` may be passed where `to` is expected (equal, or widened). */
int converts_to(const compiler *cs, sc_ltype from, sc_ltype to);
int is_reserved(const char *s, int len);

/* ---- statements (lang_stmt.c) ---- */
int parse_type(compiler *cs, sc_ltype *t, int allow_void);
int at_type(const compiler *cs);
int declare_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int *reg);
const function *find_function(const compiler *cs, const char *s, int len);
/* A call of user function f with argument operands: the result in *out. */
int call_function(compiler *cs, const ltoken *name, operand *args, int n_args, operand *out);
/* Whether the call of `name` with these arguments goes to a function of the program: one of
 * that name exists and, where a built-in has the name too (desktop_builtins), its parameters
 * take the arguments. */
int calls_user_function(const compiler *cs, const ltoken *name, const operand *args, int n_args);

#endif
