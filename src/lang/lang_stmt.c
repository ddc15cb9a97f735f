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
    return cs->tok.kind == T_IDENT && (sc_lt_parse(cs->tok.start, cs->tok.len, &t) == 0 ||
                                       find_struct(cs, cs->tok.start, cs->tok.len));
}

int parse_type_ex(compiler *cs, sc_ltype *t, int allow_void, int *unsized)
{
    if (is_precision_word(&cs->tok))
        next(cs);
    if (is_word(cs, "struct"))
        return parse_struct(cs, t);
    if (!at_type(cs))
        return fail_expected(cs, "a type");
    const variable *s = find_struct(cs, cs->tok.start, cs->tok.len);
    if (s)
        *t = s->type;
    else
        sc_lt_parse(cs->tok.start, cs->tok.len, t);
    if (is_void(*t) && !allow_void)
        return fail_at(cs, &cs->tok, "a variable cannot be void");
    next(cs);
    if (is_punct(cs, '[') && is_void(*t))
        return fail_at(cs, &cs->tok, "an array cannot be of void");
    return is_punct(cs, '[') ? parse_array_suffix(cs, *t, t, unsized) : 0;
}

int parse_type(compiler *cs, sc_ltype *t, int allow_void)
{
    return parse_type_ex(cs, t, allow_void, NULL);
}

int declare_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int *reg)
{
    *reg = alloc_regs(cs, type_size(cs, t));
    return *reg < 0 ? -1 : bind_variable(cs, name, t, is_const, *reg);
}

int bind_variable(compiler *cs, const ltoken *name, sc_ltype t, int is_const, int reg)
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
    if (sc_expr_grow((void **)&cs->vars, &cs->cap_vars, cs->n_vars + 1, sizeof *cs->vars) < 0)
        return fail_at(cs, NULL, "out of memory");
    variable *v = &cs->vars[cs->n_vars++];
    memset(v, 0, sizeof *v);
    memcpy(v->name, name->start, (size_t)name->len);
    v->type = t;
    v->reg = reg;
    v->is_const = is_const;
    v->scope = cs->scope;
    return 0;
}

void open_scope(compiler *cs) { cs->scope++; }

void close_scope(compiler *cs)
{
    while (cs->n_vars > 0 && cs->vars[cs->n_vars - 1].scope == cs->scope)
        cs->n_vars--;
    cs->scope--;
}

int zero_fill(compiler *cs, const ltoken *at, int reg, int n)
{
    int zero = const_reg(cs, SC_KIND_FLOAT, 0.0); /* 0 of every kind */
    if (zero < 0 || emit_at(cs, at, OP_MOV, reg, zero, 0, 0, 1) < 0)
        return -1;
    for (int done = 1; done < n; done *= 2) /* doubling the zeroed prefix */
        if (emit_at(cs, at, OP_MOV, reg + done, reg, 0, 0, n - done < done ? n - done : done) < 0)
            return -1;
    return 0;
}

/* The type of an unsized array's initializer (`float a[] = float[](...)`) when it is an array
 * of elem; else elem (then the initializer's check fails). */
static sc_ltype sized_by(const compiler *cs, sc_ltype elem, sc_ltype init)
{
    return is_array(cs, init) && sc_lt_equal(aggregate_of(cs, init)->elem, elem) ? init : elem;
}

/* NAME [ '[' [N] ']' ]: the declarator's type from the declaration's. */
static int declarator_type(compiler *cs, sc_ltype *t, int *unsized)
{
    if (!is_punct(cs, '['))
        return 0;
    if (*unsized || is_array(cs, *t))
        return fail_at(cs, &cs->tok, "arrays of arrays are not GLSL ES 3.00");
    return parse_array_suffix(cs, *t, t, unsized);
}

/* One declarator: NAME [= initializer]; the variable exists after its initializer. A const
 * integer scalar with a constant initializer is a constant expression. */
static int parse_declarator(compiler *cs, sc_ltype t, int is_const, int unsized)
{
    ltoken name = cs->tok;
    char ab[16], bb[16];
    if (name.kind != T_IDENT)
        return fail_expected(cs, "a variable name");
    next(cs);
    if (declarator_type(cs, &t, &unsized) < 0)
        return -1;
    operand init;
    int has_init = is_punct(cs, '=');
    ltoken eq = cs->tok;
    if (has_init) {
        next(cs);
        if (parse_assignment(cs, &init) < 0 || widen_to(cs, &eq, t, &init) < 0)
            return -1;
        t = unsized ? sized_by(cs, t, init.type) : t;
        if (!sc_lt_equal(init.type, t))
            return fail_at(cs, &eq, "cannot initialize %s%s '%.*s' with %s", type_str(cs, t, ab),
                           unsized ? "[]" : "", name.len, name.start, type_str(cs, init.type, bb));
    } else if (is_const || unsized) {
        return fail_at(cs, &name, "%s '%.*s' needs an initializer",
                       unsized ? "an array of unknown size" : "const", name.len, name.start);
    }
    int reg;
    if (declare_variable(cs, &name, t, is_const, &reg) < 0)
        return -1;
    if (has_init) {
        cs->vars[cs->n_vars - 1].has_value = is_const && init.is_literal;
        cs->vars[cs->n_vars - 1].value = init.literal;
        return emit_at(cs, &eq, OP_MOV, reg, init.reg, 0, 0, type_size(cs, t)) < 0 ? -1 : 0;
    }
    /* zero, also when a function's declaration runs again (its registers are static) */
    return zero_fill(cs, &name, reg, type_size(cs, t));
}

static int parse_declaration_rest(compiler *cs, sc_ltype t, int is_const, int unsized)
{
    for (;;) {
        if (parse_declarator(cs, t, is_const, unsized) < 0)
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
        snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "",
                 type_str(cs, types[i], tb));
    }
    return fail_at(cs, name, "no function '%.*s' takes (%s)", name->len, name->start, list);
}

/* Records a call for the checks of the whole program (check_calls). */
static int add_edge(compiler *cs, const ltoken *name, int callee)
{
    if (sc_expr_grow((void **)&cs->edges, &cs->cap_edges, cs->n_edges + 1, sizeof *cs->edges) < 0)
        return fail_at(cs, NULL, "out of memory");
    cs->edges[cs->n_edges++] = (call_edge){cs->cur_func, callee, name->line, name->column};
    return 0;
}

/* OP_CALL of function `index`; before its definition, a link of its chain of calls. */
static int emit_call(compiler *cs, const ltoken *name, int index)
{
    function *f = &cs->funcs[index];
    int i = emit_at(cs, name, OP_CALL, 0, 0, 0, f->defined ? f->entry : f->call_chain, 0);
    if (i < 0 || add_edge(cs, name, index) < 0)
        return -1;
    if (!f->defined)
        f->call_chain = i;
    return 0;
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
                                           type_size(cs, args[i].type)) < 0)
            return -1;
    }
    if (emit_call(cs, name, (int)(f - cs->funcs)) < 0)
        return -1;
    for (int i = 0; i < n_args; i++)
        if ((f->qual[i] & Q_OUT) && store(cs, &args[i], f->param_regs[i], name) < 0)
            return -1;
    memset(out, 0, sizeof *out);
    out->type = f->ret;
    out->lv_index = -1;
    out->why = "a function's result";
    if (is_void(f->ret))
        return 0;
    int n = type_size(cs, f->ret);
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
    int unsized = 0;
    if (parse_type(cs, &t, 0) < 0)
        return -1;
    ltoken name = cs->tok;
    if (name.kind == T_IDENT)
        next(cs);
    else
        name.len = 0;
    if (declarator_type(cs, &t, &unsized) < 0)
        return -1;
    if (unsized)
        return fail_at(cs, &name, "a parameter cannot be an array of unknown size");
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

static int check_new_function(compiler *cs, const ltoken *name)
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
    return 0;
}

static const char *qualifier_name(int q)
{
    static const char *const names[] = {"", "in", "out", "inout", "", "const in"};
    return names[q];
}

/* A second declaration (a prototype, or the definition after one) must agree with the first. */
static int check_redeclaration(compiler *cs, const ltoken *name, const function *old, sc_ltype ret,
                               const function *f)
{
    char ab[16], bb[16];
    if (!sc_lt_equal(old->ret, ret))
        return fail_at(cs, name, "'%s' returns %s here but %s where first declared", old->name,
                       type_str(cs, ret, ab), type_str(cs, old->ret, bb));
    for (int i = 0; i < f->n_params; i++)
        if (f->qual[i] != old->qual[i])
            return fail_at(cs, name,
                           "parameter %d of '%s' is '%s' here but '%s' where first declared", i + 1,
                           old->name, qualifier_name(f->qual[i]), qualifier_name(old->qual[i]));
    return 0;
}

/* The function's entry in the table, *index: the earlier declaration of the same parameter
 * types, or a new one with its parameter and result registers. */
static int declare_function(compiler *cs, const ltoken *name, sc_ltype ret, function *f, int *index)
{
    const function *old = find_overload(cs, name, f->params, f->n_params);
    if (old) {
        *index = (int)(old - cs->funcs);
        return check_redeclaration(cs, name, old, ret, f);
    }
    if (check_new_function(cs, name) < 0)
        return -1;
    memcpy(f->name, name->start, (size_t)name->len);
    f->ret = ret;
    f->ret_reg = is_void(ret) ? 0 : alloc_regs(cs, type_size(cs, ret));
    f->call_chain = -1;
    for (int i = 0; i < f->n_params && f->ret_reg >= 0; i++)
        if ((f->param_regs[i] = alloc_regs(cs, type_size(cs, f->params[i]))) < 0)
            return -1;
    if (f->ret_reg < 0)
        return -1;
    if (sc_expr_grow((void **)&cs->funcs, &cs->cap_funcs, cs->n_funcs + 1, sizeof *cs->funcs) < 0)
        return fail_at(cs, NULL, "out of memory");
    *index = cs->n_funcs;
    cs->funcs[cs->n_funcs++] = *f;
    return 0;
}

static int is_statement_keyword(const compiler *cs);

/* The parameters as variables of the body's scope, then the body. */
static int parse_body(compiler *cs, function *f, const ltoken *names)
{
    open_scope(cs);
    for (int i = 0; i < f->n_params; i++)
        if (names[i].len > 0 &&
            bind_variable(cs, &names[i], f->params[i], f->qual[i] >> 2, f->param_regs[i]) < 0)
            return -1;
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

/* A prototype (`TYPE NAME(params);`) or a definition, which may follow prototypes. */
static int parse_function(compiler *cs, sc_ltype ret, const ltoken *name)
{
    function f;
    ltoken names[MAX_PARAMS];
    int index = -1;
    memset(&f, 0, sizeof f);
    if (cs->scope != 0)
        return fail_at(cs, name, "a function must be defined at the top level");
    if (parse_params(cs, &f, names) < 0 || declare_function(cs, name, ret, &f, &index) < 0)
        return -1;
    if (is_punct(cs, ';')) {
        next(cs);
        return 0;
    }
    if (cs->funcs[index].defined)
        return fail_at(cs, name, "'%.*s' is already defined with these parameter types", name->len,
                       name->start);
    int skip = emit_at(cs, name, OP_JMP, 0, 0, 0, -1, 0);
    if (skip < 0)
        return -1;
    function *def = &cs->funcs[index];
    def->entry = here(cs);
    def->defined = 1;
    patch_chain(cs, def->call_chain, def->entry);
    cs->cur_func = index;
    int status = parse_body(cs, def, names);
    if (status == 0)
        status = emit_at(cs, name, is_void(ret) ? OP_RET : OP_NORETURN, 0, 0, 0, 0, 0);
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
    loop_ctx loop = {-1, -1, 0, NULL};
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
    loop_ctx loop = {-1, -1, 0, NULL};
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
    loop_ctx loop = {-1, -1, 0, NULL};
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
    loop_ctx *loop = cs->loop;
    while (loop && !is_break && loop->is_switch)
        loop = loop->enclosing;
    if (!loop)
        return fail_at(cs, &at, "%s",
                       is_break ? "'break' outside a loop or switch" : "'continue' outside a loop");
    next(cs);
    int *chain = is_break ? &loop->break_chain : &loop->continue_chain;
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
        if (!is_void(f->ret))
            return fail_at(cs, &at, "'%s' must return a %s", f->name, type_str(cs, f->ret, ab));
    } else {
        operand v;
        if (parse_expression(cs, &v) < 0 || widen_to(cs, &at, f->ret, &v) < 0)
            return -1;
        if (!sc_lt_equal(v.type, f->ret))
            return fail_at(cs, &at, "'%s' returns %s, not %s", f->name, type_str(cs, f->ret, ab),
                           type_str(cs, v.type, bb));
        if (emit_at(cs, &at, OP_MOV, f->ret_reg, v.reg, 0, 0, type_size(cs, v.type)) < 0)
            return -1;
    }
    if (emit_at(cs, &at, OP_RET, 0, 0, 0, 0, 0) < 0)
        return -1;
    return expect(cs, ';', "';' after 'return'");
}

/* An expression statement; at the top level its value is printed, unless it is void or an
 * assignment. The last one of a program may omit its ';'. */
static int parse_expression_statement(compiler *cs, int top_level)
{
    ltoken first = cs->tok;
    operand v;
    if (parse_expression(cs, &v) < 0)
        return -1;
    if (top_level && !v.is_assignment && !is_void(v.type)) {
        const char *end = cs->prev_end;
        while (end > first.start && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n'))
            end--;
        if (emit_value(cs, &first, end, &v) < 0)
            return -1;
    }
    if (top_level && cs->tok.kind == T_END)
        return 0;
    return expect(cs, ';', "';' after the expression");
}

/* A declaration or a function (top level): [const] [precision] TYPE NAME ..., or a structure's
 * definition, alone or with declarators. */
static int parse_declaration(compiler *cs, int top_level)
{
    int is_const = is_word(cs, "const"), unsized = 0;
    if (is_const)
        next(cs);
    int defines = is_word(cs, "struct");
    sc_ltype t;
    if (parse_type_ex(cs, &t, 1, &unsized) < 0)
        return -1;
    if (defines && is_punct(cs, ';')) {
        next(cs);
        return 0;
    }
    ltoken name = cs->tok;
    if (name.kind == T_IDENT && peek(cs).kind == T_PUNCT && peek(cs).punct == '(') {
        if (!top_level || is_const)
            return fail_at(cs, &name, "a function must be defined at the top level");
        if (unsized)
            return fail_at(cs, &name, "a function cannot return an array of unknown size");
        next(cs);
        return parse_function(cs, t, &name);
    }
    if (is_void(t))
        return fail_at(cs, &name, "a variable cannot be void");
    return parse_declaration_rest(cs, t, is_const, unsized);
}

/* 1 if the tokens after the current one are '[' ... ']' NAME (an array type declaring). */
static int array_type_declares(const compiler *cs)
{
    lexer lx = cs->lx;
    ltoken t;
    int depth = 0;
    do {
        lex_next(&lx, &t);
        depth += t.kind == T_PUNCT ? (t.punct == '[') - (t.punct == ']') : 0;
    } while (depth > 0 && t.kind != T_END && t.kind != T_BAD);
    lex_next(&lx, &t);
    return t.kind == T_IDENT;
}

/* 1 if the statement is a declaration: const, a precision, a structure, or TYPE followed by a
 * name (TYPE may be an array type). */
static int at_declaration(const compiler *cs)
{
    if (is_word(cs, "const") || is_precision_word(&cs->tok) || is_word(cs, "struct"))
        return 1;
    ltoken after = peek(cs);
    return at_type(cs) && (after.kind == T_IDENT || (after.kind == T_PUNCT && after.punct == '[' &&
                                                     array_type_declares(cs)));
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
    if (is_word(cs, "switch"))
        return parse_switch(cs);
    if (is_word(cs, "case") || is_word(cs, "default"))
        return misplaced_label(cs);
    return fail_at(cs, &cs->tok, "'%.*s' is not supported", cs->tok.len, cs->tok.start);
}

static int is_statement_keyword(const compiler *cs)
{
    static const char *const words[] = {
        "if",        "for",     "while",     "do",      "break",   "continue",  "return",
        "precision", "discard", "switch",    "case",    "default", "uniform",   "in",
        "out",       "inout",   "attribute", "varying", "layout",  "invariant", NULL};
    for (int i = 0; words[i]; i++)
        if (is_word(cs, words[i]))
            return 1;
    return 0;
}

int parse_statement(compiler *cs, int top_level)
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

static int by_callee(const void *a, const void *b)
{
    const call_edge *x = a, *y = b;
    return (x->callee > y->callee) - (x->callee < y->callee);
}

/* Removes, leaves first, the functions that call no remaining function (each edge's caller
 * loses one pending call when its callee goes); what remains calls in a cycle. 1 if
 * function i is in or leads to a cycle. The edges are sorted by callee. */
static int *find_cycles(compiler *cs)
{
    int n = cs->n_funcs, *pending = calloc((size_t)n + 1, sizeof *pending);
    int *queue = malloc(((size_t)n + 1) * sizeof *queue), head = 0, tail = 0;
    int *first = malloc(((size_t)n + 2) * sizeof *first);
    if (!pending || !queue || !first) {
        free(pending), free(queue), free(first);
        return NULL;
    }
    for (int i = 0, e = 0; i <= n; i++) { /* first[i]: the first edge into function i */
        while (e < cs->n_edges && cs->edges[e].callee < i)
            e++;
        first[i] = e;
    }
    first[n + 1] = cs->n_edges;
    for (int e = 0; e < cs->n_edges; e++)
        if (cs->edges[e].caller >= 0)
            pending[cs->edges[e].caller]++;
    for (int i = 0; i < n; i++)
        if (pending[i] == 0)
            queue[tail++] = i;
    while (head < tail) {
        int f = queue[head++];
        for (int e = first[f]; e < first[f + 1]; e++) {
            int caller = cs->edges[e].caller;
            if (caller >= 0 && --pending[caller] == 0)
                queue[tail++] = caller;
        }
    }
    free(queue);
    free(first);
    return pending;
}

/* The first call by f of a function in or leading to a cycle. */
static int call_in_cycle(const compiler *cs, const int *pending, int f)
{
    int e = 0;
    while (cs->edges[e].caller != f || !pending[cs->edges[e].callee])
        e++;
    return e;
}

/* Every called function is defined; no function calls itself through others (GLSL ES forbids
 * recursion). Errors name the call. */
static int check_calls(compiler *cs)
{
    if (cs->n_edges == 0)
        return 0;
    qsort(cs->edges, (size_t)cs->n_edges, sizeof *cs->edges, by_callee);
    for (int e = 0; e < cs->n_edges; e++) {
        const call_edge *c = &cs->edges[e];
        if (!cs->funcs[c->callee].defined) {
            ltoken at = {.line = c->line, .column = c->column};
            return fail_at(cs, &at, "'%s' is called but never defined (only declared)",
                           cs->funcs[c->callee].name);
        }
    }
    int *pending = find_cycles(cs), f = 0;
    if (!pending)
        return fail_at(cs, NULL, "out of memory");
    while (f < cs->n_funcs && !pending[f])
        f++;
    if (f == cs->n_funcs) {
        free(pending);
        return 0;
    }
    /* every remaining function calls a remaining one: n steps from any end inside a cycle */
    for (int step = 0; step < cs->n_funcs; step++)
        f = cs->edges[call_in_cycle(cs, pending, f)].callee;
    const call_edge *c = &cs->edges[call_in_cycle(cs, pending, f)];
    free(pending);
    ltoken at = {.line = c->line, .column = c->column};
    return fail_at(cs, &at, "'%s' calls '%s', which leads back to '%s': GLSL ES forbids recursion",
                   cs->funcs[c->caller].name, cs->funcs[c->callee].name, cs->funcs[c->caller].name);
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
    if (check_calls(cs) < 0 || attach_labels(cs) < 0)
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
    cs.src_len = (int)len;
    long bound = options ? options->max_iterations : 0;
    cs.prog->max_iterations = bound > 0 ? bound : SC_LANG_DEFAULT_MAX_ITERATIONS;
    int status = compile_into(&cs, inputs, n_inputs);
    free(cs.vars);
    free(cs.funcs);
    free(cs.types);
    free(cs.members);
    free(cs.labels);
    free(cs.edges);
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
