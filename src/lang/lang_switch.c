/* The switch statement (GLSL ES 3.00 §6.2):
 *
 *   switch := 'switch' '(' expr ')' '{' { label | statement } '}'
 *   label  := 'case' CONSTANT ':' | 'default' ':'
 *
 * The selector is an int or uint scalar; each case label a constant integer expression of the
 * same type, no two equal; at most one default; no statement before the first label; labels only
 * directly in the body, the last one followed by a statement. Execution falls through from one label's statements to the next until
 * a break. Laid out as: selector; JMP dispatch; body; JMP end; dispatch: zero the body's
 * variables, compare with each label, jump to the first equal one, else to default or the
 * end. */
#include <stdlib.h>

#include "lang/lang_compiler.h"

typedef struct {
    double value;
    int pc;
} case_label;

typedef struct switch_ctx {
    sc_ltype type;
    case_label *cases;
    int n_cases, cap_cases;
    int default_pc; /* -1: none */
    int labels;     /* labels read so far */
    ltoken last;    /* the last label, while no statement follows it */
    int bare;       /* 1 while no statement follows the last label */
} switch_ctx;

int misplaced_label(compiler *cs)
{
    return fail_at(cs, &cs->tok, "'%.*s' %s", cs->tok.len, cs->tok.start,
                   cs->sw ? "must be directly in the body of the switch, not nested in a statement"
                          : "outside a switch");
}

static int add_case(compiler *cs, switch_ctx *sw, const ltoken *at, double value)
{
    for (int i = 0; i < sw->n_cases; i++)
        if (sw->cases[i].value == value)
            return fail_at(cs, at, "a second 'case %.0f' in this switch", value);
    if (sc_expr_grow((void **)&sw->cases, &sw->cap_cases, sw->n_cases + 1, sizeof *sw->cases) < 0)
        return fail_at(cs, NULL, "out of memory");
    sw->cases[sw->n_cases++] = (case_label){value, here(cs)};
    return 0;
}

/* 'case' CONSTANT ':' or 'default' ':'; the label's address is the next instruction. */
static int parse_label(compiler *cs, switch_ctx *sw)
{
    ltoken at = cs->tok;
    char tb[16];
    int is_default = is_word(cs, "default");
    next(cs);
    if (is_default) {
        if (sw->default_pc >= 0)
            return fail_at(cs, &at, "a second 'default' in this switch");
        sw->default_pc = here(cs);
    } else {
        operand v;
        if (parse_assignment(cs, &v) < 0)
            return -1;
        if (!v.is_literal || !sc_lt_equal(v.type, sw->type))
            return fail_at(cs, &at,
                           "a case label must be a constant %s expression (the selector's type)",
                           type_str(cs, sw->type, tb));
        if (add_case(cs, sw, &at, v.literal) < 0)
            return -1;
    }
    sw->labels++;
    sw->last = at;
    sw->bare = 1;
    return expect(cs, ':', is_default ? "':' after 'default'" : "':' after the case label");
}

/* The body between the braces, in the switch's scope. */
static int parse_switch_body(compiler *cs, switch_ctx *sw)
{
    while (!is_punct(cs, '}')) {
        if (cs->tok.kind == T_END)
            return fail_expected(cs, "'}' to end the switch");
        if (is_word(cs, "case") || is_word(cs, "default")) {
            if (parse_label(cs, sw) < 0)
                return -1;
            continue;
        }
        if (sw->labels == 0)
            return fail_at(cs, &cs->tok, "a statement before the first 'case' of a switch");
        if (parse_statement(cs, 0) < 0)
            return -1;
        sw->bare = 0;
    }
    if (sw->bare)
        return fail_at(cs, &sw->last, "the last label of a switch needs a statement after it");
    next(cs);
    return 0;
}

/* The dispatch: the body's variables zeroed (a jump may skip their declarations), then the
 * labels compared with the selector in `reg`. */
static int emit_dispatch(compiler *cs, const ltoken *at, const switch_ctx *sw, int reg,
                         int first_var, loop_ctx *ctx)
{
    for (int i = first_var; i < cs->n_vars; i++)
        if (!cs->vars[i].is_type &&
            zero_fill(cs, at, cs->vars[i].reg, type_size(cs, cs->vars[i].type)) < 0)
            return -1;
    int equal = alloc_regs(cs, 1);
    for (int i = 0; i < sw->n_cases && equal >= 0; i++) {
        int label = const_reg(cs, (sc_kind)sw->type.kind, sw->cases[i].value);
        int cmp = label < 0 ? -1 : emit_at(cs, at, OP_EQ, equal, reg, label, 0, 1);
        if (cmp < 0 || emit_at(cs, at, OP_JNZ, 0, equal, 0, sw->cases[i].pc, 0) < 0)
            return -1;
    }
    if (equal < 0)
        return -1;
    if (sw->default_pc >= 0)
        return emit_at(cs, at, OP_JMP, 0, 0, 0, sw->default_pc, 0) < 0 ? -1 : 0;
    int jump = emit_at(cs, at, OP_JMP, 0, 0, 0, ctx->break_chain, 0);
    if (jump >= 0)
        ctx->break_chain = jump;
    return jump < 0 ? -1 : 0;
}

static int parse_selector(compiler *cs, operand *sel)
{
    ltoken at = cs->tok;
    char tb[16];
    if (parse_expression(cs, sel) < 0)
        return -1;
    if (!sc_lt_is_scalar(sel->type) || !sc_lt_is_integer(sel->type))
        return fail_at(cs, &at, "a switch selects by an int or uint, not %s",
                       type_str(cs, sel->type, tb));
    return 0;
}

int parse_switch(compiler *cs)
{
    ltoken at = cs->tok;
    operand sel;
    next(cs);
    if (expect(cs, '(', "'(' after 'switch'") < 0 || parse_selector(cs, &sel) < 0 ||
        expect(cs, ')', "')' after the switch's selector") < 0 ||
        expect(cs, '{', "'{' to start the switch's body") < 0)
        return -1;
    int to_dispatch = emit_at(cs, &at, OP_JMP, 0, 0, 0, -1, 0);
    switch_ctx sw = {.type = sel.type, .default_pc = -1};
    loop_ctx ctx = {-1, -1, 1, cs->loop};
    switch_ctx *outer = cs->sw;
    cs->sw = &sw;
    cs->loop = &ctx;
    open_scope(cs);
    int first_var = cs->n_vars;
    int status = to_dispatch < 0 ? -1 : parse_switch_body(cs, &sw);
    int to_end = status < 0 ? -1 : emit_at(cs, &at, OP_JMP, 0, 0, 0, ctx.break_chain, 0);
    if (to_end >= 0) {
        ctx.break_chain = to_end;
        patch_chain(cs, to_dispatch, here(cs));
        status = emit_dispatch(cs, &at, &sw, sel.reg, first_var, &ctx);
    }
    close_scope(cs);
    cs->sw = outer;
    cs->loop = ctx.enclosing;
    free(sw.cases);
    if (status < 0 || to_end < 0)
        return -1;
    patch_chain(cs, ctx.break_chain, here(cs));
    return 0;
}
