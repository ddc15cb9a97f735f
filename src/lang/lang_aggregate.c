/* Arrays and structures (GLSL ES 3.00 §4.1.8, §4.1.9): types of the compiler only. A value of
 * either lives in consecutive registers (an array's elements in order, a structure's members in
 * order), so assignment, comparison, passing and returning move or compare one block, an
 * element or member at a constant index is a register offset, and an element at a computed
 * index uses the interpreter's OP_LOAD and OP_STORE with the element's size as the stride. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_compiler.h"

/* ---- the table of types ---- */

int is_aggregate(sc_ltype t) { return t.cols == 0; }
int is_void(sc_ltype t) { return t.kind == VOID_KIND; }

const aggregate *aggregate_of(const compiler *cs, sc_ltype t)
{
    return &cs->types[(t.kind - AGG_KIND) * 256 + t.rows];
}

int is_array(const compiler *cs, sc_ltype t)
{
    return is_aggregate(t) && aggregate_of(cs, t)->length > 0;
}

int is_struct(const compiler *cs, sc_ltype t)
{
    return is_aggregate(t) && aggregate_of(cs, t)->length == 0;
}

int type_size(const compiler *cs, sc_ltype t)
{
    return is_aggregate(t) ? aggregate_of(cs, t)->size : sc_ltype_size(t);
}

static int type_depth(const compiler *cs, sc_ltype t)
{
    return is_aggregate(t) ? aggregate_of(cs, t)->depth : 0;
}

const char *type_str(const compiler *cs, sc_ltype t, char *buf)
{
    return is_aggregate(t) ? aggregate_of(cs, t)->name : sc_ltype_name(t, buf, 16);
}

/* A new entry of the table; its type in *t. */
static aggregate *new_aggregate(compiler *cs, const ltoken *at, sc_ltype *t)
{
    if (cs->n_types == MAX_AGG_TYPES) {
        fail_at(cs, at, "too many array and structure types (at most %d)", MAX_AGG_TYPES);
        return NULL;
    }
    if (sc_expr_grow((void **)&cs->types, &cs->cap_types, cs->n_types + 1, sizeof *cs->types) < 0) {
        fail_at(cs, NULL, "out of memory");
        return NULL;
    }
    int i = cs->n_types++;
    *t = sc_lt((sc_kind)(AGG_KIND + i / 256), 0, i % 256);
    aggregate *a = &cs->types[i];
    memset(a, 0, sizeof *a);
    return a;
}

int array_of(compiler *cs, const ltoken *at, sc_ltype elem, int length, sc_ltype *out)
{
    char eb[16];
    if (is_array(cs, elem))
        return fail_at(cs, at, "an array of arrays (%s[%d]): GLSL ES 3.00 has one dimension",
                       type_str(cs, elem, eb), length);
    for (int i = 0; i < cs->n_types; i++)
        if (cs->types[i].length == length && sc_lt_equal(cs->types[i].elem, elem)) {
            *out = sc_lt((sc_kind)(AGG_KIND + i / 256), 0, i % 256);
            return 0;
        }
    int elem_size = type_size(cs, elem);
    if (length > MAX_REGS / elem_size)
        return fail_at(cs, at, "array too large (more than %d registers)", MAX_REGS);
    if (type_depth(cs, elem) >= MAX_TYPE_DEPTH)
        return fail_at(cs, at, "types nested too deeply (more than %d levels)", MAX_TYPE_DEPTH);
    aggregate *a = new_aggregate(cs, at, out);
    if (!a)
        return -1;
    snprintf(a->name, sizeof a->name, "%.64s[%d]", type_str(cs, elem, eb), length);
    a->size = elem_size * length;
    a->depth = type_depth(cs, elem) + 1;
    a->elem = elem;
    a->length = length;
    return 0;
}

/* ---- parsing types ---- */

/* An array's size: a constant integer expression above 0. */
static int parse_array_size(compiler *cs, int *length)
{
    ltoken at = cs->tok;
    operand n;
    if (parse_assignment(cs, &n) < 0)
        return -1;
    if (!n.is_literal || !sc_lt_is_integer(n.type) || !sc_lt_is_scalar(n.type))
        return fail_at(cs, &at, "an array's size must be a constant integer expression");
    if (!(n.literal > 0 && n.literal <= MAX_REGS))
        return fail_at(cs, &at, "an array's size must be from 1 to %d, not %.0f", MAX_REGS,
                       n.literal);
    *length = (int)n.literal;
    return 0;
}

int parse_array_suffix(compiler *cs, sc_ltype t, sc_ltype *out, int *unsized)
{
    ltoken bracket = cs->tok;
    int length = 0;
    next(cs); /* '[' */
    if (is_punct(cs, ']')) {
        if (!unsized)
            return fail_at(cs, &bracket, "an array's size is needed here");
        *unsized = 1;
        *out = t;
        next(cs);
        return is_punct(cs, '[') ? fail_at(cs, &cs->tok, "arrays of arrays are not GLSL ES 3.00")
                                 : 0;
    }
    if (parse_array_size(cs, &length) < 0 || expect(cs, ']', "']' after the array's size") < 0 ||
        array_of(cs, &bracket, t, length, out) < 0)
        return -1;
    if (is_punct(cs, '['))
        return fail_at(cs, &cs->tok, "arrays of arrays are not GLSL ES 3.00");
    return 0;
}

const variable *find_struct(const compiler *cs, const char *s, int len)
{
    const variable *v = find_variable(cs, s, len);
    return v && v->is_type ? v : NULL;
}

static int find_member(const compiler *cs, const aggregate *a, const ltoken *name)
{
    for (int i = a->first; i < a->first + a->count; i++)
        if ((int)strlen(cs->members[i].name) == name->len &&
            strncmp(cs->members[i].name, name->start, (size_t)name->len) == 0)
            return i;
    return -1;
}

static int add_member(compiler *cs, int index, sc_ltype t, const ltoken *name)
{
    aggregate *a = &cs->types[index];
    if (name->len >= MAX_NAME)
        return fail_at(cs, name, "name '%.20s...' is too long", name->start);
    if (find_member(cs, a, name) >= 0)
        return fail_at(cs, name, "structure '%s' already has a member '%.*s'", a->name, name->len,
                       name->start);
    if (type_size(cs, t) > MAX_REGS - a->size)
        return fail_at(cs, name, "structure too large (more than %d registers)", MAX_REGS);
    if (sc_expr_grow((void **)&cs->members, &cs->cap_members, cs->n_members + 1,
                     sizeof *cs->members) < 0)
        return fail_at(cs, NULL, "out of memory");
    member *m = &cs->members[cs->n_members++];
    memset(m, 0, sizeof *m);
    memcpy(m->name, name->start, (size_t)name->len);
    m->type = t;
    m->offset = a->size;
    a->size += type_size(cs, t);
    a->count++;
    if (type_depth(cs, t) + 1 > a->depth)
        a->depth = type_depth(cs, t) + 1;
    return 0;
}

/* One member declaration: [precision] TYPE NAME [ '[' N ']' ] { ',' NAME ... } ';'. */
static int parse_member_declaration(compiler *cs, int index)
{
    sc_ltype t;
    if (is_word(cs, "struct"))
        return fail_at(cs, &cs->tok, "a structure cannot be defined inside another (GLSL ES)");
    if (is_word(cs, "const") || is_word(cs, "in") || is_word(cs, "out") || is_word(cs, "inout"))
        return fail_at(cs, &cs->tok, "a structure's members take no qualifier but a precision");
    if (parse_type(cs, &t, 0) < 0)
        return -1;
    for (;;) {
        ltoken name = cs->tok;
        sc_ltype mt = t;
        if (name.kind != T_IDENT)
            return fail_expected(cs, "a member name");
        next(cs);
        if (is_punct(cs, '[') &&
            (is_array(cs, t) ? fail_at(cs, &cs->tok, "arrays of arrays are not GLSL ES 3.00")
                             : parse_array_suffix(cs, t, &mt, NULL)) < 0)
            return -1;
        if (type_depth(cs, mt) >= MAX_TYPE_DEPTH)
            return fail_at(cs, &name, "types nested too deeply (more than %d levels)",
                           MAX_TYPE_DEPTH);
        if (add_member(cs, index, mt, &name) < 0)
            return -1;
        if (is_punct(cs, '='))
            return fail_at(cs, &cs->tok, "a structure's members cannot have initializers");
        if (!is_punct(cs, ','))
            return expect(cs, ';', "';' after the member");
        next(cs);
    }
}

int parse_struct(compiler *cs, sc_ltype *t)
{
    ltoken kw = cs->tok;
    next(cs); /* struct */
    ltoken name = cs->tok;
    if (name.kind != T_IDENT)
        return fail_at(cs, &kw, "a structure needs a name (GLSL ES has no anonymous ones)");
    next(cs);
    if (expect(cs, '{', "'{' after the structure's name") < 0)
        return -1;
    aggregate *a = new_aggregate(cs, &name, t);
    if (!a)
        return -1;
    int index = cs->n_types - 1;
    snprintf(a->name, sizeof a->name, "%.*s", name.len < MAX_NAME ? name.len : MAX_NAME - 1,
             name.start);
    a->first = cs->n_members;
    if (is_punct(cs, '}'))
        return fail_at(cs, &cs->tok, "structure '%s' has no member", a->name);
    while (!is_punct(cs, '}'))
        if (parse_member_declaration(cs, index) < 0)
            return -1;
    next(cs);
    /* the name is declared after the body: a member cannot have the structure's own type */
    if (bind_variable(cs, &name, *t, 1, -1) < 0)
        return -1;
    cs->vars[cs->n_vars - 1].is_type = 1;
    return 0;
}

/* ---- values ---- */

operand part_of(const operand *o, sc_ltype t, int offset)
{
    operand r = *o;
    r.type = t;
    r.reg = o->reg + offset;
    r.is_literal = 0;
    r.is_assignment = 0;
    r.lv_reg = o->lv_reg + o->lv_comp[0] + offset;
    memset(r.lv_comp, 0, sizeof r.lv_comp);
    for (int k = 0; k < sc_ltype_size(t) && !is_aggregate(t); k++)
        r.lv_comp[k] = (unsigned char)k;
    return r;
}

int not_aggregate(compiler *cs, const ltoken *op, const char *op_name, const operand *o)
{
    char tb[16];
    if (is_aggregate(o->type))
        return fail_at(cs, op, "operator '%s' cannot apply to %s", op_name,
                       type_str(cs, o->type, tb));
    return 0;
}

int parse_member(compiler *cs, operand *o)
{
    ltoken dot = cs->tok;
    next(cs);
    ltoken name = cs->tok;
    const aggregate *a = aggregate_of(cs, o->type);
    if (name.kind != T_IDENT)
        return fail_expected(cs, "a member name after '.'");
    int i = find_member(cs, a, &name);
    if (i < 0)
        return fail_at(cs, &dot, "structure '%s' has no member '%.*s'", a->name, name.len,
                       name.start);
    next(cs);
    *o = part_of(o, cs->members[i].type, cs->members[i].offset);
    return 0;
}

/* Copies argument `arg` (converted to t where the dialect allows) to register dst. */
static int place_argument(compiler *cs, const ltoken *at, const char *what, int i, sc_ltype t,
                          operand *arg, int dst)
{
    char ab[16], tb[16];
    if (widen_to(cs, at, t, arg) < 0)
        return -1;
    if (!sc_lt_equal(arg->type, t))
        return fail_at(cs, at, "%s: argument %d is %s, not %s", what, i + 1,
                       type_str(cs, arg->type, ab), type_str(cs, t, tb));
    return emit_at(cs, at, OP_MOV, dst, arg->reg, 0, 0, type_size(cs, t)) < 0 ? -1 : 0;
}

static int construct_array(compiler *cs, const ltoken *at, sc_ltype t, operand *args, int n_args,
                           operand *out)
{
    const aggregate *a = aggregate_of(cs, t);
    sc_ltype elem = a->elem;
    char what[MAX_NAME + 16];
    snprintf(what, sizeof what, "%s", a->name);
    if (n_args != a->length)
        return fail_at(cs, at, "%s: expects %d arguments, got %d", what, a->length, n_args);
    int size = type_size(cs, elem), dst = alloc_regs(cs, a->size);
    if (dst < 0)
        return -1;
    for (int i = 0; i < n_args; i++)
        if (place_argument(cs, at, what, i, elem, &args[i], dst + i * size) < 0)
            return -1;
    *out = value_at(t, dst);
    return 0;
}

static int construct_struct(compiler *cs, const ltoken *at, sc_ltype t, operand *args, int n_args,
                            operand *out)
{
    const aggregate *a = aggregate_of(cs, t);
    char what[MAX_NAME + 16];
    snprintf(what, sizeof what, "%s", a->name);
    if (n_args != a->count)
        return fail_at(cs, at, "%s: expects %d arguments (one per member), got %d", what, a->count,
                       n_args);
    int first = a->first, dst = alloc_regs(cs, a->size);
    if (dst < 0)
        return -1;
    for (int i = 0; i < n_args; i++) {
        const member *m = &cs->members[first + i];
        if (place_argument(cs, at, what, i, m->type, &args[i], dst + m->offset) < 0)
            return -1;
    }
    *out = value_at(t, dst);
    return 0;
}

int construct_aggregate(compiler *cs, const ltoken *at, sc_ltype t, int unsized, operand *args,
                        int n_args, operand *out)
{
    if (unsized) {
        if (n_args == 0)
            return fail_at(cs, at, "an array constructor needs at least one argument");
        if (array_of(cs, at, t, n_args, &t) < 0)
            return -1;
    }
    if (is_array(cs, t))
        return construct_array(cs, at, t, args, n_args, out);
    return construct_struct(cs, at, t, args, n_args, out);
}

/* ---- printing at the top level ---- */

/* Appends text to the labels; its offset in them, or -1. */
static int add_label(compiler *cs, const char *text, int len)
{
    if (cs->n_labels > (1 << 24) - len - 1)
        return fail_at(cs, NULL, "too many printed values");
    if (sc_expr_grow((void **)&cs->labels, &cs->cap_labels, cs->n_labels + len + 1, 1) < 0)
        return fail_at(cs, NULL, "out of memory");
    memcpy(cs->labels + cs->n_labels, text, (size_t)len);
    cs->labels[cs->n_labels + len] = '\0';
    cs->n_labels += len + 1;
    return cs->n_labels - len - 1;
}

static int add_emit(compiler *cs, int start, int len, sc_ltype t)
{
    sc_program *pr = cs->prog;
    if (sc_expr_grow((void **)&pr->emits, &pr->cap_emits, pr->n_emits + 1, sizeof *pr->emits) < 0)
        return fail_at(cs, NULL, "out of memory");
    pr->emits[pr->n_emits] = (emit_site){start, len, t};
    return pr->n_emits++;
}

static int emit_leaf(compiler *cs, const ltoken *at, const char *name, int len, sc_ltype t, int reg)
{
    int label = add_label(cs, name, len);
    int site = label < 0 ? -1 : add_emit(cs, cs->src_len + 1 + label, len, t);
    return site < 0 || emit_at(cs, at, OP_EMIT, 0, reg, 0, site, 0) < 0 ? -1 : 0;
}

typedef struct {
    char name[4096];
    int len;
    int printed;
} leaf_walk;

/* Each scalar, vector or matrix inside type t at reg, named by w->name plus its path; the
 * recursion is bounded by MAX_TYPE_DEPTH. */
static int emit_leaves(compiler *cs, const ltoken *at, leaf_walk *w, sc_ltype t, int reg)
{
    if (!is_aggregate(t)) {
        if (++w->printed > MAX_PRINTED)
            return fail_at(cs, at, "more than %d values to print: print parts of it", MAX_PRINTED);
        return emit_leaf(cs, at, w->name, w->len, t, reg);
    }
    const aggregate *a = aggregate_of(cs, t);
    int len = w->len, n = a->length ? a->length : a->count;
    for (int i = 0; i < n; i++) {
        const member *m = a->length ? NULL : &cs->members[a->first + i];
        int room = (int)sizeof w->name - len;
        int add = m ? snprintf(w->name + len, (size_t)room, ".%s", m->name)
                    : snprintf(w->name + len, (size_t)room, "[%d]", i);
        if (add >= room)
            return fail_at(cs, at, "the printed value's name is too long");
        w->len = len + add;
        sc_ltype part = m ? m->type : a->elem;
        int offset = m ? m->offset : i * type_size(cs, a->elem);
        if (emit_leaves(cs, at, w, part, reg + offset) < 0)
            return -1;
    }
    w->len = len;
    return 0;
}

int emit_value(compiler *cs, const ltoken *first, const char *end, const operand *v)
{
    int len = (int)(end - first->start);
    if (!is_aggregate(v->type)) {
        int site = add_emit(cs, (int)(first->start - cs->src), len, v->type);
        return site < 0 || emit_at(cs, first, OP_EMIT, 0, v->reg, 0, site, 0) < 0 ? -1 : 0;
    }
    static const char dots[] = "(...)";
    leaf_walk w;
    w.printed = 0;
    w.len = len < 2048 ? len : (int)sizeof dots - 1;
    memcpy(w.name, len < 2048 ? first->start : dots, (size_t)w.len);
    return emit_leaves(cs, first, &w, v->type, v->reg);
}

int attach_labels(compiler *cs)
{
    sc_program *pr = cs->prog;
    if (cs->n_labels == 0)
        return 0;
    char *src = realloc(pr->src, (size_t)cs->src_len + 1 + (size_t)cs->n_labels);
    if (!src)
        return fail_at(cs, NULL, "out of memory");
    memcpy(src + cs->src_len + 1, cs->labels, (size_t)cs->n_labels);
    pr->src = src;
    cs->src = src;
    return 0;
}
