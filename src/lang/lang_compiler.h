/* The compiler's shared state (shadecalc/lang.h): lexer (lang_lex.c), expressions
 * (lang_expr.c), statements, functions and the program (lang_stmt.c). One pass: the parser
 * checks types and emits the bytecode of lang_internal.h as it reads. */
#ifndef SHADECALC_LANG_COMPILER_H
#define SHADECALC_LANG_COMPILER_H

#include "lang/lang_internal.h"

/* MAX_DEPTH bounds the recursion of the parser (nested parentheses, calls, unary operators,
 * conditionals, assignments and blocks), so that no input overflows the C stack. */
enum { MAX_DEPTH = 256, MAX_NAME = 64, MAX_PARAMS = 8, MAX_CALL_ARGS = 16, MAX_REGS = 1 << 22 };

/* Arrays and structures exist only in the compiler (lang_aggregate.c): an sc_ltype with cols 0
 * names entry (kind - AGG_KIND) × 256 + rows of the compiler's table of them; they live in
 * consecutive registers (an array's elements, a structure's members, in order). void is kind
 * VOID_KIND. MAX_TYPE_DEPTH bounds the nesting of structures and arrays. */
enum {
    AGG_KIND = 4,
    VOID_KIND = 255,
    MAX_AGG_TYPES = (VOID_KIND - AGG_KIND) * 256,
    MAX_TYPE_DEPTH = 32,
    MAX_PRINTED = 4096
};

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
    signed char tie; /* T_FLOAT: the side of num its decimal lies on (sc_literal); else 0 */
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
    int is_type;   /* a structure's name (its type in `type`), not a variable */
    int has_value; /* a const int or uint whose initializer is a constant expression: `value` */
    double value;
} variable;

typedef struct {
    char name[MAX_NAME];
    sc_ltype type;
    int offset; /* in registers from the structure's first */
} member;

typedef struct {
    char name[MAX_NAME + 16]; /* "S", "float[3]", "S[12]" */
    int size;                 /* registers */
    int depth;                /* 1 + the deepest member's or element's depth */
    sc_ltype elem;            /* an array: its elements' type and length */
    int length;               /* 0 for a structure */
    int first, count;         /* a structure: its members in compiler.members */
} aggregate;

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
    int defined;    /* 0 while only a prototype declares it */
    int call_chain; /* calls made before the definition, patched to `entry` there */
} function;

/* A call of a user function (or by the top level, caller -1), for the checks of a whole
 * program: every called function defined, no recursion through prototypes. */
typedef struct {
    int caller, callee;
    int line, column;
} call_edge;

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
typedef struct loop_ctx {
    int break_chain, continue_chain;
    int is_switch;              /* a switch: continue belongs to the enclosing loop */
    struct loop_ctx *enclosing; /* the loop or switch around it */
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
    aggregate *types;
    int n_types, cap_types;
    member *members;
    int n_members, cap_members;
    char *labels; /* names of printed elements and members, appended to the source at the end */
    int n_labels, cap_labels;
    int src_len;
    call_edge *edges;
    int n_edges, cap_edges;
    struct switch_ctx *sw; /* the switch whose body is being compiled, if any */
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
/* The GLSL name of t; buf (16 bytes) holds it unless t is an array or a structure. */
const char *type_str(const compiler *cs, sc_ltype t, char *buf);

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
/* A value of type t in registers from reg, not assignable. */
operand value_at(sc_ltype t, int reg);
/* The operand of a part at `offset` registers inside aggregate o (a member, an element at a
 * constant index), of type t: assignable where o is. */
operand part_of(const operand *o, sc_ltype t, int offset);
/* 0, or an error naming the operator when o is an array or a structure. */
int not_aggregate(compiler *cs, const ltoken *op, const char *op_name, const operand *o);

/* ---- statements (lang_stmt.c) ---- */
int parse_type(compiler *cs, sc_ltype *t, int allow_void);
/* The same; `float[]` allowed when unsized is not NULL (then *unsized is 1). */
int parse_type_ex(compiler *cs, sc_ltype *t, int allow_void, int *unsized);
int at_type(const compiler *cs);
int declare_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int *reg);
/* The variable `name` of type t in existing registers at reg. */
int bind_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int reg);
void open_scope(compiler *cs);
void close_scope(compiler *cs); /* its variables and structures end */
int parse_statement(compiler *cs, int top_level);
/* Fills n registers from reg with zero in a few moves. */
int zero_fill(compiler *cs, const ltoken *at, int reg, int n);

/* ---- arrays and structures (lang_aggregate.c) ---- */
int is_aggregate(sc_ltype t);
int is_void(sc_ltype t);
const aggregate *aggregate_of(const compiler *cs, sc_ltype t);
int is_array(const compiler *cs, sc_ltype t);
int is_struct(const compiler *cs, sc_ltype t);
/* Registers of a value of type t. */
int type_size(const compiler *cs, sc_ltype t);
/* The type t[length] (interned: equal arrays are the same type). */
int array_of(compiler *cs, const ltoken *at, sc_ltype elem, int length, sc_ltype *out);
/* '[' [size] ']' after a type or a name: the array of t; an empty size gives *unsized = 1
 * (and t itself) where unsized is not NULL. */
int parse_array_suffix(compiler *cs, sc_ltype t, sc_ltype *out, int *unsized);
/* 'struct' NAME '{' members '}': the new structure type. */
int parse_struct(compiler *cs, sc_ltype *t);
/* The variable table's structure named by the current token, or NULL. */
const variable *find_struct(const compiler *cs, const char *s, int len);
/* The constructor of an array (type t; unsized: from the argument count) or a structure. */
int construct_aggregate(compiler *cs, const ltoken *at, sc_ltype t, int unsized, operand *args,
                        int n_args, operand *out);
/* s.member for a structure operand o (the current token is '.'). */
int parse_member(compiler *cs, operand *o);
/* Emits the printing of a top-level value: an array or structure one element or member (as
 * EXPR[i], EXPR.name) at a time. */
int emit_value(compiler *cs, const ltoken *first, const char *end, const operand *v);
/* Appends the names of printed parts to the program's source, once compiled. */
int attach_labels(compiler *cs);

/* ---- switch (lang_switch.c) ---- */
int parse_switch(compiler *cs);
/* 'case' or 'default': an error outside a switch's body (the body parses its own). */
int misplaced_label(compiler *cs);
const function *find_function(const compiler *cs, const char *s, int len);
/* A call of user function f with argument operands: the result in *out. */
int call_function(compiler *cs, const ltoken *name, operand *args, int n_args, operand *out);
/* Whether the call of `name` with these arguments goes to a function of the program: one of
 * that name exists and, where a built-in has the name too (desktop_builtins), its parameters
 * take the arguments. */
int calls_user_function(const compiler *cs, const ltoken *name, const operand *args, int n_args);

#endif
