/* libFuzzer harness: the expression parser, type checker and evaluators must accept or reject
 * any input without crashing, leaking or reading out of bounds, in every precision and with
 * dual numbers. */
#include <stdint.h>
#include <stdlib.h>

#include "shadecalc/expr.h"
#include "tests/support/fuzz_text.h"

static void ignore_domain(void *user, int column, const char *func, const char *rule)
{
    (void)user;
    (void)column;
    (void)func;
    (void)rule;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = fuzz_text(data, size);
    if (!src)
        return 0;
    sc_expr_input inputs[2] = {{"x", SC_FLOAT}, {"v", SC_VEC3}};
    sc_value values[2] = {{SC_FLOAT, {0.5}}, {SC_VEC3, {1, -2, 3}}};
    sc_expr_error err;
    sc_expr *e = sc_expr_compile(src, inputs, 2, &err);
    if (e) {
        for (int p = SC_DOUBLE; p <= SC_LOWP; p++) {
            sc_value v = sc_expr_eval(e, (sc_prec)p, values, ignore_domain, NULL);
            if (v.type != sc_expr_result_type(e))
                abort();
        }
        sc_dual_value duals[2] = {{values[0], {{SC_FLOAT, {1}}, {SC_FLOAT, {0}}}},
                                  {values[1], {{SC_VEC3, {0}}, {SC_VEC3, {0, 1, 0}}}}};
        if (sc_expr_eval_dual(e, duals).x.type != sc_expr_result_type(e))
            abort();
        sc_expr_free(e);
    } else if (err.column < 0 || err.column > (int)size + 1 || err.message[0] == '\0') {
        abort();
    }
    free(src);
    return 0;
}
