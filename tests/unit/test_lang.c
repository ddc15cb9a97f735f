/* The language of shadecalc/lang.h: integer semantics against the same operations in C on
 * fixed-width types, control flow against closed forms, functions, matrices against explicit
 * loops, built-ins against their C definitions, and every error with its line and column. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/lang.h"

enum { MAX_VALUES = 64 };

typedef struct {
    sc_lvalue v[MAX_VALUES];
    int n;
    int domain_hits;
} results;

static int collect(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    results *r = user;
    (void)text, (void)len, (void)line;
    if (r->n < MAX_VALUES)
        r->v[r->n++] = *v;
    return 0;
}

static void count_domain(void *user, int line, int column, const char *func, const char *rule)
{
    results *r = user;
    (void)line, (void)column, (void)func, (void)rule;
    r->domain_hits++;
}

/* Compiles and runs src in precision p; fails the test on any error. */
static results run_in(sc_prec p, const char *src)
{
    results r;
    memset(&r, 0, sizeof r);
    sc_lang_error err;
    sc_program *prog = sc_program_compile(src, NULL, 0, NULL, &err);
    if (!prog)
        fail_msg("'%s' did not compile: %d:%d: %s", src, err.line, err.column, err.message);
    if (sc_program_run(prog, p, NULL, collect, count_domain, &r, &err) != 0)
        fail_msg("'%s' failed at run time: %d:%d: %s", src, err.line, err.column, err.message);
    sc_program_free(prog);
    return r;
}

static results run(const char *src) { return run_in(SC_HIGHP, src); }

/* The single value of src, a scalar. */
static double scalar_in(sc_prec p, const char *src)
{
    results r = run_in(p, src);
    assert_int_equal(r.n, 1);
    assert_int_equal(sc_ltype_size(r.v[0].type), 1);
    return r.v[0].v[0];
}

static double scalar(const char *src) { return scalar_in(SC_HIGHP, src); }

static void assert_compile_error(const char *src, int line, int column, const char *text)
{
    sc_lang_error err;
    sc_program *prog = sc_program_compile(src, NULL, 0, NULL, &err);
    if (prog) {
        sc_program_free(prog);
        fail_msg("'%s' compiled; expected an error containing '%s'", src, text);
    }
    if (err.line != line || err.column != column || !strstr(err.message, text))
        fail_msg("'%s': got %d:%d '%s', want %d:%d '...%s...'", src, err.line, err.column,
                 err.message, line, column, text);
}

static void assert_runtime_error(const char *src, long bound, int line, const char *text)
{
    sc_lang_error err;
    sc_lang_options options = {bound, 0, 0};
    sc_program *prog = sc_program_compile(src, NULL, 0, &options, &err);
    if (!prog)
        fail_msg("'%s' did not compile: %s", src, err.message);
    results r;
    memset(&r, 0, sizeof r);
    int status = sc_program_run(prog, SC_HIGHP, NULL, collect, NULL, &r, &err);
    sc_program_free(prog);
    if (status != -1 || err.line != line || !strstr(err.message, text))
        fail_msg("'%s': status %d, %d:%d '%s', want line %d '...%s...'", src, status, err.line,
                 err.column, err.message, line, text);
}

static void empty_programs_print_nothing(void **state)
{
    (void)state;
    assert_int_equal(run("").n, 0);
    assert_int_equal(run("// nothing\n/* at all */ ;").n, 0);
}

/* ---- integers ---- */

static void int_arithmetic_wraps_like_c_fixed_width_types(void **state)
{
    (void)state;
    assert_true(scalar("2147483647 + 1;") == (double)(int32_t)(UINT32_C(2147483647) + 1u));
    assert_true(scalar("-2147483648 - 1;") == (double)(int32_t)(UINT32_C(0x80000000) - 1u));
    assert_true(scalar("65536 * 65537;") ==
                (double)(int32_t)(uint32_t)(UINT64_C(65536) * UINT64_C(65537)));
    assert_true(scalar("0u - 1u;") == (double)(uint32_t)(0u - 1u));
    assert_true(scalar("~0u;") == (double)UINT32_MAX);
    assert_true(scalar("~5;") == (double)~5);
    /* mediump: 16 bits, lowp: 9 bits, two's complement */
    assert_true(scalar_in(SC_MEDIUMP, "32767 + 1;") == (double)(int16_t)(uint16_t)32768u);
    assert_true(scalar_in(SC_MEDIUMP, "65535u + 2u;") == (double)(uint16_t)(65535u + 2u));
    assert_true(scalar_in(SC_LOWP, "255 + 1;") == -256.0);
    assert_true(scalar_in(SC_LOWP, "511u + 1u;") == 0.0);
    assert_int_equal(sc_int_bits(SC_DOUBLE), 32);
}

/* a / b and a % b truncate toward zero, as C99 does. */
static void int_division_truncates_toward_zero(void **state)
{
    (void)state;
    static const int pairs[][2] = {{7, 2},  {-7, 2}, {7, -2},          {-7, -2},        {1, 3},
                                   {-1, 3}, {0, 5},  {2147483647, 10}, {-2147483647, 7}};
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        char src[96];
        int a = pairs[i][0], b = pairs[i][1];
        snprintf(src, sizeof src, "int a = %d; int b = %d; a / b; a %% b;", a, b);
        results r = run(src);
        assert_int_equal(r.n, 2);
        assert_true(r.v[0].v[0] == (double)(a / b));
        assert_true(r.v[1].v[0] == (double)(a % b));
    }
    /* INT_MIN / -1 wraps (C would overflow): the 32-bit two's complement of 2^31 */
    assert_true(scalar("int m = -2147483647 - 1; m / -1;") == -2147483648.0);
    assert_true(scalar("int m = -2147483647 - 1; m % -1;") == 0.0);
    assert_true(scalar("17u / 5u;") == 3.0);
}

static void division_by_zero_is_all_ones_and_reported(void **state)
{
    (void)state;
    results r = run("7 / 0; 7 % 0; 7u / 0u; ivec2(1, 2) / 0;");
    assert_int_equal(r.n, 4);
    assert_true(r.v[0].v[0] == -1.0 && r.v[1].v[0] == -1.0);
    assert_true(r.v[2].v[0] == (double)UINT32_MAX);
    assert_true(r.v[3].v[0] == -1.0 && r.v[3].v[1] == -1.0);
    assert_int_equal(r.domain_hits, 5);
}

static void shifts_take_the_count_modulo_32(void **state)
{
    (void)state;
    for (int count = 0; count < 40; count += 3) {
        char src[64];
        snprintf(src, sizeof src, "1u << %d; 2147483648u >> %d; -8 >> %d;", count, count, count);
        results r = run(src);
        assert_true(r.v[0].v[0] == (double)(UINT32_C(1) << (count & 31)));
        assert_true(r.v[1].v[0] == (double)(UINT32_C(2147483648) >> (count & 31)));
        /* arithmetic shift: floor(-8 / 2^count) */
        assert_true(r.v[2].v[0] == floor(-8.0 / ldexp(1.0, count & 31)));
        assert_int_equal(r.domain_hits, count > 31 ? 3 : 0);
    }
    assert_true(scalar("ivec3(1, 2, 3) << 2 == ivec3(4, 8, 12);") == 1.0);
    assert_true(scalar("ivec2(8) >> ivec2(1, 2) == ivec2(4, 2);") == 1.0);
}

static void length_method_counts_components_and_columns(void **state)
{
    (void)state;
    assert_true(scalar("vec3(1.0).length();") == 3.0);
    assert_true(scalar("mat4x2(1.0).length();") == 4.0);
    assert_true(scalar("vec4 v; int s = 0; for (int i = 0; i < v.length(); i++) s++; s;") == 4.0);
}

static void bitwise_operators(void **state)
{
    (void)state;
    assert_true(scalar("0xF0F0 & 0x0FF0;") == (double)(0xF0F0 & 0x0FF0));
    assert_true(scalar("0xF0F0 | 0x0FF0;") == (double)(0xF0F0 | 0x0FF0));
    assert_true(scalar("0xF0F0 ^ 0x0FF0;") == (double)(0xF0F0 ^ 0x0FF0));
    assert_true(scalar("017;") == 15.0);
    assert_true(scalar("-1 & 0xFF;") == 255.0);
}

static void conversions_follow_glsl(void **state)
{
    (void)state;
    assert_true(scalar("int(3.7);") == 3.0);
    assert_true(scalar("int(-3.7);") == -3.0);
    assert_true(scalar("int(1e20);") == 2147483647.0);      /* saturated */
    assert_true(scalar("uint(-2.5);") == 0.0);              /* saturated */
    assert_true(scalar("uint(-1);") == (double)UINT32_MAX); /* the bit pattern */
    assert_true(scalar("int(4294967295u);") == -1.0);
    assert_true(scalar("float(16777217);") == 16777216.0); /* rounded to binary32 */
    assert_true(scalar("bool(0.5);") == 1.0);
    assert_true(scalar("int(true);") == 1.0);
    assert_true(scalar("float(vec3(2.0, 3.0, 4.0));") == 2.0);
    assert_true(scalar_in(SC_MEDIUMP, "int(1e6);") == 32767.0);
    results r = run("ivec3(vec3(1.5, -1.5, 2.9)); bvec2(0, 2); vec2(ivec2(3, 4)); ivec4(7);");
    assert_true(r.v[0].v[0] == 1 && r.v[0].v[1] == -1 && r.v[0].v[2] == 2);
    assert_true(r.v[1].v[0] == 0 && r.v[1].v[1] == 1);
    assert_true(r.v[2].v[0] == 3 && r.v[2].v[1] == 4);
    assert_true(r.v[3].v[3] == 7);
}

/* int and uint inputs: truncated and wrapped; NaN and magnitudes beyond 2^63 give 0 */
static void integer_inputs_wrap(void **state)
{
    (void)state;
    sc_lang_input in[2] = {{"i", {SC_KIND_INT, 1, 1}}, {"u", {SC_KIND_UINT, 1, 1}}};
    sc_lang_error err;
    sc_program *prog = sc_program_compile("i; u;", in, 2, NULL, &err);
    assert_non_null(prog);
    static const double given[][2] = {{-1.0, -1.0}, {2147483648.0, 4294967297.5}, {NAN, 1e30}};
    static const double want[][2] = {{-1.0, 4294967295.0}, {-2147483648.0, 1.0}, {0.0, 0.0}};
    for (int k = 0; k < 3; k++) {
        sc_lvalue values[2] = {{in[0].type, {given[k][0]}}, {in[1].type, {given[k][1]}}};
        results r;
        memset(&r, 0, sizeof r);
        assert_int_equal(sc_program_run(prog, SC_HIGHP, values, collect, NULL, &r, &err), 0);
        assert_true(r.v[0].v[0] == want[k][0] && r.v[1].v[0] == want[k][1]);
    }
    sc_program_free(prog);
}

/* ---- floats ---- */

static void highp_rounds_every_operation_to_binary32(void **state)
{
    (void)state;
    float a = 0.1f, b = 0.2f, c = 0.3f;
    float sum = a + b, product = sum * c;
    assert_true(scalar("(0.1 + 0.2) * 0.3;") == (double)product);
    assert_true(scalar_in(SC_DOUBLE, "0.1 + 0.2;") == 0.1 + 0.2);
    assert_true(scalar("1.0 / 3.0;") == (double)(1.0f / 3.0f));
    /* negating a float beyond the integers' range (no integer conversion on the way) */
    assert_true(scalar_in(SC_DOUBLE, "-1e300;") == -1e300);
    assert_true(isnan(scalar("-(0.0 / 0.0);")));
    /* a float literal beyond the integers' range is no index candidate (no conversion) */
    assert_true(scalar_in(SC_DOUBLE, "1e19;") == 1e19);
}

static void matrices_multiply_as_linear_algebra(void **state)
{
    (void)state;
    /* A: mat3x2 (3 columns of 2 rows), B: mat2x3 (2 columns of 3 rows): A*B is mat2 */
    double a[6] = {1, 2, 3, 4, 5, 6}, b[6] = {7, 8, 9, 10, 11, 12}, want[4];
    for (int c = 0; c < 2; c++)
        for (int r = 0; r < 2; r++) {
            want[c * 2 + r] = 0;
            for (int k = 0; k < 3; k++)
                want[c * 2 + r] += a[k * 2 + r] * b[c * 3 + k];
        }
    results res = run("mat3x2(1, 2, 3, 4, 5, 6) * mat2x3(7, 8, 9, 10, 11, 12);"
                      "mat2x3(1, 2, 3, 4, 5, 6) * vec2(1, -1);"
                      "vec3(1, 0, 2) * mat2x3(1, 2, 3, 4, 5, 6);"
                      "mat2x3(2.0) + mat2x3(1.0);");
    assert_int_equal(res.v[0].type.cols, 2);
    assert_int_equal(res.v[0].type.rows, 2);
    for (int k = 0; k < 4; k++)
        assert_true(res.v[0].v[k] == want[k]);
    assert_true(res.v[1].v[0] == 1 - 4 && res.v[1].v[1] == 2 - 5 && res.v[1].v[2] == 3 - 6);
    assert_true(res.v[2].v[0] == 1 + 2 * 3 && res.v[2].v[1] == 4 + 2 * 6);
    assert_true(res.v[3].v[0] == 3 && res.v[3].v[1] == 0 && res.v[3].v[4] == 3);
}

/* ---- control flow ---- */

static void loops_match_closed_forms(void **state)
{
    (void)state;
    /* sum of 0..n-1 = n(n-1)/2; odd numbers below 2n sum to n^2 */
    assert_true(scalar("int s = 0; for (int i = 0; i < 100; i++) s += i; s;") == 100 * 99 / 2);
    assert_true(scalar("int s = 0; for (int i = 0; i < 40; i++) { if (i % 2 == 0) continue; "
                       "s += i; } s;") == 20 * 20);
    assert_true(scalar("int n = 0; while (n * n < 1000) n++; n;") == ceil(sqrt(1000.0)));
    assert_true(scalar("int i = 0; do { i += 3; if (i > 10) break; } while (true); i;") == 12.0);
    assert_true(scalar("int c = 0; for (int i = 0; i < 5; i++) for (int j = 0; j < i; j++) c++; "
                       "c;") == 10.0);
    assert_true(scalar("int i = 5; do i--; while (false); i;") == 4.0);
}

static void conditionals_and_short_circuit(void **state)
{
    (void)state;
    assert_true(scalar("int n = 0; bool b = false && (++n > 0); n;") == 0.0);
    assert_true(scalar("int n = 0; bool b = true || (++n > 0); n;") == 0.0);
    assert_true(scalar("int n = 0; bool b = true && (++n > 0); n;") == 1.0);
    assert_true(scalar("true ^^ false;") == 1.0);
    assert_true(scalar("1 < 2 ? 10 : 20;") == 10.0);
    assert_true(scalar("float x = -2.0; if (x > 0.0) x = 1.0; else if (x < -1.0) x = 3.0; x;") ==
                3.0);
    assert_true(scalar("vec2(1.0, 2.0) == vec2(1.0, 2.0);") == 1.0);
    assert_true(scalar("mat2(1.0) != mat2(1.0);") == 0.0);
}

static void scopes_shadow_and_end(void **state)
{
    (void)state;
    assert_true(scalar("int x = 1; { int x = 2; x += 5; } x;") == 1.0);
    assert_true(scalar("int x = 1; for (int x = 0; x < 3; x++) {} x;") == 1.0);
    assert_compile_error("{ int y = 1; } y;", 1, 16, "unknown variable 'y'");
    /* a declaration without initializer is zero each time it runs */
    results r = run("float f() { float a; a += 1.0; return a; } f(); f(); ivec3 z; z;");
    assert_true(r.v[0].v[0] == 1.0 && r.v[1].v[0] == 1.0);
    assert_true(r.v[2].v[0] == 0.0 && r.v[2].v[2] == 0.0);
}

/* ---- functions ---- */

static void functions_pass_in_out_and_inout(void **state)
{
    (void)state;
    results r = run("void split(in float x, out int whole, inout float acc) {"
                    "  whole = int(x); acc += x - float(whole); }"
                    "int w; float acc = 1.0; split(2.75, w, acc); w; acc;"
                    "float twice(float x) { x *= 2.0; return x; } float y = 3.0; twice(y); y;");
    assert_int_equal(r.n, 4);
    assert_true(r.v[0].v[0] == 2.0 && r.v[1].v[0] == 1.75);
    assert_true(r.v[2].v[0] == 6.0 && r.v[3].v[0] == 3.0); /* in parameters are copies */
}

static void overloads_resolve_by_parameter_types(void **state)
{
    (void)state;
    results r = run("float f(float x) { return 1.0; } float f(int x) { return 2.0; }"
                    "float f(vec2 x) { return 3.0; } f(1.0); f(1); f(vec2(0.0));"
                    "int fact(int n) { int p = 1; for (int i = 2; i <= n; i++) p *= i; return p; }"
                    "fact(10); fact(5) + fact(3);");
    assert_true(r.v[0].v[0] == 1.0 && r.v[1].v[0] == 2.0 && r.v[2].v[0] == 3.0);
    assert_true(r.v[3].v[0] == 3628800.0 && r.v[4].v[0] == 126.0);
}

/* ---- built-ins ---- */

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static void integer_and_bool_builtins(void **state)
{
    (void)state;
    results r = run("lessThan(ivec3(1, 5, 3), ivec3(2, 2, 3)); equal(bvec2(true), bvec2(true, "
                    "false)); any(bvec2(false, true)); all(bvec2(false, true)); not(bvec2(true, "
                    "false)); abs(-5); sign(ivec2(-3, 0)); min(7, 3); max(uvec2(1u, 9u), 4u);"
                    "clamp(ivec2(-5, 50), 0, 10); isnan(0.0 / 0.0); isinf(vec2(1.0 / 0.0, 1.0));");
    assert_int_equal(r.n, 12);
    assert_true(r.v[0].v[0] == 1 && r.v[0].v[1] == 0 && r.v[0].v[2] == 0);
    assert_true(r.v[1].v[0] == 1 && r.v[1].v[1] == 0);
    assert_true(r.v[2].v[0] == 1 && r.v[3].v[0] == 0);
    assert_true(r.v[4].v[0] == 0 && r.v[4].v[1] == 1);
    assert_true(r.v[5].v[0] == 5 && r.v[6].v[0] == -1 && r.v[6].v[1] == 0);
    assert_true(r.v[7].v[0] == 3 && r.v[8].v[0] == 4 && r.v[8].v[1] == 9);
    assert_true(r.v[9].v[0] == 0 && r.v[9].v[1] == 10);
    assert_true(r.v[10].v[0] == 1 && r.v[11].v[0] == 1 && r.v[11].v[1] == 0);
    assert_true(scalar("abs(-2147483647 - 1);") == -2147483648.0); /* wraps as on GPUs */
}

static void bit_casts_and_packing(void **state)
{
    (void)state;
    assert_true(scalar("floatBitsToUint(1.5);") == (double)bits_of(1.5f));
    assert_true(scalar("floatBitsToInt(-2.0);") == (double)(int32_t)bits_of(-2.0f));
    assert_true(scalar("intBitsToFloat(1078530011);") == (double)3.14159274f);
    assert_true(scalar("uintBitsToFloat(0x7f800000u);") == INFINITY);
    /* packSnorm2x16: round(clamp(c, -1, 1) * 32767) in the low then the high 16 bits */
    uint32_t lo = (uint32_t)(int32_t)lrint(0.5 * 32767.0) & 0xFFFFu;
    uint32_t hi = (uint32_t)(int32_t)lrint(-1.0 * 32767.0) & 0xFFFFu;
    assert_true(scalar("packSnorm2x16(vec2(0.5, -3.0));") == (double)(lo | hi << 16));
    assert_true(scalar("packUnorm2x16(vec2(1.0, 0.0));") == 65535.0);
    results r = run("unpackUnorm2x16(65535u); unpackSnorm2x16(0x80017fffu); "
                    "unpackHalf2x16(packHalf2x16(vec2(0.333, 65504.0)));");
    assert_true(r.v[0].v[0] == 1.0 && r.v[0].v[1] == 0.0);
    assert_true(r.v[1].v[0] == 1.0 && r.v[1].v[1] == -1.0);
    /* 0.333 in binary32, then to binary16: 10 bits after the leading one, in [0.25, 0.5) */
    assert_true(r.v[2].v[0] == ldexp(nearbyint(ldexp((double)0.333f, 12)), -12));
    assert_true(r.v[2].v[1] == 65504.0);
}

static void float_builtins_keep_working(void **state)
{
    (void)state;
    assert_true(scalar_in(SC_DOUBLE, "pow(2.0, 10.0);") == 1024.0);
    assert_true(scalar_in(SC_DOUBLE, "length(vec3(3.0, 0.0, 4.0));") == 5.0);
    assert_true(scalar_in(SC_DOUBLE, "min(3.0, 2.0);") == 2.0);
}

/* ---- desktop GLSL's implicit int -> float ---- */

static results run_desktop_with(const char *src, int builtins)
{
    results r;
    memset(&r, 0, sizeof r);
    sc_lang_error err;
    sc_lang_options options = {0, 1, builtins};
    sc_program *prog = sc_program_compile(src, NULL, 0, &options, &err);
    if (!prog)
        fail_msg("'%s' did not compile: %d:%d: %s", src, err.line, err.column, err.message);
    if (sc_program_run(prog, SC_DOUBLE, NULL, collect, count_domain, &r, &err) != 0)
        fail_msg("'%s' failed: %s", src, err.message);
    sc_program_free(prog);
    return r;
}

static results run_desktop(const char *src) { return run_desktop_with(src, 0); }

/* BRDF Explorer's files define their own smoothstep and reflect (GLSL 1.10 to 4.60 allow it) */
static void desktop_dialect_redefines_builtins(void **state)
{
    (void)state;
    results r = run_desktop_with("float smoothstep(float a, float b, float x) { return 7.0; }"
                                 "vec3 reflect(vec3 i, vec3 n) { return vec3(9.0); }"
                                 "smoothstep(0.0, 1.0, 0.5); smoothstep(0, 1, 0);"
                                 "smoothstep(vec2(0.0), vec2(1.0), vec2(0.5)).y;"
                                 "reflect(vec3(1.0), vec3(0.0, 1.0, 0.0)).x;"
                                 "reflect(vec2(1.0, -1.0), vec2(0.0, 1.0)).y;",
                                 1);
    assert_int_equal(r.n, 5);
    assert_true(r.v[0].v[0] == 7.0 && r.v[1].v[0] == 7.0); /* the program's, ints widened */
    assert_true(r.v[2].v[0] == 0.5);                       /* the built-in: vec2 arguments */
    assert_true(r.v[3].v[0] == 9.0);
    assert_true(r.v[4].v[0] == 1.0); /* built-in reflect(i, n) = i - 2 dot(n, i) n */
    /* without the option (and in GLSL ES) it stays an error */
    sc_lang_error err;
    sc_lang_options options = {0, 1, 0};
    assert_null(sc_program_compile("float sin(float x) { return x; }", NULL, 0, &options, &err));
    assert_true(strstr(err.message, "built-in") != NULL);
}

static void desktop_dialect_converts_ints_to_float(void **state)
{
    (void)state;
    results r = run_desktop("float x = 1; x; 1 - 0.25; clamp(0.5, 0, 1); pow(2.0, 2);"
                            "float f(float a) { return a * 2; } f(3); x = 2; x < 3;"
                            "vec3(1.0) * 2; min(7, 3); 1 / 2;");
    assert_int_equal(r.n, 9);
    static const double want[] = {1.0, 0.75, 0.5, 4.0, 6.0};
    for (int i = 0; i < 5; i++)
        assert_true(r.v[i].type.kind == SC_KIND_FLOAT && r.v[i].v[0] == want[i]);
    assert_true(r.v[5].type.kind == SC_KIND_BOOL && r.v[5].v[0] == 1.0);
    assert_true(r.v[6].type.rows == 3 && r.v[6].v[2] == 2.0);
    /* an int operation stays an int one */
    assert_true(r.v[7].type.kind == SC_KIND_INT && r.v[7].v[0] == 3.0);
    assert_true(r.v[8].type.kind == SC_KIND_INT && r.v[8].v[0] == 0.0);
    /* never float -> int */
    sc_lang_error err;
    sc_lang_options options = {0, 1, 0};
    assert_null(sc_program_compile("int i = 1.5;", NULL, 0, &options, &err));
    assert_true(strstr(err.message, "cannot initialize int") != NULL);
    /* wrong calls stay errors (the retry with widened arguments happens once) */
    assert_null(sc_program_compile("pow(1.0);", NULL, 0, &options, &err));
    assert_true(strstr(err.message, "pow: expects 2 arguments") != NULL);
    assert_null(sc_program_compile("clamp(true, 0, 1);", NULL, 0, &options, &err));
}

/* ---- errors ---- */

static void type_errors_name_line_and_column(void **state)
{
    (void)state;
    assert_compile_error("1 + 2.0;", 1, 3, "int and float");
    assert_compile_error("float x = 1;", 1, 9, "cannot initialize float 'x' with int");
    assert_compile_error("int x;\nx = 2.0;", 2, 3, "cannot assign float to int");
    assert_compile_error("vec2(1.0) < vec2(2.0);", 1, 11, "lessThan");
    assert_compile_error("1.0 % 2.0;", 1, 5, "operator '%'");
    assert_compile_error("if (1) {}", 1, 5, "a condition must be a bool");
    assert_compile_error("sin(1);", 1, 1, "argument 1 is int");
    assert_compile_error("const int c = 1; c = 2;", 1, 20, "cannot assign to a constant");
    assert_compile_error("vec3 v; v.xx = vec2(1.0);", 1, 14, "repeats a component");
    assert_compile_error("vec3(1.0)[3];", 1, 10, "index 3 is out of range 0..2");
    assert_compile_error("\n\n  lessThn(1, 2);", 3, 3, "did you mean 'lessThan'");
    assert_compile_error("float f(float x) { return f(x); }", 1, 27, "forbids recursion");
    assert_compile_error("float f(float x);\nf(1.0);", 2, 1, "never defined");
    assert_compile_error("float f(float x) { return 1; }", 1, 20, "returns float, not int");
    assert_compile_error("void f(out float x) { x = 1.0; } f(2.0);", 1, 34, "out parameter");
    assert_compile_error("break;", 1, 1, "outside a loop");
    assert_compile_error("return 1;", 1, 1, "outside a function");
    assert_compile_error("float sin(float x) { return x; }", 1, 7, "built-in");
    assert_compile_error("int x = 1; int x = 2;", 1, 16, "already declared");
    assert_compile_error("4294967296;", 1, 1, "does not fit in 32 bits");
    assert_compile_error("/* open", 1, 1, "unterminated comment");
    assert_compile_error("1;\n  /* open\n\n", 2, 3, "unterminated comment");
    assert_compile_error("#define X 1\nX;", 1, 1, "preprocessor");
    assert_compile_error("void f() {} f() + 1;", 1, 17, "void");
}

static void runtime_errors_name_the_line(void **state)
{
    (void)state;
    assert_runtime_error("int i = 0;\nwhile (true) i++;", 1000, 2,
                         "more than 1000 loop iterations");
    assert_runtime_error("for (;;) {}", 0, 1, "more than 10000000 loop iterations");
    assert_runtime_error("vec3 v;\nint i = -1;\nv[i];", 0, 3, "index -1 is out of range 0..2");
    assert_runtime_error("float g(float x) { if (x > 0.0) return 1.0; }\ng(-1.0);", 0, 1,
                         "without 'return'");
}

/* ---- arrays, structures, switch, prototypes, modf ---- */

/* The value of the last expression of src, a scalar. */
static double last_scalar(const char *src)
{
    results r = run(src);
    assert_true(r.n >= 1);
    assert_int_equal(sc_ltype_size(r.v[r.n - 1].type), 1);
    return r.v[r.n - 1].v[0];
}

static void arrays_index_assign_and_compare(void **state)
{
    (void)state;
    assert_true(scalar("float a[3] = float[3](1.0, 2.0, 4.0); a[0] + a[1] * a[2];") == 9.0);
    assert_true(scalar("float[3] b = float[](1.0, 2.0, 3.0); b.length();") == 3.0);
    assert_true(scalar("float c[] = float[](1.0, 2.0, 3.0, 4.0); c.length();") == 4.0);
    assert_true(scalar("float z[3]; z[0] + z[1] + z[2];") == 0.0);
    /* sum of squares 1..5 through computed indices: n(n+1)(2n+1)/6 */
    assert_true(scalar("int s = 0; int a[5] = int[5](1, 2, 3, 4, 5);\n"
                       "for (int i = 0; i < a.length(); i++) s += a[i] * a[i]; s;") ==
                5.0 * 6.0 * 11.0 / 6.0);
    assert_true(scalar("int a[4]; for (int i = 0; i < 4; i++) a[i] = i * i; a[3] - a[1];") ==
                9.0 - 1.0);
    /* assignment copies the whole array */
    assert_true(scalar("float a[2] = float[2](1.0, 2.0); float b[2]; b = a; a[0] = 5.0; b[0];") ==
                1.0);
    results r = run("float a[2] = float[2](1.0, 2.0); float b[2] = float[2](1.0, 2.0);\n"
                    "a == b; a != b; b[1] = -2.0; a == b; (true ? a : b)[1]; (false ? a : b)[1];");
    assert_int_equal(r.n, 5);
    assert_true(r.v[0].v[0] == 1.0 && r.v[1].v[0] == 0.0 && r.v[2].v[0] == 0.0);
    assert_true(r.v[3].v[0] == 2.0 && r.v[4].v[0] == -2.0);
    /* vectors in arrays: a component stored through a computed index */
    r = run("vec3 v[2]; int i = 1; v[i].y = 2.0; v[i][2] = 3.0; v[1];");
    assert_int_equal(r.n, 1);
    assert_true(r.v[0].v[0] == 0.0 && r.v[0].v[1] == 2.0 && r.v[0].v[2] == 3.0);
    /* sizes are constant integer expressions, const arrays constant */
    assert_true(scalar("const int N = 2; float a[N * 2 + 1]; a.length();") == 5.0);
    assert_true(scalar("const int K[3] = int[3](1, 2, 3); K[2] - K[0];") == 2.0);
    assert_true(scalar("mat2 m[2]; m[1][1][0] = 4.0; m[1][1].x;") == 4.0);
}

static void arrays_pass_to_and_return_from_functions(void **state)
{
    (void)state;
    assert_true(scalar("float sum(float a[3]) { return a[0] + a[1] + a[2]; }\n"
                       "sum(float[3](1.0, 2.0, 3.5));") == 6.5);
    assert_true(scalar("void fill(out int a[3]) { for (int i = 0; i < 3; i++) a[i] = 10 * i; }\n"
                       "int b[3]; fill(b); b[2];") == 20.0);
    assert_true(scalar("void twice(inout float[2] a) { a[0] *= 2.0; a[1] *= 2.0; }\n"
                       "float c[2] = float[2](1.5, 3.0); twice(c); c[1];") == 6.0);
    assert_true(scalar("float[2] pair(float x) { return float[2](x, -x); } pair(2.0)[1];") == -2.0);
    /* an in parameter is a copy */
    assert_true(last_scalar("float first(float a[2]) { a[0] = 9.0; return a[0]; }\n"
                            "float c[2] = float[2](1.0, 2.0); first(c); c[0];") == 1.0);
}

static void structures_construct_select_assign_and_compare(void **state)
{
    (void)state;
    assert_true(scalar("struct P { vec2 pos; float w; };\n"
                       "P p = P(vec2(1.0, 2.0), 0.5); p.pos.y * p.w;") == 1.0);
    assert_true(scalar("struct A { float x; }; struct B { A a; A arr[2]; };\n"
                       "B b = B(A(1.0), A[2](A(2.0), A(3.0))); b.arr[1].x - b.a.x;") == 2.0);
    results r = run("struct P { vec2 pos; float w; }; P p = P(vec2(1.0), 0.5);\n"
                    "P q = p; p == q; q.w = 1.0; p == q; p != q; p.w;");
    assert_int_equal(r.n, 4);
    assert_true(r.v[0].v[0] == 1.0 && r.v[1].v[0] == 0.0 && r.v[2].v[0] == 1.0);
    assert_true(r.v[3].v[0] == 0.5);
    /* (1 + 2i)(3 - i) = 5 + 5i, with structures as parameters and results */
    r = run("struct C { float re, im; };\n"
            "C mul(C a, C b) { return C(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }\n"
            "C z = mul(C(1.0, 2.0), C(3.0, -1.0)); z.re; z.im;");
    assert_int_equal(r.n, 2);
    assert_true(r.v[0].v[0] == 5.0 && r.v[1].v[0] == 5.0);
    /* members of array elements at computed indices, read and written */
    assert_true(
        scalar("struct T { int a; int b; }; T ts[3];\n"
               "for (int i = 0; i < 3; i++) ts[i].b = i + 1; ts[2].b * ts[1].b + ts[0].a;") == 6.0);
    assert_true(scalar("struct P { vec2 pos; float w; }; P ps[2]; int i = 1;\n"
                       "ps[i] = P(vec2(3.0), 4.0); ps[1].w + ps[0].w;") == 4.0);
    assert_true(scalar("struct P { vec2 pos; float w; };\n"
                       "void set(out P p) { p.w = 3.0; p.pos = vec2(1.0, 2.0); }\n"
                       "P p; set(p); p.pos.y + p.w;") == 5.0);
    /* a structure declared in a block ends with it; one declared with its definition */
    assert_true(last_scalar("{ struct L { int k; }; L l = L(3); l.k; }\n"
                            "struct L { float k; } m = L(1.5); m.k;") == 1.5);
}

typedef struct {
    char text[8][32];
    int n;
} texts;

static int collect_text(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    texts *t = user;
    (void)line, (void)v;
    if (t->n < 8)
        snprintf(t->text[t->n++], sizeof t->text[0], "%.*s", len, text);
    return 0;
}

/* A top-level array or structure prints each element or member, named by its path. */
static void aggregates_print_element_by_element(void **state)
{
    (void)state;
    sc_lang_error err;
    sc_program *prog = sc_program_compile(
        "struct S { float x; ivec2 v[2]; };\nS s; s; float[2](1.0, 2.0);", NULL, 0, NULL, &err);
    assert_non_null(prog);
    texts t = {.n = 0};
    assert_int_equal(sc_program_run(prog, SC_HIGHP, NULL, collect_text, NULL, &t, &err), 0);
    sc_program_free(prog);
    static const char *const want[] = {"s.x", "s.v[0]", "s.v[1]", "float[2](1.0, 2.0)[0]",
                                       "float[2](1.0, 2.0)[1]"};
    assert_int_equal(t.n, 5);
    for (int i = 0; i < 5; i++)
        assert_string_equal(t.text[i], want[i]);
}

static void switch_selects_falls_through_and_breaks(void **state)
{
    (void)state;
    static const int in[] = {0, 1, 2, 7, -3};
    static const int want[] = {10, 1 + 5, 2 + 5, -1, -1};
    for (int i = 0; i < 5; i++) {
        char src[200];
        snprintf(src, sizeof src,
                 "int f(int x) { switch (x) { case 0: return 10; case 1: case 2: x += 5; break;\n"
                 "default: x = -1; } return x; } f(%d);",
                 in[i]);
        assert_true(scalar(src) == want[i]);
    }
    /* continue belongs to the loop; break to the switch: 2 × (10 + 1 + 2 × 100) */
    assert_true(
        scalar("int s = 0; for (int i = 0; i < 6; i++) { switch (i % 3) {\n"
               "case 0: continue; case 1: s += 10; break; default: s += 1; } s += 100; } s;") ==
        422.0);
    assert_true(scalar("uint u = 3u; int r = 0; switch (u) { case 1u + 2u: r = 1; } r;") == 1.0);
    assert_true(scalar("int r = 0; switch (5) { case 1: r = 1; } r;") == 0.0); /* no label */
    assert_true(scalar("int r = 0; switch (1) { case 1: switch (2) { case 2: r += 1; break; }\n"
                       "r += 10; break; case 3: r += 100; } r;") == 11.0);
    assert_true(scalar("const int K = -4; int r = 0; switch (-4) { case K: r = 2; } r;") == 2.0);
    /* a variable declared in one case is zero in a later one its declaration was skipped for */
    results r = run("int g(int x) { switch (x) { case 0: int y = 5; case 1: y += 1; return y; }\n"
                    "return -1; } g(0); g(1);");
    assert_true(r.v[0].v[0] == 6.0 && r.v[1].v[0] == 1.0);
}

static void prototypes_declare_before_definitions(void **state)
{
    (void)state;
    assert_true(scalar("float g(float x);\nfloat h(float x) { return g(x) * 2.0; }\n"
                       "float g(float x) { return x + 1.0; }\nfloat g(float);\nh(1.5);") == 5.0);
    assert_true(scalar("void set(out int r);\nint r; set(r); r;\nvoid set(out int x) { x = 7; }") ==
                7.0);
}

/* modf(x, out i): i = trunc(x), the result x - i (both exact). */
static void modf_splits_whole_and_fraction(void **state)
{
    (void)state;
    static const double xs[] = {2.75, -1.5, 0.25, -0.0, 8388607.5, 3.0};
    for (int k = 0; k < 6; k++) {
        char src[100];
        snprintf(src, sizeof src, "float i; float f = modf(%.2f, i); f; i;", xs[k]);
        results r = run(src);
        assert_int_equal(r.n, 2);
        assert_true(r.v[1].v[0] == trunc(xs[k]));
        assert_true(r.v[0].v[0] == xs[k] - trunc(xs[k]));
    }
    results r = run("vec3 i; modf(vec3(1.25, -2.5, 7.0), i); i;");
    assert_true(r.v[0].v[0] == 0.25 && r.v[0].v[1] == -0.5 && r.v[0].v[2] == 0.0);
    assert_true(r.v[1].v[0] == 1.0 && r.v[1].v[1] == -2.0 && r.v[1].v[2] == 7.0);
    assert_true(scalar_in(SC_MEDIUMP, "float i; modf(1000.5, i);") == 0.5);
}

static void aggregate_errors_name_line_and_column(void **state)
{
    (void)state;
    assert_compile_error("float a[2];\na + a;", 2, 3, "operator '+' cannot apply to float[2]");
    assert_compile_error("float a[2]; a[2];", 1, 14, "index 2 is out of range 0..1");
    assert_compile_error("float a[2]; int b[2]; a == b;", 1, 25, "float[2] and int[2]");
    assert_compile_error("float a[2] = float[3](1.0, 2.0, 3.0);", 1, 12,
                         "cannot initialize float[2] 'a' with float[3]");
    assert_compile_error("float[2](1.0);", 1, 1, "float[2]: expects 2 arguments, got 1");
    assert_compile_error("float a[0];", 1, 9, "from 1 to");
    assert_compile_error("int n = 2; float a[n];", 1, 20, "constant integer expression");
    assert_compile_error("float a[2][2];", 1, 11, "arrays of arrays");
    assert_compile_error("float a[2]; vec2(a);", 1, 13, "argument 1 is float[2]");
    assert_compile_error("float a[2]; sin(a);", 1, 13, "no arrays or structures");
    assert_compile_error("float a[2]; a.x;", 1, 14, "cannot swizzle a float[2]");
    assert_compile_error("float a[];", 1, 7, "needs an initializer");
    assert_compile_error("struct S { float x; };\nS s; s.y;", 2, 7, "no member 'y'");
    assert_compile_error("struct S { float x; }; S(1);", 1, 24, "argument 1 is int, not float");
    assert_compile_error("struct S { float x; }; S s; s++;", 1, 30, "needs a number, not S");
    assert_compile_error("struct S { float x; }; S s; -s;", 1, 29, "cannot apply to S");
    assert_compile_error("struct S { struct T { float x; } t; };", 1, 12, "inside another");
    assert_compile_error("struct S { float x; float x; };", 1, 27, "already has a member 'x'");
    assert_compile_error("struct S { };", 1, 12, "no member");
    assert_compile_error("struct S { float x; }; S;", 1, 24, "is a structure, not a variable");
    assert_compile_error("{ struct L { int k; }; } L l;", 1, 26, "unknown variable 'L'");
    assert_compile_error("struct S { S s; };", 1, 12, "expected a type");
}

static void switch_and_prototype_errors(void **state)
{
    (void)state;
    assert_compile_error("switch (1.0) { case 1: ; }", 1, 9, "int or uint, not float");
    assert_compile_error("switch (1) { case 1: ; case 1: ; }", 1, 24, "a second 'case 1'");
    assert_compile_error("switch (1) { default: ; default: ; }", 1, 25, "a second 'default'");
    assert_compile_error("int x; switch (x) { x = 1; case 1: ; }", 1, 21, "before the first");
    assert_compile_error("case 1: ;", 1, 1, "outside a switch");
    assert_compile_error("switch (1) { case 1: { case 2: ; } }", 1, 24, "directly in the body");
    assert_compile_error("int y; switch (1) { case y: ; }", 1, 21, "constant int expression");
    assert_compile_error("switch (1u) { case 1: ; }", 1, 15, "constant uint expression");
    assert_compile_error("switch (1) { case 1: ; default: }", 1, 24, "needs a statement");
    assert_compile_error("switch (1) { case 1: continue; }", 1, 22, "'continue' outside a loop");
    assert_compile_error("float f(float x);\nint f(float x) { return 1; }", 2, 5,
                         "returns int here but float");
    assert_compile_error("void f(in float x);\nvoid f(inout float x) {}", 2, 6,
                         "parameter 1 of 'f' is 'inout' here but 'in'");
    assert_compile_error("float f(float x) { return x; }\nfloat f(float y) { return y; }", 2, 7,
                         "already defined");
    assert_compile_error("float a(float x);\nfloat b(float x) { return a(x); }\n"
                         "float a(float x) { return b(x); }",
                         3, 27, "forbids recursion");
    assert_compile_error("float a(float x); float c(float x);\nfloat b(float x) { return c(x); }\n"
                         "float c(float x) { return a(x); }\nfloat a(float x) { return b(x); }",
                         4, 27, "forbids recursion");
    assert_compile_error("float i; modf(1.5, 2.0);", 1, 10, "out parameter");
    assert_compile_error("int i; modf(1.5, i);", 1, 8, "modf takes");
}

/* Deep nesting is an error, never a C stack overflow, however it nests. */
static void deep_nesting_is_an_error(void **state)
{
    (void)state;
    enum { N = 100000 };
    static const char *const openers[] = {"(", "{", "-", "x = ", "true ? "};
    for (size_t k = 0; k < sizeof openers / sizeof openers[0]; k++) {
        size_t len = strlen(openers[k]);
        char *src = malloc(N * len + 16);
        assert_non_null(src);
        strcpy(src, "int x; "); /* x exists for the assignments */
        for (int i = 0; i < N; i++)
            memcpy(src + 7 + i * len, openers[k], len);
        strcpy(src + 7 + N * len, "1");
        sc_lang_error err;
        sc_program *prog = sc_program_compile(src, NULL, 0, NULL, &err);
        assert_null(prog);
        if (!strstr(err.message, "nested too deeply"))
            fail_msg("'%s'...: %s", openers[k], err.message);
        free(src);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(empty_programs_print_nothing),
        cmocka_unit_test(int_arithmetic_wraps_like_c_fixed_width_types),
        cmocka_unit_test(int_division_truncates_toward_zero),
        cmocka_unit_test(division_by_zero_is_all_ones_and_reported),
        cmocka_unit_test(shifts_take_the_count_modulo_32),
        cmocka_unit_test(bitwise_operators),
        cmocka_unit_test(length_method_counts_components_and_columns),
        cmocka_unit_test(conversions_follow_glsl),
        cmocka_unit_test(integer_inputs_wrap),
        cmocka_unit_test(highp_rounds_every_operation_to_binary32),
        cmocka_unit_test(matrices_multiply_as_linear_algebra),
        cmocka_unit_test(loops_match_closed_forms),
        cmocka_unit_test(conditionals_and_short_circuit),
        cmocka_unit_test(scopes_shadow_and_end),
        cmocka_unit_test(functions_pass_in_out_and_inout),
        cmocka_unit_test(overloads_resolve_by_parameter_types),
        cmocka_unit_test(integer_and_bool_builtins),
        cmocka_unit_test(bit_casts_and_packing),
        cmocka_unit_test(float_builtins_keep_working),
        cmocka_unit_test(desktop_dialect_converts_ints_to_float),
        cmocka_unit_test(desktop_dialect_redefines_builtins),
        cmocka_unit_test(type_errors_name_line_and_column),
        cmocka_unit_test(runtime_errors_name_the_line),
        cmocka_unit_test(deep_nesting_is_an_error),
        cmocka_unit_test(arrays_index_assign_and_compare),
        cmocka_unit_test(arrays_pass_to_and_return_from_functions),
        cmocka_unit_test(structures_construct_select_assign_and_compare),
        cmocka_unit_test(aggregates_print_element_by_element),
        cmocka_unit_test(switch_selects_falls_through_and_breaks),
        cmocka_unit_test(prototypes_declare_before_definitions),
        cmocka_unit_test(modf_splits_whole_and_fraction),
        cmocka_unit_test(aggregate_errors_name_line_and_column),
        cmocka_unit_test(switch_and_prototype_errors),
    };
    return cmocka_run_group_tests_name("lang", tests, NULL, NULL);
}
