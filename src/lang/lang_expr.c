/* Expressions of the language (GLSL ES 3.00 §5): parsed, type-checked and compiled to bytecode
 * in one pass. Precedence, loosest first (each level a loop, so a long chain costs no depth):
 *
 *   expression  := assignment { ',' assignment }
 *   assignment  := unary ASSIGN_OP assignment | conditional
 *   conditional := binary [ '?' expression ':' assignment ]
 *   binary      := || ^^ && | ^ & (== !=) (< > <= >=) (<< >>) (+ -) (* / %), left to right
 *   unary       := ('+' | '-' | '!' | '~' | '++' | '--') unary | postfix
 *   postfix     := primary { '.' SWIZZLE | '[' expression ']' | '++' | '--' }
 *   primary     := literal | true | false | IDENT | IDENT '(' args ')' | TYPE '(' args ')'
 *                | '(' expression ')'
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_compiler.h"
#include "util/text.h"

/* ---- errors ---- */

int fail_at(compiler *cs, const ltoken *t, const char *fmt, ...)
{
    if (!cs->failed) {
        cs->failed = 1;
        cs->err->line = t ? t->line : 0;
        cs->err->column = t ? t->column : 0;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(cs->err->message, sizeof cs->err->message, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static const char *describe(const ltoken *t, char *buf, size_t size)
{
    if (t->kind == T_END)
        return "end of input";
    snprintf(buf, size, "'%.*s'", t->len > 20 ? 20 : t->len, t->start);
    return buf;
}

int fail_expected(compiler *cs, const char *what)
{
    char buf[32];
    if (cs->tok.kind == T_BAD)
        return fail_at(cs, &cs->tok, "%s: %s", cs->tok.msg, describe(&cs->tok, buf, sizeof buf));
    return fail_at(cs, &cs->tok, "expected %s, found %s", what,
                   describe(&cs->tok, buf, sizeof buf));
}

int expect(compiler *cs, int p, const char *what)
{
    if (!is_punct(cs, p))
        return fail_expected(cs, what);
    next(cs);
    return 0;
}

/* ---- emitting ---- */

int alloc_regs(compiler *cs, int n)
{
    sc_program *pr = cs->prog;
    if (pr->n_regs > MAX_REGS - n)
        return fail_at(cs, &cs->tok, "program too large (more than %d registers)", MAX_REGS);
    pr->n_regs += n;
    return pr->n_regs - n;
}

int emit(compiler *cs, insn in)
{
    sc_program *pr = cs->prog;
    if (sc_expr_grow((void **)&pr->code, &pr->cap_code, pr->n_code + 1, sizeof *pr->code) < 0)
        return fail_at(cs, NULL, "out of memory");
    pr->code[pr->n_code] = in;
    return pr->n_code++;
}

int emit_at(compiler *cs, const ltoken *t, int op, int dst, int a, int b, int c, int n)
{
    insn in = {.op = (unsigned char)op, .dst = dst, .a = a, .b = b, .c = c, .n = n};
    in.line = t ? t->line : 0;
    in.column = t ? t->column : 0;
    return emit(cs, in);
}

int here(const compiler *cs) { return cs->prog->n_code; }

void patch_chain(compiler *cs, int chain, int target)
{
    while (chain >= 0) {
        int prev = cs->prog->code[chain].c;
        cs->prog->code[chain].c = target;
        chain = prev;
    }
}

static int add_constant(compiler *cs, sc_kind kind, double value, signed char tie)
{
    sc_program *pr = cs->prog;
    int reg = alloc_regs(cs, 1);
    if (reg < 0 || sc_expr_grow((void **)&pr->consts, &pr->cap_consts, pr->n_consts + 1,
                                sizeof *pr->consts) < 0)
        return reg < 0 ? -1 : fail_at(cs, NULL, "out of memory");
    pr->consts[pr->n_consts++] = (constant){reg, kind, value, tie};
    return reg;
}

int const_reg(compiler *cs, sc_kind kind, double value) { return add_constant(cs, kind, value, 0); }

operand value_at(sc_ltype t, int reg)
{
    operand o;
    memset(&o, 0, sizeof o);
    o.type = t;
    o.reg = reg;
    o.why = "a value that is not a variable";
    o.lv_index = -1;
    return o;
}

/* A register holding a copy of o's value (so that later stores do not change it). */
static int copy_of(compiler *cs, const operand *o, const ltoken *at)
{
    int n = type_size(cs, o->type), reg = alloc_regs(cs, n);
    if (reg < 0 || emit_at(cs, at, OP_MOV, reg, o->reg, 0, 0, n) < 0)
        return -1;
    return reg;
}

/* ---- names ---- */

static const char *const keywords[] = {
    "const",    "in",     "out",    "inout",     "uniform", "attribute", "varying",  "layout",
    "centroid", "flat",   "smooth", "invariant", "highp",   "mediump",   "lowp",     "precision",
    "if",       "else",   "for",    "while",     "do",      "break",     "continue", "return",
    "discard",  "switch", "case",   "default",   "struct",  "true",      "false",    NULL};

int is_reserved(const char *s, int len)
{
    sc_ltype t;
    if (sc_lt_parse(s, len, &t) == 0 || sc_builtin_exists(s, len) ||
        sc_lang_builtin_exists(s, len) || (len == 4 && strncmp(s, "modf", 4) == 0))
        return 1;
    for (int i = 0; keywords[i]; i++)
        if ((int)strlen(keywords[i]) == len && strncmp(keywords[i], s, (size_t)len) == 0)
            return 1;
    return len >= 3 && strncmp(s, "gl_", 3) == 0;
}

const variable *find_variable(const compiler *cs, const char *s, int len)
{
    for (int i = cs->n_vars - 1; i >= 0; i--)
        if ((int)strlen(cs->vars[i].name) == len && strncmp(cs->vars[i].name, s, (size_t)len) == 0)
            return &cs->vars[i];
    return NULL;
}

/* ---- constructors (§5.4) ---- */

/* Moves n components from src to dst, converted from kind `from` to `to`. */
static int move_components(compiler *cs, const ltoken *at, sc_kind to, sc_kind from, int dst,
                           int src, int n)
{
    int i = emit_at(cs, at, to == from ? OP_MOV : OP_CVT, dst, src, 0, 0, n);
    if (i >= 0) {
        cs->prog->code[i].kind = (unsigned char)to;
        cs->prog->code[i].kind2 = (unsigned char)from;
    }
    return i;
}

/* matCxR(matrix): the overlap copied, the rest from the identity. */
static int matrix_from_matrix(compiler *cs, const ltoken *at, sc_ltype t, const operand *m, int dst)
{
    int zero = const_reg(cs, SC_KIND_FLOAT, 0.0), one = const_reg(cs, SC_KIND_FLOAT, 1.0);
    if (zero < 0 || one < 0)
        return -1;
    for (int c = 0; c < t.cols; c++)
        for (int r = 0; r < t.rows; r++) {
            int inside = c < m->type.cols && r < m->type.rows;
            int src = inside ? m->reg + c * m->type.rows + r : (c == r ? one : zero);
            if (emit_at(cs, at, OP_MOV, dst + c * t.rows + r, src, 0, 0, 1) < 0)
                return -1;
        }
    return 0;
}

/* A scalar splat: every component of a vector, the diagonal of a matrix. */
static int splat(compiler *cs, const ltoken *at, sc_ltype t, const operand *s, int dst)
{
    int zero = sc_lt_is_matrix(t) ? const_reg(cs, SC_KIND_FLOAT, 0.0) : -1;
    for (int k = 0; k < sc_ltype_size(t); k++) {
        int diagonal = !sc_lt_is_matrix(t) || k % (t.rows + 1) == 0;
        if (sc_lt_is_matrix(t) && zero < 0)
            return -1;
        if (diagonal ? move_components(cs, at, t.kind, s->type.kind, dst + k, s->reg, 1) < 0
                     : emit_at(cs, at, OP_MOV, dst + k, zero, 0, 0, 1) < 0)
            return -1;
    }
    return 0;
}

static int check_construct(compiler *cs, const ltoken *at, sc_ltype t, const operand *args,
                           int n_args)
{
    char tb[16], ab[16];
    int need = sc_ltype_size(t), have = 0;
    if (n_args == 0)
        return fail_at(cs, at, "%s: expects at least 1 argument", type_str(cs, t, tb));
    for (int i = 0; i < n_args; i++)
        if (is_aggregate(args[i].type))
            return fail_at(cs, at,
                           "%s: argument %d is %s (an array or structure is not components)",
                           type_str(cs, t, tb), i + 1, type_str(cs, args[i].type, ab));
    if (n_args == 1 && (sc_lt_is_scalar(t) || sc_lt_is_scalar(args[0].type) ||
                        (sc_lt_is_matrix(t) && sc_lt_is_matrix(args[0].type))))
        return 0;
    if (sc_lt_is_scalar(t))
        return fail_at(cs, at, "%s: expects 1 argument, got %d", type_str(cs, t, tb), n_args);
    for (int i = 0; i < n_args; i++) {
        if (sc_lt_is_matrix(t) && sc_lt_is_matrix(args[i].type))
            return fail_at(cs, at, "%s: argument %d is %s; a matrix constructs a matrix only alone",
                           type_str(cs, t, tb), i + 1, type_str(cs, args[i].type, ab));
        if (have >= need)
            return fail_at(cs, at, "%s: too many arguments (argument %d is not used)",
                           type_str(cs, t, tb), i + 1);
        have += sc_ltype_size(args[i].type);
    }
    if (have < need)
        return fail_at(cs, at, "%s: not enough components (%d given, %d needed)",
                       type_str(cs, t, tb), have, need);
    return 0;
}

static int construct(compiler *cs, const ltoken *at, sc_ltype t, const operand *args, int n_args,
                     operand *out)
{
    if (check_construct(cs, at, t, args, n_args) < 0)
        return -1;
    int size = sc_ltype_size(t), dst = alloc_regs(cs, size), status = 0;
    if (dst < 0)
        return -1;
    if (n_args == 1 && sc_lt_is_matrix(t) && sc_lt_is_matrix(args[0].type))
        status = matrix_from_matrix(cs, at, t, &args[0], dst);
    else if (n_args == 1 && sc_lt_is_scalar(args[0].type) && !sc_lt_is_scalar(t))
        status = splat(cs, at, t, &args[0], dst);
    else
        for (int i = 0, k = 0; i < n_args && k < size && status >= 0; i++) {
            int n = sc_ltype_size(args[i].type);
            n = n < size - k ? n : size - k;
            status = move_components(cs, at, t.kind, args[i].type.kind, dst + k, args[i].reg, n);
            k += n;
        }
    *out = value_at(t, dst);
    return status < 0 ? -1 : 0;
}

/* ---- desktop GLSL's implicit int -> float ---- */

int converts_to(const compiler *cs, sc_ltype from, sc_ltype to)
{
    return sc_lt_equal(from, to) ||
           (cs->implicit && to.kind == SC_KIND_FLOAT && sc_lt_is_integer(from) && from.cols == 1 &&
            to.cols == 1 && from.rows == to.rows);
}

int widen_to(compiler *cs, const ltoken *at, sc_ltype target, operand *v)
{
    if (sc_lt_equal(v->type, target) || !converts_to(cs, v->type, target))
        return 0;
    int n = sc_ltype_size(target), dst = alloc_regs(cs, n);
    if (dst < 0 || move_components(cs, at, SC_KIND_FLOAT, v->type.kind, dst, v->reg, n) < 0)
        return -1;
    *v = value_at(target, dst);
    return 0;
}

/* The integer one of a and b widened when the other is a float (same shape or a scalar). */
static int widen_pair(compiler *cs, const ltoken *at, operand *a, operand *b)
{
    sc_ltype ta = a->type, tb = b->type;
    if (!cs->implicit || ta.kind == tb.kind)
        return 0;
    if (ta.kind == SC_KIND_FLOAT)
        return widen_to(cs, at, sc_lt(SC_KIND_FLOAT, tb.cols, tb.rows), b);
    if (tb.kind == SC_KIND_FLOAT)
        return widen_to(cs, at, sc_lt(SC_KIND_FLOAT, ta.cols, ta.rows), a);
    return 0;
}

/* ---- built-in calls ---- */

static int add_call(compiler *cs, builtin_call call)
{
    sc_program *pr = cs->prog;
    if (sc_expr_grow((void **)&pr->calls, &pr->cap_calls, pr->n_calls + 1, sizeof *pr->calls) < 0)
        return fail_at(cs, NULL, "out of memory");
    pr->calls[pr->n_calls] = call;
    return pr->n_calls++;
}

/* How to write an int or uint value `t` where a float one is expected ("" for other types). */
static const char *float_hint(sc_ltype t, char *buf, size_t size)
{
    char fb[16];
    if (!sc_lt_is_integer(t)) {
        buf[0] = '\0';
        return buf;
    }
    snprintf(buf, size, ": write a float literal (1.0, not 1) or convert (%s(...))",
             sc_ltype_name(sc_lt(SC_KIND_FLOAT, t.cols, t.rows), fb, (int)sizeof fb));
    return buf;
}

/* The float built-ins of expr/builtins.c: every argument float, vecN or matN. */
static int resolve_float_builtin(const compiler *cs, const ltoken *name, const operand *args,
                                 int n_args, builtin_call *call, char *msg, int msg_size)
{
    sc_type types[4], result;
    for (int i = 0; i < n_args; i++)
        if (sc_lt_to_expr(args[i].type, &types[i]) < 0) {
            char tb[16], hint[80];
            snprintf(msg, (size_t)msg_size,
                     "%.*s: argument %d is %s, and there is no such overload (GLSL ES converts "
                     "nothing implicitly%s)",
                     name->len, name->start, i + 1, type_str(cs, args[i].type, tb),
                     float_hint(args[i].type, hint, sizeof hint));
            return -1;
        }
    call->index = sc_builtin_resolve(name->start, name->len, types, n_args, &result, msg, msg_size);
    call->result = sc_lt_from_expr(result);
    return call->index;
}

static int all_float_shaped(const operand *args, int n_args)
{
    sc_type t;
    for (int i = 0; i < n_args; i++)
        if (sc_lt_to_expr(args[i].type, &t) < 0)
            return 0;
    return 1;
}

/* An unknown function: the closest name among the built-ins and the program's functions. */
static int unknown_function(compiler *cs, const ltoken *name)
{
    char word[MAX_NAME], msg[160];
    snprintf(word, sizeof word, "%.*s", name->len < MAX_NAME - 1 ? name->len : MAX_NAME - 1,
             name->start);
    sc_type none;
    sc_builtin_resolve(name->start, name->len, &none, 0, &none, msg, (int)sizeof msg);
    if (strstr(msg, "did you mean"))
        return fail_at(cs, name, "%s", msg);
    sc_suggestion s;
    sc_suggest_init(&s, word);
    for (int i = 0; i < sc_lang_builtin_count(); i++)
        sc_suggest_consider(&s, sc_lang_builtin_name(i));
    for (int i = 0; i < cs->n_funcs; i++)
        sc_suggest_consider(&s, cs->funcs[i].name);
    const char *best = sc_suggest_best(&s);
    return fail_at(cs, name, "unknown function '%s'%s%s%s", word, best ? " (did you mean '" : "",
                   best ? best : "", best ? "'?)" : "");
}

static int call_builtin(compiler *cs, const ltoken *name, const operand *args, int n_args,
                        operand *out);

/* A float built-in called with int arguments (desktop GLSL): them widened; else msg. Not
 * called again with float arguments, so this recursion stops at depth one. */
static int call_widened(compiler *cs, const ltoken *name, const operand *args, int n_args,
                        operand *out, const char *msg)
{
    operand wide[4];
    for (int i = 0; i < n_args; i++) {
        wide[i] = args[i];
        sc_ltype t = sc_lt(SC_KIND_FLOAT, args[i].type.cols, args[i].type.rows);
        if (widen_to(cs, name, t, &wide[i]) < 0)
            return -1;
    }
    if (!all_float_shaped(wide, n_args))
        return fail_at(cs, name, "%s", msg);
    return call_builtin(cs, name, wide, n_args, out);
}

static int call_builtin(compiler *cs, const ltoken *name, const operand *args, int n_args,
                        operand *out)
{
    builtin_call call = {.n_args = n_args};
    char msg[160] = "";
    sc_ltype types[4];
    if (n_args > 4)
        return fail_at(cs, name, "%.*s: too many arguments", name->len, name->start);
    for (int i = 0; i < n_args; i++)
        if (is_aggregate(args[i].type))
            return fail_at(cs, name,
                           "%.*s: argument %d is %s; built-ins take no arrays or structures",
                           name->len, name->start, i + 1, type_str(cs, args[i].type, msg));
    for (int i = 0; i < n_args; i++) {
        types[i] = call.types[i] = args[i].type;
        call.args[i] = args[i].reg;
    }
    int found = -1;
    if (all_float_shaped(args, n_args) && sc_builtin_exists(name->start, name->len))
        found = resolve_float_builtin(cs, name, args, n_args, &call, msg, (int)sizeof msg);
    if (found < 0 && sc_lang_builtin_exists(name->start, name->len)) {
        char lmsg[160];
        found = sc_lang_builtin_resolve(name->start, name->len, types, n_args, &call.result, lmsg,
                                        (int)sizeof lmsg);
        call.index = found;
        call.is_lang = 1;
        if (!msg[0])
            snprintf(msg, sizeof msg, "%s", lmsg);
    } else if (found < 0 && !msg[0]) {
        found = resolve_float_builtin(cs, name, args, n_args, &call, msg, (int)sizeof msg);
    }
    if (found < 0 && cs->implicit && !all_float_shaped(args, n_args) &&
        sc_builtin_exists(name->start, name->len))
        return call_widened(cs, name, args, n_args, out, msg);
    if (found < 0)
        return fail_at(cs, name, "%s", msg);
    int index = add_call(cs, call), dst = alloc_regs(cs, sc_ltype_size(call.result));
    if (index < 0 || dst < 0 || emit_at(cs, name, OP_BUILTIN, dst, 0, 0, index, 0) < 0)
        return -1;
    *out = value_at(call.result, dst);
    return 0;
}

/* ---- primary expressions ---- */

/* '(' arguments ')' into *args, a buffer of *cap operands; a heap buffer grows (the arguments
 * of an array's or a structure's constructor), a fixed one ends at MAX_CALL_ARGS. */
static int parse_arg_list(compiler *cs, operand **args, int *n_args, int *cap, int on_heap)
{
    *n_args = 0;
    next(cs); /* '(' */
    if (is_punct(cs, ')')) {
        next(cs);
        return 0;
    }
    for (;;) {
        if (*n_args == *cap && !on_heap)
            return fail_at(cs, &cs->tok, "too many arguments (at most %d)", MAX_CALL_ARGS);
        if (*n_args == *cap && sc_expr_grow((void **)args, cap, *n_args + 1, sizeof **args) < 0)
            return fail_at(cs, NULL, "out of memory");
        ltoken at = cs->tok;
        if (parse_assignment(cs, &(*args)[(*n_args)++]) < 0)
            return -1;
        if (is_void((*args)[*n_args - 1].type))
            return fail_at(cs, &at, "a void function's result is not a value");
        if (is_punct(cs, ')')) {
            next(cs);
            return 0;
        }
        if (expect(cs, ',', "',' or ')' after an argument") < 0)
            return -1;
    }
}

static int parse_args(compiler *cs, operand *args, int *n_args)
{
    int cap = MAX_CALL_ARGS;
    return parse_arg_list(cs, &args, n_args, &cap, 0);
}

/* The constructor of array or structure type t (an array of unknown size when unsized). */
static int parse_aggregate_constructor(compiler *cs, const ltoken *name, sc_ltype t, int unsized,
                                       operand *out)
{
    operand *args = NULL;
    int n_args, cap = 0;
    if (!is_punct(cs, '('))
        return fail_expected(cs, "'(' after an array type (a constructor)");
    int status = parse_arg_list(cs, &args, &n_args, &cap, 1);
    if (status == 0)
        status = construct_aggregate(cs, name, t, unsized, args, n_args, out);
    free(args);
    return status;
}

static int arithmetic(compiler *cs, const ltoken *op, int code, const operand *a, const operand *b,
                      operand *out);

/* modf(x, out i) (§8.3): i = trunc(x) and the result x - i, as Mesa computes them (exact). */
static int call_modf(compiler *cs, const ltoken *name, operand *args, int n_args, operand *out)
{
    char tb[16];
    if (n_args != 2 || args[0].type.kind != SC_KIND_FLOAT || args[0].type.cols != 1 ||
        !sc_lt_equal(args[0].type, args[1].type))
        return fail_at(cs, name, "modf takes (x, out i) of one type, float or vecN; not (%s, ...)",
                       n_args ? type_str(cs, args[0].type, tb) : "");
    if (!args[1].lv)
        return fail_at(cs, name,
                       "argument 2 of 'modf' is an out parameter: it must be a variable, not %s",
                       args[1].why);
    ltoken trunc_name = *name;
    trunc_name.start = "trunc";
    trunc_name.len = 5;
    operand whole;
    if (call_builtin(cs, &trunc_name, args, 1, &whole) < 0 ||
        arithmetic(cs, name, OP_SUB, &args[0], &whole, out) < 0)
        return -1;
    return store(cs, &args[1], whole.reg, name);
}

/* The type a name gives (a built-in type other than void, or a structure): 1, else 0. */
static int names_type(const compiler *cs, const ltoken *name, sc_ltype *t)
{
    const variable *s = find_struct(cs, name->start, name->len);
    if (s)
        *t = s->type;
    return s || (sc_lt_parse(name->start, name->len, t) == 0 && !is_void(*t));
}

static int parse_call(compiler *cs, const ltoken *name, operand *out)
{
    operand args[MAX_CALL_ARGS];
    int n_args;
    const variable *s = find_struct(cs, name->start, name->len);
    if (s)
        return parse_aggregate_constructor(cs, name, s->type, 0, out);
    if (parse_args(cs, args, &n_args) < 0)
        return -1;
    sc_ltype t;
    if (token_is_word(name, "modf"))
        return call_modf(cs, name, args, n_args, out);
    if (sc_lt_parse(name->start, name->len, &t) == 0) {
        if (t.kind > SC_KIND_BOOL)
            return fail_at(cs, name, "void is not a constructor");
        return construct(cs, name, t, args, n_args, out);
    }
    if (calls_user_function(cs, name, args, n_args))
        return call_function(cs, name, args, n_args, out);
    if (sc_builtin_exists(name->start, name->len) || sc_lang_builtin_exists(name->start, name->len))
        return call_builtin(cs, name, args, n_args, out);
    return unknown_function(cs, name);
}

static int parse_identifier(compiler *cs, operand *out)
{
    ltoken name = cs->tok;
    next(cs);
    sc_ltype t;
    if (is_punct(cs, '('))
        return parse_call(cs, &name, out);
    if (is_punct(cs, '[') && names_type(cs, &name, &t)) {
        int unsized = 0;
        if (parse_array_suffix(cs, t, &t, &unsized) < 0)
            return -1;
        return parse_aggregate_constructor(cs, &name, t, unsized, out);
    }
    if (token_is_word(&name, "true") || token_is_word(&name, "false")) {
        int reg = const_reg(cs, SC_KIND_BOOL, token_is_word(&name, "true"));
        *out = value_at(sc_lt(SC_KIND_BOOL, 1, 1), reg);
        return reg < 0 ? -1 : 0;
    }
    const variable *v = find_variable(cs, name.start, name.len);
    if (!v) {
        if (is_reserved(name.start, name.len) || find_function(cs, name.start, name.len))
            return fail_at(cs, &name, "'%.*s' is not a variable", name.len, name.start);
        return fail_at(cs, &name, "unknown variable '%.*s'", name.len, name.start);
    }
    if (v->is_type)
        return fail_at(cs, &name, "'%.*s' is a structure, not a variable", name.len, name.start);
    *out = value_at(v->type, v->reg);
    out->is_literal = v->has_value;
    out->literal = v->value;
    out->lv = !v->is_const;
    out->why = "a constant";
    out->lv_reg = v->reg;
    for (int k = 0; k < sc_ltype_size(v->type); k++)
        out->lv_comp[k] = (unsigned char)k;
    return 0;
}

static int parse_literal(compiler *cs, operand *out)
{
    static const sc_kind kinds[] = {
        [T_INT] = SC_KIND_INT, [T_UINT] = SC_KIND_UINT, [T_FLOAT] = SC_KIND_FLOAT};
    sc_kind kind = kinds[cs->tok.kind];
    int reg = add_constant(cs, kind, cs->tok.num, cs->tok.tie); /* a float: rounded once */
    *out = value_at(sc_lt(kind, 1, 1), reg);
    out->is_literal = kind != SC_KIND_FLOAT;
    out->literal = kind == SC_KIND_FLOAT ? 0.0 : sc_int_wrap(kind, 32, cs->tok.num);
    next(cs);
    return reg < 0 ? -1 : 0;
}

static int parse_primary(compiler *cs, operand *out)
{
    switch (cs->tok.kind) {
    case T_INT:
    case T_UINT:
    case T_FLOAT: return parse_literal(cs, out);
    case T_IDENT: return parse_identifier(cs, out);
    default: break;
    }
    if (is_punct(cs, '(')) {
        next(cs);
        if (parse_expression(cs, out) < 0 || expect(cs, ')', "')'") < 0)
            return -1;
        out->is_assignment = 0;
        return 0;
    }
    return fail_expected(cs, "an expression");
}

/* ---- postfix: swizzles, indexing, ++ and -- ---- */

/* The components of a swizzle (into comp) and whether one repeats. */
static int read_swizzle(compiler *cs, const ltoken *t, sc_ltype bt, unsigned char *comp,
                        int *repeats)
{
    char tb[16];
    int first_set = -1;
    *repeats = 0;
    if (t->len > 4)
        return fail_at(cs, t, "swizzle '%.*s' has more than 4 components", t->len, t->start);
    for (int i = 0; i < t->len; i++) {
        int set, k = sc_swizzle_component(t->start[i], &set);
        if (k < 0 || k >= bt.rows)
            return fail_at(cs, t, "swizzle '%.*s' names a component a %s does not have", t->len,
                           t->start, type_str(cs, bt, tb));
        if (first_set >= 0 && set != first_set)
            return fail_at(cs, t, "swizzle '%.*s' mixes component sets (xyzw, rgba, stpq)", t->len,
                           t->start);
        first_set = set;
        for (int j = 0; j < i; j++)
            *repeats |= comp[j] == k;
        comp[i] = (unsigned char)k;
    }
    return 0;
}

/* v.length(), m.length(): the number of components or columns, an int (§5.5). */
static int parse_length_method(compiler *cs, operand *o)
{
    next(cs); /* length */
    if (expect(cs, '(', "'(' after 'length'") < 0 || expect(cs, ')', "')'") < 0)
        return -1;
    int n = is_array(cs, o->type)      ? aggregate_of(cs, o->type)->length
            : sc_lt_is_matrix(o->type) ? o->type.cols
                                       : o->type.rows;
    int reg = const_reg(cs, SC_KIND_INT, n);
    *o = value_at(sc_lt(SC_KIND_INT, 1, 1), reg);
    o->is_literal = 1;
    o->literal = n;
    return reg < 0 ? -1 : 0;
}

static int parse_swizzle(compiler *cs, operand *o)
{
    if (is_struct(cs, o->type))
        return parse_member(cs, o);
    ltoken dot = cs->tok;
    next(cs);
    ltoken t = cs->tok;
    char tb[16];
    if (t.kind != T_IDENT)
        return fail_expected(cs, "swizzle letters after '.'");
    if (token_is_word(&t, "length") &&
        (sc_lt_is_vector(o->type) || sc_lt_is_matrix(o->type) || is_array(cs, o->type)))
        return parse_length_method(cs, o);
    if (!sc_lt_is_vector(o->type))
        return fail_at(cs, &dot, "cannot swizzle a %s (only vectors have components)",
                       type_str(cs, o->type, tb));
    unsigned char comp[4] = {0, 0, 0, 0};
    int repeats, n = t.len;
    if (read_swizzle(cs, &t, o->type, comp, &repeats) < 0)
        return -1;
    next(cs);
    int contiguous = 1;
    for (int i = 1; i < n; i++)
        contiguous &= comp[i] == comp[0] + i;
    int reg = contiguous ? o->reg + comp[0] : alloc_regs(cs, n);
    for (int i = 0; !contiguous && i < n && reg >= 0; i++)
        if (emit_at(cs, &t, OP_MOV, reg + i, o->reg + comp[i], 0, 0, 1) < 0)
            return -1;
    if (reg < 0)
        return -1;
    operand r = *o;
    r.type = sc_lt(o->type.kind, 1, n);
    r.reg = reg;
    r.is_literal = 0;
    for (int i = 0; i < n; i++)
        r.lv_comp[i] = o->lv_comp[comp[i]];
    if (repeats && r.lv) {
        r.lv = 0;
        r.why = "a swizzle that repeats a component";
    }
    *o = r;
    return 0;
}

/* Checks an index: an int or uint scalar, within [0, count) if it is a literal. */
static int check_index(compiler *cs, const ltoken *at, const operand *idx, int count)
{
    char tb[16];
    if (!sc_lt_is_integer(idx->type) || !sc_lt_is_scalar(idx->type))
        return fail_at(cs, at, "an index must be an int or uint, not %s",
                       type_str(cs, idx->type, tb));
    if (idx->is_literal && !(idx->literal >= 0 && idx->literal < count))
        return fail_at(cs, at, "index %.0f is out of range 0..%d", idx->literal, count - 1);
    return 0;
}

static int parse_index(compiler *cs, operand *o)
{
    ltoken bracket = cs->tok;
    char tb[16];
    const aggregate *a = is_array(cs, o->type) ? aggregate_of(cs, o->type) : NULL;
    if (!sc_lt_is_vector(o->type) && !sc_lt_is_matrix(o->type) && !a)
        return fail_at(cs, &bracket, "cannot index a %s", type_str(cs, o->type, tb));
    next(cs);
    operand idx;
    if (parse_expression(cs, &idx) < 0 || expect(cs, ']', "']'") < 0)
        return -1;
    int count = a ? a->length : sc_lt_is_matrix(o->type) ? o->type.cols : o->type.rows;
    int stride = a ? type_size(cs, a->elem) : sc_lt_is_matrix(o->type) ? o->type.rows : 1;
    if (check_index(cs, &bracket, &idx, count) < 0)
        return -1;
    operand r = *o;
    r.type = a ? a->elem : sc_lt(o->type.kind, 1, stride);
    r.is_literal = 0;
    if (idx.is_literal && a) {
        *o = part_of(o, r.type, (int)idx.literal * stride);
        return 0;
    }
    if (stride > 255)
        return fail_at(cs, &bracket,
                       "an element of %d components cannot be indexed at run time (at most 255)",
                       stride);
    if (idx.is_literal) {
        int i = (int)idx.literal;
        r.reg = o->reg + i * stride;
        for (int k = 0; k < stride; k++)
            r.lv_comp[k] = o->lv_comp[i * stride + k];
        *o = r;
        return 0;
    }
    r.reg = alloc_regs(cs, stride);
    int at = r.reg < 0 ? -1 : emit_at(cs, &bracket, OP_LOAD, r.reg, o->reg, idx.reg, count, stride);
    if (at < 0)
        return -1;
    cs->prog->code[at].kind = (unsigned char)stride;
    int contiguous = 1;
    for (int k = 1; k < sc_ltype_size(o->type); k++)
        contiguous &= o->lv_comp[k] == o->lv_comp[0] + k;
    if (r.lv && (o->lv_index >= 0 || !contiguous)) {
        r.lv = 0;
        r.why = "a target with more than one index computed at run time";
    }
    r.lv_reg = o->lv_reg + o->lv_comp[0];
    r.lv_index = idx.reg;
    r.lv_stride = stride;
    r.lv_count = count;
    for (int k = 0; k < sc_ltype_size(r.type); k++)
        r.lv_comp[k] = (unsigned char)k;
    *o = r;
    return 0;
}

static int check_assignable(compiler *cs, const ltoken *at, const operand *o)
{
    if (!o->lv)
        return fail_at(cs, at, "cannot assign to %s", o->why);
    return 0;
}

int store(compiler *cs, const operand *lv, int src, const ltoken *at)
{
    if (is_aggregate(lv->type)) { /* one block: its registers are consecutive */
        int n = type_size(cs, lv->type);
        int i = lv->lv_index < 0
                    ? emit_at(cs, at, OP_MOV, lv->lv_reg, src, 0, 0, n)
                    : emit_at(cs, at, OP_STORE, lv->lv_reg, src, lv->lv_index, lv->lv_count, n);
        if (i < 0)
            return -1;
        cs->prog->code[i].kind = (unsigned char)lv->lv_stride;
        return 0;
    }
    for (int k = 0; k < sc_ltype_size(lv->type); k++) {
        int i = lv->lv_index < 0
                    ? emit_at(cs, at, OP_MOV, lv->lv_reg + lv->lv_comp[k], src + k, 0, 0, 1)
                    : emit_at(cs, at, OP_STORE, lv->lv_reg + lv->lv_comp[k], src + k, lv->lv_index,
                              lv->lv_count, 1);
        if (i < 0)
            return -1;
        cs->prog->code[i].kind = (unsigned char)lv->lv_stride;
    }
    return 0;
}

static int arithmetic(compiler *cs, const ltoken *op, int code, const operand *a, const operand *b,
                      operand *out);

/* ++x, --x, x++, x--: the new value (prefix) or a copy of the old one (postfix). */
static int increment(compiler *cs, const ltoken *op, operand *o, int prefix)
{
    char tb[16];
    if (check_assignable(cs, op, o) < 0)
        return -1;
    if (o->type.kind == SC_KIND_BOOL || is_aggregate(o->type))
        return fail_at(cs, op, "operator '%.2s' needs a number, not %s", op->start,
                       type_str(cs, o->type, tb));
    int old = prefix ? o->reg : copy_of(cs, o, op);
    operand one = value_at(sc_lt(o->type.kind, 1, 1), const_reg(cs, o->type.kind, 1.0));
    operand sum;
    if (old < 0 || one.reg < 0 ||
        arithmetic(cs, op, op->punct == P_INC ? OP_ADD : OP_SUB, o, &one, &sum) < 0 ||
        store(cs, o, sum.reg, op) < 0)
        return -1;
    operand r = value_at(o->type, prefix ? sum.reg : old);
    r.is_assignment = 1;
    *o = r;
    return 0;
}

static int parse_postfix(compiler *cs, operand *out)
{
    if (parse_primary(cs, out) < 0)
        return -1;
    for (;;) {
        int status;
        if (is_punct(cs, '.'))
            status = parse_swizzle(cs, out);
        else if (is_punct(cs, '['))
            status = parse_index(cs, out);
        else if (is_punct(cs, P_INC) || is_punct(cs, P_DEC)) {
            ltoken op = cs->tok;
            next(cs);
            status = increment(cs, &op, out, 0);
        } else
            return 0;
        if (status < 0)
            return -1;
    }
}

/* ---- operators ---- */

/* The type of `a op b` for + - * / (§5.9); OP_MATMUL sets *matmul. */
static int arithmetic_type(sc_ltype a, sc_ltype b, int code, sc_ltype *out, int *matmul)
{
    *matmul = 0;
    if (a.kind != b.kind || a.kind == SC_KIND_BOOL)
        return -1;
    if (code == OP_MUL && sc_lt_is_matrix(a) && !sc_lt_is_scalar(b) && a.cols == b.rows) {
        *matmul = 1;
        *out = sc_lt(SC_KIND_FLOAT, b.cols == 1 ? 1 : b.cols, a.rows);
        return 0;
    }
    if (code == OP_MUL && sc_lt_is_vector(a) && sc_lt_is_matrix(b) && a.rows == b.rows) {
        *matmul = 1;
        *out = sc_lt(SC_KIND_FLOAT, 1, b.cols);
        return 0;
    }
    if (sc_lt_is_scalar(a) || sc_lt_is_scalar(b) || sc_lt_equal(a, b)) {
        *out = sc_lt_is_scalar(a) ? b : a;
        return (code == OP_MOD || code >= OP_BITAND) && !sc_lt_is_integer(a) ? -1 : 0;
    }
    return -1;
}

static const char *op_text(const ltoken *op, char *buf)
{
    snprintf(buf, 4, "%.*s", op->len > 3 ? 3 : op->len, op->start);
    if (op->punct >= P_ADD_ASSIGN) /* a compound assignment: its operator */
        buf[op->len - 1] = '\0';
    if (op->punct == P_INC || op->punct == P_DEC)
        buf[1] = '\0';
    return buf;
}

static int mismatch(compiler *cs, const ltoken *op, sc_ltype a, sc_ltype b)
{
    char ob[4], ab[16], bb[16], hint[80];
    int int_beside_float = (a.kind == SC_KIND_FLOAT) != (b.kind == SC_KIND_FLOAT);
    float_hint(a.kind == SC_KIND_FLOAT ? b : a, hint, sizeof hint);
    return fail_at(cs, op,
                   "operator '%s': operands %s and %s do not match (GLSL ES converts "
                   "nothing implicitly%s)",
                   op_text(op, ob), type_str(cs, a, ab), type_str(cs, b, bb),
                   int_beside_float ? hint : "");
}

static int emit_matmul(compiler *cs, const ltoken *op, const operand *a, const operand *b, int dst)
{
    sc_program *pr = cs->prog;
    int rows = sc_lt_is_vector(a->type) ? 1 : a->type.rows;
    int inner = sc_lt_is_vector(a->type) ? a->type.rows : a->type.cols;
    int cols = sc_lt_is_vector(b->type) ? 1 : b->type.cols;
    if (sc_expr_grow((void **)&pr->aux, &pr->cap_aux, pr->n_aux + 3, sizeof *pr->aux) < 0)
        return fail_at(cs, NULL, "out of memory");
    pr->aux[pr->n_aux] = rows;
    pr->aux[pr->n_aux + 1] = inner;
    pr->aux[pr->n_aux + 2] = cols;
    pr->n_aux += 3;
    return emit_at(cs, op, OP_MATMUL, dst, a->reg, b->reg, pr->n_aux - 3, 0);
}

/* The value of a op b when both are integer constant expressions (GLSL ES §4.3.3, for array
 * sizes and case labels): 1 and *value, else 0. Computed in 32 bits, as highp. */
static int fold(int code, sc_ltype t, const operand *a, const operand *b, double *value)
{
    if (!a->is_literal || !b->is_literal || !sc_lt_is_scalar(t) || !sc_lt_is_integer(t))
        return 0;
    long long x = (long long)a->literal, y = (long long)b->literal;
    unsigned long long ux = (unsigned long long)x, uy = (unsigned long long)y, u;
    switch (code) {
    case OP_ADD: u = ux + uy; break;
    case OP_SUB: u = ux - uy; break;
    case OP_MUL: u = ux * uy; break;
    case OP_DIV:
    case OP_MOD:
        if (y == 0)
            return 0;
        u = (unsigned long long)(code == OP_DIV ? x / y : x % y);
        break;
    case OP_BITAND: u = ux & uy; break;
    case OP_BITOR: u = ux | uy; break;
    case OP_BITXOR: u = ux ^ uy; break;
    default: return 0;
    }
    *value = sc_int_wrap_bits((sc_kind)t.kind, 32, u);
    return 1;
}

/* a op b for + - * / % & | ^ (component-wise, a scalar broadcast) and the matrix products. */
static int arithmetic(compiler *cs, const ltoken *op, int code, const operand *a0,
                      const operand *b0, operand *out)
{
    sc_ltype t;
    int matmul;
    char ob[4];
    operand wa = *a0, wb = *b0, *a = &wa, *b = &wb;
    if (not_aggregate(cs, op, op_text(op, ob), a0) < 0 ||
        not_aggregate(cs, op, op_text(op, ob), b0) < 0 || widen_pair(cs, op, a, b) < 0)
        return -1;
    if (arithmetic_type(a->type, b->type, code, &t, &matmul) < 0)
        return mismatch(cs, op, a->type, b->type);
    int dst = alloc_regs(cs, sc_ltype_size(t));
    if (dst < 0)
        return -1;
    *out = value_at(t, dst);
    if (matmul)
        return emit_matmul(cs, op, a, b, dst) < 0 ? -1 : 0;
    int i = emit_at(cs, op, code, dst, a->reg, b->reg, 0, sc_ltype_size(t));
    if (i < 0)
        return -1;
    cs->prog->code[i].kind = t.kind;
    cs->prog->code[i].flags = (unsigned char)((sc_lt_is_scalar(a->type) ? BCAST_A : 0) |
                                              (sc_lt_is_scalar(b->type) ? BCAST_B : 0));
    out->is_literal = fold(code, t, a, b, &out->literal);
    return 0;
}

/* a << b, a >> b: integers of either kind; a scalar shifted by a scalar, a vector by a scalar
 * or a vector of its size. */
static int shift(compiler *cs, const ltoken *op, const operand *a, const operand *b, operand *out)
{
    sc_ltype ta = a->type, tb = b->type;
    if (!sc_lt_is_integer(ta) || !sc_lt_is_integer(tb) || sc_lt_is_matrix(ta) ||
        !(sc_lt_is_scalar(tb) || (sc_lt_is_vector(ta) && tb.rows == ta.rows && tb.cols == 1)))
        return mismatch(cs, op, ta, tb);
    int dst = alloc_regs(cs, sc_ltype_size(ta));
    int i = dst < 0
                ? -1
                : emit_at(cs, op, op->punct == P_SHL || op->punct == P_SHL_ASSIGN ? OP_SHL : OP_SHR,
                          dst, a->reg, b->reg, 0, sc_ltype_size(ta));
    if (i < 0)
        return -1;
    cs->prog->code[i].kind = ta.kind;
    cs->prog->code[i].flags = sc_lt_is_scalar(tb) ? BCAST_B : 0;
    *out = value_at(ta, dst);
    return 0;
}

static int bool_result(compiler *cs, const ltoken *op, int code, int a, int b, int n, int kind,
                       operand *out)
{
    int dst = alloc_regs(cs, 1);
    int i = dst < 0 ? -1 : emit_at(cs, op, code, dst, a, b, 0, n);
    if (i < 0)
        return -1;
    cs->prog->code[i].kind = (unsigned char)kind;
    *out = value_at(sc_lt(SC_KIND_BOOL, 1, 1), dst);
    return 0;
}

static int comparison(compiler *cs, const ltoken *op, const operand *a0, const operand *b0,
                      operand *out)
{
    int p = op->punct;
    operand wa = *a0, wb = *b0, *a = &wa, *b = &wb;
    if (widen_pair(cs, op, a, b) < 0)
        return -1;
    if (!sc_lt_equal(a->type, b->type))
        return mismatch(cs, op, a->type, b->type);
    if (p == P_EQ || p == P_NE)
        return bool_result(cs, op, p == P_EQ ? OP_EQ : OP_NE, a->reg, b->reg,
                           type_size(cs, a->type), a->type.kind, out);
    if (!sc_lt_is_scalar(a->type) || a->type.kind == SC_KIND_BOOL) {
        char ob[4], tb[16];
        return fail_at(cs, op,
                       "operator '%s' compares scalar numbers, not %s (for vectors: "
                       "lessThan, greaterThan ...)",
                       op_text(op, ob), type_str(cs, a->type, tb));
    }
    int swap = p == '>' || p == P_GE; /* a > b is b < a */
    int code = p == '<' || p == '>' ? OP_LT : OP_LE;
    return bool_result(cs, op, code, swap ? b->reg : a->reg, swap ? a->reg : b->reg, 1,
                       a->type.kind, out);
}

static int is_bool_scalar(sc_ltype t) { return t.kind == SC_KIND_BOOL && sc_lt_is_scalar(t); }

static int logical_operand(compiler *cs, const ltoken *op, const operand *o)
{
    char ob[4], tb[16];
    if (!is_bool_scalar(o->type))
        return fail_at(cs, op, "operator '%s' needs bool operands, not %s", op_text(op, ob),
                       type_str(cs, o->type, tb));
    return 0;
}

typedef struct {
    int punct, prec, code;
} binop;

static const binop binops[] = {
    {P_OR, 1, 0},        {P_XOR, 2, OP_NE},   {P_AND, 3, 0},     {'|', 4, OP_BITOR},
    {'^', 5, OP_BITXOR}, {'&', 6, OP_BITAND}, {P_EQ, 7, 0},      {P_NE, 7, 0},
    {'<', 8, 0},         {'>', 8, 0},         {P_LE, 8, 0},      {P_GE, 8, 0},
    {P_SHL, 9, 0},       {P_SHR, 9, 0},       {'+', 10, OP_ADD}, {'-', 10, OP_SUB},
    {'*', 11, OP_MUL},   {'/', 11, OP_DIV},   {'%', 11, OP_MOD},
};

static const binop *current_binop(const compiler *cs)
{
    if (cs->tok.kind != T_PUNCT)
        return NULL;
    for (size_t i = 0; i < sizeof binops / sizeof binops[0]; i++)
        if (binops[i].punct == cs->tok.punct)
            return &binops[i];
    return NULL;
}

static int parse_binary(compiler *cs, int min_prec, operand *out);

/* a && b, a || b: b is evaluated only when a does not decide. */
static int short_circuit(compiler *cs, const ltoken *op, const binop *b, operand *lhs)
{
    if (logical_operand(cs, op, lhs) < 0)
        return -1;
    int r = alloc_regs(cs, 1);
    if (r < 0 || emit_at(cs, op, OP_MOV, r, lhs->reg, 0, 0, 1) < 0)
        return -1;
    int jump = emit_at(cs, op, op->punct == P_AND ? OP_JZ : OP_JNZ, 0, r, 0, -1, 0);
    operand rhs;
    if (jump < 0 || parse_binary(cs, b->prec + 1, &rhs) < 0 || logical_operand(cs, op, &rhs) < 0 ||
        emit_at(cs, op, OP_MOV, r, rhs.reg, 0, 0, 1) < 0)
        return -1;
    patch_chain(cs, jump, here(cs));
    *lhs = value_at(sc_lt(SC_KIND_BOOL, 1, 1), r);
    return 0;
}

static int apply_binary(compiler *cs, const ltoken *op, const binop *b, const operand *lhs,
                        const operand *rhs, operand *out)
{
    int p = op->punct;
    if (p == P_XOR) {
        if (logical_operand(cs, op, lhs) < 0 || logical_operand(cs, op, rhs) < 0)
            return -1;
        return bool_result(cs, op, OP_NE, lhs->reg, rhs->reg, 1, SC_KIND_BOOL, out);
    }
    if (p == P_SHL || p == P_SHR)
        return shift(cs, op, lhs, rhs, out);
    if (b->prec == 7 || b->prec == 8)
        return comparison(cs, op, lhs, rhs, out);
    return arithmetic(cs, op, b->code, lhs, rhs, out);
}

static int parse_unary(compiler *cs, operand *out);

/* Precedence climbing: operators of precedence >= min_prec, left to right. */
static int parse_binary(compiler *cs, int min_prec, operand *out)
{
    if (parse_unary(cs, out) < 0)
        return -1;
    const binop *b;
    while ((b = current_binop(cs)) && b->prec >= min_prec) {
        ltoken op = cs->tok;
        if (is_void(out->type))
            return fail_at(cs, &op, "a void function's result is not a value");
        next(cs);
        out->is_assignment = 0;
        if (op.punct == P_AND || op.punct == P_OR) {
            if (short_circuit(cs, &op, b, out) < 0)
                return -1;
            continue;
        }
        operand lhs = *out, rhs;
        if (parse_binary(cs, b->prec + 1, &rhs) < 0 ||
            apply_binary(cs, &op, b, &lhs, &rhs, out) < 0)
            return -1;
    }
    return 0;
}

static int unary_operator(compiler *cs, const ltoken *op, operand *o)
{
    char tb[16];
    int p = op->punct, code = p == '-' ? OP_NEG : p == '~' ? OP_BITNOT : OP_NOT;
    int ok = p == '-'   ? o->type.kind != SC_KIND_BOOL
             : p == '~' ? sc_lt_is_integer(o->type) && !sc_lt_is_matrix(o->type)
                        : is_bool_scalar(o->type);
    if (!ok || o->type.kind > SC_KIND_BOOL)
        return fail_at(cs, op, "operator '%c' cannot apply to %s", p, type_str(cs, o->type, tb));
    int n = sc_ltype_size(o->type), dst = alloc_regs(cs, n);
    int i = dst < 0 ? -1 : emit_at(cs, op, code, dst, o->reg, 0, 0, n);
    if (i < 0)
        return -1;
    cs->prog->code[i].kind = o->type.kind;
    int literal = o->is_literal && p == '-';
    double value = -o->literal;
    *o = value_at(o->type, dst);
    o->is_literal = literal;
    o->literal = value;
    return 0;
}

static int parse_unary(compiler *cs, operand *out)
{
    if (cs->depth++ > MAX_DEPTH)
        return fail_at(cs, &cs->tok,
                       "nested too deeply (more than %d levels of parentheses, calls, operators "
                       "and blocks)",
                       MAX_DEPTH);
    int status;
    char tb[16];
    ltoken op = cs->tok;
    if (op.kind == T_PUNCT && (op.punct == '-' || op.punct == '+' || op.punct == '!' ||
                               op.punct == '~' || op.punct == P_INC || op.punct == P_DEC)) {
        next(cs);
        status = parse_unary(cs, out);
        if (status == 0 && (op.punct == P_INC || op.punct == P_DEC))
            status = increment(cs, &op, out, 1);
        else if (status == 0 && op.punct != '+')
            status = unary_operator(cs, &op, out);
        else if (status == 0 && (out->type.kind == SC_KIND_BOOL || is_aggregate(out->type)))
            status = fail_at(cs, &op, "operator '+' cannot apply to %s",
                             type_str(cs, out->type, tb));
        if (status == 0 && op.punct == '+')
            out->lv = 0, out->why = "an expression";
    } else {
        status = parse_postfix(cs, out);
    }
    cs->depth--;
    return status;
}

/* ---- conditional, assignment, comma ---- */

int parse_condition(compiler *cs, int *reg)
{
    ltoken at = cs->tok;
    operand c;
    char tb[16];
    if (parse_expression(cs, &c) < 0)
        return -1;
    if (!is_bool_scalar(c.type))
        return fail_at(cs, &at, "a condition must be a bool, not %s", type_str(cs, c.type, tb));
    *reg = c.reg;
    return 0;
}

static int parse_conditional(compiler *cs, operand *out)
{
    if (parse_binary(cs, 1, out) < 0)
        return -1;
    if (!is_punct(cs, '?'))
        return 0;
    ltoken q = cs->tok;
    char tb[16], ab[16];
    if (!is_bool_scalar(out->type))
        return fail_at(cs, &q, "'?:' needs a bool condition, not %s", type_str(cs, out->type, tb));
    next(cs);
    int to_else = emit_at(cs, &q, OP_JZ, 0, out->reg, 0, -1, 0);
    operand a, b;
    if (to_else < 0 || parse_expression(cs, &a) < 0)
        return -1;
    int n = type_size(cs, a.type), r = alloc_regs(cs, n);
    if (r < 0 || emit_at(cs, &q, OP_MOV, r, a.reg, 0, 0, n) < 0 || expect(cs, ':', "':'") < 0)
        return -1;
    int to_end = emit_at(cs, &q, OP_JMP, 0, 0, 0, -1, 0);
    patch_chain(cs, to_else, here(cs));
    if (to_end < 0 || parse_assignment(cs, &b) < 0)
        return -1;
    if (!sc_lt_equal(a.type, b.type))
        return fail_at(cs, &q, "'?:' branches have different types, %s and %s",
                       type_str(cs, a.type, tb), type_str(cs, b.type, ab));
    if (emit_at(cs, &q, OP_MOV, r, b.reg, 0, 0, n) < 0)
        return -1;
    patch_chain(cs, to_end, here(cs));
    *out = value_at(a.type, r);
    return 0;
}

static int assign_code(int punct)
{
    static const int codes[][2] = {{P_ADD_ASSIGN, OP_ADD},
                                   {P_SUB_ASSIGN, OP_SUB},
                                   {P_MUL_ASSIGN, OP_MUL},
                                   {P_DIV_ASSIGN, OP_DIV},
                                   {P_MOD_ASSIGN, OP_MOD},
                                   {P_AND_ASSIGN, OP_BITAND},
                                   {P_OR_ASSIGN, OP_BITOR},
                                   {P_XOR_ASSIGN, OP_BITXOR},
                                   {P_SHL_ASSIGN, OP_SHL},
                                   {P_SHR_ASSIGN, OP_SHR},
                                   {'=', OP_MOV}};
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++)
        if (codes[i][0] == punct)
            return codes[i][1];
    return -1;
}

static int assign(compiler *cs, const ltoken *op, int code, operand *lhs, const operand *rhs)
{
    char ab[16], bb[16];
    operand value = *rhs;
    if (code == OP_SHL || code == OP_SHR) {
        if (shift(cs, op, lhs, rhs, &value) < 0)
            return -1;
    } else if (code != OP_MOV && arithmetic(cs, op, code, lhs, rhs, &value) < 0) {
        return -1;
    }
    if (widen_to(cs, op, lhs->type, &value) < 0)
        return -1;
    if (!sc_lt_equal(value.type, lhs->type))
        return fail_at(cs, op, "cannot assign %s to %s", type_str(cs, value.type, ab),
                       type_str(cs, lhs->type, bb));
    if (store(cs, lhs, value.reg, op) < 0)
        return -1;
    *lhs = value_at(lhs->type, value.reg);
    lhs->is_assignment = 1;
    return 0;
}

int parse_assignment(compiler *cs, operand *out)
{
    if (cs->depth++ > MAX_DEPTH)
        return fail_at(cs, &cs->tok, "nested too deeply (more than %d levels)", MAX_DEPTH);
    int status = parse_conditional(cs, out);
    int code = cs->tok.kind == T_PUNCT ? assign_code(cs->tok.punct) : -1;
    if (status == 0 && code >= 0) {
        ltoken op = cs->tok;
        operand rhs;
        next(cs);
        status = check_assignable(cs, &op, out);
        if (status == 0)
            status = parse_assignment(cs, &rhs);
        if (status == 0)
            status = assign(cs, &op, code, out, &rhs);
    }
    cs->depth--;
    return status;
}

int parse_expression(compiler *cs, operand *out)
{
    if (parse_assignment(cs, out) < 0)
        return -1;
    while (is_punct(cs, ',')) {
        next(cs);
        if (parse_assignment(cs, out) < 0)
            return -1;
    }
    return 0;
}
