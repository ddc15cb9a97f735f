/* Statements, functions and the program (GLSL ES 3.00 §6):
 *
 *   program    := { function | declaration | statement }     (top-level expression statements
 *                                                              are printed)
 *   function   := TYPE IDENT '(' [ param { ',' param } | 'void' ] ')' block
 *   param      := [ 'const' ] [ 'in' | 'out' | 'inout' ] [ PRECISION ] TYPE [ IDENT ]
 *   declaration:= [ 'const' ] [ PRECISION ] TYPE IDENT [ '=' assignment ] { ',' ... } ';'
 *   statement  := block | declaration | 'if' '(' expr ')' statement [ 'else' statement ]
 *               | 'for' '(' (declaration | [expr] ';') [expr] ';' [expr] ')' statement
 *               | 'while' '(' expr ')' statement | 'do' statement 'while' '(' expr ')' ';'
 *               | 'break' ';' | 'continue' ';' | 'return' [expr] ';' | [expr] ';'
 *               | 'precision' PRECISION TYPE ';'
 *
 * A function must be defined before it is called (no prototypes), so a program can only
 * recurse through a function calling itself, which is an error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_compiler.h"

static int is_precision_word(const ltoken *t)
{
    return token_is_word(t, "highp") || token_is_word(t, "mediump") || token_is_word(t, "lowp");
}

/* ---- types and variables ---- */

int at_type(const compiler *cs)
{
    sc_ltype t;
    return cs->tok.kind == T_IDENT && sc_lt_parse(cs->tok.start, cs->tok.len, &t) == 0;
}

int parse_type(compiler *cs, sc_ltype *t, int allow_void)
{
    if (is_precision_word(&cs->tok))
        next(cs);
    if (!at_type(cs))
        return fail_expected(cs, "a type");
    sc_lt_parse(cs->tok.start, cs->tok.len, t);
    if (t->kind > SC_KIND_BOOL && !allow_void)
        return fail_at(cs, &cs->tok, "a variable cannot be void");
    next(cs);
    return 0;
}

int declare_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int *reg)
{
    if (name->len >= MAX_NAME)
        return fail_at(cs, name, "name '%.20s...' is too long", name->start);
    if (is_reserved(name->start, name->len))
        return fail_at(cs, name, "'%.*s' is a reserved or built-in name", name->len, name->start);
    const variable *old = find_variable(cs, name->start, name->len);
    if (old && old->scope == cs->scope)
        return fail_at(cs, name, "'%.*s' is already declared in this scope", name->len,
                       name->start);
    if (cs->scope == 0 && find_function(cs, name->start, name->len))
        return fail_at(cs, name, "'%.*s' is already a function", name->len, name->start);
    *reg = alloc_regs(cs, sc_ltype_size(t));
    if (*reg < 0)
        return -1;
    if (sc_expr_grow((void **)&cs->vars, &cs->cap_vars, cs->n_vars + 1, sizeof *cs->vars) < 0)
        return fail_at(cs, NULL, "out of memory");
    variable *v = &cs->vars[cs->n_vars++];
    memset(v, 0, sizeof *v);
    memcpy(v->name, name->start, (size_t)name->len);
    v->type = t;
    v->reg = *reg;
    v->is_const = is_const;
    v->scope = cs->scope;
    return 0;
}

static void open_scope(compiler *cs) { cs->scope++; }

static void close_scope(compiler *cs)
{
    while (cs->n_vars > 0 && cs->vars[cs->n_vars - 1].scope == cs->scope)
        cs->n_vars--;
    cs->scope--;
}

/* One declarator: NAME [= initializer]; the variable exists after its initializer. */
static int parse_declarator(compiler *cs, sc_ltype t, int is_const)
{
    ltoken name = cs->tok;
    char ab[16], bb[16];
    if (name.kind != T_IDENT)
        return fail_expected(cs, "a variable name");
    next(cs);
    if (is_punct(cs, '['))
        return fail_at(cs, &cs->tok, "arrays are not supported");
    operand init;
    int has_init = is_punct(cs, '=');
    ltoken eq = cs->tok;
    if (has_init) {
        next(cs);
        if (parse_assignment(cs, &init) < 0 || widen_to(cs, &eq, t, &init) < 0)
            return -1;
        if (!sc_lt_equal(init.type, t))
            return fail_at(cs, &eq, "cannot initialize %s '%.*s' with %s", type_str(t, ab),
                           name.len, name.start, type_str(init.type, bb));
    } else if (is_const) {
        return fail_at(cs, &name, "const '%.*s' needs an initializer", name.len, name.start);
    }
    int reg;
    if (declare_variable(cs, &name, t, is_const, &reg) < 0)
        return -1;
    if (has_init)
        return emit_at(cs, &eq, OP_MOV, reg, init.reg, 0, 0, sc_ltype_size(t)) < 0 ? -1 : 0;
    /* zero, also when a function's declaration runs again (its registers are static) */
    int zero = const_reg(cs, (sc_kind)t.kind, 0.0);
    for (int k = 0; k < sc_ltype_size(t) && zero >= 0; k++)
        if (emit_at(cs, &name, OP_MOV, reg + k, zero, 0, 0, 1) < 0)
            return -1;
    return zero < 0 ? -1 : 0;
}

static int parse_declaration_rest(compiler *cs, sc_ltype t, int is_const)
{
    for (;;) {
        if (parse_declarator(cs, t, is_const) < 0)
            return -1;
        if (!is_punct(cs, ','))
            return expect(cs, ';', "';' after the declaration");
        next(cs);
    }
}

/* ---- functions ---- */

const function *find_function(const compiler *cs, const char *s, int len)
{
    for (int i = 0; i < cs->n_funcs; i++)
        if ((int)strlen(cs->funcs[i].name) == len &&
            strncmp(cs->funcs[i].name, s, (size_t)len) == 0)
            return &cs->funcs[i];
    return NULL;
}

static int same_params(const function *f, const sc_ltype *types, int n)
{
    if (f->n_params != n)
        return 0;
    for (int i = 0; i < n; i++)
        if (!sc_lt_equal(f->params[i], types[i]))
            return 0;
    return 1;
}

static const function *find_overload(const compiler *cs, const ltoken *name, const sc_ltype *types,
                                     int n)
{
    for (int i = 0; i < cs->n_funcs; i++) {
        const function *f = &cs->funcs[i];
        if ((int)strlen(f->name) == name->len &&
            strncmp(f->name, name->start, (size_t)name->len) == 0 && same_params(f, types, n))
            return f;
    }
    return NULL;
}

/* With implicit conversions, the first overload the arguments convert to (exact ones first). */
static const function *find_callee(const compiler *cs, const ltoken *name, const sc_ltype *types,
                                   int n)
{
    const function *exact = find_overload(cs, name, types, n);
    for (int i = 0; i < cs->n_funcs && !exact && cs->implicit; i++) {
        const function *f = &cs->funcs[i];
        int fits = (int)strlen(f->name) == name->len &&
                   strncmp(f->name, name->start, (size_t)name->len) == 0 && f->n_params == n;
        for (int k = 0; k < n && fits; k++)
            fits = converts_to(cs, types[k], f->params[k]) && (f->qual[k] & Q_OUT) == 0;
        if (fits)
            return f;
    }
    return exact;
}

static int is_builtin_function(const ltoken *name)
{
    return sc_builtin_exists(name->start, name->len) ||
           sc_lang_builtin_exists(name->start, name->len);
}

int calls_user_function(const compiler *cs, const ltoken *name, const operand *args, int n_args)
{
    if (!find_function(cs, name->start, name->len))
        return 0;
    if (!cs->desktop_builtins || !is_builtin_function(name))
        return 1;
    sc_ltype types[MAX_CALL_ARGS];
    for (int i = 0; i < n_args; i++)
        types[i] = args[i].type;
    return find_callee(cs, name, types, n_args) != NULL;
}

static int no_overload(compiler *cs, const ltoken *name, const sc_ltype *types, int n)
{
    char list[120] = "", tb[16];
    for (int i = 0; i < n; i++) {
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", type_str(types[i], tb));
    }
    return fail_at(cs, name, "no function '%.*s' takes (%s)", name->len, name->start, list);
}

/* Copies the arguments into the parameters, calls, copies out/inout parameters back. */
int call_function(compiler *cs, const ltoken *name, operand *args, int n_args, operand *out)
{
    sc_ltype types[MAX_CALL_ARGS];
    memset(types, 0, sizeof types);
    for (int i = 0; i < n_args; i++)
        types[i] = args[i].type;
    const function *f = find_callee(cs, name, types, n_args);
    if (!f)
        return no_overload(cs, name, types, n_args);
    if (f - cs->funcs == cs->cur_func)
        return fail_at(cs, name, "'%s' calls itself: GLSL ES forbids recursion", f->name);
    for (int i = 0; i < n_args; i++) {
        if ((f->qual[i] & Q_OUT) && !args[i].lv)
            return fail_at(cs, name,
                           "argument %d of '%s' is an out parameter: it must be a "
                           "variable, not %s",
                           i + 1, f->name, args[i].why);
        if (widen_to(cs, name, f->params[i], &args[i]) < 0)
            return -1;
        if ((f->qual[i] & Q_IN) && emit_at(cs, name, OP_MOV, f->param_regs[i], args[i].reg, 0, 0,
                                           sc_ltype_size(args[i].type)) < 0)
            return -1;
    }
    if (emit_at(cs, name, OP_CALL, 0, 0, 0, f->entry, 0) < 0)
        return -1;
    for (int i = 0; i < n_args; i++)
        if ((f->qual[i] & Q_OUT) && store(cs, &args[i], f->param_regs[i], name) < 0)
            return -1;
    memset(out, 0, sizeof *out);
    out->type = f->ret;
    out->lv_index = -1;
    out->why = "a function's result";
    if (f->ret.kind > SC_KIND_BOOL)
        return 0;
    int n = sc_ltype_size(f->ret);
    out->reg = alloc_regs(cs, n); /* a copy: a second call would overwrite ret_reg */
    if (out->reg < 0)
        return -1;
    return emit_at(cs, name, OP_MOV, out->reg, f->ret_reg, 0, 0, n) < 0 ? -1 : 0;
}

static int parse_param(compiler *cs, function *f, ltoken *names)
{
    int is_const = is_word(cs, "const");
    if (is_const)
        next(cs);
    int q = Q_IN;
    if (is_word(cs, "in") || is_word(cs, "out") || is_word(cs, "inout")) {
        q = is_word(cs, "in") ? Q_IN : is_word(cs, "out") ? Q_OUT : Q_INOUT;
        next(cs);
    }
    if (is_const && q != Q_IN)
        return fail_at(cs, &cs->tok, "a const parameter must be an in parameter");
    if (f->n_params == MAX_PARAMS)
        return fail_at(cs, &cs->tok, "too many parameters (at most %d)", MAX_PARAMS);
    sc_ltype t;
    if (parse_type(cs, &t, 0) < 0)
        return -1;
    ltoken name = cs->tok;
    if (name.kind == T_IDENT)
        next(cs);
    else
        name.len = 0;
    names[f->n_params] = name;
    f->params[f->n_params] = t;
    f->qual[f->n_params] = q | (is_const ? 4 : 0);
    f->n_params++;
    return 0;
}

static int parse_params(compiler *cs, function *f, ltoken *names)
{
    next(cs); /* '(' */
    if (is_word(cs, "void") && peek(cs).kind == T_PUNCT && peek(cs).punct == ')')
        next(cs);
    if (is_punct(cs, ')')) {
        next(cs);
        return 0;
    }
    for (;;) {
        if (parse_param(cs, f, names) < 0)
            return -1;
        if (is_punct(cs, ')')) {
            next(cs);
            return 0;
        }
        if (expect(cs, ',', "',' or ')' after a parameter") < 0)
            return -1;
    }
}

static int check_new_function(compiler *cs, const ltoken *name, const function *f)
{
    if (is_reserved(name->start, name->len) && !(cs->desktop_builtins && is_builtin_function(name)))
        return fail_at(cs, name,
                       "'%.*s' is a built-in or reserved name (GLSL ES does not let a "
                       "program redefine or overload built-ins)",
                       name->len, name->start);
    if (name->len >= MAX_NAME)
        return fail_at(cs, name, "name '%.20s...' is too long", name->start);
    if (find_variable(cs, name->start, name->len))
        return fail_at(cs, name, "'%.*s' is already a variable", name->len, name->start);
    if (find_overload(cs, name, f->params, f->n_params))
        return fail_at(cs, name, "'%.*s' is already defined with these parameter types", name->len,
                       name->start);
    return 0;
}

static int parse_statement(compiler *cs, int top_level);
static int is_statement_keyword(const compiler *cs);

/* The parameters as variables of the body's scope, then the body. */
static int parse_body(compiler *cs, function *f, const ltoken *names)
{
    open_scope(cs);
    for (int i = 0; i < f->n_params; i++) {
        int reg;
        if (names[i].len == 0) {
            f->param_regs[i] = alloc_regs(cs, sc_ltype_size(f->params[i]));
            if (f->param_regs[i] < 0)
                return -1;
            continue;
        }
        if (declare_variable(cs, &names[i], f->params[i], f->qual[i] >> 2, &reg) < 0)
            return -1;
        f->param_regs[i] = reg;
    }
    int status = expect(cs, '{', "'{' to start the function's body");
    while (status == 0 && !is_punct(cs, '}')) {
        if (cs->tok.kind == T_END)
            return fail_expected(cs, "'}' to end the function's body");
        status = parse_statement(cs, 0);
    }
    if (status == 0)
        next(cs);
    close_scope(cs);
    return status;
}

static int parse_function(compiler *cs, sc_ltype ret, const ltoken *name)
{
    function f;
    ltoken names[MAX_PARAMS];
    memset(&f, 0, sizeof f);
    if (cs->scope != 0)
        return fail_at(cs, name, "a function must be defined at the top level");
    if (parse_params(cs, &f, names) < 0 || check_new_function(cs, name, &f) < 0)
        return -1;
    if (is_punct(cs, ';'))
        return fail_at(cs, name,
                       "function prototypes are not supported: define '%.*s' before "
                       "its first call",
                       name->len, name->start);
    memcpy(f.name, name->start, (size_t)name->len);
    f.ret = ret;
    f.ret_reg = ret.kind > SC_KIND_BOOL ? 0 : alloc_regs(cs, sc_ltype_size(ret));
    int skip = emit_at(cs, name, OP_JMP, 0, 0, 0, -1, 0);
    if (f.ret_reg < 0 || skip < 0 ||
        sc_expr_grow((void **)&cs->funcs, &cs->cap_funcs, cs->n_funcs + 1, sizeof *cs->funcs) < 0)
        return f.ret_reg < 0 || skip < 0 ? -1 : fail_at(cs, NULL, "out of memory");
    f.entry = here(cs);
    cs->cur_func = cs->n_funcs;
    cs->funcs[cs->n_funcs++] = f;
    /* the parameter registers are known only in the body: the table's copy is updated there */
    int status = parse_body(cs, &cs->funcs[cs->cur_func], names);
    if (status == 0)
        status = emit_at(cs, name, ret.kind > SC_KIND_BOOL ? OP_RET : OP_NORETURN, 0, 0, 0, 0, 0);
    cs->cur_func = -1;
    patch_chain(cs, skip, here(cs));
    return status < 0 ? -1 : 0;
}

/* ---- statements ---- */

static int parse_substatement(compiler *cs)
{
    open_scope(cs);
    int status = parse_statement(cs, 0);
    close_scope(cs);
    return status;
}

static int parse_block(compiler *cs)
{
    next(cs); /* '{' */
    open_scope(cs);
    int status = 0;
    while (status == 0 && !is_punct(cs, '}')) {
        if (cs->tok.kind == T_END)
            return fail_expected(cs, "'}'");
        status = parse_statement(cs, 0);
    }
    close_scope(cs);
    if (status == 0)
        next(cs);
    return status;
}

static int parse_paren_condition(compiler *cs, int *reg)
{
    if (expect(cs, '(', "'('") < 0 || parse_condition(cs, reg) < 0)
        return -1;
    return expect(cs, ')', "')'");
}

static int parse_if(compiler *cs)
{
    ltoken at = cs->tok;
    int cond;
    next(cs);
    if (parse_paren_condition(cs, &cond) < 0)
        return -1;
    int to_else = emit_at(cs, &at, OP_JZ, 0, cond, 0, -1, 0);
    if (to_else < 0 || parse_substatement(cs) < 0)
        return -1;
    if (!is_word(cs, "else")) {
        patch_chain(cs, to_else, here(cs));
        return 0;
    }
    next(cs);
    int to_end = emit_at(cs, &at, OP_JMP, 0, 0, 0, -1, 0);
    patch_chain(cs, to_else, here(cs));
    if (to_end < 0 || parse_substatement(cs) < 0)
        return -1;
    patch_chain(cs, to_end, here(cs));
    return 0;
}

/* The body of a loop, with its break and continue chains; continue goes to `cont` (or, if it
 * is -1, to the chain patched by the caller). */
static int parse_loop_body(compiler *cs, const ltoken *at, loop_ctx *loop)
{
    loop_ctx *outer = cs->loop;
    cs->loop = loop;
    int status = emit_at(cs, at, OP_LOOP, 0, 0, 0, 0, 0) < 0 ? -1 : parse_substatement(cs);
    cs->loop = outer;
    return status;
}

static int parse_while(compiler *cs)
{
    ltoken at = cs->tok;
    int cond, top = here(cs);
    loop_ctx loop = {-1, -1};
    next(cs);
    if (parse_paren_condition(cs, &cond) < 0)
        return -1;
    int exit = emit_at(cs, &at, OP_JZ, 0, cond, 0, -1, 0);
    if (exit < 0 || parse_loop_body(cs, &at, &loop) < 0 ||
        emit_at(cs, &at, OP_JMP, 0, 0, 0, top, 0) < 0)
        return -1;
    patch_chain(cs, loop.continue_chain, top);
    patch_chain(cs, exit, here(cs));
    patch_chain(cs, loop.break_chain, here(cs));
    return 0;
}

static int parse_do(compiler *cs)
{
    ltoken at = cs->tok;
    int cond, top = here(cs);
    loop_ctx loop = {-1, -1};
    next(cs);
    if (parse_loop_body(cs, &at, &loop) < 0)
        return -1;
    if (!is_word(cs, "while"))
        return fail_expected(cs, "'while' after the body of 'do'");
    next(cs);
    patch_chain(cs, loop.continue_chain, here(cs));
    if (parse_paren_condition(cs, &cond) < 0 || expect(cs, ';', "';' after 'do ... while'") < 0 ||
        emit_at(cs, &at, OP_JNZ, 0, cond, 0, top, 0) < 0)
        return -1;
    patch_chain(cs, loop.break_chain, here(cs));
    return 0;
}

/* for (init; cond; step) body, laid out as: init; test: cond; JZ exit; JMP body; step: step;
 * JMP test; body: body; JMP step; exit (the step is read before the body but runs after it). */
static int parse_for_clauses(compiler *cs, const ltoken *at, int *exit, int *step)
{
    int cond = -1;
    operand ignored;
    if (is_punct(cs, '{') || (is_statement_keyword(cs) && !is_word(cs, "precision")))
        return fail_expected(cs, "a declaration or an expression after 'for ('");
    if (parse_statement(cs, 0) < 0) /* init */
        return -1;
    int test = here(cs);
    if (!is_punct(cs, ';') && parse_condition(cs, &cond) < 0)
        return -1;
    *exit = cond < 0 ? -1 : emit_at(cs, at, OP_JZ, 0, cond, 0, -1, 0);
    int to_body = emit_at(cs, at, OP_JMP, 0, 0, 0, -1, 0);
    *step = here(cs);
    if ((cond >= 0 && *exit < 0) || to_body < 0 ||
        expect(cs, ';', "';' after the loop's condition") < 0)
        return -1;
    if (!is_punct(cs, ')') && parse_expression(cs, &ignored) < 0)
        return -1;
    if (emit_at(cs, at, OP_JMP, 0, 0, 0, test, 0) < 0 ||
        expect(cs, ')', "')' after the loop's step") < 0)
        return -1;
    patch_chain(cs, to_body, here(cs));
    return 0;
}

static int parse_for(compiler *cs)
{
    ltoken at = cs->tok;
    loop_ctx loop = {-1, -1};
    int exit = -1, step = -1;
    next(cs);
    if (expect(cs, '(', "'(' after 'for'") < 0)
        return -1;
    open_scope(cs);
    int status = parse_for_clauses(cs, &at, &exit, &step);
    if (status == 0)
        status = parse_loop_body(cs, &at, &loop);
    if (status == 0 && emit_at(cs, &at, OP_JMP, 0, 0, 0, step, 0) < 0)
        status = -1;
    close_scope(cs);
    if (status < 0)
        return -1;
    patch_chain(cs, loop.continue_chain, step);
    patch_chain(cs, exit, here(cs));
    patch_chain(cs, loop.break_chain, here(cs));
    return 0;
}

static int parse_jump(compiler *cs)
{
    ltoken at = cs->tok;
    int is_break = is_word(cs, "break");
    if (!cs->loop)
        return fail_at(cs, &at, "'%s' outside a loop", is_break ? "break" : "continue");
    next(cs);
    int *chain = is_break ? &cs->loop->break_chain : &cs->loop->continue_chain;
    int i = emit_at(cs, &at, OP_JMP, 0, 0, 0, *chain, 0);
    if (i < 0)
        return -1;
    *chain = i;
    return expect(cs, ';', "';'");
}

static int parse_return(compiler *cs)
{
    ltoken at = cs->tok;
    char ab[16], bb[16];
    if (cs->cur_func < 0)
        return fail_at(cs, &at, "'return' outside a function");
    const function *f = &cs->funcs[cs->cur_func];
    next(cs);
    if (is_punct(cs, ';')) {
        if (f->ret.kind <= SC_KIND_BOOL)
            return fail_at(cs, &at, "'%s' must return a %s", f->name, type_str(f->ret, ab));
    } else {
        operand v;
        if (parse_expression(cs, &v) < 0 || widen_to(cs, &at, f->ret, &v) < 0)
            return -1;
        if (!sc_lt_equal(v.type, f->ret))
            return fail_at(cs, &at, "'%s' returns %s, not %s", f->name, type_str(f->ret, ab),
                           type_str(v.type, bb));
        if (emit_at(cs, &at, OP_MOV, f->ret_reg, v.reg, 0, 0, sc_ltype_size(v.type)) < 0)
            return -1;
    }
    if (emit_at(cs, &at, OP_RET, 0, 0, 0, 0, 0) < 0)
        return -1;
    return expect(cs, ';', "';' after 'return'");
}

static int add_emit(compiler *cs, const char *start, const operand *v)
{
    sc_program *pr = cs->prog;
    const char *end = cs->prev_end;
    while (end > start && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n'))
        end--;
    if (sc_expr_grow((void **)&pr->emits, &pr->cap_emits, pr->n_emits + 1, sizeof *pr->emits) < 0)
        return fail_at(cs, NULL, "out of memory");
    pr->emits[pr->n_emits] = (emit_site){(int)(start - cs->src), (int)(end - start), v->type};
    return pr->n_emits++;
}

/* An expression statement; at the top level its value is printed, unless it is void or an
 * assignment. The last one of a program may omit its ';'. */
static int parse_expression_statement(compiler *cs, int top_level)
{
    ltoken first = cs->tok;
    operand v;
    if (parse_expression(cs, &v) < 0)
        return -1;
    if (top_level && !v.is_assignment && v.type.kind <= SC_KIND_BOOL) {
        int site = add_emit(cs, first.start, &v);
        if (site < 0 || emit_at(cs, &first, OP_EMIT, 0, v.reg, 0, site, 0) < 0)
            return -1;
    }
    if (top_level && cs->tok.kind == T_END)
        return 0;
    return expect(cs, ';', "';' after the expression");
}

/* A declaration or a function (top level): [const] [precision] TYPE NAME ... */
static int parse_declaration(compiler *cs, int top_level)
{
    int is_const = is_word(cs, "const");
    if (is_const)
        next(cs);
    sc_ltype t;
    if (parse_type(cs, &t, 1) < 0)
        return -1;
    ltoken name = cs->tok;
    if (name.kind == T_IDENT && peek(cs).kind == T_PUNCT && peek(cs).punct == '(') {
        if (!top_level || is_const)
            return fail_at(cs, &name, "a function must be defined at the top level");
        next(cs);
        return parse_function(cs, t, &name);
    }
    if (t.kind > SC_KIND_BOOL)
        return fail_at(cs, &name, "a variable cannot be void");
    return parse_declaration_rest(cs, t, is_const);
}

/* 1 if the statement is a declaration: const, a precision, or TYPE followed by a name. */
static int at_declaration(const compiler *cs)
{
    if (is_word(cs, "const") || is_precision_word(&cs->tok))
        return 1;
    ltoken after = peek(cs);
    return at_type(cs) && after.kind == T_IDENT;
}

static int skip_precision_statement(compiler *cs)
{
    next(cs);
    if (!is_precision_word(&cs->tok))
        return fail_expected(cs, "highp, mediump or lowp after 'precision'");
    next(cs);
    sc_ltype t;
    if (parse_type(cs, &t, 0) < 0)
        return -1;
    return expect(cs, ';', "';' after the precision statement");
}

static int parse_keyword_statement(compiler *cs)
{
    if (is_word(cs, "if"))
        return parse_if(cs);
    if (is_word(cs, "for"))
        return parse_for(cs);
    if (is_word(cs, "while"))
        return parse_while(cs);
    if (is_word(cs, "do"))
        return parse_do(cs);
    if (is_word(cs, "break") || is_word(cs, "continue"))
        return parse_jump(cs);
    if (is_word(cs, "return"))
        return parse_return(cs);
    if (is_word(cs, "precision"))
        return skip_precision_statement(cs);
    return fail_at(cs, &cs->tok, "'%.*s' is not supported", cs->tok.len, cs->tok.start);
}

static int is_statement_keyword(const compiler *cs)
{
    static const char *const words[] = {"if",        "for",     "while",     "do",        "break",
                                        "continue",  "return",  "precision", "discard",   "switch",
                                        "struct",    "uniform", "in",        "out",       "inout",
                                        "attribute", "varying", "layout",    "invariant", NULL};
    for (int i = 0; words[i]; i++)
        if (is_word(cs, words[i]))
            return 1;
    return 0;
}

static int parse_statement(compiler *cs, int top_level)
{
    if (cs->depth++ > MAX_DEPTH)
        return fail_at(cs, &cs->tok, "nested too deeply (more than %d levels)", MAX_DEPTH);
    int status;
    if (is_punct(cs, '{'))
        status = parse_block(cs);
    else if (is_punct(cs, ';'))
        next(cs), status = 0;
    else if (is_statement_keyword(cs))
        status = parse_keyword_statement(cs);
    else if (at_declaration(cs))
        status = parse_declaration(cs, top_level);
    else
        status = parse_expression_statement(cs, top_level);
    cs->depth--;
    return status;
}

/* ---- the program ---- */

static int declare_inputs(compiler *cs, const sc_lang_input *inputs, int n_inputs)
{
    if (n_inputs > (int)(sizeof cs->prog->input_regs / sizeof cs->prog->input_regs[0]))
        return fail_at(cs, NULL, "too many inputs");
    for (int i = 0; i < n_inputs; i++) {
        ltoken name = {
            .kind = T_IDENT, .start = inputs[i].name, .len = (int)strlen(inputs[i].name)};
        if (declare_variable(cs, &name, inputs[i].type, 1, &cs->prog->input_regs[i]) < 0)
            return -1;
        cs->prog->input_types[i] = inputs[i].type;
    }
    cs->prog->n_inputs = n_inputs;
    return 0;
}

static int compile_into(compiler *cs, const sc_lang_input *inputs, int n_inputs)
{
    if (declare_inputs(cs, inputs, n_inputs) < 0)
        return -1;
    lex_init(&cs->lx, cs->src);
    next(cs);
    while (cs->tok.kind != T_END)
        if (parse_statement(cs, 1) < 0)
            return -1;
    cs->prog->max_call_depth = cs->n_funcs + 1;
    return emit_at(cs, &cs->tok, OP_HALT, 0, 0, 0, 0, 0) < 0 ? -1 : 0;
}

sc_program *sc_program_compile(const char *src, const sc_lang_input *inputs, int n_inputs,
                               const sc_lang_options *options, sc_lang_error *err)
{
    compiler cs;
    memset(&cs, 0, sizeof cs);
    memset(err, 0, sizeof *err);
    cs.err = err;
    cs.cur_func = -1;
    cs.implicit = options && options->implicit_int_to_float;
    cs.desktop_builtins = options && options->desktop_builtins;
    cs.prog = calloc(1, sizeof *cs.prog);
    size_t len = strlen(src);
    char *copy = cs.prog ? malloc(len + 1) : NULL;
    if (!copy) {
        free(cs.prog);
        snprintf(err->message, sizeof err->message, "out of memory");
        return NULL;
    }
    memcpy(copy, src, len + 1);
    cs.prog->src = copy;
    cs.src = copy;
    long bound = options ? options->max_iterations : 0;
    cs.prog->max_iterations = bound > 0 ? bound : SC_LANG_DEFAULT_MAX_ITERATIONS;
    int status = compile_into(&cs, inputs, n_inputs);
    free(cs.vars);
    free(cs.funcs);
    if (status < 0) {
        sc_program_free(cs.prog);
        return NULL;
    }
    return cs.prog;
}

void sc_program_free(sc_program *prog)
{
    if (!prog)
        return;
    free(prog->src);
    free(prog->code);
    free(prog->calls);
    free(prog->emits);
    free(prog->consts);
    free(prog->aux);
    free(prog);
}
