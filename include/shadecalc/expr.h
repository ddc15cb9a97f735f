/*
 * shadecalc/expr.h — GLSL ES expressions, compiled once and evaluated in any precision.
 *
 *   sc_type, sc_value        float vec2 vec3 vec4 mat2 mat3 mat4; components as doubles,
 *                            matrices column-major (element (r, c) is v[c·n + r])
 *   sc_type_name             "vec3" ...; sc_type_size: number of components;
 *   sc_type_matrix_n         N of matN; sc_type_is_vector
 *   sc_expr_compile          source -> program (statements `NAME = EXPR;` then one expression)
 *   sc_expr_eval             run a program in a precision, with values for its inputs
 *   sc_expr_eval_dual        run it in double with derivatives (forward-mode AD, dual numbers)
 *   sc_expr_result_type      type of the final expression
 *   sc_expr_free
 *
 * The float expression language of user surfaces (the man page's NORMAL, Surfaces; `eval` and
 * `sweep` use the GLSL ES language of shadecalc/lang.h): float literals (`1`, `1.`, `.5`, `1e-3`),
 * constructors `float vec2 vec3 vec4 mat2 mat3 mat4` with GLSL's rules, swizzles
 * (`.xyzw .rgba .stpq`), indexing by an integer literal (`m[1]`, `v[0]`), unary `- +`, binary
 * `+ - * /` with GLSL's component-wise, scalar-vector, matrix×vector and matrix×matrix rules,
 * parentheses, and every GLSL ES built-in of shadecalc/pmath.h. Types are checked at compile
 * time; every error carries the 1-based column of the offending token.
 *
 * Evaluation rounds every literal, operation and built-in result to the precision
 * (shadecalc/pmath.h), so `highp` reproduces binary32 evaluation in source order and `double`
 * is the reference. Arguments outside a built-in's GLSL ES domain (docs/formulas.md §9) give the IEEE result
 * of the formula and are reported through the domain callback.
 */
#ifndef SHADECALC_EXPR_H
#define SHADECALC_EXPR_H

#include "shadecalc/api.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

typedef enum { SC_FLOAT, SC_VEC2, SC_VEC3, SC_VEC4, SC_MAT2, SC_MAT3, SC_MAT4 } sc_type;

typedef struct {
    sc_type type;
    double v[16];
} sc_value;

const char *sc_type_name(sc_type t);
int sc_type_size(sc_type t);
int sc_type_matrix_n(sc_type t); /* side of a matN, 0 for float and vectors */
int sc_type_is_vector(sc_type t);

/* A compile error: the 1-based column in the source and a message without the column. */
typedef struct {
    int column;
    char message[160];
} sc_expr_error;

/* An input the caller provides at each evaluation (a sweep variable, a -D definition). */
typedef struct {
    const char *name;
    sc_type type;
} sc_expr_input;

typedef struct sc_expr sc_expr;

/* Compiles `src`, which may use the n_inputs named inputs. Returns NULL and fills *err on a
 * syntax or type error (or on memory exhaustion: column 0). */
sc_expr *sc_expr_compile(const char *src, const sc_expr_input *inputs, int n_inputs,
                         sc_expr_error *err);
void sc_expr_free(sc_expr *e);
sc_type sc_expr_result_type(const sc_expr *e);

/* Called for each component whose arguments are outside the built-in's GLSL ES domain:
 * `column` of the call, the built-in's name, and the rule broken ("x < 0"). */
typedef void (*sc_expr_domain_fn)(void *user, int column, const char *func, const char *rule);

/* Evaluates e in precision p with inputs[i] for the i-th declared input (their values rounded
 * to p on entry). Thread-safe: e is not modified. */
sc_value sc_expr_eval(const sc_expr *e, sc_prec p, const sc_value *inputs,
                      sc_expr_domain_fn on_domain, void *user);

/* Forward-mode automatic differentiation: a value and its derivatives along SC_DUAL_DIRS
 * directions (each tangent has the value's type). */
enum { SC_DUAL_DIRS = 2 };
typedef struct {
    sc_value x;
    sc_value d[SC_DUAL_DIRS];
} sc_dual_value;

/* Evaluates e in double precision with dual numbers: inputs[i].x is the i-th input and
 * inputs[i].d[k] its derivative along direction k (seed u with d[0] = 1, v with d[1] = 1 to get
 * ∂/∂u and ∂/∂v). Derivatives are exact up to rounding: every operation and built-in applies
 * its derivative rule (chain, product and quotient rules; d(A⁻¹) = −A⁻¹·dA·A⁻¹; the determinant
 * by multilinearity in the columns). At a kink (abs, min, max, clamp, mod, fract, floor, step,
 * faceforward, refract's total reflection) the derivative is that of the branch the value took;
 * where the derivative is infinite (sqrt at 0, asin at ±1) it is ±Inf or NaN, as the formula
 * says. No domain callback: evaluate with sc_expr_eval to hear about domain errors. NaN values
 * and derivatives if out of memory. Thread-safe: e is not modified. */
sc_dual_value sc_expr_eval_dual(const sc_expr *e, const sc_dual_value *inputs);

SC_END_DECLS

#endif
