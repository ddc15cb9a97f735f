/* libFuzzer harness: the --var parser and `$name` substitution (shadecalc/sweep.h) accept or
 * reject any input without crashing; an accepted variable has finite values at both ends and
 * inside, ranges stay between their ends, and substitution never overruns its buffer.
 * Input: the --var argument, a newline, a text to substitute into. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/sweep.h"
#include "tests/support/fuzz_text.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_values(const sc_sweep_var *v)
{
    const long probe[] = {0, v->count / 3, v->count / 2, v->count - 1};
    double lo = fmin(v->start, v->stop), hi = fmax(v->start, v->stop);
    for (int i = 0; i < 4; i++) {
        double x = sc_sweep_var_value(v, probe[i]);
        if (!isfinite(x))
            abort();
        double slack = 1e-12 * fmax(fabs(lo), fabs(hi));
        if (v->spacing != SC_SPACING_LIST && (x < lo - slack || x > hi + slack))
            abort(); /* a range stays within its ends (up to rounding) */
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *input = fuzz_text(data, size);
    if (!input)
        return 0;
    char *text = strchr(input, '\n');
    if (text)
        *text++ = '\0';
    char err[256];
    sc_sweep_var v;
    sc_sweep_grid g = {.n = 0};
    if (sc_sweep_var_parse(input, &v, err, sizeof err) == 0) {
        check_values(&v);
        if (v.spacing != SC_SPACING_LIST && sc_sweep_var_set_log(&v, err, sizeof err) == 0)
            check_values(&v);
        if (sc_sweep_grid_add(&g, &v, err, sizeof err) == 0 && text) {
            double value = sc_sweep_var_value(&g.var[0], g.var[0].count - 1);
            char out[64];
            memset(out, 'x', sizeof out);
            if (sc_sweep_substitute(text, &g, &value, out, 48, err, sizeof err) == 0 &&
                strlen(out) >= 48)
                abort();
            if (out[48] != 'x') /* nothing written past the size given */
                abort();
        }
    }
    sc_sweep_grid_free(&g);
    free(input);
    return 0;
}
