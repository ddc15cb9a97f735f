/* libFuzzer harness: the .brdf parser and compiler (shadecalc/brdf_file.h) accept or reject any
 * text without crashing, leaking or hanging; an error names the file and a line; an accepted
 * file evaluates in every precision (its loops are bounded per evaluation), with its parameters
 * at their defaults and at their ends. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/brdf_file.h"
#include "tests/support/fuzz_text.h"

static void evaluate(const sc_brdf_file *f)
{
    sc_brdf b;
    sc_brdf_file_defaults(f, &b);
    const double n[3] = {0, 0, 1}, l[3] = {0.6, 0, 0.8}, v[3] = {0, -0.28, 0.96};
    sc_frame frame;
    sc_frame_make(n, NULL, &frame);
    double out[3];
    for (int p = SC_DOUBLE; p <= SC_LOWP; p++)
        sc_brdf_file_eval((sc_prec)p, &b, &frame, l, v, out);
    const sc_brdf_param *params;
    int count = sc_brdf_file_params(f, &params);
    for (int i = 0; i < count; i++)
        if (params[i].type == SC_BRDF_PARAM_FLOAT)
            b.file_values[params[i].offset] = params[i].max;
    sc_brdf_file_eval(SC_HIGHP, &b, &frame, l, v, out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size), err[512];
    if (!text)
        return 0;
    sc_brdf_file *f = sc_brdf_file_parse(text, "fuzz.brdf", err, sizeof err);
    if (f) {
        evaluate(f);
        sc_brdf_file_free(f);
    } else if (strncmp(err, "fuzz.brdf:", 10) != 0) {
        abort(); /* every error names the file and its line */
    }
    free(text);
    return 0;
}
