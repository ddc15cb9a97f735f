/* The expression language's lexer, recursive-descent parser and type checker
 * (shadecalc/expr.h; grammar in the man page):
 *
 *   program  := { IDENT '=' expr ';' } expr [';']
 *   expr     := term { ('+' | '-') term }
 *   term     := unary { ('*' | '/') unary }
 *   unary    := ('-' | '+') unary | postfix
 *   postfix  := primary { '.' SWIZZLE | '[' INTEGER ']' }
 *   primary  := NUMBER | IDENT | IDENT '(' [ expr { ',' expr } ] ')' | '(' expr ')'
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/expr_internal.h"

/* MAX_DEPTH bounds the parser's recursion: every level of parentheses, of call arguments and
 * every unary operator goes through parse_unary once. Binary operators are parsed by loops, so
 * a flat chain of any length costs no depth (and its evaluation none: expr_internal.h). */
enum { MAX_DEPTH = 256, MAX_ARGS = 16, MAX_NAME = 64 };

typedef enum { TOK_END, TOK_NUMBER, TOK_IDENT, TOK_PUNCT, TOK_BAD } tok_kind;

typedef struct {
    tok_kind kind;
    const char *start;
    int len;
    int column;
    double num;
    signed char tie; /* TOK_NUMBER: the side of num its decimal lies on (sc_literal) */
} token;

typedef struct {
    char name[MAX_NAME];
    sc_type type;
    node_kind kind; /* NODE_INPUT or NODE_SLOT */
    int index;
} symbol;

typedef struct {
    const char *src;
    const char *pos;
    token tok;
    sc_expr *e;
    sc_expr_error *err;
    int failed;
    int depth;
    int n_pending; /* values computed and not yet consumed (add_node) */
    symbol syms[SC_EXPR_MAX_STATEMENTS + 32];
    int n_syms;
} parser;

/* ---- errors ---- */

static int fail(parser *ps, int column, const char *fmt, const char *a, const char *b)
{
    if (!ps->failed) {
        ps->failed = 1;
        ps->err->column = column;
        snprintf(ps->err->message, sizeof ps->err->message, fmt, a, b);
    }
    return -1;
}

static int fail_msg(parser *ps, int column, const char *msg)
{
    return fail(ps, column, "%s", msg, "");
}

/* The current token, quoted for a message. */
static const char *describe(const token *t, char *buf, size_t size)
{
    if (t->kind == TOK_END)
        return "end of input";
    snprintf(buf, size, "'%.*s'", t->len > 20 ? 20 : t->len, t->start);
    return buf;
}

static int fail_expected(parser *ps, const char *what)
{
    char buf[32];
    if (ps->tok.kind == TOK_BAD)
        return fail(ps, ps->tok.column, "unexpected %s", describe(&ps->tok, buf, sizeof buf), "");
    return fail(ps, ps->tok.column, "expected %s, found %s", what,
                describe(&ps->tok, buf, sizeof buf));
}

/* ---- lexer ---- */

static int is_ident_start(int c) { return isalpha(c) || c == '_'; }
static int is_ident_char(int c) { return isalnum(c) || c == '_'; }

/* A decimal float literal: digits [. digits] [e [+-] digits] or . digits [...], optional 'f'. */
static const char *scan_number(const char *s)
{
    const char *p = s;
    int digits = 0;
    while (isdigit((unsigned char)*p))
        p++, digits++;
    if (*p == '.')
        for (p++; isdigit((unsigned char)*p); p++)
            digits++;
    if (!digits)
        return s;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        if (*q == '+' || *q == '-')
            q++;
        if (!isdigit((unsigned char)*q))
            return NULL;
        while (isdigit((unsigned char)*q))
            q++;
        p = q;
    }
    return p;
}

static void next(parser *ps)
{
    while (isspace((unsigned char)*ps->pos))
        ps->pos++;
    token *t = &ps->tok;
    t->start = ps->pos;
    t->column = (int)(ps->pos - ps->src) + 1;
    t->len = 1;
    unsigned char c = (unsigned char)*ps->pos;
    if (c == '\0') {
        t->kind = TOK_END;
        t->len = 0;
        return;
    }
    if (isdigit(c) || (c == '.' && isdigit((unsigned char)ps->pos[1]))) {
        const char *end = scan_number(ps->pos);
        t->kind = end ? TOK_NUMBER : TOK_BAD;
        if (!end) { /* an exponent without digits: the token runs through 'e' and its sign */
            end = ps->pos + strcspn(ps->pos, "eE") + 1;
            end += *end == '+' || *end == '-';
        }
        sc_literal lit = sc_literal_read(ps->pos, NULL);
        t->num = lit.value;
        t->tie = lit.tie;
        if (*end == 'f' || *end == 'F')
            end++;
        if (is_ident_char((unsigned char)*end) || *end == '.')
            t->kind = TOK_BAD;
        while (is_ident_char((unsigned char)*end) || *end == '.')
            end++;
        t->len = (int)(end - ps->pos);
    } else if (is_ident_start(c)) {
        const char *end = ps->pos;
        while (is_ident_char((unsigned char)*end))
            end++;
        t->kind = TOK_IDENT;
        t->len = (int)(end - ps->pos);
    } else {
        t->kind = strchr("+-*/(),.;=[]", c) ? TOK_PUNCT : TOK_BAD;
    }
    ps->pos = t->start + t->len;
}

static int is_punct(const parser *ps, char c)
{
    return ps->tok.kind == TOK_PUNCT && ps->tok.start[0] == c;
}

static int expect_punct(parser *ps, char c, const char *what)
{
    if (!is_punct(ps, c))
        return fail_expected(ps, what);
    next(ps);
    return 0;
}

/* ---- building the tree ---- */

int sc_expr_grow(void **buf, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 0;
    int cap2 = *cap ? *cap * 2 : 32;
    while (cap2 < need)
        cap2 *= 2;
    void *p = realloc(*buf, (size_t)cap2 * elem);
    if (!p)
        return -1;
    *buf = p;
    *cap = cap2;
    return 0;
}

/* Appends a node whose n_operands operands are the last values computed: the parser adds
 * every node after its operands, left to right, so the nodes are in post-order and the values
 * behave as a stack (expr_internal.h). */
static int add_node(parser *ps, expr_node node, int n_operands)
{
    sc_expr *e = ps->e;
    if (sc_expr_grow((void **)&e->nodes, &e->cap_nodes, e->n_nodes + 1, sizeof *e->nodes) < 0)
        return fail_msg(ps, 0, "out of memory");
    node.count = n_operands;
    node.base = ps->n_pending - n_operands;
    ps->n_pending = node.base + 1;
    if (ps->n_pending > e->n_values)
        e->n_values = ps->n_pending;
    e->nodes[e->n_nodes] = node;
    return e->n_nodes++;
}

static sc_type type_of(const parser *ps, int node) { return ps->e->nodes[node].type; }

static int parse_expr(parser *ps);

/* ---- names ---- */

static int type_from_name(const char *s, int len, sc_type *out)
{
    for (int t = SC_FLOAT; t <= SC_MAT4; t++) {
        const char *name = sc_type_name((sc_type)t);
        if ((int)strlen(name) == len && strncmp(name, s, (size_t)len) == 0) {
            *out = (sc_type)t;
            return 0;
        }
    }
    return -1;
}

static const symbol *find_symbol(const parser *ps, const char *s, int len)
{
    for (int i = ps->n_syms - 1; i >= 0; i--)
        if ((int)strlen(ps->syms[i].name) == len && strncmp(ps->syms[i].name, s, (size_t)len) == 0)
            return &ps->syms[i];
    return NULL;
}

static int add_symbol(parser *ps, const char *s, int len, sc_type type, node_kind kind, int index,
                      int column)
{
    sc_type ignored;
    if (len >= MAX_NAME)
        return fail(ps, column, "name '%.20s...' is too long", s, "");
    if (type_from_name(s, len, &ignored) == 0 || sc_builtin_exists(s, len)) {
        char name[MAX_NAME];
        snprintf(name, sizeof name, "%.*s", len, s);
        return fail(ps, column, "'%s' is a built-in name and cannot be a variable", name, "");
    }
    if (ps->n_syms >= (int)(sizeof ps->syms / sizeof ps->syms[0]))
        return fail_msg(ps, column, "too many variables");
    symbol *sym = &ps->syms[ps->n_syms++];
    snprintf(sym->name, sizeof sym->name, "%.*s", len, s);
    sym->type = type;
    sym->kind = kind;
    sym->index = index;
    return 0;
}

/* ---- primary expressions ---- */

static int parse_args(parser *ps, int *args, int *n_args)
{
    *n_args = 0;
    next(ps); /* '(' */
    if (is_punct(ps, ')')) {
        next(ps);
        return 0;
    }
    for (;;) {
        if (*n_args == MAX_ARGS)
            return fail_msg(ps, ps->tok.column, "too many arguments (at most 16)");
        int a = parse_expr(ps);
        if (a < 0)
            return -1;
        args[(*n_args)++] = a;
        if (is_punct(ps, ')')) {
            next(ps);
            return 0;
        }
        if (expect_punct(ps, ',', "',' or ')' after an argument") < 0)
            return -1;
    }
}

static int parse_call(parser *ps, token name)
{
    int args[MAX_ARGS], n_args;
    if (parse_args(ps, args, &n_args) < 0)
        return -1;
    sc_type types[MAX_ARGS], ctor;
    for (int i = 0; i < n_args; i++)
        types[i] = type_of(ps, args[i]);
    char msg[sizeof ps->err->message];
    expr_node node = {.column = name.column};
    if (type_from_name(name.start, name.len, &ctor) == 0) {
        if (sc_construct_check(ctor, types, n_args, msg, (int)sizeof msg) < 0)
            return fail_msg(ps, name.column, msg);
        node.kind = NODE_CONSTRUCT;
        node.type = ctor;
    } else {
        node.op = sc_builtin_resolve(name.start, name.len, types, n_args, &node.type, msg,
                                     (int)sizeof msg);
        if (node.op < 0)
            return fail_msg(ps, name.column, msg);
        node.kind = NODE_CALL;
    }
    return add_node(ps, node, n_args);
}

static int parse_identifier(parser *ps)
{
    token name = ps->tok;
    next(ps);
    if (is_punct(ps, '('))
        return parse_call(ps, name);
    const symbol *sym = find_symbol(ps, name.start, name.len);
    char buf[MAX_NAME];
    snprintf(buf, sizeof buf, "%.*s", name.len, name.start);
    if (!sym) {
        sc_type t;
        if (type_from_name(name.start, name.len, &t) == 0 ||
            sc_builtin_exists(name.start, name.len))
            return fail(ps, name.column, "'%s' is a function: expected '(' after it", buf, "");
        return fail(ps, name.column, "unknown variable '%s'", buf, "");
    }
    expr_node node = {
        .kind = sym->kind, .type = sym->type, .column = name.column, .op = sym->index};
    return add_node(ps, node, 0);
}

static int parse_primary(parser *ps)
{
    token t = ps->tok;
    switch (t.kind) {
    case TOK_NUMBER: {
        next(ps);
        expr_node node = {
            .kind = NODE_NUMBER, .type = SC_FLOAT, .column = t.column, .num = t.num, .tie = t.tie};
        return add_node(ps, node, 0);
    }
    case TOK_IDENT: return parse_identifier(ps);
    case TOK_BAD: {
        char buf[32];
        return fail(ps, t.column, "unexpected %s", describe(&t, buf, sizeof buf), "");
    }
    default: break;
    }
    if (is_punct(ps, '(')) {
        next(ps);
        int inner = parse_expr(ps);
        if (inner < 0 || expect_punct(ps, ')', "')'") < 0)
            return -1;
        return inner;
    }
    return fail_expected(ps, "an expression");
}

/* ---- postfix: swizzles and indexing ---- */

int sc_swizzle_component(char c, int *set)
{
    static const char *const sets[] = {"xyzw", "rgba", "stpq"};
    for (int s = 0; s < 3; s++) {
        const char *at = strchr(sets[s], c);
        if (at && c) {
            *set = s;
            return (int)(at - sets[s]);
        }
    }
    return -1;
}

static int parse_swizzle(parser *ps, int base)
{
    int dot_column = ps->tok.column;
    next(ps); /* '.' */
    token t = ps->tok;
    sc_type bt = type_of(ps, base);
    if (t.kind != TOK_IDENT)
        return fail_expected(ps, "swizzle letters after '.'");
    if (!sc_type_is_vector(bt))
        return fail(ps, dot_column, "cannot swizzle a %s (only vectors have components)",
                    sc_type_name(bt), "");
    char letters[8];
    snprintf(letters, sizeof letters, "%.*s", t.len > 5 ? 5 : t.len, t.start);
    if (t.len > 4)
        return fail(ps, t.column, "swizzle '%s...' has more than 4 components", letters, "");
    expr_node node = {.kind = NODE_SWIZZLE, .column = t.column, .swz_len = t.len};
    int first_set = -1;
    for (int i = 0; i < t.len; i++) {
        int set, k = sc_swizzle_component(t.start[i], &set);
        if (k < 0 || k >= sc_type_size(bt))
            return fail(ps, t.column, "swizzle '%s' names a component a %s does not have", letters,
                        sc_type_name(bt));
        if (first_set >= 0 && set != first_set)
            return fail(ps, t.column, "swizzle '%s' mixes component sets (xyzw, rgba, stpq)",
                        letters, "");
        first_set = set;
        node.swz[i] = (unsigned char)k;
    }
    node.type = t.len == 1 ? SC_FLOAT : (sc_type)(SC_VEC2 + t.len - 2);
    next(ps);
    return add_node(ps, node, 1);
}

static int parse_index(parser *ps, int base)
{
    int column = ps->tok.column;
    next(ps); /* '[' */
    sc_type bt = type_of(ps, base);
    token t = ps->tok;
    int limit = sc_type_matrix_n(bt) ? sc_type_matrix_n(bt) : sc_type_size(bt);
    if (bt == SC_FLOAT)
        return fail_msg(ps, column, "cannot index a float");
    if (t.kind != TOK_NUMBER || !(t.num >= 0 && t.num < limit) || t.num != (double)(int)t.num) {
        char buf[48];
        snprintf(buf, sizeof buf, "an integer index 0..%d", limit - 1);
        return fail_expected(ps, buf);
    }
    next(ps);
    if (expect_punct(ps, ']', "']'") < 0)
        return -1;
    expr_node node = {.kind = NODE_INDEX, .column = column, .op = (int)t.num};
    node.type = sc_type_matrix_n(bt) ? (sc_type)(SC_VEC2 + limit - 2) : SC_FLOAT;
    return add_node(ps, node, 1);
}

static int parse_postfix(parser *ps)
{
    int base = parse_primary(ps);
    while (base >= 0) {
        if (is_punct(ps, '.'))
            base = parse_swizzle(ps, base);
        else if (is_punct(ps, '['))
            base = parse_index(ps, base);
        else
            break;
    }
    return base;
}

/* ---- operators ---- */

/* GLSL ES §5.9: scalar with anything, same types component-wise, except matrix * matrix,
 * matrix * vector and vector * matrix, which are the linear-algebra products. */
static int binary_type(sc_type a, sc_type b, char op, sc_type *out)
{
    if (a == SC_FLOAT || b == SC_FLOAT) {
        *out = a == SC_FLOAT ? b : a;
        return 0;
    }
    if (a == b) {
        *out = a;
        return 0;
    }
    int an = sc_type_matrix_n(a), bn = sc_type_matrix_n(b);
    if (op == '*' && an && !bn && sc_type_size(b) == an) {
        *out = b;
        return 0;
    }
    if (op == '*' && bn && !an && sc_type_size(a) == bn) {
        *out = a;
        return 0;
    }
    return -1;
}

static int make_binary(parser *ps, token op, int lhs, int rhs)
{
    sc_type t;
    if (binary_type(type_of(ps, lhs), type_of(ps, rhs), op.start[0], &t) < 0) {
        char msg[96];
        snprintf(msg, sizeof msg, "operator '%c': operands %s and %s do not match", op.start[0],
                 sc_type_name(type_of(ps, lhs)), sc_type_name(type_of(ps, rhs)));
        return fail_msg(ps, op.column, msg);
    }
    expr_node node = {.kind = NODE_BINARY, .type = t, .column = op.column, .op = op.start[0]};
    return add_node(ps, node, 2);
}

static int parse_unary(parser *ps)
{
    if (ps->depth++ > MAX_DEPTH) { /* depth: the levels of nesting around this operand */
        char msg[sizeof ps->err->message];
        snprintf(msg, sizeof msg,
                 "expression nested too deeply (more than %d levels of parentheses, calls and "
                 "unary operators)",
                 MAX_DEPTH);
        return fail_msg(ps, ps->tok.column, msg);
    }
    int result;
    if (is_punct(ps, '-') || is_punct(ps, '+')) {
        token op = ps->tok;
        next(ps);
        int operand = parse_unary(ps);
        if (operand < 0 || op.start[0] == '+')
            result = operand;
        else {
            expr_node node = {
                .kind = NODE_NEGATE, .type = type_of(ps, operand), .column = op.column};
            result = add_node(ps, node, 1);
        }
    } else {
        result = parse_postfix(ps);
    }
    ps->depth--;
    return result;
}

static int parse_term(parser *ps)
{
    int lhs = parse_unary(ps);
    while (lhs >= 0 && (is_punct(ps, '*') || is_punct(ps, '/'))) {
        token op = ps->tok;
        next(ps);
        int rhs = parse_unary(ps);
        lhs = rhs < 0 ? -1 : make_binary(ps, op, lhs, rhs);
    }
    return lhs;
}

static int parse_expr(parser *ps)
{
    int lhs = parse_term(ps);
    while (lhs >= 0 && (is_punct(ps, '+') || is_punct(ps, '-'))) {
        token op = ps->tok;
        next(ps);
        int rhs = parse_term(ps);
        lhs = rhs < 0 ? -1 : make_binary(ps, op, lhs, rhs);
    }
    return lhs;
}

/* ---- statements and the program ---- */

/* True if the current token starts `NAME =` (an assignment, not an expression). */
static int at_assignment(const parser *ps)
{
    if (ps->tok.kind != TOK_IDENT)
        return 0;
    const char *p = ps->pos;
    while (isspace((unsigned char)*p))
        p++;
    return *p == '=';
}

static int parse_statement(parser *ps)
{
    sc_expr *e = ps->e;
    token name = ps->tok;
    next(ps); /* NAME */
    next(ps); /* '=' */
    int root = parse_expr(ps);
    if (root < 0 || expect_punct(ps, ';', "';' after the assignment") < 0)
        return -1;
    if (e->n_stmts == SC_EXPR_MAX_STATEMENTS)
        return fail_msg(ps, name.column, "too many statements (at most 64)");
    if (add_symbol(ps, name.start, name.len, type_of(ps, root), NODE_SLOT, e->n_stmts,
                   name.column) < 0)
        return -1;
    e->n_stmts++;
    return 0;
}

static int parse_program(parser *ps)
{
    next(ps);
    while (at_assignment(ps))
        if (parse_statement(ps) < 0)
            return -1;
    if (ps->tok.kind == TOK_END)
        return fail_expected(ps, ps->e->n_stmts ? "an expression after the statements"
                                                : "an expression");
    int root = parse_expr(ps);
    if (root < 0)
        return -1;
    if (is_punct(ps, ';'))
        next(ps);
    if (ps->tok.kind != TOK_END)
        return fail_expected(ps, "an operator or the end of the expression");
    ps->e->root = root;
    return 0;
}

sc_expr *sc_expr_compile(const char *src, const sc_expr_input *inputs, int n_inputs,
                         sc_expr_error *err)
{
    parser *ps = calloc(1, sizeof *ps);
    sc_expr *e = calloc(1, sizeof *e);
    int ok = ps && e;
    if (ok) {
        ps->src = ps->pos = src;
        ps->e = e;
        ps->err = err;
        e->n_inputs = n_inputs;
        for (int i = 0; i < n_inputs && ok; i++)
            ok = add_symbol(ps, inputs[i].name, (int)strlen(inputs[i].name), inputs[i].type,
                            NODE_INPUT, i, 0) == 0;
        ok = ok && parse_program(ps) == 0;
    } else {
        err->column = 0;
        snprintf(err->message, sizeof err->message, "out of memory");
    }
    free(ps);
    if (!ok) {
        sc_expr_free(e);
        return NULL;
    }
    return e;
}

void sc_expr_free(sc_expr *e)
{
    if (!e)
        return;
    free(e->nodes);
    free(e);
}

sc_type sc_expr_result_type(const sc_expr *e) { return e->nodes[e->root].type; }
