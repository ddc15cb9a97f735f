/* Evaluation of a compiled expression in a precision (shadecalc/expr.h): one pass over the
 * flat program, every literal, operation and built-in result rounded to the precision. */
#include <math.h>
#include <stdlib.h>

#include "expr/expr_internal.h"
#include "shadecalc/pmath.h"

/* Up to this many values an evaluation needs no allocation (most expressions: a flat chain
 * needs 2, each level of nesting a few more, each statement 1). */
enum { LOCAL_VALUES = 32 };

typedef struct {
    sc_prec p;
    const sc_value *inputs;
    sc_expr_domain_fn on_domain;
    void *user;
} eval_state;

static sc_value rounded(sc_prec p, sc_value v)
{
    for (int k = 0; k < sc_type_size(v.type); k++)
        v.v[k] = sc_round(p, v.v[k]);
    return v;
}

static double scalar_op(sc_prec p, int op, double a, double b)
{
    switch (op) {
    case '+': return sc_p_add(p, a, b);
    case '-': return sc_p_sub(p, a, b);
    case '*': return sc_p_mul(p, a, b);
    default: return sc_p_div(p, a, b);
    }
}

/* GLSL ES §5.9: matrix products are linear algebra; everything else is component-wise with a
 * scalar operand broadcast. */
sc_value sc_expr_binary(sc_prec p, int op, sc_type type, const sc_value *a, const sc_value *b)
{
    sc_value out = {type, {0}};
    int an = sc_type_matrix_n(a->type), bn = sc_type_matrix_n(b->type);
    if (op == '*' && an && bn)
        sc_p_matmul(p, a->v, b->v, an, out.v);
    else if (op == '*' && an && sc_type_is_vector(b->type))
        sc_p_mat_vec(p, a->v, b->v, an, out.v);
    else if (op == '*' && bn && sc_type_is_vector(a->type))
        sc_p_vec_mat(p, a->v, b->v, bn, out.v);
    else
        for (int k = 0; k < sc_type_size(type); k++)
            out.v[k] = scalar_op(p, op, a->v[a->type == SC_FLOAT ? 0 : k],
                                 b->v[b->type == SC_FLOAT ? 0 : k]);
    return out;
}

static sc_value eval_call(const eval_state *st, const expr_node *n, const sc_value *args)
{
    call_context ctx = {st->p, n->column, sc_builtin_name(n->op), st->on_domain, st->user};
    return sc_builtin_eval(n->op, &ctx, args, n->count);
}

sc_value sc_expr_select(const expr_node *n, const sc_value *base)
{
    sc_value out = {n->type, {0}};
    if (n->kind == NODE_SWIZZLE) {
        for (int i = 0; i < n->swz_len; i++)
            out.v[i] = base->v[n->swz[i]];
        return out;
    }
    int size = sc_type_size(n->type); /* an index: one component, or one matrix column */
    for (int i = 0; i < size; i++)
        out.v[i] = base->v[n->op * size + i];
    return out;
}

/* Node n from the values computed before it (its operands are values[n->base ...]). */
static sc_value eval_node(const eval_state *st, const expr_node *n, const sc_value *values)
{
    const sc_value *args = values + n->base;
    switch (n->kind) {
    case NODE_NUMBER:
        return (sc_value){SC_FLOAT, {sc_literal_round(st->p, (sc_literal){n->num, n->tie})}};
    case NODE_INPUT: return rounded(st->p, st->inputs[n->op]);
    case NODE_SLOT: return values[n->op];
    case NODE_NEGATE:
        return sc_expr_binary(st->p, '*', n->type, &args[0], &(sc_value){SC_FLOAT, {-1.0}});
    case NODE_BINARY: return sc_expr_binary(st->p, n->op, n->type, &args[0], &args[1]);
    case NODE_CALL: return eval_call(st, n, args);
    case NODE_CONSTRUCT: return sc_construct(n->type, args, n->count);
    default: return sc_expr_select(n, &args[0]);
    }
}

sc_value sc_expr_nan(sc_type t)
{
    sc_value v = {t, {0}};
    for (int k = 0; k < sc_type_size(t); k++)
        v.v[k] = NAN;
    return v;
}

void *sc_expr_values(const sc_expr *e, size_t size, void *local, size_t local_size)
{
    size_t need = (size_t)e->n_values * size;
    return need <= local_size ? local : malloc(need);
}

/* The program is flat (expr_internal.h): one pass over the nodes, no recursion. The values
 * are not cleared: each is written before it is read. */
sc_value sc_expr_eval(const sc_expr *e, sc_prec p, const sc_value *inputs,
                      sc_expr_domain_fn on_domain, void *user)
{
    sc_value local[LOCAL_VALUES];
    sc_value *values = sc_expr_values(e, sizeof *values, local, sizeof local);
    if (values == NULL)
        return sc_expr_nan(sc_expr_result_type(e));
    eval_state st = {p, inputs, on_domain, user};
    for (int i = 0; i < e->n_nodes; i++)
        values[e->nodes[i].base] = eval_node(&st, &e->nodes[i], values);
    sc_value out = values[e->n_stmts];
    if (values != local)
        free(values);
    return out;
}
