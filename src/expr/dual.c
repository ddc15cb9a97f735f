/* Forward-mode automatic differentiation of a compiled expression (shadecalc/expr.h,
 * sc_expr_eval_dual): the flat program of eval.c run with dual values (a value and SC_DUAL_DIRS
 * tangents). Values are computed exactly as sc_expr_eval in double precision; each node adds
 * its derivative rule. Linear nodes (+, −, negation, constructors, swizzles, indexing,
 * transpose) apply themselves to the tangents; bilinear ones (*, dot, cross, outerProduct,
 * matrixCompMult) follow the product rule d(a∘b) = da∘b + a∘db; the rest have explicit rules. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "expr/expr_internal.h"

static const double PI = 3.14159265358979323846, LN2 = 0.69314718055994530942;

static sc_value zero_of(sc_type t) { return (sc_value){t, {0}}; }

static sc_dual_value constant(sc_value x)
{
    sc_dual_value out = {x, {zero_of(x.type), zero_of(x.type)}};
    return out;
}

/* Component k of v, a float broadcasting to every k. */
static double comp(const sc_value *v, int k) { return v->v[v->type == SC_FLOAT ? 0 : k]; }

static sc_value binary(int op, sc_type type, const sc_value *a, const sc_value *b)
{
    return sc_expr_binary(SC_DOUBLE, op, type, a, b);
}

static sc_value add(const sc_value *a, const sc_value *b) { return binary('+', a->type, a, b); }

static sc_value scaled(const sc_value *a, double s)
{
    return binary('*', a->type, a, &(sc_value){SC_FLOAT, {s}});
}

/* ---- arithmetic ---- */

/* Component-wise a / b (GLSL divides matrices component-wise too): d(a/b) = (da − q·db)/b. */
static sc_dual_value divide(sc_type type, const sc_dual_value *a, const sc_dual_value *b)
{
    sc_dual_value out = constant(zero_of(type));
    for (int k = 0; k < sc_type_size(type); k++) {
        double bk = comp(&b->x, k), q = comp(&a->x, k) / bk;
        out.x.v[k] = q;
        for (int j = 0; j < SC_DUAL_DIRS; j++)
            out.d[j].v[k] = (comp(&a->d[j], k) - q * comp(&b->d[j], k)) / bk;
    }
    return out;
}

static sc_dual_value dual_binary(int op, sc_type type, const sc_dual_value *a,
                                 const sc_dual_value *b)
{
    if (op == '/')
        return divide(type, a, b);
    sc_dual_value out;
    out.x = binary(op, type, &a->x, &b->x);
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        if (op != '*') {
            out.d[j] = binary(op, type, &a->d[j], &b->d[j]);
            continue;
        }
        sc_value left = binary('*', type, &a->d[j], &b->x);
        sc_value right = binary('*', type, &a->x, &b->d[j]);
        out.d[j] = add(&left, &right);
    }
    return out;
}

/* Constructors are affine (matN(matM) fills from the identity): a tangent is
 * construct(tangents) − construct(zeros). */
static sc_dual_value dual_construct(sc_type type, const sc_dual_value *args, int n)
{
    sc_value xs[16], ds[16], zeros[16];
    sc_dual_value out;
    for (int i = 0; i < n; i++) {
        xs[i] = args[i].x;
        zeros[i] = zero_of(args[i].x.type);
    }
    out.x = sc_construct(type, xs, n);
    sc_value offset = sc_construct(type, zeros, n);
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        for (int i = 0; i < n; i++)
            ds[i] = args[i].d[j];
        sc_value d = sc_construct(type, ds, n);
        out.d[j] = binary('-', type, &d, &offset);
    }
    return out;
}

/* ---- built-ins ---- */

typedef struct {
    int index;
    const sc_dual_value *args;
    int n_args;
    sc_value x; /* the built-in's value */
} dual_call;

static sc_value builtin(int index, const sc_value *args, int n_args)
{
    call_context ctx = {SC_DOUBLE, 0, sc_builtin_name(index), NULL, NULL};
    return sc_builtin_eval(index, &ctx, args, n_args);
}

/* The built-in applied to the values, with argument `i` replaced by its tangent along j. */
static sc_value with_tangent(const dual_call *c, int i, int j)
{
    sc_value args[3];
    for (int a = 0; a < c->n_args; a++)
        args[a] = a == i ? c->args[a].d[j] : c->args[a].x;
    return builtin(c->index, args, c->n_args);
}

/* Partial derivatives of a component-wise built-in f(a0, a1, a2) with value f. */
typedef void (*partials_fn)(const double *a, double f, double *df);

static void d_zero(const double *a, double f, double *df)
{
    (void)a;
    (void)f;
    df[0] = df[1] = df[2] = 0.0;
}
static void d_one(const double *a, double f, double *df)
{
    d_zero(a, f, df);
    df[0] = 1.0;
}
static void d_radians(const double *a, double f, double *df)
{
    (void)a;
    (void)f;
    df[0] = (PI / 180.0);
}
static void d_degrees(const double *a, double f, double *df)
{
    (void)a;
    (void)f;
    df[0] = (180.0 / PI);
}
static void d_sin(const double *a, double f, double *df)
{
    (void)f;
    df[0] = cos(a[0]);
}
static void d_cos(const double *a, double f, double *df)
{
    (void)f;
    df[0] = -sin(a[0]);
}
static void d_tan(const double *a, double f, double *df)
{
    (void)a;
    df[0] = 1.0 + f * f;
}
static void d_asin(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / sqrt(1.0 - a[0] * a[0]);
}
static void d_acos(const double *a, double f, double *df)
{
    (void)f;
    df[0] = -1.0 / sqrt(1.0 - a[0] * a[0]);
}
static void d_atan(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / (1.0 + a[0] * a[0]);
}
static void d_sinh(const double *a, double f, double *df)
{
    (void)f;
    df[0] = cosh(a[0]);
}
static void d_cosh(const double *a, double f, double *df)
{
    (void)f;
    df[0] = sinh(a[0]);
}
static void d_tanh(const double *a, double f, double *df)
{
    (void)a;
    df[0] = 1.0 - f * f;
}
static void d_asinh(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / sqrt(a[0] * a[0] + 1.0);
}
static void d_acosh(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / sqrt((a[0] - 1.0) * (a[0] + 1.0));
}
static void d_atanh(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / ((1.0 - a[0]) * (1.0 + a[0]));
}
static void d_exp(const double *a, double f, double *df)
{
    (void)a;
    df[0] = f;
}
static void d_log(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / a[0];
}
static void d_exp2(const double *a, double f, double *df)
{
    (void)a;
    df[0] = f * LN2;
}
static void d_log2(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 / (a[0] * LN2);
}
static void d_sqrt(const double *a, double f, double *df)
{
    (void)a;
    df[0] = 0.5 / f;
}
static void d_inversesqrt(const double *a, double f, double *df) { df[0] = -0.5 * f / a[0]; }
static void d_abs(const double *a, double f, double *df)
{
    (void)f;
    df[0] = a[0] > 0.0 ? 1.0 : a[0] < 0.0 ? -1.0 : 0.0;
}
/* atan(y, x): ∂/∂y = x/(x² + y²), ∂/∂x = −y/(x² + y²). */
static void d_atan2(const double *a, double f, double *df)
{
    (void)f;
    double r2 = a[0] * a[0] + a[1] * a[1];
    df[0] = a[1] / r2;
    df[1] = -a[0] / r2;
}
/* pow(x, y) = x^y: ∂/∂x = y·x^(y−1), ∂/∂y = x^y·ln x (0 where x <= 0, the limit as x → 0+). */
static void d_pow(const double *a, double f, double *df)
{
    df[0] = a[1] * pow(a[0], a[1] - 1.0);
    df[1] = a[0] > 0.0 ? f * log(a[0]) : 0.0;
}
/* mod(x, y) = x − y·floor(x/y). */
static void d_mod(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0;
    df[1] = -floor(a[0] / a[1]);
}
/* min(x, y) = y < x ? y : x and max(x, y) = x < y ? y : x (pmath.c): the branch taken. */
static void d_min(const double *a, double f, double *df)
{
    (void)f;
    df[1] = a[1] < a[0];
    df[0] = 1.0 - df[1];
}
static void d_max(const double *a, double f, double *df)
{
    (void)f;
    df[1] = a[0] < a[1];
    df[0] = 1.0 - df[1];
}
/* clamp(x, lo, hi) = min(max(x, lo), hi). */
static void d_clamp(const double *a, double f, double *df)
{
    (void)f;
    double m = a[0] < a[1] ? a[1] : a[0];
    int high = a[2] < m;
    df[2] = high;
    df[1] = !high && a[0] < a[1];
    df[0] = !high && !(a[0] < a[1]);
}
/* mix(x, y, a) = x(1 − a) + y·a. */
static void d_mix(const double *a, double f, double *df)
{
    (void)f;
    df[0] = 1.0 - a[2];
    df[1] = a[2];
    df[2] = a[1] - a[0];
}
/* smoothstep(e0, e1, x) = t²(3 − 2t), t = clamp((x − e0)/(e1 − e0), 0, 1): df/dt = 6t(1 − t),
 * ∂t/∂x = 1/w, ∂t/∂e0 = (x − e1)/w², ∂t/∂e1 = −(x − e0)/w² with w = e1 − e0, inside (0, 1). */
static void d_smoothstep(const double *a, double f, double *df)
{
    (void)f;
    double w = a[1] - a[0], t = (a[2] - a[0]) / w;
    double dfdt = (t > 0.0 && t < 1.0) ? 6.0 * t * (1.0 - t) : 0.0;
    df[0] = dfdt * (a[2] - a[1]) / (w * w);
    df[1] = -dfdt * (a[2] - a[0]) / (w * w);
    df[2] = dfdt / w;
}

/* A component-wise built-in: d out_k = Σ_i ∂f/∂a_i · d a_i,k (a float argument broadcasts). */
static sc_dual_value componentwise(const dual_call *c, partials_fn partials)
{
    sc_dual_value out = constant(c->x);
    for (int k = 0; k < sc_type_size(c->x.type); k++) {
        double a[3] = {0, 0, 0}, df[3] = {0, 0, 0};
        for (int i = 0; i < c->n_args; i++)
            a[i] = comp(&c->args[i].x, k);
        partials(a, c->x.v[k], df);
        for (int j = 0; j < SC_DUAL_DIRS; j++)
            for (int i = 0; i < c->n_args; i++)
                out.d[j].v[k] += df[i] * comp(&c->args[i].d[j], k);
    }
    return out;
}

static double vdot(const double *a, const double *b, int n)
{
    double s = 0.0;
    for (int k = 0; k < n; k++)
        s += a[k] * b[k];
    return s;
}

/* transpose: linear, d f(a) = f(da). */
static sc_dual_value rule_linear(const dual_call *c)
{
    sc_dual_value out = {c->x, {{0}}};
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        out.d[j] = with_tangent(c, 0, j);
    return out;
}

/* dot, cross, outerProduct, matrixCompMult: bilinear, d f(a, b) = f(da, b) + f(a, db). */
static sc_dual_value rule_bilinear(const dual_call *c)
{
    sc_dual_value out = {c->x, {{0}}};
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        sc_value left = with_tangent(c, 0, j), right = with_tangent(c, 1, j);
        out.d[j] = add(&left, &right);
    }
    return out;
}

/* d‖a‖ = a·da/‖a‖ (0 at a = 0, where the length has no derivative). */
static double length_tangent(const sc_value *a, const sc_value *da, double length)
{
    return length > 0.0 ? vdot(a->v, da->v, sc_type_size(a->type)) / length : 0.0;
}

static sc_dual_value rule_length(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        out.d[j].v[0] = length_tangent(&c->args[0].x, &c->args[0].d[j], c->x.v[0]);
    return out;
}

/* distance(a, b) = ‖a − b‖. */
static sc_dual_value rule_distance(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    sc_type t = c->args[0].x.type;
    sc_value diff = binary('-', t, &c->args[0].x, &c->args[1].x);
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        sc_value ddiff = binary('-', t, &c->args[0].d[j], &c->args[1].d[j]);
        out.d[j].v[0] = length_tangent(&diff, &ddiff, c->x.v[0]);
    }
    return out;
}

/* n = a/‖a‖: dn = (da − n(n·da))/‖a‖ (0 at a = 0). */
static sc_dual_value rule_normalize(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    const sc_value *a = &c->args[0].x;
    int size = sc_type_size(a->type);
    double length = sqrt(vdot(a->v, a->v, size));
    for (int j = 0; j < SC_DUAL_DIRS && length > 0.0; j++) {
        const double *da = c->args[0].d[j].v;
        double along = vdot(c->x.v, da, size);
        for (int k = 0; k < size; k++)
            out.d[j].v[k] = (da[k] - c->x.v[k] * along) / length;
    }
    return out;
}

/* faceforward(N, I, Nref) = N if Nref·I < 0, else −N: the same sign on dN. */
static sc_dual_value rule_faceforward(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    int size = sc_type_size(c->x.type);
    double sign = vdot(c->args[2].x.v, c->args[1].x.v, size) < 0.0 ? 1.0 : -1.0;
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        out.d[j] = scaled(&c->args[0].d[j], sign);
    return out;
}

/* reflect(I, N) = I − 2(N·I)N: d = dI − 2((dN·I + N·dI)N + (N·I)dN). */
static sc_dual_value rule_reflect(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    const sc_dual_value *i = &c->args[0], *n = &c->args[1];
    int size = sc_type_size(i->x.type);
    double ni = vdot(n->x.v, i->x.v, size);
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        double dni = vdot(n->d[j].v, i->x.v, size) + vdot(n->x.v, i->d[j].v, size);
        for (int k = 0; k < size; k++)
            out.d[j].v[k] = i->d[j].v[k] - 2.0 * (dni * n->x.v[k] + ni * n->d[j].v[k]);
    }
    return out;
}

/* refract(I, N, η) = ηI − (ηc + √k)N with c = N·I, k = 1 − η²(1 − c²); 0 (and dk ignored)
 * where k < 0 (total internal reflection). dk = 2η²c·dc − 2η(1 − c²)dη. */
static sc_dual_value rule_refract(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    const sc_dual_value *i = &c->args[0], *n = &c->args[1], *eta = &c->args[2];
    int size = sc_type_size(i->x.type);
    double e = eta->x.v[0], ci = vdot(n->x.v, i->x.v, size);
    double k = 1.0 - e * e * (1.0 - ci * ci), root = sqrt(k);
    for (int j = 0; j < SC_DUAL_DIRS && k >= 0.0; j++) {
        double de = eta->d[j].v[0];
        double dc = vdot(n->d[j].v, i->x.v, size) + vdot(n->x.v, i->d[j].v, size);
        double dk = 2.0 * e * e * ci * dc - 2.0 * e * (1.0 - ci * ci) * de;
        double dscale = de * ci + e * dc + (root > 0.0 ? dk / (2.0 * root) : 0.0);
        for (int m = 0; m < size; m++)
            out.d[j].v[m] = de * i->x.v[m] + e * i->d[j].v[m] - dscale * n->x.v[m] -
                            (e * ci + root) * n->d[j].v[m];
    }
    return out;
}

/* det is linear in each column: d det A = Σ_c det(A with column c replaced by dA's). */
static sc_dual_value rule_determinant(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    const sc_dual_value *a = &c->args[0];
    int n = sc_type_matrix_n(a->x.type);
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        for (int col = 0; col < n; col++) {
            sc_value m = a->x;
            memcpy(&m.v[col * n], &a->d[j].v[col * n], (size_t)n * sizeof(double));
            out.d[j].v[0] += builtin(c->index, &m, 1).v[0];
        }
    return out;
}

/* d(A⁻¹) = −A⁻¹·dA·A⁻¹. */
static sc_dual_value rule_inverse(const dual_call *c)
{
    sc_dual_value out = constant(c->x);
    sc_type t = c->x.type;
    for (int j = 0; j < SC_DUAL_DIRS; j++) {
        sc_value left = binary('*', t, &c->x, &c->args[0].d[j]);
        sc_value product = binary('*', t, &left, &c->x);
        out.d[j] = scaled(&product, -1.0);
    }
    return out;
}

/* Every built-in of builtins.c by name and arity: partial derivatives (component-wise) or a
 * rule. */
typedef struct {
    const char *name;
    int arity;
    partials_fn partials;
    sc_dual_value (*rule)(const dual_call *c);
} derivative;

/* clang-format off */
static const derivative derivatives[] = {
    {"radians", 1, d_radians, 0},   {"degrees", 1, d_degrees, 0},
    {"sin", 1, d_sin, 0},           {"cos", 1, d_cos, 0},
    {"tan", 1, d_tan, 0},           {"asin", 1, d_asin, 0},
    {"acos", 1, d_acos, 0},         {"atan", 1, d_atan, 0},
    {"atan", 2, d_atan2, 0},        {"pow", 2, d_pow, 0},
    {"sinh", 1, d_sinh, 0},         {"cosh", 1, d_cosh, 0},
    {"tanh", 1, d_tanh, 0},         {"asinh", 1, d_asinh, 0},
    {"acosh", 1, d_acosh, 0},       {"atanh", 1, d_atanh, 0},
    {"exp", 1, d_exp, 0},           {"log", 1, d_log, 0},
    {"exp2", 1, d_exp2, 0},         {"log2", 1, d_log2, 0},
    {"sqrt", 1, d_sqrt, 0},         {"inversesqrt", 1, d_inversesqrt, 0},
    {"abs", 1, d_abs, 0},           {"sign", 1, d_zero, 0},
    {"floor", 1, d_zero, 0},        {"ceil", 1, d_zero, 0},
    {"trunc", 1, d_zero, 0},        {"round", 1, d_zero, 0},
    {"roundEven", 1, d_zero, 0},
    {"fract", 1, d_one, 0},         {"mod", 2, d_mod, 0},
    {"min", 2, d_min, 0},           {"max", 2, d_max, 0},
    {"clamp", 3, d_clamp, 0},       {"mix", 3, d_mix, 0},
    {"step", 2, d_zero, 0},         {"smoothstep", 3, d_smoothstep, 0},
    {"length", 1, 0, rule_length},  {"distance", 2, 0, rule_distance},
    {"dot", 2, 0, rule_bilinear},   {"cross", 2, 0, rule_bilinear},
    {"normalize", 1, 0, rule_normalize}, {"faceforward", 3, 0, rule_faceforward},
    {"reflect", 2, 0, rule_reflect}, {"refract", 3, 0, rule_refract},
    {"matrixCompMult", 2, 0, rule_bilinear}, {"outerProduct", 2, 0, rule_bilinear},
    {"transpose", 1, 0, rule_linear}, {"determinant", 1, 0, rule_determinant},
    {"inverse", 1, 0, rule_inverse},
};
/* clang-format on */

static const derivative *derivative_of(const char *name, int arity)
{
    for (size_t i = 0; i < sizeof derivatives / sizeof derivatives[0]; i++)
        if (derivatives[i].arity == arity && strcmp(derivatives[i].name, name) == 0)
            return &derivatives[i];
    return NULL;
}

static sc_dual_value dual_builtin(int index, const sc_dual_value *args, int n_args)
{
    sc_value xs[3];
    for (int i = 0; i < n_args; i++)
        xs[i] = args[i].x;
    dual_call c = {index, args, n_args, builtin(index, xs, n_args)};
    const derivative *d = derivative_of(sc_builtin_name(index), n_args);
    if (d == NULL) /* a built-in without a rule: its value, derivative NaN (never silent 0) */
        return (sc_dual_value){c.x, {scaled(&c.x, NAN), scaled(&c.x, NAN)}};
    return d->partials ? componentwise(&c, d->partials) : d->rule(&c);
}

/* ---- the walk ---- */

static sc_dual_value negate(const sc_dual_value *a)
{
    sc_dual_value out = {scaled(&a->x, -1.0), {{0}}};
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        out.d[j] = scaled(&a->d[j], -1.0);
    return out;
}

static sc_dual_value dual_select(const expr_node *n, const sc_dual_value *base)
{
    sc_dual_value out;
    out.x = sc_expr_select(n, &base->x);
    for (int j = 0; j < SC_DUAL_DIRS; j++)
        out.d[j] = sc_expr_select(n, &base->d[j]);
    return out;
}

/* Node n from the values computed before it (its operands are values[n->base ...]). */
static sc_dual_value dual_node(const sc_dual_value *inputs, const expr_node *n,
                               const sc_dual_value *values)
{
    const sc_dual_value *args = values + n->base;
    switch (n->kind) {
    case NODE_NUMBER: return constant((sc_value){SC_FLOAT, {n->num}});
    case NODE_INPUT: return inputs[n->op];
    case NODE_SLOT: return values[n->op];
    case NODE_NEGATE: return negate(&args[0]);
    case NODE_BINARY: return dual_binary(n->op, n->type, &args[0], &args[1]);
    case NODE_CALL: return dual_builtin(n->op, args, n->count);
    case NODE_CONSTRUCT: return dual_construct(n->type, args, n->count);
    default: return dual_select(n, &args[0]);
    }
}

/* The value of e with its derivatives: one pass over the flat program (expr_internal.h); NaN
 * values and derivatives if out of memory. The values are on the C stack for small
 * expressions (the common case, no allocation), else on the heap. */
sc_dual_value sc_expr_eval_dual(const sc_expr *e, const sc_dual_value *inputs)
{
    enum { LOCAL_VALUES = 24 };
    sc_dual_value local[LOCAL_VALUES];
    sc_dual_value *values = sc_expr_values(e, sizeof *values, local, sizeof local);
    if (values == NULL) {
        sc_value nan = sc_expr_nan(sc_expr_result_type(e));
        return (sc_dual_value){nan, {nan, nan}};
    }
    for (int i = 0; i < e->n_nodes; i++)
        values[e->nodes[i].base] = dual_node(inputs, &e->nodes[i], values);
    sc_dual_value out = values[e->n_stmts];
    if (values != local)
        free(values);
    return out;
}
