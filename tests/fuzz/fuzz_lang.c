/* libFuzzer harness: the language's compiler and interpreter (shadecalc/lang.h) must accept or
 * reject any program without crashing, leaking, reading out of bounds or hanging, in every
 * precision (loops are bounded by a small iteration limit). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/lang.h"

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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = malloc(size + 1);
    if (!src)
        return 0;
    memcpy(src, data, size);
    src[size] = '\0';
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
        sc_program_free(prog);
    } else if (err.line < 0 || err.column < 0 || err.message[0] == '\0') {
        abort();
    }
    free(src);
    return 0;
}
