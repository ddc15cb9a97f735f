/* The interpreter of compiled programs (shadecalc/lang.h, bytecode in lang_internal.h): one
 * loop over the instructions, no recursion. Floats are rounded to the precision after every
 * operation (shadecalc/pmath.h); integers are computed exactly in 64 bits and wrapped to the
 * precision's width (sc_int_bits), so no C integer operation overflows. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_vm.h"
#include "shadecalc/pmath.h"

typedef struct {
    const sc_program *prog;
    sc_prec p;
    int bits;
    double *r;
    vm_report report;
    sc_lang_error *err;
    long iterations;
} machine;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static int
runtime_error(sc_lang_error *err, const insn *in, const char *fmt, ...)
{
    va_list ap;
    err->line = in->line;
    err->column = in->column;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

int vm_index(const insn *in, double i, long long *offset, sc_lang_error *err)
{
    if (!(i >= 0 && i < in->c))
        return runtime_error(err, in, "index %lld is out of range 0..%lld", (long long)i,
                             (long long)in->c - 1);
    *offset = (long long)i * in->kind;
    return 0;
}

int vm_too_many_iterations(const insn *in, long bound, sc_lang_error *err)
{
    return runtime_error(err, in, "more than %ld loop iterations (the bound: --max-iterations)",
                         bound);
}

int vm_too_deep(const insn *in, int depth, sc_lang_error *err)
{
    return runtime_error(err, in, "calls nested too deeply (%d)", depth);
}

int vm_no_return(const insn *in, sc_lang_error *err)
{
    return runtime_error(err, in, "the function ended without 'return'");
}

static const vm_report *reporter(const machine *m) { return &m->report; }

/* ---- arithmetic on one element (shared with lang_block.c through lang_vm.h) ---- */

static void report(const vm_report *r, const insn *in, const char *func, const char *rule)
{
    if (r->fn)
        r->fn(r->user, in->line, in->column, func, rule);
}

static double float_binary(sc_prec p, int op, double a, double b)
{
    switch (op) {
    case OP_ADD: return sc_p_add(p, a, b);
    case OP_SUB: return sc_p_sub(p, a, b);
    case OP_MUL: return sc_p_mul(p, a, b);
    default: return sc_p_div(p, a, b);
    }
}

/* x / 0 and x % 0 give every bit set (int -1, uint 2^32 - 1), as Direct3D 10 defines it. */
static unsigned long long divide(const vm_report *r, const insn *in, long long a, long long b)
{
    if (b == 0) {
        report(r, in, in->op == OP_DIV ? "operator '/'" : "operator '%'", "division by zero");
        return ~0ULL;
    }
    /* |a| < 2^32: a / b and a % b fit in 64 bits (INT_MIN / -1 included) */
    return (unsigned long long)(in->op == OP_DIV ? a / b : a % b);
}

/* The shift count: b modulo 32, as GPUs and Mesa compute it; outside 0..31 is reported. */
static int shift_count(const vm_report *r, const insn *in, long long b)
{
    if (b < 0 || b > 31)
        report(r, in, in->op == OP_SHL ? "operator '<<'" : "operator '>>'",
               "shift count outside 0..31");
    return (int)((unsigned long long)b & 31u);
}

static double shift_right(sc_kind kind, long long a, int count)
{
    if (kind == SC_KIND_UINT || a >= 0)
        return (double)(a >> count);
    return (double)(-1 - ((-1 - a) >> count)); /* arithmetic shift of a negative int */
}

/* An integer operation: exact in 64 bits (operands are below 2^32 in magnitude), then wrapped. */
double vm_integer_binary(const insn *in, int bits, double x, double y, const vm_report *r)
{
    long long a = (long long)x, b = (long long)y;
    unsigned long long ua = (unsigned long long)a, ub = (unsigned long long)b, u;
    sc_kind kind = (sc_kind)in->kind;
    switch (in->op) {
    case OP_ADD: u = ua + ub; break;
    case OP_SUB: u = ua - ub; break;
    case OP_MUL: u = ua * ub; break;
    case OP_DIV:
    case OP_MOD: u = divide(r, in, a, b); break;
    case OP_BITAND: u = ua & ub; break;
    case OP_BITOR: u = ua | ub; break;
    case OP_BITXOR: u = ua ^ ub; break;
    case OP_SHL: u = ua << shift_count(r, in, b); break;
    default: return sc_int_wrap(kind, bits, shift_right(kind, a, shift_count(r, in, b)));
    }
    return sc_int_wrap_bits(kind, bits, u);
}

static void binary(const machine *m, const insn *in)
{
    double *r = m->r;
    int sa = in->flags & BCAST_A ? 0 : 1, sb = in->flags & BCAST_B ? 0 : 1;
    for (int k = 0; k < in->n; k++) {
        double a = r[in->a + k * sa], b = r[in->b + k * sb];
        r[in->dst + k] = in->kind == SC_KIND_FLOAT
                             ? float_binary(m->p, in->op, a, b)
                             : vm_integer_binary(in, m->bits, a, b, reporter(m));
    }
}

double vm_unary(const insn *in, int bits, double a)
{
    if (in->op == OP_NOT)
        return a == 0.0;
    if (in->kind == SC_KIND_FLOAT)
        return -a;
    /* an integer: its bits, complemented or negated, wrapped */
    unsigned long long u = (unsigned long long)(long long)a;
    return sc_int_wrap_bits((sc_kind)in->kind, bits, in->op == OP_BITNOT ? ~u : 0 - u);
}

static void unary(const machine *m, const insn *in)
{
    for (int k = 0; k < in->n; k++)
        m->r[in->dst + k] = vm_unary(in, m->bits, m->r[in->a + k]);
}

static void compare(const machine *m, const insn *in)
{
    double *r = m->r, a = r[in->a], b = r[in->b];
    if (in->op == OP_LT || in->op == OP_LE) {
        r[in->dst] = in->op == OP_LT ? a < b : a <= b;
        return;
    }
    int equal = 1;
    for (int k = 0; k < in->n; k++)
        equal &= r[in->a + k] == r[in->b + k];
    r[in->dst] = in->op == OP_EQ ? equal : !equal;
}

/* Element (r, c) of the product is dot(row r of a, column c of b), rounded as sc_p_dot rounds. */
void vm_matmul(sc_prec p, const int *dims, const double *a, const double *b, double *out)
{
    int rows = dims[0], inner = dims[1], cols = dims[2];
    double row[4];
    for (int c = 0; c < cols; c++)
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < inner; j++)
                row[j] = a[j * rows + i];
            out[c * rows + i] = sc_p_dot(p, row, b + c * inner, inner);
        }
}

static void matmul(const machine *m, const insn *in)
{
    const int *dims = m->prog->aux + in->c;
    double out[16];
    vm_matmul(m->p, dims, m->r + in->a, m->r + in->b, out);
    memcpy(m->r + in->dst, out, (size_t)(dims[0] * dims[2]) * sizeof *out);
}

static void convert(const machine *m, const insn *in)
{
    for (int k = 0; k < in->n; k++)
        m->r[in->dst + k] = sc_convert((sc_kind)in->kind, (sc_kind)in->kind2, m->r[in->a + k],
                                       m->p);
}

/* ---- built-ins ---- */

typedef struct {
    const vm_report *r;
    int line;
} domain_context;

static void forward_domain(void *user, int column, const char *func, const char *rule)
{
    const domain_context *d = user;
    if (d->r->fn)
        d->r->fn(d->r->user, d->line, column, func, rule);
}

void vm_builtin(sc_prec p, const builtin_call *call, const insn *in, const double *const *args,
                double *dst, const vm_report *r)
{
    if (call->is_lang) {
        sc_lang_builtin_eval(call->index, p, args, call->types, call->n_args, call->result, dst);
        return;
    }
    sc_value values[4];
    for (int i = 0; i < call->n_args; i++) {
        sc_lt_to_expr(call->types[i], &values[i].type);
        memcpy(values[i].v, args[i], (size_t)sc_ltype_size(call->types[i]) * sizeof(double));
    }
    domain_context d = {r, in->line};
    call_context ctx = {p, in->column, sc_builtin_name(call->index), forward_domain, &d};
    sc_value v = sc_builtin_eval(call->index, &ctx, values, call->n_args);
    memcpy(dst, v.v, (size_t)sc_ltype_size(call->result) * sizeof(double));
}

static void call_builtin(const machine *m, const insn *in)
{
    const builtin_call *call = &m->prog->calls[in->c];
    const double *args[4];
    for (int i = 0; i < call->n_args; i++)
        args[i] = m->r + call->args[i];
    vm_builtin(m->p, call, in, args, m->r + in->dst, reporter(m));
}

/* ---- the loop ---- */

static int emit_value(machine *m, const insn *in, sc_lang_emit_fn emit, void *user)
{
    const emit_site *site = &m->prog->emits[in->c];
    sc_lvalue v;
    memset(&v, 0, sizeof v);
    v.type = site->type;
    memcpy(v.v, m->r + in->a, (size_t)sc_ltype_size(site->type) * sizeof(double));
    return emit && emit(user, m->prog->src + site->start, site->len, in->line, &v) ? 1 : 0;
}

static int execute(machine *m, int *stack, sc_lang_emit_fn emit, void *user)
{
    const insn *code = m->prog->code;
    int sp = 0, pc = 0;
    long long offset = 0;
    for (;;) {
        const insn *in = &code[pc++];
        double *r = m->r;
        switch ((opcode)in->op) {
        case OP_MOV: memmove(r + in->dst, r + in->a, (size_t)in->n * sizeof *r); break;
        case OP_CVT: convert(m, in); break;
        case OP_ADD:
        case OP_SUB:
        case OP_MUL:
        case OP_DIV:
        case OP_MOD:
        case OP_BITAND:
        case OP_BITOR:
        case OP_BITXOR:
        case OP_SHL:
        case OP_SHR: binary(m, in); break;
        case OP_NEG:
        case OP_BITNOT:
        case OP_NOT: unary(m, in); break;
        case OP_LT:
        case OP_LE:
        case OP_EQ:
        case OP_NE: compare(m, in); break;
        case OP_MATMUL: matmul(m, in); break;
        case OP_JMP: pc = in->c; break;
        case OP_JZ: pc = r[in->a] == 0.0 ? in->c : pc; break;
        case OP_JNZ: pc = r[in->a] != 0.0 ? in->c : pc; break;
        case OP_LOOP:
            if (++m->iterations > m->prog->max_iterations)
                return vm_too_many_iterations(in, m->prog->max_iterations, m->err);
            break;
        case OP_CALL:
            if (sp > m->prog->max_call_depth)
                return vm_too_deep(in, sp, m->err);
            stack[sp++] = pc;
            pc = in->c;
            break;
        case OP_RET: pc = stack[--sp]; break;
        case OP_NORETURN: return vm_no_return(in, m->err);
        case OP_BUILTIN: call_builtin(m, in); break;
        case OP_LOAD:
            if (vm_index(in, r[in->b], &offset, m->err) < 0)
                return -1;
            memcpy(r + in->dst, r + in->a + offset, (size_t)in->n * sizeof *r);
            break;
        case OP_STORE:
            if (vm_index(in, r[in->b], &offset, m->err) < 0)
                return -1;
            memcpy(r + in->dst + offset, r + in->a, (size_t)in->n * sizeof *r);
            break;
        case OP_EMIT:
            if (emit_value(m, in, emit, user))
                return 1;
            break;
        case OP_HALT: return 0;
        }
    }
}

double vm_in_precision(sc_prec p, int bits, sc_kind kind, double x)
{
    if (kind == SC_KIND_FLOAT)
        return sc_round(p, x);
    if (kind == SC_KIND_BOOL)
        return x != 0.0;
    return sc_int_wrap(kind, bits, x);
}

double vm_constant_in_precision(sc_prec p, int bits, const constant *c)
{
    if (c->kind == SC_KIND_FLOAT)
        return sc_literal_round(p, (sc_literal){c->value, c->tie});
    return vm_in_precision(p, bits, c->kind, c->value);
}

static void load_inputs(machine *m, const sc_lvalue *inputs)
{
    const sc_program *pr = m->prog;
    for (int i = 0; i < pr->n_consts; i++)
        m->r[pr->consts[i].reg] = vm_constant_in_precision(m->p, m->bits, &pr->consts[i]);
    for (int i = 0; i < pr->n_inputs; i++)
        for (int k = 0; k < sc_ltype_size(pr->input_types[i]); k++)
            m->r[pr->input_regs[i] + k] = vm_in_precision(
                m->p, m->bits, (sc_kind)pr->input_types[i].kind, inputs[i].v[k]);
}

int sc_program_run(const sc_program *prog, sc_prec p, const sc_lvalue *inputs, sc_lang_emit_fn emit,
                   sc_lang_domain_fn on_domain, void *user, sc_lang_error *err)
{
    machine m = {prog, p, sc_int_bits(p), NULL, {on_domain, user}, err, 0};
    memset(err, 0, sizeof *err);
    m.r = calloc((size_t)prog->n_regs + 1, sizeof *m.r);
    int *stack = malloc(((size_t)prog->max_call_depth + 1) * sizeof *stack);
    int status = -1;
    if (m.r && stack) {
        load_inputs(&m, inputs);
        status = execute(&m, stack, emit, user);
    } else {
        snprintf(err->message, sizeof err->message, "out of memory");
    }
    free(m.r);
    free(stack);
    return status;
}
