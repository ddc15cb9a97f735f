/* The expression language (shadecalc/expr.h): every error path of the parser and type checker,
 * GLSL's constructor and operator rules, and evaluation against double-precision formulas. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/expr.h"

/* Compiles and evaluates src in precision p; fails the test on a compile error. */
static sc_value eval_in(sc_prec p, const char *src)
{
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, NULL, 0, &err);
    if (!e)
        fail_msg("'%s' did not compile: column %d: %s", src, err.column, err.message);
    sc_value v = sc_expr_eval(e, p, NULL, NULL, NULL);
    sc_expr_free(e);
    return v;
}

static sc_value eval_d(const char *src) { return eval_in(SC_DOUBLE, src); }

static void assert_value(sc_value v, sc_type type, const double *want)
{
    assert_int_equal(v.type, type);
    for (int k = 0; k < sc_type_size(type); k++)
        if (!(v.v[k] == want[k] || (isnan(v.v[k]) && isnan(want[k]))))
            fail_msg("component %d: got %.17g, want %.17g", k, v.v[k], want[k]);
}

/* The compile error of src: its column and that the message contains `text`. */
static void assert_error(const char *src, int column, const char *text)
{
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, NULL, 0, &err);
    if (e) {
        sc_expr_free(e);
        fail_msg("'%s' compiled; expected an error containing '%s'", src, text);
    }
    if (err.column != column || !strstr(err.message, text))
        fail_msg("'%s': got column %d '%s', want column %d '...%s...'", src, err.column,
                 err.message, column, text);
}

static void literals_are_glsl_floats(void **state)
{
    (void)state;
    assert_true(eval_d("1").v[0] == 1.0);
    assert_true(eval_d("1.").v[0] == 1.0);
    assert_true(eval_d(".5").v[0] == 0.5);
    assert_true(eval_d("1e-3").v[0] == 1e-3);
    assert_true(eval_d("2.5E+2").v[0] == 250.0);
    assert_true(eval_d("2.0f").v[0] == 2.0);
    /* highp rounds the literal to binary32 */
    assert_true(eval_in(SC_HIGHP, "0.1").v[0] == (double)0.1f);
    assert_true(eval_in(SC_HIGHP, "1e40").v[0] == INFINITY);
}

static void precedence_and_associativity(void **state)
{
    (void)state;
    assert_true(eval_d("1 + 2 * 3").v[0] == 7.0);
    assert_true(eval_d("(1 + 2) * 3").v[0] == 9.0);
    assert_true(eval_d("8 / 4 / 2").v[0] == 1.0);
    assert_true(eval_d("8 - 4 - 2").v[0] == 2.0);
    assert_true(eval_d("-2 * -3").v[0] == 6.0);
    assert_true(eval_d("+2 - -3").v[0] == 5.0);
    assert_true(signbit(eval_d("-0.0").v[0]));
}

static void constructors_follow_glsl(void **state)
{
    (void)state;
    assert_value(eval_d("vec3(1)"), SC_VEC3, (double[]){1, 1, 1});
    assert_value(eval_d("vec4(vec2(1,2), 3, 4)"), SC_VEC4, (double[]){1, 2, 3, 4});
    assert_value(eval_d("vec2(vec4(5,6,7,8))"), SC_VEC2, (double[]){5, 6});
    assert_value(eval_d("vec3(vec2(1,2), vec2(3,4))"), SC_VEC3, (double[]){1, 2, 3});
    assert_value(eval_d("float(vec3(7,8,9))"), SC_FLOAT, (double[]){7});
    assert_value(eval_d("mat2(3)"), SC_MAT2, (double[]){3, 0, 0, 3});
    assert_value(eval_d("mat2(1,2,3,4)"), SC_MAT2, (double[]){1, 2, 3, 4});
    assert_value(eval_d("mat2(vec2(1,2), vec2(3,4))"), SC_MAT2, (double[]){1, 2, 3, 4});
    assert_value(eval_d("mat2(mat3(1,2,3,4,5,6,7,8,9))"), SC_MAT2, (double[]){1, 2, 4, 5});
    assert_value(eval_d("mat3(mat2(2))"), SC_MAT3, (double[]){2, 0, 0, 0, 2, 0, 0, 0, 1});
}

static void swizzles_and_indexing(void **state)
{
    (void)state;
    assert_value(eval_d("vec4(1,2,3,4).wzyx"), SC_VEC4, (double[]){4, 3, 2, 1});
    assert_value(eval_d("vec3(1,2,3).xxy"), SC_VEC3, (double[]){1, 1, 2});
    assert_value(eval_d("vec4(1,2,3,4).ba"), SC_VEC2, (double[]){3, 4});
    assert_value(eval_d("vec2(5,6).t"), SC_FLOAT, (double[]){6});
    assert_value(eval_d("vec4(1,2,3,4).xyz.zy"), SC_VEC2, (double[]){3, 2});
    assert_value(eval_d("mat2(1,2,3,4)[1]"), SC_VEC2, (double[]){3, 4});
    assert_value(eval_d("mat2(1,2,3,4)[1][0]"), SC_FLOAT, (double[]){3});
    assert_value(eval_d("vec3(7,8,9)[2]"), SC_FLOAT, (double[]){9});
}

static void operators_follow_glsl_rules(void **state)
{
    (void)state;
    assert_value(eval_d("vec2(1,2) * 3"), SC_VEC2, (double[]){3, 6});
    assert_value(eval_d("1 - vec2(1,2)"), SC_VEC2, (double[]){0, -1});
    assert_value(eval_d("vec3(1,2,3) * vec3(4,5,6)"), SC_VEC3, (double[]){4, 10, 18});
    /* column-major: mat2(1,2,3,4) has columns (1,2) and (3,4) */
    assert_value(eval_d("mat2(1,2,3,4) * vec2(1,0)"), SC_VEC2, (double[]){1, 2});
    assert_value(eval_d("mat2(1,2,3,4) * vec2(1,1)"), SC_VEC2, (double[]){4, 6});
    assert_value(eval_d("vec2(1,1) * mat2(1,2,3,4)"), SC_VEC2, (double[]){3, 7});
    /* [1 3; 2 4] · [5 7; 6 8] = [23 31; 34 46] */
    assert_value(eval_d("mat2(1,2,3,4) * mat2(5,6,7,8)"), SC_MAT2, (double[]){23, 34, 31, 46});
    assert_value(eval_d("mat2(1,2,3,4) / mat2(1,2,3,4)"), SC_MAT2, (double[]){1, 1, 1, 1});
    assert_value(eval_d("-mat2(1,2,3,4)"), SC_MAT2, (double[]){-1, -2, -3, -4});
}

static void statements_bind_variables(void **state)
{
    (void)state;
    assert_value(eval_d("a = 2; b = a * a; b + a"), SC_FLOAT, (double[]){6});
    assert_value(eval_d("v = vec3(1,2,3); v.zx;"), SC_VEC2, (double[]){3, 1});
    assert_value(eval_d("a = 1; a = a + 1; a * 10"), SC_FLOAT, (double[]){20});
}

static void inputs_are_rounded_to_the_precision(void **state)
{
    (void)state;
    sc_expr_input in[2] = {{"x", SC_FLOAT}, {"v", SC_VEC2}};
    sc_value vals[2] = {{SC_FLOAT, {0.1}}, {SC_VEC2, {1, 2}}};
    sc_expr_error err;
    sc_expr *e = sc_expr_compile("x * v", in, 2, &err);
    assert_non_null(e);
    assert_int_equal(sc_expr_result_type(e), SC_VEC2);
    sc_value r = sc_expr_eval(e, SC_HIGHP, vals, NULL, NULL);
    assert_true(r.v[0] == (double)0.1f && r.v[1] == (double)(0.1f * 2.0f));
    sc_expr_free(e);
}

static void builtins_against_double_formulas(void **state)
{
    (void)state;
    assert_true(eval_d("pow(2, 0.5)").v[0] == sqrt(2.0));
    assert_true(eval_d("atan(1, -1)").v[0] == atan2(1.0, -1.0));
    assert_true(eval_d("atan(0.5)").v[0] == atan(0.5));
    assert_true(eval_d("inversesqrt(4)").v[0] == 0.5);
    assert_true(eval_d("radians(180)").v[0] == 3.14159265358979323846);
    assert_value(eval_d("mod(vec2(-1, 1), 3)"), SC_VEC2, (double[]){2, 1});
    assert_value(eval_d("mod(1, -3)"), SC_FLOAT, (double[]){-2});
    assert_value(eval_d("sign(vec3(-2, 0, 5))"), SC_VEC3, (double[]){-1, 0, 1});
    assert_value(eval_d("step(1, vec2(1, 0.5))"), SC_VEC2, (double[]){1, 0});
    assert_value(eval_d("clamp(vec2(-1, 3), 0, 1)"), SC_VEC2, (double[]){0, 1});
    assert_value(eval_d("clamp(vec2(-1, 3), vec2(0), vec2(2))"), SC_VEC2, (double[]){0, 2});
    assert_value(eval_d("mix(vec2(0, 10), vec2(10, 20), 0.25)"), SC_VEC2, (double[]){2.5, 12.5});
    assert_value(eval_d("smoothstep(0, 1, 0.5)"), SC_FLOAT, (double[]){0.5});
    assert_value(eval_d("fract(-0.25)"), SC_FLOAT, (double[]){0.75});
    assert_value(eval_d("min(vec2(1, 5), 3)"), SC_VEC2, (double[]){1, 3});
    assert_value(eval_d("max(vec2(1, 5), vec2(2, 4))"), SC_VEC2, (double[]){2, 5});
}

static void geometric_and_matrix_builtins(void **state)
{
    (void)state;
    assert_value(eval_d("normalize(vec3(3,0,4))"), SC_VEC3, (double[]){0.6, 0, 0.8});
    assert_value(eval_in(SC_HIGHP, "normalize(vec3(3,0,4))"), SC_VEC3,
                 (double[]){(double)0.6f, 0, (double)0.8f});
    assert_true(eval_d("length(vec2(3,4))").v[0] == 5.0);
    assert_true(eval_d("distance(vec2(1,1), vec2(4,5))").v[0] == 5.0);
    assert_true(eval_d("dot(vec3(1,2,3), vec3(4,5,6))").v[0] == 32.0);
    assert_value(eval_d("cross(vec3(1,0,0), vec3(0,1,0))"), SC_VEC3, (double[]){0, 0, 1});
    assert_value(eval_d("reflect(vec3(1,-1,0), vec3(0,1,0))"), SC_VEC3, (double[]){1, 1, 0});
    assert_value(eval_d("faceforward(vec2(0,1), vec2(0,1), vec2(0,1))"), SC_VEC2,
                 (double[]){0, -1});
    assert_value(eval_d("refract(vec2(0,-1), vec2(0,1), 0.5)"), SC_VEC2, (double[]){0, -1});
    assert_value(eval_d("transpose(mat2(1,2,3,4))"), SC_MAT2, (double[]){1, 3, 2, 4});
    assert_true(eval_d("determinant(mat2(1,2,3,4))").v[0] == -2.0);
    /* det of [2 0 1; 1 3 2; 1 1 1] by the rule of Sarrus: 6 + 0 + 1 - 3 - 4 - 0 = 0 ... use a
     * non-singular one: [2 0 1; 1 3 2; 1 1 2] = 12 + 0 + 1 - 3 - 4 - 0 = 6 */
    assert_true(eval_d("determinant(mat3(2,1,1, 0,3,1, 1,2,2))").v[0] == 6.0);
    assert_true(eval_d("determinant(mat4(2))").v[0] == 16.0);
    assert_value(eval_d("inverse(mat2(1,2,3,4))"), SC_MAT2, (double[]){-2, 1, 1.5, -0.5});
    sc_value id = eval_d("m = mat4(2,1,0,0, 1,3,1,0, 0,1,4,1, 0,0,1,5); inverse(m) * m");
    for (int k = 0; k < 16; k++)
        assert_true(fabs(id.v[k] - (k % 5 == 0 ? 1.0 : 0.0)) < 1e-15);
    assert_value(eval_d("matrixCompMult(mat2(1,2,3,4), mat2(2))"), SC_MAT2, (double[]){2, 0, 0, 8});
    assert_value(eval_d("outerProduct(vec2(1,2), vec2(3,4))"), SC_MAT2, (double[]){3, 6, 4, 8});
}

static void precisions_round_each_operation(void **state)
{
    (void)state;
    /* binary32: 16777216 + 1 rounds back to 16777216 */
    assert_true(eval_in(SC_HIGHP, "16777216 + 1 - 16777216").v[0] == 0.0);
    assert_true(eval_in(SC_DOUBLE, "16777216 + 1 - 16777216").v[0] == 1.0);
    /* binary16: 2048 + 1 rounds to 2048 (ties to even); 300 * 300 overflows */
    assert_true(eval_in(SC_MEDIUMP, "2048 + 1").v[0] == 2048.0);
    assert_true(eval_in(SC_MEDIUMP, "300 * 300").v[0] == INFINITY);
    /* lowp saturates at 511/256 */
    assert_true(eval_in(SC_LOWP, "1.5 + 1.5").v[0] == 511.0 / 256.0);
    assert_true(eval_in(SC_LOWP, "0.3").v[0] == 77.0 / 256.0);
}

typedef struct {
    int count;
    int column;
    char func[32], rule[32];
} domain_log;

static void log_domain(void *user, int column, const char *func, const char *rule)
{
    domain_log *log = user;
    log->count++;
    log->column = column;
    snprintf(log->func, sizeof log->func, "%s", func);
    snprintf(log->rule, sizeof log->rule, "%s", rule);
}

static domain_log domain_of(const char *src, sc_value *out)
{
    domain_log log = {0, 0, "", ""};
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, NULL, 0, &err);
    assert_non_null(e);
    *out = sc_expr_eval(e, SC_HIGHP, NULL, log_domain, &log);
    sc_expr_free(e);
    return log;
}

static void domain_errors_are_reported_with_the_ieee_result(void **state)
{
    (void)state;
    sc_value v;
    domain_log log = domain_of("1 + pow(-2.0, 0.5)", &v);
    assert_int_equal(log.count, 1);
    assert_int_equal(log.column, 5);
    assert_string_equal(log.func, "pow");
    assert_string_equal(log.rule, "x < 0");
    assert_true(isnan(v.v[0]));
    log = domain_of("acos(1.5)", &v);
    assert_string_equal(log.rule, "|x| > 1");
    assert_true(isnan(v.v[0]));
    log = domain_of("inversesqrt(0.0)", &v);
    assert_string_equal(log.rule, "x <= 0");
    assert_true(v.v[0] == INFINITY);
    log = domain_of("log(vec3(1, 0, -1))", &v);
    assert_int_equal(log.count, 2);
    log = domain_of("atan(0.0, 0.0)", &v);
    assert_string_equal(log.rule, "y = 0 and x = 0");
    log = domain_of("clamp(1.0, 2.0, 0.0)", &v);
    assert_string_equal(log.rule, "minVal > maxVal");
    log = domain_of("smoothstep(1.0, 1.0, 0.5)", &v);
    assert_string_equal(log.rule, "edge0 >= edge1");
    log = domain_of("inverse(mat2(1,2,2,4))", &v);
    assert_string_equal(log.rule, "the matrix is singular");
    log = domain_of("pow(2.0, 0.5) + sqrt(4.0) + log(1.0)", &v);
    assert_int_equal(log.count, 0);
}

static void syntax_errors_name_the_column(void **state)
{
    (void)state;
    assert_error("", 1, "expected an expression, found end of input");
    assert_error("1 +", 4, "expected an expression, found end of input");
    assert_error("(1 + 2", 7, "expected ')'");
    assert_error("1 2", 3, "expected an operator or the end of the expression, found '2'");
    assert_error("1 $ 2", 3, "unexpected '$'");
    assert_error("1e+", 1, "unexpected '1e+'");
    assert_error("2x", 1, "unexpected '2x'");
    assert_error("1.2.3", 1, "unexpected '1.2.3'");
    assert_error("sin(1,)", 7, "expected an expression");
    assert_error("sin(1 2)", 7, "expected ',' or ')' after an argument");
    assert_error("a = 1;", 7, "expected an expression after the statements");
    assert_error("a = 1 a", 7, "expected ';' after the assignment");
    assert_error("vec3(1).", 9, "expected swizzle letters");
    assert_error("vec2(1)[", 9, "expected an integer index 0..1");
    assert_error("vec2(1)[2]", 9, "expected an integer index 0..1");
    assert_error("vec2(1)[0.5]", 9, "integer index");
    assert_error("vec2(1)[0", 10, "expected ']'");
}

static void type_errors_name_the_column(void **state)
{
    (void)state;
    assert_error("dot(vec3(1), vec2(1))", 1,
                 "dot: arguments vec3 and vec2 must have the same type");
    assert_error("1 + foo(2)", 5, "unknown function 'foo'");
    assert_error("x + 1", 1, "unknown variable 'x'");
    assert_error("sin + 1", 1, "'sin' is a function: expected '(' after it");
    assert_error("pow(1)", 1, "pow: expects 2 arguments, got 1");
    assert_error("atan(1, 2, 3)", 1, "atan: expects 1 or 2 arguments, got 3");
    assert_error("sin(mat2(1))", 1, "sin: argument 1 is mat2, expected float or a vector");
    assert_error("cross(vec2(1), vec2(1))", 1, "cross: argument 1 is vec2, expected vec3");
    assert_error("clamp(vec3(1), vec2(0), vec2(1))", 1,
                 "clamp: argument 2 is vec2, expected float or vec3");
    assert_error("clamp(vec3(1), 0, vec3(1))", 1,
                 "clamp: argument 3 is vec3, expected float or vec3");
    assert_error("refract(vec3(1), vec3(1), vec3(1))", 1,
                 "refract: argument 3 is vec3, expected float");
    assert_error("determinant(vec2(1))", 1, "determinant: argument 1 is vec2, expected a matrix");
    assert_error("vec2(1) + vec3(1)", 9, "operator '+': operands vec2 and vec3 do not match");
    assert_error("mat2(1) * vec3(1)", 9, "operator '*': operands mat2 and vec3 do not match");
    assert_error("mat2(1) + mat3(1)", 9, "operands mat2 and mat3 do not match");
    assert_error("vec3(1,2)", 1, "vec3: not enough components (2 given, 3 needed)");
    assert_error("vec2(1,2,3)", 1, "vec2: too many arguments (argument 3 is not used)");
    assert_error("vec2()", 1, "vec2: expects at least 1 argument");
    assert_error("float(1, 2)", 1, "float: expects 1 argument, got 2");
    assert_error("mat2(mat2(1), 1)", 1, "a matrix constructs a matrix only alone");
    assert_error("vec2(1).z", 9, "swizzle 'z' names a component a vec2 does not have");
    assert_error("vec4(1).xyzwx", 9, "more than 4 components");
    assert_error("vec4(1).xg", 9, "mixes component sets");
    assert_error("(1.0).x", 6, "cannot swizzle a float");
    assert_error("mat2(1).x", 8, "cannot swizzle a mat2");
    assert_error("(1.0)[0]", 6, "cannot index a float");
    assert_error("dot = 1; dot", 1, "'dot' is a built-in name and cannot be a variable");
    assert_error("vec2 = 1; 1", 1, "'vec2' is a built-in name");
}

static void deep_nesting_is_an_error_not_a_crash(void **state)
{
    (void)state;
    char src[2100];
    memset(src, '(', 1000);
    src[1000] = '1';
    memset(src + 1001, ')', 1000);
    src[2001] = '\0';
    sc_expr_error err;
    assert_null(sc_expr_compile(src, NULL, 0, &err));
    assert_non_null(strstr(err.message, "nested too deeply"));
    memset(src, '-', 2000);
    src[2000] = '1';
    src[2001] = '\0';
    assert_null(sc_expr_compile(src, NULL, 0, &err));
}

/* ---- deep and long expressions: evaluated without recursion, or a clear error ---- */

/* src built by repeating: prefix, `times` copies of `open`, `core`, `times` copies of `close`. */
static char *repeated(const char *open, int times, const char *core, const char *close)
{
    size_t lo = strlen(open), lc = strlen(close), lcore = strlen(core);
    char *src = malloc((size_t)times * (lo + lc) + lcore + 1), *p = src;
    assert_non_null(src);
    for (int i = 0; i < times; i++, p += lo)
        memcpy(p, open, lo);
    memcpy(p, core, lcore);
    p += lcore;
    for (int i = 0; i < times; i++, p += lc)
        memcpy(p, close, lc);
    *p = '\0';
    return src;
}

/* A flat chain compiles to a left-leaning tree as deep as it is long: 200 000 additions of 0.1
 * in highp against the same sum in C binary32 arithmetic, and in double against double. */
static void long_flat_chains_evaluate(void **state)
{
    (void)state;
    enum { TERMS = 200000 };
    char *src = repeated("0.1+", TERMS - 1, "0.1", "");
    float sum32 = 0.1f;
    double sum64 = 0.1;
    for (int i = 1; i < TERMS; i++) {
        sum32 += 0.1f;
        sum64 += 0.1;
    }
    assert_true(eval_in(SC_HIGHP, src).v[0] == (double)sum32);
    assert_true(eval_d(src).v[0] == sum64);
    free(src);
}

/* Statements keep their values while long chains run after them. */
static void statements_survive_long_chains(void **state)
{
    (void)state;
    char *chain = repeated("1+", 9999, "1", "");
    size_t len = 2 * strlen(chain) + 64;
    char *src = malloc(len);
    assert_non_null(src);
    snprintf(src, len, "a = %s; b = a * 2.; b - a + %s", chain, chain);
    assert_true(eval_d(src).v[0] == 20000.0);
    free(chain);
    free(src);
}

/* A right-leaning tree needs parentheses: 1 - (1 - (... - 1)) as deep as the nesting limit
 * allows, against the alternating sum. */
static void right_leaning_trees_evaluate_to_the_limit(void **state)
{
    (void)state;
    enum { LEVELS = 256 };
    char *src = repeated("2-(", LEVELS, "1", ")");
    double want = 1.0;
    for (int i = 0; i < LEVELS; i++)
        want = 2.0 - want;
    assert_true(eval_d(src).v[0] == want);
    free(src);
    src = repeated("2-(", LEVELS + 1, "1", ")");
    assert_error(src, 3 * (LEVELS + 1) + 1, "more than 256 levels");
    free(src);
}

/* Unary chains: every unary operator is a level of nesting. */
static void deep_unary_chains_evaluate_or_name_the_limit(void **state)
{
    (void)state;
    char *src = repeated("-", 256, "1", "");
    assert_true(eval_d(src).v[0] == 1.0);
    free(src);
    src = repeated("-(", 128, "1", ")"); /* each level: a parenthesis and a minus */
    assert_true(eval_d(src).v[0] == 1.0);
    free(src);
    src = repeated("-", 257, "1", "");
    assert_error(src, 258, "expression nested too deeply (more than 256 levels");
    free(src);
    assert_error("!1", 1, "unexpected '!'"); /* no logical not in the language */
}

/* Nested calls keep earlier arguments pending: dot(vec2(1, .5), vec2(x, 1)) = x + 0.5 at each
 * level, and its derivative in x is 1 (the dual evaluator runs the same program). */
static void nested_calls_evaluate_with_derivatives(void **state)
{
    (void)state;
    enum { LEVELS = 128 }; /* a call and its vec2 argument: two levels each */
    char *src = repeated("dot(vec2(1, .5), vec2(", LEVELS, "u", ", 1))");
    sc_expr_input in = {"u", SC_FLOAT};
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, &in, 1, &err);
    if (!e)
        fail_msg("column %d: %s", err.column, err.message);
    sc_value u = {SC_FLOAT, {0.25}};
    assert_true(sc_expr_eval(e, SC_HIGHP, &u, NULL, NULL).v[0] == 0.25 + 0.5 * LEVELS);
    sc_dual_value du = {u, {{SC_FLOAT, {1.0}}, {SC_FLOAT, {0.0}}}};
    sc_dual_value out = sc_expr_eval_dual(e, &du);
    assert_true(out.x.v[0] == 0.25 + 0.5 * LEVELS && out.d[0].v[0] == 1.0 && out.d[1].v[0] == 0.0);
    sc_expr_free(e);
    free(src);
}

/* A literal is rounded once to the precision: 7.038531e-26, which binary64 puts on a binary32
 * midpoint, is strtof's binary32 (not the even neighbour a rounding through binary64 gives);
 * 1.000488281250000000000000000001, which binary64 puts on the binary16 midpoint 1 + 2^-11, is
 * the binary16 above it, 1 + 2^-10; double keeps strtod's value. */
static void literals_round_once(void **state)
{
    (void)state;
    const char *tiny = "7.038531e-26", *above = "1.000488281250000000000000000001";
    assert_true(eval_in(SC_HIGHP, tiny).v[0] == strtof(tiny, NULL));
    assert_true(eval_in(SC_HIGHP, "-7.038531e-26").v[0] == -strtof(tiny, NULL));
    assert_true(eval_in(SC_DOUBLE, tiny).v[0] == strtod(tiny, NULL));
    assert_true(eval_in(SC_MEDIUMP, above).v[0] == 1 + 0x1p-10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(literals_are_glsl_floats),
        cmocka_unit_test(precedence_and_associativity),
        cmocka_unit_test(constructors_follow_glsl),
        cmocka_unit_test(swizzles_and_indexing),
        cmocka_unit_test(operators_follow_glsl_rules),
        cmocka_unit_test(statements_bind_variables),
        cmocka_unit_test(inputs_are_rounded_to_the_precision),
        cmocka_unit_test(builtins_against_double_formulas),
        cmocka_unit_test(geometric_and_matrix_builtins),
        cmocka_unit_test(precisions_round_each_operation),
        cmocka_unit_test(domain_errors_are_reported_with_the_ieee_result),
        cmocka_unit_test(syntax_errors_name_the_column),
        cmocka_unit_test(type_errors_name_the_column),
        cmocka_unit_test(deep_nesting_is_an_error_not_a_crash),
        cmocka_unit_test(long_flat_chains_evaluate),
        cmocka_unit_test(statements_survive_long_chains),
        cmocka_unit_test(right_leaning_trees_evaluate_to_the_limit),
        cmocka_unit_test(deep_unary_chains_evaluate_or_name_the_limit),
        cmocka_unit_test(nested_calls_evaluate_with_derivatives),
        cmocka_unit_test(literals_round_once),
    };
    return cmocka_run_group_tests_name("expr", tests, NULL, NULL);
}
