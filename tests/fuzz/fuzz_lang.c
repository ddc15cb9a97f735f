/* libFuzzer harness: the language's compiler and interpreter (shadecalc/lang.h) must accept or
 * reject any program without crashing, leaking, reading out of bounds or hanging, in every
 * precision (loops are bounded by a small iteration limit); and block execution
 * (sc_program_run_block) must give every value of every element as runs of one element give
 * it, bit for bit (NaN for NaN), and stop at the same element: a difference aborts. */
#include <stdint.h>
#include <stdlib.h>

#include "shadecalc/lang.h"
#include "tests/support/lang_value.h"
#include "tests/support/fuzz_text.h"

static int check_value(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    (void)user;
    if (len < 0 || line < 1 || (len > 0 && !text) || sc_ltype_size(v->type) < 1 ||
        sc_ltype_size(v->type) > 16)
        abort();
    return 0;
}

static void ignore_domain(void *user, int line, int column, const char *func, const char *rule)
{
    (void)user, (void)line, (void)column, (void)func, (void)rule;
}

/* ---- block execution against one element at a time ---- */

enum { ELEMENTS = 3 };

static const double xs[ELEMENTS] = {0.5, -1.25, 3.0};
static const double vs[3][ELEMENTS] = {{1, 0, 2}, {-2, 0.5, 2}, {3, -4, 2}}; /* v's columns */

static void compare_value(const sc_program *prog, sc_prec p, int value)
{
    double cols[16][ELEMENTS];
    double *out[16];
    for (int k = 0; k < 16; k++)
        out[k] = cols[k];
    const double *in[4] = {xs, vs[0], vs[1], vs[2]};
    sc_lang_block job = {p, ELEMENTS, in, value, out, NULL, NULL};
    sc_lang_error err;
    long ran = sc_program_run_block(prog, &job, &err), first_failed = ELEMENTS;
    for (int e = 0; e < ELEMENTS; e++) {
        sc_lvalue values[2] = {{{SC_KIND_FLOAT, 1, 1}, {xs[e]}},
                               {{SC_KIND_FLOAT, 1, 3}, {vs[0][e], vs[1][e], vs[2][e]}}};
        double one[16] = {0};
        lang_value_pick pick = {value, 0, one};
        if (sc_program_run(prog, p, values, lang_value_keep, ignore_domain, &pick, &err) < 0) {
            first_failed = first_failed < e ? first_failed : e;
            continue;
        }
        for (int k = 0; k < sc_ltype_size(sc_program_value_type(prog, value)); k++)
            if (!lang_same_bits(one[k], cols[k][e]))
                abort();
    }
    if (ran != first_failed)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = fuzz_text(data, size);
    if (!src)
        return 0;
    sc_lang_input inputs[2] = {{"x", {SC_KIND_FLOAT, 1, 1}}, {"v", {SC_KIND_FLOAT, 1, 3}}};
    sc_lvalue values[2] = {{{SC_KIND_FLOAT, 1, 1}, {0.5}}, {{SC_KIND_FLOAT, 1, 3}, {1, -2, 3}}};
    sc_lang_options options = {10000, (int)(size & 1), (int)(size >> 1 & 1)};
    sc_lang_error err;
    sc_program *prog = sc_program_compile(src, inputs, 2, &options, &err);
    if (prog) {
        for (int p = SC_DOUBLE; p <= SC_LOWP; p++)
            if (sc_program_run(prog, (sc_prec)p, values, check_value, ignore_domain, NULL, &err) <
                    0 &&
                err.message[0] == '\0')
                abort();
        for (int p = SC_DOUBLE; p <= SC_LOWP; p++)
            for (int v = 0; v < sc_program_values(prog) && v < 8; v++)
                compare_value(prog, (sc_prec)p, v);
        sc_program_free(prog);
    } else if (err.line < 0 || err.column < 0 || err.message[0] == '\0') {
        abort();
    }
    free(src);
    return 0;
}
