/* The GLSL ES 3.00 built-in functions of the expression language (§8.1–§8.6): their signatures,
 * type checking, GLSL ES domains, and evaluation through shadecalc/pmath.h. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "expr/expr_internal.h"
#include "shadecalc/pmath.h"
#include "util/text.h"

/* Signature letters, one per argument:
 *   G  the genType (float, vec2, vec3 or vec4), the same for every G and g
 *   g  the genType or float (every g of one call alike)
 *   F  float     V  a vector (vec2..vec4, every V alike)     3  vec3
 *   M  a square matrix (every M alike)
 * Result letters: G the genType, F float, M the matrix argument's type, O the matN of vecN. */
typedef double (*fn1)(sc_prec, double);
typedef double (*fn2)(sc_prec, double, double);
typedef double (*fn3)(sc_prec, double, double, double);
/* The GLSL ES domain of a component-wise built-in: NULL if the components a[] are inside it,
 * else the rule they break. */
typedef const char *(*domain_fn)(const double *a);
typedef sc_value (*eval_fn)(const call_context *ctx, const sc_value *args);

typedef struct {
    const char *name;
    const char *sig;
    char result;
    fn1 f1; /* component-wise forms: exactly one of f1 f2 f3 eval */
    fn2 f2;
    fn3 f3;
    domain_fn domain;
    eval_fn eval;
} builtin;

/* ---- GLSL ES domains (docs/formulas.md §9: undefined inputs) ---- */

static const char *log_domain(const double *a) { return a[0] <= 0.0 ? "x <= 0" : NULL; }
static const char *sqrt_domain(const double *a) { return a[0] < 0.0 ? "x < 0" : NULL; }
static const char *asin_domain(const double *a) { return fabs(a[0]) > 1.0 ? "|x| > 1" : NULL; }
static const char *acosh_domain(const double *a) { return a[0] < 1.0 ? "x < 1" : NULL; }
static const char *atanh_domain(const double *a) { return fabs(a[0]) >= 1.0 ? "|x| >= 1" : NULL; }
static const char *pow_domain(const double *a)
{
    if (a[0] < 0.0)
        return "x < 0";
    return a[0] == 0.0 && a[1] <= 0.0 ? "x = 0 and y <= 0" : NULL;
}
static const char *atan2_domain(const double *a)
{
    return a[0] == 0.0 && a[1] == 0.0 ? "y = 0 and x = 0" : NULL;
}
static const char *clamp_domain(const double *a) { return a[1] > a[2] ? "minVal > maxVal" : NULL; }
static const char *smoothstep_domain(const double *a)
{
    return a[0] >= a[1] ? "edge0 >= edge1" : NULL;
}

/* ---- geometric and matrix evaluators ---- */

static int vec_n(const sc_value *v) { return sc_type_size(v->type); }
static sc_value scalar(double x) { return (sc_value){SC_FLOAT, {x}}; }

static sc_value eval_length(const call_context *c, const sc_value *a)
{
    return scalar(sc_p_length(c->p, a[0].v, vec_n(&a[0])));
}
static sc_value eval_distance(const call_context *c, const sc_value *a)
{
    return scalar(sc_p_distance(c->p, a[0].v, a[1].v, vec_n(&a[0])));
}
static sc_value eval_dot(const call_context *c, const sc_value *a)
{
    return scalar(sc_p_dot(c->p, a[0].v, a[1].v, vec_n(&a[0])));
}
static sc_value eval_cross(const call_context *c, const sc_value *a)
{
    sc_value out = {SC_VEC3, {0}};
    sc_p_cross(c->p, a[0].v, a[1].v, out.v);
    return out;
}
static sc_value eval_normalize(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    sc_p_normalize(c->p, a[0].v, vec_n(&a[0]), out.v);
    return out;
}
static sc_value eval_faceforward(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    sc_p_faceforward(c->p, a[0].v, a[1].v, a[2].v, vec_n(&a[0]), out.v);
    return out;
}
static sc_value eval_reflect(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    sc_p_reflect(c->p, a[0].v, a[1].v, vec_n(&a[0]), out.v);
    return out;
}
static sc_value eval_refract(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    sc_p_refract(c->p, a[0].v, a[1].v, a[2].v[0], vec_n(&a[0]), out.v);
    return out;
}
static sc_value eval_comp_mult(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    sc_p_comp_mult(c->p, a[0].v, a[1].v, sc_type_matrix_n(a[0].type), out.v);
    return out;
}
static sc_value eval_outer(const call_context *c, const sc_value *a)
{
    int n = vec_n(&a[0]);
    sc_value out = {(sc_type)(SC_MAT2 + n - 2), {0}};
    sc_p_outer(c->p, a[0].v, a[1].v, n, out.v);
    return out;
}
static sc_value eval_transpose(const call_context *c, const sc_value *a)
{
    (void)c;
    sc_value out = a[0];
    sc_p_transpose(a[0].v, sc_type_matrix_n(a[0].type), out.v);
    return out;
}
static sc_value eval_determinant(const call_context *c, const sc_value *a)
{
    return scalar(sc_p_determinant(c->p, a[0].v, sc_type_matrix_n(a[0].type)));
}
static sc_value eval_inverse(const call_context *c, const sc_value *a)
{
    sc_value out = a[0];
    double det = sc_p_inverse(c->p, a[0].v, sc_type_matrix_n(a[0].type), out.v);
    if (det == 0.0 && c->on_domain)
        c->on_domain(c->user, c->column, c->name, "the matrix is singular");
    return out;
}

/* clang-format off */
static const builtin builtins[] = {
    {"radians", "G", 'G', sc_p_radians, 0, 0, 0, 0},
    {"degrees", "G", 'G', sc_p_degrees, 0, 0, 0, 0},
    {"sin", "G", 'G', sc_p_sin, 0, 0, 0, 0},
    {"cos", "G", 'G', sc_p_cos, 0, 0, 0, 0},
    {"tan", "G", 'G', sc_p_tan, 0, 0, 0, 0},
    {"asin", "G", 'G', sc_p_asin, 0, 0, asin_domain, 0},
    {"acos", "G", 'G', sc_p_acos, 0, 0, asin_domain, 0},
    {"atan", "G", 'G', sc_p_atan, 0, 0, 0, 0},
    {"atan", "GG", 'G', 0, sc_p_atan2, 0, atan2_domain, 0},
    {"sinh", "G", 'G', sc_p_sinh, 0, 0, 0, 0},
    {"cosh", "G", 'G', sc_p_cosh, 0, 0, 0, 0},
    {"tanh", "G", 'G', sc_p_tanh, 0, 0, 0, 0},
    {"asinh", "G", 'G', sc_p_asinh, 0, 0, 0, 0},
    {"acosh", "G", 'G', sc_p_acosh, 0, 0, acosh_domain, 0},
    {"atanh", "G", 'G', sc_p_atanh, 0, 0, atanh_domain, 0},
    {"pow", "GG", 'G', 0, sc_p_pow, 0, pow_domain, 0},
    {"exp", "G", 'G', sc_p_exp, 0, 0, 0, 0},
    {"log", "G", 'G', sc_p_log, 0, 0, log_domain, 0},
    {"exp2", "G", 'G', sc_p_exp2, 0, 0, 0, 0},
    {"log2", "G", 'G', sc_p_log2, 0, 0, log_domain, 0},
    {"sqrt", "G", 'G', sc_p_sqrt, 0, 0, sqrt_domain, 0},
    {"inversesqrt", "G", 'G', sc_p_inversesqrt, 0, 0, log_domain, 0},
    {"abs", "G", 'G', sc_p_abs, 0, 0, 0, 0},
    {"sign", "G", 'G', sc_p_sign, 0, 0, 0, 0},
    {"floor", "G", 'G', sc_p_floor, 0, 0, 0, 0},
    {"ceil", "G", 'G', sc_p_ceil, 0, 0, 0, 0},
    {"trunc", "G", 'G', sc_p_trunc, 0, 0, 0, 0},
    {"round", "G", 'G', sc_p_round, 0, 0, 0, 0},
    {"roundEven", "G", 'G', sc_p_roundeven, 0, 0, 0, 0},
    {"fract", "G", 'G', sc_p_fract, 0, 0, 0, 0},
    {"mod", "Gg", 'G', 0, sc_p_mod, 0, 0, 0},
    {"min", "Gg", 'G', 0, sc_p_min, 0, 0, 0},
    {"max", "Gg", 'G', 0, sc_p_max, 0, 0, 0},
    {"clamp", "Ggg", 'G', 0, 0, sc_p_clamp, clamp_domain, 0},
    {"mix", "GGg", 'G', 0, 0, sc_p_mix, 0, 0},
    {"step", "gG", 'G', 0, sc_p_step, 0, 0, 0},
    {"smoothstep", "ggG", 'G', 0, 0, sc_p_smoothstep, smoothstep_domain, 0},
    {"length", "G", 'F', 0, 0, 0, 0, eval_length},
    {"distance", "GG", 'F', 0, 0, 0, 0, eval_distance},
    {"dot", "GG", 'F', 0, 0, 0, 0, eval_dot},
    {"cross", "33", 'G', 0, 0, 0, 0, eval_cross},
    {"normalize", "G", 'G', 0, 0, 0, 0, eval_normalize},
    {"faceforward", "GGG", 'G', 0, 0, 0, 0, eval_faceforward},
    {"reflect", "GG", 'G', 0, 0, 0, 0, eval_reflect},
    {"refract", "GGF", 'G', 0, 0, 0, 0, eval_refract},
    {"matrixCompMult", "MM", 'M', 0, 0, 0, 0, eval_comp_mult},
    {"outerProduct", "VV", 'O', 0, 0, 0, 0, eval_outer},
    {"transpose", "M", 'M', 0, 0, 0, 0, eval_transpose},
    {"determinant", "M", 'F', 0, 0, 0, 0, eval_determinant},
    {"inverse", "M", 'M', 0, 0, 0, 0, eval_inverse},
};
/* clang-format on */
enum { N_BUILTINS = (int)(sizeof builtins / sizeof builtins[0]) };

const char *sc_builtin_name(int index) { return builtins[index].name; }

static int name_is(const char *name, const char *s, int len)
{
    return (int)strlen(name) == len && strncmp(name, s, (size_t)len) == 0;
}

int sc_builtin_exists(const char *name, int name_len)
{
    for (int i = 0; i < N_BUILTINS; i++)
        if (name_is(builtins[i].name, name, name_len))
            return 1;
    return 0;
}

static int is_gentype(sc_type t) { return t <= SC_VEC4; }

/* "unknown function 'NAME'", with the closest built-in's name when one is near. */
static void unknown_function(const char *name, int name_len, char *msg, int msg_size)
{
    char word[64];
    snprintf(word, sizeof word, "%.*s", name_len, name);
    sc_suggestion s;
    sc_suggest_init(&s, word);
    for (int i = 0; i < N_BUILTINS; i++)
        sc_suggest_consider(&s, builtins[i].name);
    const char *best = sc_suggest_best(&s);
    snprintf(msg, (size_t)msg_size, "unknown function '%s'%s%s%s", word,
             best ? " (did you mean '" : "", best ? best : "", best ? "'?)" : "");
}

/* What a signature letter accepts, for messages. */
static const char *letter_wants(char letter)
{
    switch (letter) {
    case 'F': return "float";
    case 'V': return "a vector";
    case '3': return "vec3";
    case 'M': return "a matrix";
    default: return "float or a vector";
    }
}

static int letter_accepts(char letter, sc_type t)
{
    switch (letter) {
    case 'F': return t == SC_FLOAT;
    case 'V': return sc_type_is_vector(t);
    case '3': return t == SC_VEC3;
    case 'M': return sc_type_matrix_n(t) != 0;
    default: return is_gentype(t);
    }
}

/* The first argument with letter `want` (or -1). */
static int first_with(const char *sig, char want)
{
    const char *at = strchr(sig, want);
    return at ? (int)(at - sig) : -1;
}

/* Checks that every argument with a letter in `letters` has the type of the first such one. */
static int same_types(const builtin *b, const sc_type *args, const char *letters, char *msg,
                      int msg_size)
{
    int first = -1;
    for (int i = 0; b->sig[i]; i++) {
        if (!strchr(letters, b->sig[i]))
            continue;
        if (first < 0)
            first = i;
        else if (args[i] != args[first]) {
            snprintf(msg, (size_t)msg_size, "%s: arguments %s and %s must have the same type",
                     b->name, sc_type_name(args[first]), sc_type_name(args[i]));
            return -1;
        }
    }
    return 0;
}

static int check_signature(const builtin *b, const sc_type *args, char *msg, int msg_size)
{
    for (int i = 0; b->sig[i]; i++)
        if (!letter_accepts(b->sig[i], args[i])) {
            snprintf(msg, (size_t)msg_size, "%s: argument %d is %s, expected %s", b->name, i + 1,
                     sc_type_name(args[i]), letter_wants(b->sig[i]));
            return -1;
        }
    if (same_types(b, args, "G3VM", msg, msg_size) < 0)
        return -1;
    /* Each g is float or the genType; all g of a call alike. */
    int g = first_with(b->sig, 'g'), gen = first_with(b->sig, 'G');
    for (int i = 0; g >= 0 && b->sig[i]; i++) {
        if (b->sig[i] != 'g')
            continue;
        if (args[i] != args[g] || (args[i] != SC_FLOAT && args[i] != args[gen])) {
            snprintf(msg, (size_t)msg_size, "%s: argument %d is %s, expected float or %s", b->name,
                     i + 1, sc_type_name(args[i]), sc_type_name(args[gen]));
            return -1;
        }
    }
    return 0;
}

static sc_type result_type(const builtin *b, const sc_type *args)
{
    switch (b->result) {
    case 'F': return SC_FLOAT;
    case 'O': return (sc_type)(SC_MAT2 + sc_type_size(args[0]) - 2);
    case 'M': return args[0];
    default: return args[first_with(b->sig, 'G') >= 0 ? first_with(b->sig, 'G') : 0];
    }
}

int sc_builtin_resolve(const char *name, int name_len, const sc_type *args, int n_args,
                       sc_type *result, char *msg, int msg_size)
{
    int found = 0, arities[2] = {0, 0};
    for (int i = 0; i < N_BUILTINS; i++) {
        const builtin *b = &builtins[i];
        if (!name_is(b->name, name, name_len))
            continue;
        if ((int)strlen(b->sig) == n_args) {
            if (check_signature(b, args, msg, msg_size) < 0)
                return -1;
            *result = result_type(b, args);
            return i;
        }
        if (found < 2)
            arities[found] = (int)strlen(b->sig);
        found++;
    }
    if (!found)
        unknown_function(name, name_len, msg, msg_size);
    else if (found == 1)
        snprintf(msg, (size_t)msg_size, "%.*s: expects %d argument%s, got %d", name_len, name,
                 arities[0], arities[0] == 1 ? "" : "s", n_args);
    else
        snprintf(msg, (size_t)msg_size, "%.*s: expects %d or %d arguments, got %d", name_len, name,
                 arities[0], arities[1], n_args);
    return -1;
}

/* A component-wise call: component k of each argument (a float argument broadcasts). */
static sc_value eval_componentwise(const builtin *b, const call_context *ctx, const sc_value *args,
                                   int n_args, sc_type type)
{
    sc_value out = {type, {0}};
    for (int k = 0; k < sc_type_size(type); k++) {
        double a[3] = {0, 0, 0};
        for (int i = 0; i < n_args; i++)
            a[i] = args[i].v[args[i].type == SC_FLOAT ? 0 : k];
        const char *rule = b->domain ? b->domain(a) : NULL;
        if (rule && ctx->on_domain)
            ctx->on_domain(ctx->user, ctx->column, b->name, rule);
        out.v[k] = b->f1   ? b->f1(ctx->p, a[0])
                   : b->f2 ? b->f2(ctx->p, a[0], a[1])
                           : b->f3(ctx->p, a[0], a[1], a[2]);
    }
    return out;
}

sc_value sc_builtin_eval(int index, const call_context *ctx, const sc_value *args, int n_args)
{
    const builtin *b = &builtins[index];
    if (b->eval)
        return b->eval(ctx, args);
    sc_type types[3];
    for (int i = 0; i < n_args; i++)
        types[i] = args[i].type;
    return eval_componentwise(b, ctx, args, n_args, result_type(b, types));
}

int sc_builtin_componentwise(int index, sc_builtin_scalar *out)
{
    const builtin *b = &builtins[index];
    *out = (sc_builtin_scalar){b->f1, b->f2, b->f3, b->domain};
    return b->eval ? -1 : 0;
}
