/* Block execution of compiled programs (sc_program_run_block, shadecalc/lang.h).
 *
 * The register file is structure of arrays: register k of lane i is r[k·cap + i], so every
 * register is a column of `cap` lanes (elements) and an instruction's handler loops over the
 * lanes, its dispatch paid once per block. Every lane computes exactly what the interpreter of
 * one element (lang_run.c) computes: the float operations round as it rounds (the loops below
 * spell out sc_round for double and highp so that the compiler can vectorise them), and every
 * other operation calls the same element function (lang_vm.h).
 *
 * Divergence: each lane has its own instruction address (pc), call stack and iteration count
 * (shared by every lane until the block first diverges: they are then the same).
 * While every running lane is at one address the block is "uniform" and runs unmasked; when a
 * branch or a return sends lanes to different addresses, each step runs the instruction at the
 * lowest address for the lanes that are there (an execution mask, as a list of lanes), and the
 * block is uniform again when the lanes meet. Lanes are independent, so the order in which they
 * advance changes nothing in their values; the lowest address first makes the lanes that left
 * an if, a loop or a function early wait for the others where the code joins.
 *
 * Registers start at zero in a run of one element. A block does not clear its registers: a
 * register is zeroed when its first access in the block is a read or a masked write, and only
 * then (a generation number per register says whether it was written in this block), so a block
 * costs what its instructions cost. Errors stop only their lane. */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_vm.h"
#include "shadecalc/pmath.h"

#if defined(__GNUC__) && !defined(__clang__)
/* GCC's -O2 vectorises only loops whose trip count is a multiple of the vector length */
#pragma GCC optimize("vect-cost-model=cheap")
#endif

/* The opcodes this file runs are those of lang_internal.h up to OP_HALT, numbered as below. A
 * program with an opcode added after OP_HALT runs one element at a time (run_each); an opcode
 * inserted before it must be taught to this file first. */
_Static_assert(OP_SHR == 11 && OP_NOT == 14 && OP_NE == 18 && OP_HALT == 31,
               "lang_block.c: teach the block interpreter the new opcodes");

/* Lanes per block: at most MAX_LANES, and the registers of a block within REGISTER_BUDGET
 * doubles (2 MiB), so that they stay in the cache. */
enum { MAX_LANES = 256, REGISTER_BUDGET = 1 << 18, DIVERGED = -1 };

/* The lanes an instruction runs for: lanes idx[0..count), or 0..count-1 when idx is NULL (every
 * lane of the block, unmasked). */
typedef struct {
    const int *idx;
    int count;
} lanes;

/* Runs the statements after the lane set for each lane i of s (both loops plain, so that the
 * unmasked one can be vectorised). */
#define FOR_LANES(s, i, ...)                                                                       \
    do {                                                                                           \
        if ((s).idx) {                                                                             \
            for (int j_ = 0; j_ < (s).count; j_++) {                                               \
                int i = (s).idx[j_];                                                               \
                __VA_ARGS__                                                                        \
            }                                                                                      \
        } else {                                                                                   \
            for (int i = 0; i < (s).count; i++) {                                                  \
                __VA_ARGS__                                                                        \
            }                                                                                      \
        }                                                                                          \
    } while (0)

typedef struct {
    const sc_program *prog;
    const sc_lang_block *job;
    sc_prec p;
    int bits;
    int cap;   /* lanes of a column */
    int width; /* lanes of this block (<= cap) */
    int depth; /* call stack entries per lane */
    long base; /* the element of lane 0 */
    double *r;
    unsigned *gen; /* gen[k] == cur: register k was written (or zeroed) in this block */
    unsigned cur;
    int *pcs, *sps, *stack; /* per lane; pcs only while the block is not uniform */
    long *iterations;
    int lockstep; /* the block has not diverged: sps, stack, iterations of lane cap serve all */
    int *live, n_live; /* lanes still running, ascending */
    int *sel;          /* the lanes of a masked step */
    unsigned char *stopped;
    int n_stopped; /* lanes that stopped in this step (halted or failed) */
    long failed;   /* the lowest failed element, or job->n */
    sc_lang_error *err;
} block_machine;

static double *col(const block_machine *m, int reg) { return m->r + (size_t)reg * (size_t)m->cap; }

/* ---- registers not yet written in this block ---- */

/* Registers reg..reg+n-1 are read: those not written in this block are zeroed first. */
static void reading(block_machine *m, int reg, int n)
{
    for (int k = 0; k < n; k++)
        if (m->gen[reg + k] != m->cur) {
            memset(col(m, reg + k), 0, (size_t)m->width * sizeof(double));
            m->gen[reg + k] = m->cur;
        }
}

/* Registers reg..reg+n-1 are written for the lanes of s: every lane, or the others must read 0. */
static void writing(block_machine *m, lanes s, int reg, int n)
{
    if (s.idx) {
        reading(m, reg, n);
        return;
    }
    for (int k = 0; k < n; k++)
        m->gen[reg + k] = m->cur;
}

static int size_of(sc_ltype t) { return sc_ltype_size(t); }

/* The registers instruction `in` reads and writes, prepared as above. */
static void prepare(block_machine *m, const insn *in, lanes s)
{
    const int *dims;
    const builtin_call *call;
    int na = in->flags & BCAST_A ? 1 : in->n, nb = in->flags & BCAST_B ? 1 : in->n;
    if (vm_is_compare(in->op)) {
        int n = in->op == OP_LT || in->op == OP_LE ? 1 : in->n;
        reading(m, in->a, n);
        reading(m, in->b, n);
        writing(m, s, in->dst, 1);
        return;
    }
    if (vm_is_binary(in->op) || vm_is_unary(in->op) || in->op == OP_MOV || in->op == OP_CVT) {
        if (vm_is_binary(in->op))
            reading(m, in->b, nb);
        reading(m, in->a, na);
        writing(m, s, in->dst, in->n);
        return;
    }
    switch ((opcode)in->op) {
    case OP_MATMUL:
        dims = m->prog->aux + in->c;
        reading(m, in->a, dims[0] * dims[1]);
        reading(m, in->b, dims[1] * dims[2]);
        writing(m, s, in->dst, dims[0] * dims[2]);
        break;
    case OP_JZ:
    case OP_JNZ: reading(m, in->a, 1); break;
    case OP_BUILTIN:
        call = &m->prog->calls[in->c];
        for (int i = 0; i < call->n_args; i++)
            reading(m, call->args[i], size_of(call->types[i]));
        writing(m, s, in->dst, size_of(call->result));
        break;
    case OP_LOAD:
        reading(m, in->a, in->c * in->kind);
        reading(m, in->b, 1);
        writing(m, s, in->dst, in->n);
        break;
    case OP_STORE: /* writes one element of the array: the others keep their values */
        reading(m, in->a, in->n);
        reading(m, in->b, 1);
        reading(m, in->dst, in->c * in->kind);
        break;
    case OP_EMIT: reading(m, in->a, size_of(m->prog->emits[in->c].type)); break;
    default: break;
    }
}

/* ---- lanes that stop ---- */

static void stop_lane(block_machine *m, int lane)
{
    m->stopped[lane] = 1;
    m->n_stopped++;
}

/* Lane `lane` failed with *e: its element is reported if it is the lowest that failed. */
static void fail_lane(block_machine *m, int lane, const sc_lang_error *e)
{
    stop_lane(m, lane);
    if (m->base + lane < m->failed) {
        m->failed = m->base + lane;
        *m->err = *e;
    }
}

static void drop_stopped(block_machine *m)
{
    int kept = 0;
    for (int j = 0; j < m->n_live; j++) {
        int lane = m->live[j];
        if (m->stopped[lane])
            m->stopped[lane] = 0;
        else
            m->live[kept++] = lane;
    }
    m->n_live = kept;
    m->n_stopped = 0;
}

/* ---- domain reports of one lane ---- */

typedef struct {
    const block_machine *m;
    int lane;
} lane_report;

static void forward_domain(void *user, int line, int column, const char *func, const char *rule)
{
    const lane_report *l = user;
    const sc_lang_block *job = l->m->job;
    if (job->on_domain)
        job->on_domain(job->user, l->m->base + l->lane, line, column, func, rule);
}

/* ---- arithmetic over columns ---- */

#define ROUND_DOUBLE(x) (x)
#define ROUND_HIGHP(x) ((double)(float)(x)) /* sc_round(SC_HIGHP, x) */
#define ROUND_ANY(x) sc_round(p, (x))

/* d = a op b for the lanes of s, rounded by ROUND as sc_p_add ... sc_p_div round. */
#define ARITHMETIC(ROUND)                                                                          \
    switch (op) {                                                                                  \
    case OP_ADD: FOR_LANES(s, i, d[i] = ROUND(a[i] + b[i]);); break;                               \
    case OP_SUB: FOR_LANES(s, i, d[i] = ROUND(a[i] - b[i]);); break;                               \
    case OP_MUL: FOR_LANES(s, i, d[i] = ROUND(a[i] * b[i]);); break;                               \
    default: FOR_LANES(s, i, d[i] = ROUND(a[i] / b[i]);); break;                                   \
    }

static void column_arithmetic(sc_prec p, int op, double *d, const double *a, const double *b,
                              lanes s)
{
    if (p == SC_DOUBLE)
        ARITHMETIC(ROUND_DOUBLE)
    else if (p == SC_HIGHP)
        ARITHMETIC(ROUND_HIGHP)
    else
        ARITHMETIC(ROUND_ANY)
}

static double integer_lane(const block_machine *m, const insn *in, int lane, double a, double b)
{
    lane_report l = {m, lane};
    vm_report r = {forward_domain, &l};
    return vm_integer_binary(in, m->bits, a, b, &r);
}

static void op_binary(block_machine *m, const insn *in, lanes s)
{
    int sa = in->flags & BCAST_A ? 0 : 1, sb = in->flags & BCAST_B ? 0 : 1;
    for (int k = 0; k < in->n; k++) {
        double *d = col(m, in->dst + k);
        const double *a = col(m, in->a + k * sa), *b = col(m, in->b + k * sb);
        if (in->kind == SC_KIND_FLOAT) {
            column_arithmetic(m->p, in->op, d, a, b, s);
            continue;
        }
        FOR_LANES(s, i, d[i] = integer_lane(m, in, i, a[i], b[i]););
    }
}

static void op_unary(block_machine *m, const insn *in, lanes s)
{
    for (int k = 0; k < in->n; k++) {
        double *d = col(m, in->dst + k);
        const double *a = col(m, in->a + k);
        if (in->op == OP_NEG && in->kind == SC_KIND_FLOAT)
            FOR_LANES(s, i, d[i] = -a[i];);
        else
            FOR_LANES(s, i, d[i] = vm_unary(in, m->bits, a[i]););
    }
}

static void op_convert(block_machine *m, const insn *in, lanes s)
{
    sc_kind to = (sc_kind)in->kind, from = (sc_kind)in->kind2;
    for (int k = 0; k < in->n; k++) {
        double *d = col(m, in->dst + k);
        const double *a = col(m, in->a + k);
        FOR_LANES(s, i, d[i] = sc_convert(to, from, a[i], m->p););
    }
}

/* Whether the n components of a and b are equal in lane i. */
static int equal_lane(const block_machine *m, const insn *in, int lane)
{
    int equal = 1;
    for (int k = 0; k < in->n; k++)
        equal &= col(m, in->a + k)[lane] == col(m, in->b + k)[lane];
    return equal;
}

static void op_compare(block_machine *m, const insn *in, lanes s)
{
    double *d = col(m, in->dst);
    const double *a = col(m, in->a), *b = col(m, in->b);
    switch (in->op) {
    case OP_LT: FOR_LANES(s, i, d[i] = a[i] < b[i];); return;
    case OP_LE: FOR_LANES(s, i, d[i] = a[i] <= b[i];); return;
    default: break;
    }
    /* == and != of whole values: every component of a lane is read before its result is
     * written (the result may overwrite an operand) */
    FOR_LANES(s, i, d[i] = (in->op == OP_EQ) == equal_lane(m, in, i););
}

/* memmove of n registers for the lanes of s. */
static void op_move(block_machine *m, const insn *in, lanes s)
{
    if (!s.idx) {
        memmove(col(m, in->dst), col(m, in->a), (size_t)in->n * (size_t)m->cap * sizeof(double));
        return;
    }
    int forward = in->dst <= in->a;
    for (int j = 0; j < in->n; j++) {
        int k = forward ? j : in->n - 1 - j;
        double *d = col(m, in->dst + k);
        const double *a = col(m, in->a + k);
        FOR_LANES(s, i, d[i] = a[i];);
    }
}

/* n registers from `reg` of lane i into v[0..n), or back. */
static void gather(const block_machine *m, int reg, int n, int lane, double *v)
{
    for (int k = 0; k < n; k++)
        v[k] = col(m, reg + k)[lane];
}

static void scatter(block_machine *m, int reg, int n, int lane, const double *v)
{
    for (int k = 0; k < n; k++)
        col(m, reg + k)[lane] = v[k];
}

static void matmul_lane(block_machine *m, const insn *in, const int *dims, int lane)
{
    double a[16], b[16], out[16];
    gather(m, in->a, dims[0] * dims[1], lane, a);
    gather(m, in->b, dims[1] * dims[2], lane, b);
    vm_matmul(m->p, dims, a, b, out);
    scatter(m, in->dst, dims[0] * dims[2], lane, out);
}

static void op_matmul(block_machine *m, const insn *in, lanes s)
{
    const int *dims = m->prog->aux + in->c;
    FOR_LANES(s, i, matmul_lane(m, in, dims, i););
}

/* ---- built-ins ---- */

static int overlaps(int a, int na, int b, int nb) { return a < b + nb && b < a + na; }

/* Reports lane i's arguments (from the columns c) if they are outside the built-in's domain. */
static void check_domain(const block_machine *m, const insn *in, const sc_builtin_scalar *f,
                         const char *name, const double *const *c, int lane)
{
    double a[3] = {c[0][lane], c[1] ? c[1][lane] : 0, c[2] ? c[2][lane] : 0};
    const char *rule = f->domain(a);
    lane_report l = {m, lane};
    if (rule)
        forward_domain(&l, in->line, in->column, name, rule);
}

/* ---- column forms of the cheap component-wise built-ins ---- */

/* mix, clamp, min, max and sqrt in highp, as sc_p_mix ... sc_p_sqrt compute them: the binary32
 * function of src/math/common.c and sqrt.c on the arguments rounded to binary32 (the same
 * operations in the same order), the result exact in binary64. */
#define F32(x) ((float)(x))
static void column_highp(const sc_builtin_scalar *f, double *d, const double *const *c, lanes s)
{
    const double *x = c[0], *y = c[1], *z = c[2];
    if (f->f3 == sc_p_mix)
        FOR_LANES(s, i, d[i] = (double)(F32(x[i]) * (1.0f - F32(z[i])) + F32(y[i]) * F32(z[i])););
    else if (f->f3 == sc_p_clamp)
        FOR_LANES(s, i, float v = F32(x[i]) < F32(y[i]) ? F32(y[i]) : F32(x[i]);
                  d[i] = (double)(F32(z[i]) < v ? F32(z[i]) : v););
    else if (f->f2 == sc_p_min)
        FOR_LANES(s, i, d[i] = (double)(F32(y[i]) < F32(x[i]) ? F32(y[i]) : F32(x[i])););
    else if (f->f2 == sc_p_max)
        FOR_LANES(s, i, d[i] = (double)(F32(x[i]) < F32(y[i]) ? F32(y[i]) : F32(x[i])););
    else
        FOR_LANES(s, i, d[i] = (double)F32(sqrt((double)F32(x[i]))););
}

/* The same in double: the GLSL ES §8.3 defining formulas of src/pmath.c in binary64. */
static void column_double(const sc_builtin_scalar *f, double *d, const double *const *c, lanes s)
{
    const double *x = c[0], *y = c[1], *z = c[2];
    if (f->f3 == sc_p_mix)
        FOR_LANES(s, i, d[i] = x[i] * (1.0 - z[i]) + y[i] * z[i];);
    else if (f->f3 == sc_p_clamp)
        FOR_LANES(s, i, double v = x[i] < y[i] ? y[i] : x[i]; d[i] = z[i] < v ? z[i] : v;);
    else if (f->f2 == sc_p_min)
        FOR_LANES(s, i, d[i] = y[i] < x[i] ? y[i] : x[i];);
    else if (f->f2 == sc_p_max)
        FOR_LANES(s, i, d[i] = x[i] < y[i] ? y[i] : x[i];);
    else
        FOR_LANES(s, i, d[i] = sqrt(x[i]););
}

static int has_column_form(sc_prec p, const sc_builtin_scalar *f)
{
    return (p == SC_HIGHP || p == SC_DOUBLE) &&
           (f->f3 == sc_p_mix || f->f3 == sc_p_clamp || f->f2 == sc_p_min || f->f2 == sc_p_max ||
            f->f1 == sc_p_sqrt);
}

/* Whether the columns c[0..n) hold the same bits in every lane of s. */
static int same_in_lanes(const double *const *c, int n, lanes s)
{
    int first = s.idx ? s.idx[0] : 0, differ = 0;
    for (int j = 0; j < n; j++) {
        const double *x = c[j];
        FOR_LANES(s, i, differ |= memcmp(&x[i], &x[first], sizeof *x) != 0;);
    }
    return !differ;
}

/* Column d of the scalar function f for the lanes of s. */
static void scalar_lanes(sc_prec p, const sc_builtin_scalar *f, double *d, const double *const *c,
                         lanes s)
{
    if (f->f1)
        FOR_LANES(s, i, d[i] = f->f1(p, c[0][i]););
    else if (f->f2)
        FOR_LANES(s, i, d[i] = f->f2(p, c[0][i], c[1][i]););
    else
        FOR_LANES(s, i, d[i] = f->f3(p, c[0][i], c[1][i], c[2][i]););
}

/* The same when the arguments are the same in every lane (a function of constants, such as
 * pow(baseColor.r, 2.2)): computed once. */
static void scalar_once(sc_prec p, const sc_builtin_scalar *f, double *d, const double *const *c,
                        lanes s)
{
    int first = s.idx ? s.idx[0] : 0;
    const double *x[3] = {c[0] + first, c[1] ? c[1] + first : NULL, c[2] ? c[2] + first : NULL};
    double v;
    scalar_lanes(p, f, &v, x, (lanes){NULL, 1});
    FOR_LANES(s, i, d[i] = v;);
}

/* Whether a lane of s may be outside f's domain: a vectorisable scan for sqrt and clamp (the
 * rules of their domain functions in expr/builtins.c), 1 for the others. */
static int may_leave_domain(const sc_builtin_scalar *f, const double *const *c, lanes s)
{
    int outside = 0;
    if (f->f1 == sc_p_sqrt)
        FOR_LANES(s, i, outside |= c[0][i] < 0.0;);
    else if (f->f3 == sc_p_clamp)
        FOR_LANES(s, i, outside |= c[1][i] > c[2][i];);
    else
        return 1;
    return outside;
}

/* Reports the lanes of s whose arguments are outside f's domain (checked once if the arguments
 * are the same in every lane). */
static void check_domains(const block_machine *m, const insn *in, const sc_builtin_scalar *f,
                          const double *const *c, int same, lanes s)
{
    const char *name = sc_builtin_name(m->prog->calls[in->c].index);
    if (same) {
        int first = s.idx ? s.idx[0] : 0;
        double a[3] = {c[0][first], c[1] ? c[1][first] : 0, c[2] ? c[2][first] : 0};
        if (!f->domain(a))
            return;
    } else if (!may_leave_domain(f, c, s)) {
        return;
    }
    FOR_LANES(s, i, check_domain(m, in, f, name, c, i););
}

/* A component-wise float built-in: its scalar function over each component's column. */
static void builtin_columns(block_machine *m, const insn *in, const builtin_call *call,
                            const sc_builtin_scalar *f, lanes s)
{
    sc_prec p = m->p;
    int column_form = has_column_form(p, f);
    for (int k = 0; k < size_of(call->result); k++) {
        const double *c[3] = {NULL, NULL, NULL};
        for (int j = 0; j < call->n_args; j++)
            c[j] = col(m, call->args[j] + (sc_lt_is_scalar(call->types[j]) ? 0 : k));
        double *d = col(m, in->dst + k);
        int same = !column_form && same_in_lanes(c, call->n_args, s);
        if (f->domain)
            check_domains(m, in, f, c, same, s);
        if (same)
            scalar_once(p, f, d, c, s);
        else if (!column_form)
            scalar_lanes(p, f, d, c, s);
        else if (p == SC_HIGHP)
            column_highp(f, d, c, s);
        else
            column_double(f, d, c, s);
    }
}

/* Any built-in, one lane at a time through the interpreter's element function. */
static void builtin_lane(block_machine *m, const insn *in, const builtin_call *call, int lane)
{
    double args[4][16], out[16];
    const double *pa[4];
    for (int j = 0; j < call->n_args; j++) {
        gather(m, call->args[j], size_of(call->types[j]), lane, args[j]);
        pa[j] = args[j];
    }
    lane_report l = {m, lane};
    vm_report r = {forward_domain, &l};
    vm_builtin(m->p, call, in, pa, out, &r);
    scatter(m, in->dst, size_of(call->result), lane, out);
}

static void builtin_lanes(block_machine *m, const insn *in, const builtin_call *call, lanes s)
{
    FOR_LANES(s, i, builtin_lane(m, in, call, i););
}

/* Column d = dot of the n components from registers a and b, rounded as sc_p_dot rounds it
 * (tmp: a scratch column). */
static void column_dot(block_machine *m, int a, int b, int n, double *d, double *tmp, lanes s)
{
    column_arithmetic(m->p, OP_MUL, d, col(m, a), col(m, b), s);
    for (int k = 1; k < n; k++) {
        column_arithmetic(m->p, OP_MUL, tmp, col(m, a + k), col(m, b + k), s);
        column_arithmetic(m->p, OP_ADD, d, d, tmp, s);
    }
}

/* dot, length and normalize over columns, rounded as sc_p_dot, sc_p_length and sc_p_normalize
 * round them; 0, or -1 for the other built-ins. */
static int builtin_geometric(block_machine *m, const insn *in, const builtin_call *call, lanes s)
{
    const char *name = sc_builtin_name(call->index);
    int n = size_of(call->types[0]), arg = call->args[0];
    double *tmp = col(m, m->prog->n_regs + 1), *len = col(m, m->prog->n_regs + 2);
    sc_prec p = m->p;
    if (strcmp(name, "dot") == 0) {
        column_dot(m, arg, call->args[1], n, col(m, in->dst), tmp, s);
        return 0;
    }
    if (strcmp(name, "length") != 0 && strcmp(name, "normalize") != 0)
        return -1;
    double *d = col(m, in->dst);
    column_dot(m, arg, arg, n, len, tmp, s);
    FOR_LANES(s, i, len[i] = sc_p_sqrt(p, len[i]););
    if (name[0] == 'l')
        FOR_LANES(s, i, d[i] = len[i];);
    for (int k = 0; name[0] == 'n' && k < n; k++)
        column_arithmetic(p, OP_DIV, col(m, in->dst + k), col(m, arg + k), len, s);
    return 0;
}

static void op_builtin(block_machine *m, const insn *in, lanes s)
{
    const builtin_call *call = &m->prog->calls[in->c];
    sc_builtin_scalar f;
    int separate = 1; /* the result overlaps no argument */
    for (int j = 0; j < call->n_args; j++)
        separate &= !overlaps(in->dst, size_of(call->result), call->args[j],
                              size_of(call->types[j]));
    if (!call->is_lang && separate && sc_builtin_componentwise(call->index, &f) == 0)
        builtin_columns(m, in, call, &f, s);
    else if (call->is_lang || !separate || builtin_geometric(m, in, call, s) < 0)
        builtin_lanes(m, in, call, s);
}

/* ---- indexing, values ---- */

static void index_lane(block_machine *m, const insn *in, double index, int lane)
{
    long long offset;
    sc_lang_error e;
    if (vm_index(in, index, &offset, &e) < 0) {
        fail_lane(m, lane, &e);
        return;
    }
    for (int k = 0; k < in->n; k++) {
        if (in->op == OP_LOAD)
            col(m, in->dst + k)[lane] = col(m, in->a + (int)offset + k)[lane];
        else
            col(m, in->dst + (int)offset + k)[lane] = col(m, in->a + k)[lane];
    }
}

static void op_index(block_machine *m, const insn *in, lanes s)
{
    const double *index = col(m, in->b);
    FOR_LANES(s, i, index_lane(m, in, index[i], i););
}

static void op_emit(block_machine *m, const insn *in, lanes s)
{
    if (in->c != m->job->value)
        return;
    for (int k = 0; k < size_of(m->prog->emits[in->c].type); k++) {
        double *out = m->job->out[k] + m->base;
        const double *a = col(m, in->a + k);
        FOR_LANES(s, i, out[i] = a[i];);
    }
}

/* ---- control flow: each returns the lanes' next address, or DIVERGED after setting pcs ---- */

static int branch(block_machine *m, const insn *in, int pc, lanes s)
{
    const double *c = col(m, in->a);
    int jump_on_zero = in->op == OP_JZ, taken = 0;
    FOR_LANES(s, i, taken += (c[i] == 0.0) == jump_on_zero;);
    if (taken == s.count || taken == 0)
        return taken ? in->c : pc + 1;
    FOR_LANES(s, i, m->pcs[i] = (c[i] == 0.0) == jump_on_zero ? in->c : pc + 1;);
    return DIVERGED;
}

/* Until the block first diverges, its lanes run in lockstep: they have run the same
 * instructions, so one call stack and one iteration count, those of the extra lane m->cap,
 * stand for every lane's (see diverge). */

static void fail_lanes(block_machine *m, const sc_lang_error *e, lanes s)
{
    FOR_LANES(s, i, fail_lane(m, i, e););
}

static void iteration_lane(block_machine *m, const insn *in, int lane, lanes s)
{
    long bound = m->prog->max_iterations;
    if (++m->iterations[lane] <= bound)
        return;
    sc_lang_error e;
    vm_too_many_iterations(in, bound, &e);
    fail_lanes(m, &e, s);
}

static void count_iteration(block_machine *m, const insn *in, lanes s)
{
    if (m->lockstep)
        iteration_lane(m, in, m->cap, s);
    else
        FOR_LANES(s, i, iteration_lane(m, in, i, (lanes){&i, 1}););
}

static void call_lane(block_machine *m, const insn *in, int pc, int lane, lanes s)
{
    if (m->sps[lane] <= m->prog->max_call_depth) {
        m->stack[lane * m->depth + m->sps[lane]++] = pc + 1;
        return;
    }
    sc_lang_error e;
    vm_too_deep(in, m->sps[lane], &e);
    fail_lanes(m, &e, s);
}

static int call(block_machine *m, const insn *in, int pc, lanes s)
{
    if (m->lockstep)
        call_lane(m, in, pc, m->cap, s);
    else
        FOR_LANES(s, i, call_lane(m, in, pc, i, (lanes){&i, 1}););
    return in->c;
}

static int ret(block_machine *m, lanes s)
{
    if (m->lockstep)
        return m->stack[m->cap * m->depth + --m->sps[m->cap]];
    FOR_LANES(s, i, m->pcs[i] = m->stack[i * m->depth + --m->sps[i]];);
    int first = m->pcs[s.idx ? s.idx[0] : 0], same = 1;
    FOR_LANES(s, i, same &= m->pcs[i] == first;);
    return same ? first : DIVERGED;
}

/* The lanes part: each running lane takes the shared call stack and iteration count. */
static void diverge(block_machine *m)
{
    int shared = m->cap, sp = m->sps[shared];
    for (int j = 0; j < m->n_live; j++) {
        int lane = m->live[j];
        m->sps[lane] = sp;
        m->iterations[lane] = m->iterations[shared];
        memcpy(m->stack + lane * m->depth, m->stack + shared * m->depth, (size_t)sp * sizeof(int));
    }
    m->lockstep = 0;
}

static void no_return(block_machine *m, const insn *in, lanes s)
{
    sc_lang_error e;
    vm_no_return(in, &e);
    FOR_LANES(s, i, fail_lane(m, i, &e););
}

/* Runs instruction pc for the lanes of s. */
/* The instructions other than arithmetic and comparisons. */
static int other_step(block_machine *m, const insn *in, int pc, lanes s)
{
    switch ((opcode)in->op) {
    case OP_MOV: op_move(m, in, s); break;
    case OP_CVT: op_convert(m, in, s); break;
    case OP_MATMUL: op_matmul(m, in, s); break;
    case OP_JMP: return in->c;
    case OP_JZ:
    case OP_JNZ: return branch(m, in, pc, s);
    case OP_LOOP: count_iteration(m, in, s); break;
    case OP_CALL: return call(m, in, pc, s);
    case OP_RET: return ret(m, s);
    case OP_NORETURN: no_return(m, in, s); break;
    case OP_BUILTIN: op_builtin(m, in, s); break;
    case OP_LOAD:
    case OP_STORE: op_index(m, in, s); break;
    case OP_EMIT: op_emit(m, in, s); break;
    case OP_HALT: FOR_LANES(s, i, stop_lane(m, i);); break;
    default: break; /* arithmetic and comparisons: step */
    }
    return pc + 1;
}

static int step(block_machine *m, const insn *in, int pc, lanes s)
{
    if (vm_is_binary(in->op))
        op_binary(m, in, s);
    else if (vm_is_unary(in->op))
        op_unary(m, in, s);
    else if (vm_is_compare(in->op))
        op_compare(m, in, s);
    else
        return other_step(m, in, pc, s);
    return pc + 1;
}

/* ---- the scheduler ---- */

/* The lanes at the lowest address, into m->sel; returns that address, and in *others the
 * lowest address of the other lanes (INT_MAX if none). */
static int lowest_address(block_machine *m, lanes *s, int *others)
{
    int pc = INT_MAX, count = 0;
    *others = INT_MAX;
    for (int j = 0; j < m->n_live; j++) {
        int at = m->pcs[m->live[j]];
        if (at < pc) {
            *others = pc;
            pc = at;
        } else if (at > pc && at < *others) {
            *others = at;
        }
    }
    for (int j = 0; j < m->n_live; j++)
        if (m->pcs[m->live[j]] == pc)
            m->sel[count++] = m->live[j];
    *s = (lanes){m->sel, count};
    return pc;
}

/* 1 with *pc set if every running lane is at one address. */
static int converged(const block_machine *m, int *pc)
{
    for (int j = 1; j < m->n_live; j++)
        if (m->pcs[m->live[j]] != m->pcs[m->live[0]])
            return 0;
    *pc = m->pcs[m->live[0]];
    return 1;
}

/* Runs the block's lanes to their end. Uniform: every lane at pc, unmasked. Otherwise the lanes
 * of s are at pc, the lowest address, and go on alone while they stay below `others` (the
 * lowest address of the waiting lanes); each lane's pcs entry is valid when they stop. */
static void run_lanes(block_machine *m)
{
    int uniform = 1, pc = 0, others = INT_MAX;
    lanes s = {NULL, m->width};
    while (m->n_live > 0) {
        if (uniform)
            s = (lanes){m->n_live == m->width ? NULL : m->live, m->n_live};
        const insn *in = &m->prog->code[pc];
        prepare(m, in, s);
        int next = step(m, in, pc, s), stopped = m->n_stopped;
        if (next == DIVERGED && m->lockstep)
            diverge(m);
        if (stopped)
            drop_stopped(m);
        if (m->n_live == 0)
            break;
        if (uniform && next != DIVERGED) {
            pc = next;
            continue;
        }
        if (!uniform && next != DIVERGED && !stopped && next < others) {
            pc = next; /* the same lanes go on */
            continue;
        }
        if (next != DIVERGED)
            FOR_LANES(s, i, m->pcs[i] = next;);
        uniform = converged(m, &pc);
        if (!uniform)
            pc = lowest_address(m, &s, &others);
    }
}

/* ---- blocks ---- */

/* Input column `reg` of this block from values[0..width), rounded or wrapped to the precision. */
static void fill_input(block_machine *m, int reg, const double *values, sc_kind kind)
{
    double *d = col(m, reg);
    lanes all = {NULL, m->width};
    if (kind == SC_KIND_FLOAT && m->p == SC_DOUBLE)
        memcpy(d, values, (size_t)m->width * sizeof *d);
    else if (kind == SC_KIND_FLOAT && m->p == SC_HIGHP)
        FOR_LANES(all, i, d[i] = ROUND_HIGHP(values[i]););
    else
        FOR_LANES(all, i, d[i] = vm_in_precision(m->p, m->bits, kind, values[i]););
    m->gen[reg] = m->cur;
}

/* The constants, in every lane: written by the first block, kept by the others (no instruction
 * writes a constant's register). */
static void fill_constants(block_machine *m, int first_block)
{
    const sc_program *pr = m->prog;
    for (int i = 0; i < pr->n_consts; i++) {
        int reg = pr->consts[i].reg;
        if (first_block) {
            double v = vm_constant_in_precision(m->p, m->bits, &pr->consts[i]);
            double *d = col(m, reg);
            for (int lane = 0; lane < m->cap; lane++)
                d[lane] = v;
        }
        m->gen[reg] = m->cur;
    }
}

static void start_block(block_machine *m, long base, int width)
{
    const sc_program *pr = m->prog;
    m->base = base;
    m->width = width;
    if (++m->cur == 0) { /* the generations wrapped: start them again */
        memset(m->gen, 0, (size_t)pr->n_regs * sizeof *m->gen);
        m->cur = 1;
    }
    fill_constants(m, base == 0);
    int column = 0;
    for (int i = 0; i < pr->n_inputs; i++)
        for (int k = 0; k < size_of(pr->input_types[i]); k++)
            fill_input(m, pr->input_regs[i] + k, m->job->inputs[column++] + base,
                       (sc_kind)pr->input_types[i].kind);
    for (int i = 0; i < width; i++)
        m->live[i] = i;
    m->n_live = width;
    m->lockstep = 1;
    m->sps[m->cap] = 0;
    m->iterations[m->cap] = 0;
}

static int lanes_for(const sc_program *prog, long n)
{
    long cap = REGISTER_BUDGET / ((long)prog->n_regs + 1);
    cap = cap < 1 ? 1 : cap > MAX_LANES ? MAX_LANES : cap;
    return (int)(cap < n ? cap : n);
}

static int allocate(block_machine *m)
{
    size_t cap = (size_t)m->cap, regs = (size_t)m->prog->n_regs + 1;
    m->r = malloc((regs + 2) * cap * sizeof *m->r); /* and two scratch columns */
    m->gen = calloc(regs, sizeof *m->gen);
    m->pcs = malloc(cap * sizeof *m->pcs);
    m->sps = malloc((cap + 1) * sizeof *m->sps); /* and the lockstep lane */
    m->stack = malloc((cap + 1) * (size_t)m->depth * sizeof *m->stack);
    m->iterations = malloc((cap + 1) * sizeof *m->iterations);
    m->live = malloc(cap * sizeof *m->live);
    m->sel = malloc(cap * sizeof *m->sel);
    m->stopped = calloc(cap, 1);
    return m->r && m->gen && m->pcs && m->sps && m->stack && m->iterations && m->live && m->sel &&
                   m->stopped
               ? 0
               : -1;
}

static void release(block_machine *m)
{
    free(m->r);
    free(m->gen);
    free(m->pcs);
    free(m->sps);
    free(m->stack);
    free(m->iterations);
    free(m->live);
    free(m->sel);
    free(m->stopped);
}

/* ---- one element at a time: for bytecode this file does not know ---- */

typedef struct {
    const sc_lang_block *job;
    const char *text; /* the chosen value's source text (identifies its emits) */
    long element;
} each_run;

static int capture(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    const each_run *e = user;
    (void)len, (void)line;
    for (int k = 0; text == e->text && k < sc_ltype_size(v->type); k++)
        e->job->out[k][e->element] = v->v[k];
    return 0;
}

static void forward_each(void *user, int line, int column, const char *func, const char *rule)
{
    const each_run *e = user;
    if (e->job->on_domain)
        e->job->on_domain(e->job->user, e->element, line, column, func, rule);
}

static long run_each(const sc_program *prog, const sc_lang_block *job, sc_lang_error *err)
{
    each_run e = {job, prog->src + prog->emits[job->value].start, 0};
    long failed = job->n;
    for (; e.element < job->n; e.element++) {
        sc_lvalue in[64];
        int column = 0;
        for (int i = 0; i < prog->n_inputs; i++) {
            in[i].type = prog->input_types[i];
            for (int k = 0; k < size_of(in[i].type); k++)
                in[i].v[k] = job->inputs[column++][e.element];
        }
        sc_lang_error e_err;
        if (sc_program_run(prog, job->prec, in, capture, forward_each, &e, &e_err) < 0 &&
            failed == job->n) {
            failed = e.element;
            *err = e_err;
        }
    }
    return failed;
}

static int knows_every_opcode(const sc_program *prog)
{
    for (int pc = 0; pc < prog->n_code; pc++)
        if (prog->code[pc].op > OP_HALT)
            return 0;
    return 1;
}

/* ---- the API ---- */

int sc_program_values(const sc_program *prog) { return prog->n_emits; }

sc_ltype sc_program_value_type(const sc_program *prog, int value)
{
    return prog->emits[value].type;
}

long sc_program_run_block(const sc_program *prog, const sc_lang_block *job, sc_lang_error *err)
{
    memset(err, 0, sizeof *err);
    if (job->n <= 0)
        return 0;
    if (job->value < 0 || job->value >= prog->n_emits) {
        snprintf(err->message, sizeof err->message, "the program has no value %d", job->value);
        return 0;
    }
    if (!knows_every_opcode(prog))
        return run_each(prog, job, err);
    block_machine m = {.prog = prog,
                       .job = job,
                       .p = job->prec,
                       .bits = sc_int_bits(job->prec),
                       .cap = lanes_for(prog, job->n),
                       .depth = prog->max_call_depth + 1,
                       .failed = job->n,
                       .err = err};
    if (allocate(&m) < 0) {
        release(&m);
        snprintf(err->message, sizeof err->message, "out of memory");
        return 0;
    }
    for (long base = 0; base < job->n; base += m.cap) {
        start_block(&m, base, job->n - base < m.cap ? (int)(job->n - base) : m.cap);
        run_lanes(&m);
    }
    release(&m);
    return m.failed;
}
