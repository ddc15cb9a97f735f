/* Block execution (sc_program_run_block) against runs of one element (sc_program_run), bit for
 * bit (NaN for NaN), in every precision: every value of every program of the corpus (each string of
 * tests/unit/test_lang.c that compiles, each case of the tests/mesa cases files), and programs whose
 * control flow differs between elements (branches, loops with element-dependent trip counts,
 * early returns, calls from several sites, errors in some elements) on random inputs. Domain
 * reports and runtime errors must match element by element too. Run from the source tree. */
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
#include "tests/support/lang_value.h"

enum { MAX_ELEMENTS = 600, MAX_REPORTS = 4096, MAX_INPUT_COLUMNS = 8, MAX_SOURCE = 1 << 20 };

/* ---- what one element gives ---- */

typedef struct {
    long element;
    int line, column;
    const char *func, *rule;
} report;

typedef struct {
    report r[MAX_REPORTS];
    int n;
} report_log;

typedef struct {
    lang_value_pick pick; /* first: the run's user pointer is also the pick's */
    report_log *log;
    long element;
} element_run;

static void log_report(report_log *log, long element, int line, int column, const char *func,
                       const char *rule)
{
    if (log->n < MAX_REPORTS)
        log->r[log->n++] = (report){element, line, column, func, rule};
}

static void element_domain(void *user, int line, int column, const char *func, const char *rule)
{
    element_run *e = user;
    log_report(e->log, e->element, line, column, func, rule);
}

static void block_domain(void *user, long element, int line, int column, const char *func,
                         const char *rule)
{
    log_report(user, element, line, column, func, rule);
}

/* The reports of one element, in their order, from a log. */
static int reports_of(const report_log *log, long element, report *out)
{
    int n = 0;
    for (int i = 0; i < log->n; i++)
        if (log->r[i].element == element)
            out[n++] = log->r[i];
    return n;
}

static int same_report(const report *a, const report *b)
{
    return a->line == b->line && a->column == b->column && strcmp(a->func, b->func) == 0 &&
           strcmp(a->rule, b->rule) == 0;
}

/* ---- the comparison ---- */

/* Equal bits; NaN for NaN whatever their sign and payload, which C leaves open (x + y may
 * return either operand's NaN, and a compiler may swap the operands of + and *). */
typedef struct {
    const double *columns[MAX_INPUT_COLUMNS]; /* input components, n values each */
    long n;
} input_set;

/* The input values of element e, as sc_program_run takes them. */
static void element_inputs(const sc_program *prog, const sc_lang_input *decl, int n_inputs,
                           const input_set *in, long e, sc_lvalue *values)
{
    (void)prog;
    int column = 0;
    for (int i = 0; i < n_inputs; i++) {
        values[i].type = decl[i].type;
        for (int k = 0; k < sc_ltype_size(decl[i].type); k++)
            values[i].v[k] = in->columns[column++][e];
    }
}

static report_log block_log, element_log;

/* Value `value` of prog for every element, both ways, in precision p: equal bits, equal reports,
 * the same first failing element and error. */
static void compare_value(const char *src, const sc_program *prog, const sc_lang_input *decl,
                          int n_inputs, const input_set *in, sc_prec p, int value)
{
    int size = sc_ltype_size(sc_program_value_type(prog, value));
    static double block_out[16][MAX_ELEMENTS];
    double *cols[16];
    for (int k = 0; k < 16; k++) {
        cols[k] = block_out[k];
        memset(block_out[k], 0, sizeof block_out[k]);
    }
    block_log.n = element_log.n = 0;
    sc_lang_block job = {p, in->n, in->columns, value, cols, block_domain, &block_log};
    sc_lang_error berr, eerr;
    memset(&eerr, 0, sizeof eerr);
    long ran = sc_program_run_block(prog, &job, &berr), first_failed = in->n;
    for (long e = 0; e < in->n; e++) {
        double one[16] = {0};
        sc_lvalue values[8];
        element_inputs(prog, decl, n_inputs, in, e, values);
        element_run run = {{value, 0, one}, &element_log, e};
        sc_lang_error err;
        int rc = sc_program_run(prog, p, values, lang_value_keep, element_domain, &run, &err);
        if (rc < 0 && first_failed == in->n) {
            first_failed = e;
            eerr = err;
        }
        for (int k = 0; rc == 0 && k < size; k++) {
            if (!lang_same_bits(one[k], block_out[k][e]))
                fail_msg("%s\nprecision %d value %d element %ld component %d: block %a, alone %a",
                         src, (int)p, value, e, k, block_out[k][e], one[k]);
        }
        report a[64], b[64];
        int na = reports_of(&element_log, e, a), nb = reports_of(&block_log, e, b);
        if (na != nb)
            fail_msg("%s\nelement %ld: %d domain reports alone, %d in the block", src, e, na, nb);
        for (int i = 0; i < na; i++)
            if (!same_report(&a[i], &b[i]))
                fail_msg("%s\nelement %ld: report %d differs", src, e, i);
    }
    if (ran != first_failed)
        fail_msg("%s\nprecision %d: the block stopped at %ld, alone at %ld", src, (int)p, ran,
                 first_failed);
    if (ran < in->n && (berr.line != eerr.line || berr.column != eerr.column ||
                        strcmp(berr.message, eerr.message) != 0))
        fail_msg("%s\nerrors differ: %d:%d %s / %d:%d %s", src, berr.line, berr.column,
                 berr.message, eerr.line, eerr.column, eerr.message);
}

/* Every value of src in every precision; 0, or -1 if src does not compile. */
static int compare_program(const char *src, const sc_lang_input *decl, int n_inputs,
                           const input_set *in)
{
    sc_lang_error err;
    sc_lang_options options = {20000, 0, 0};
    sc_program *prog = sc_program_compile(src, decl, n_inputs, &options, &err);
    if (!prog)
        return -1;
    for (int p = SC_DOUBLE; p <= SC_LOWP; p++)
        for (int v = 0; v < sc_program_values(prog); v++)
            compare_value(src, prog, decl, n_inputs, in, (sc_prec)p, v);
    sc_program_free(prog);
    return 0;
}

/* ---- the corpus ---- */

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        fail_msg("cannot open %s (run the unit tests from the source tree)", path);
    char *buf = malloc(MAX_SOURCE);
    assert_non_null(buf);
    size_t len = fread(buf, 1, MAX_SOURCE - 1, f);
    fclose(f);
    buf[len] = '\0';
    return buf;
}

/* The C string literal at *s (after its opening quote), unescaped and appended to out; *s moves
 * past its closing quote. */
static void take_literal(const char **s, char *out, size_t *len, size_t cap)
{
    const char *p = *s;
    for (; *p && *p != '"'; p++) {
        char c = *p;
        if (c == '\\') {
            p++;
            c = *p == 'n' ? '\n' : *p == 't' ? '\t' : *p;
        }
        if (*len + 1 < cap)
            out[(*len)++] = c;
    }
    out[*len] = '\0';
    *s = *p ? p + 1 : p;
}

/* Each string of a C file (adjacent literals joined) that compiles is a program; returns how
 * many were compared. */
static int compare_c_strings(const char *path, const input_set *in)
{
    char *text = read_file(path), *lit = malloc(MAX_SOURCE);
    assert_non_null(lit);
    int compared = 0;
    for (const char *s = text; *s; s++) {
        if (*s == '\'' && s[1] && s[2] == '\'') { /* a character constant such as '"' */
            s += 2;
            continue;
        }
        if (*s != '"')
            continue;
        size_t len = 0;
        s++;
        take_literal(&s, lit, &len, MAX_SOURCE);
        for (;;) { /* adjacent literals */
            const char *t = s;
            while (*t == ' ' || *t == '\n')
                t++;
            if (*t != '"')
                break;
            s = t + 1;
            take_literal(&s, lit, &len, MAX_SOURCE);
        }
        compared += compare_program(lit, NULL, 0, in) == 0;
        s--;
    }
    free(lit);
    free(text);
    return compared;
}

/* Each case of a tests/mesa cases file: its `@` lines, then its expression. */
static int compare_cases(const char *path, const input_set *in)
{
    char *text = read_file(path), *prelude = calloc(1, MAX_SOURCE), *src = malloc(MAX_SOURCE);
    assert_non_null(prelude);
    assert_non_null(src);
    int compared = 0;
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        if (line[0] == '#')
            continue;
        if (line[0] == '@') {
            strcat(strcat(prelude, line + 1), "\n");
            continue;
        }
        const char *tab = strchr(line, '\t');
        if (!tab)
            continue;
        snprintf(src, MAX_SOURCE, "%s%s", prelude, tab + 1);
        compared += compare_program(src, NULL, 0, in) == 0;
    }
    free(src);
    free(prelude);
    free(text);
    return compared;
}

static input_set no_inputs(long n)
{
    input_set in;
    memset(&in, 0, sizeof in);
    in.n = n;
    return in;
}

static void test_lang_corpus(void **state)
{
    (void)state;
    input_set in = no_inputs(67); /* more than one block of some programs, fewer of others */
    int n = compare_c_strings("tests/unit/test_lang.c", &in);
    if (n < 60)
        fail_msg("only %d programs in tests/unit/test_lang.c", n);
}

static void test_mesa_cases(void **state)
{
    (void)state;
    input_set in = no_inputs(5);
    assert_true(compare_cases("tests/mesa/language.cases", &in) > 80);
    assert_true(compare_cases("tests/mesa/expressions.cases", &in) > 80);
}

/* ---- divergent programs on random inputs ---- */

static uint64_t rng_state = 0x9E3779B97F4A7C15u;

static double uniform(void)
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

/* Mostly in [-4, 4], some special values (zeros, infinities, NaN, large, tiny). */
static double random_input(void)
{
    static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, 65504.0, 1e-30, 1e30, 3.0};
    double u = uniform();
    if (u < 0.1)
        return special[(int)(uniform() * 9)];
    if (u < 0.12)
        return uniform() < 0.5 ? INFINITY : NAN;
    return (uniform() - 0.5) * 8.0;
}

static double columns_store[MAX_INPUT_COLUMNS][MAX_ELEMENTS];

static input_set random_inputs(long n)
{
    input_set in;
    in.n = n;
    for (int c = 0; c < MAX_INPUT_COLUMNS; c++) {
        for (long e = 0; e < n; e++)
            columns_store[c][e] = random_input();
        in.columns[c] = columns_store[c];
    }
    return in;
}

static const char *const divergent[] = {
    /* if/else on the element, both sides computing */
    "float y = x > 0.0 ? sqrt(x) : log(-x); y * 2.0",
    "float y; if (x < v.y) { y = pow(x, v.z); } else { y = inversesqrt(v.x) + x; } y",
    /* loops whose trip count depends on the element, break and continue */
    "int n = int(clamp(abs(x) * 3.0, 0.0, 20.0)); float s = 0.0;\n"
    "for (int i = 0; i < n; i++) { if (i == 7) continue; s += float(i) * v.x; if (s > 9.0) break; "
    "}\n"
    "s",
    "int k = 0; float t = abs(x) + 1.0; while (t > 1.0 && k < 40) { t *= 0.7; k++; } ivec2(k, k * "
    "k)",
    "int k = int(abs(x)); do { k -= 3; } while (k > 0); k",
    /* early return, calls from several sites, out parameters */
    "float f(float a) { if (a < 0.0) return -1.0; float s = a; for (int i = 0; i < int(a); i++) "
    "s = s * 0.5 + 1.0; return s; }\n"
    "float g(float a, out float b) { b = a * 2.0; if (a > 1.0) return f(a); return f(-a) + b; }\n"
    "float b; float r = x > 0.5 ? g(x, b) : f(v.z); vec2(r, b)",
    "void split(float a, out int w, out float r) { if (a > 0.0) { w = int(a); r = a - float(w); } "
    "}\n"
    "int w; float r; split(x, w, r); split(v.y, w, r); vec2(float(w), r)",
    /* integers: division by zero, shifts past the width and wrapping in some elements */
    "int a = int(x * 1000.0), b = int(v.x); ivec4(a / b, a % (b + 1), a << b, a >> (b & 40))",
    "uint u = uint(abs(x) * 1e9); uvec2(u * 3u + 7u, u / uint(v.y))",
    /* domain errors in some elements, vectors, matrices */
    "vec3 n = normalize(v); vec4(n, dot(n, vec3(x)))",
    "mat3 m = mat3(v, v.yzx, vec3(x)); inverse(m) * v",
    "acos(x) + asin(v.x) + atanh(v.y) + smoothstep(v.z, x, 0.5)",
    "bvec3 b = lessThan(v, vec3(x)); any(b) ? float(x) : dot(v, v)",
    /* runtime errors in some elements only */
    "vec3 a = v; int i = int(x); a[i] = 2.0; a",
    "float h(float a) { if (a > 0.0) return a; } h(x)",
    "float s = 0.0; for (int i = 0; i < int(x * 5000.0); i++) s += 1.0; s",
    /* the precisions' rounding over many operations */
    "float acc = x; for (int i = 0; i < 12; i++) acc = acc * v.x + v.y / (v.z + float(i)); acc",
    /* the column forms of mix, clamp, min, max, sqrt (NaN, infinities, lo > hi, x < 0 in some
     * elements), built-ins of constants computed once (a domain error in every element) */
    "vec4(mix(x, v.y, v.z), clamp(x, v.x, v.y), sqrt(v.z), min(x, v.x))",
    "vec3 a = max(v, vec3(x)); vec3 b = mix(v, v.zxy, x); vec3 c = clamp(v, -1.0, x); a + b * c",
    "vec2(min(v.xy, x).y, sqrt(x * v.x))",
    "vec3(pow(0.82, 2.2), log(-1.0), sqrt(-4.0)) * x",
    "float c = 2.0; vec2(pow(c, x), exp(c) + inversesqrt(c - 2.0))",
    /* errors while the elements still share one call stack and iteration count */
    "float s = 0.0; for (int i = 0; i < 30000; i++) s += x; s",
    "float g(float a) { if (a > 1e30) return a; } float f(float a) { return g(a) + 1.0; } f(2.0)",
};

static void test_divergent(void **state)
{
    (void)state;
    sc_lang_input decl[2] = {{"x", {SC_KIND_FLOAT, 1, 1}}, {"v", {SC_KIND_FLOAT, 1, 3}}};
    for (size_t i = 0; i < sizeof divergent / sizeof divergent[0]; i++)
        for (int round = 0; round < 3; round++) {
            input_set in = random_inputs(round == 0 ? 1 : round == 1 ? 3 : MAX_ELEMENTS);
            if (compare_program(divergent[i], decl, 2, &in) < 0)
                fail_msg("did not compile: %s", divergent[i]);
        }
}

/* The disney BRDF of bench/programs/disney.glsl on random directions and parameters. */
static void test_disney(void **state)
{
    (void)state;
    char *brdf = read_file("bench/programs/disney.glsl");
    char *src = malloc(strlen(brdf) + 128);
    assert_non_null(src);
    sprintf(src,
            "%s\nBRDF(normalize(L), normalize(V), vec3(0, 0, 1), vec3(1, 0, 0), "
            "vec3(0, 1, 0))\n",
            brdf);
    sc_lang_input decl[2] = {{"L", {SC_KIND_FLOAT, 1, 3}}, {"V", {SC_KIND_FLOAT, 1, 3}}};
    input_set in = random_inputs(MAX_ELEMENTS);
    if (compare_program(src, decl, 2, &in) < 0)
        fail_msg("bench/programs/disney.glsl did not compile");
    free(src);
    free(brdf);
}

/* Inputs are rounded and wrapped as sc_program_run rounds them; n = 0 runs nothing; a value
 * that does not exist is an error. */
static void test_edges(void **state)
{
    (void)state;
    sc_lang_input decl[3] = {
        {"i", {SC_KIND_INT, 1, 1}}, {"b", {SC_KIND_BOOL, 1, 1}}, {"u", {SC_KIND_UINT, 1, 2}}};
    input_set in = random_inputs(MAX_ELEMENTS);
    for (long e = 0; e < in.n; e++)
        columns_store[0][e] *= 1e9; /* beyond 32 bits: wrapped */
    assert_int_equal(compare_program("i + 1; b; u * 3u; i", decl, 3, &in), 0);
    sc_lang_error err;
    sc_program *prog = sc_program_compile("1.0", NULL, 0, NULL, &err);
    assert_non_null(prog);
    double out[1];
    double *cols[1] = {out};
    sc_lang_block job = {SC_HIGHP, 0, NULL, 0, cols, NULL, NULL};
    assert_int_equal(sc_program_run_block(prog, &job, &err), 0);
    job.n = 1;
    job.value = 1;
    assert_int_equal(sc_program_run_block(prog, &job, &err), 0);
    assert_non_null(strstr(err.message, "no value 1"));
    sc_program_free(prog);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lang_corpus), cmocka_unit_test(test_mesa_cases),
        cmocka_unit_test(test_divergent),   cmocka_unit_test(test_disney),
        cmocka_unit_test(test_edges),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
