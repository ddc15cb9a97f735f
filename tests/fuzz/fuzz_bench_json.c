/* libFuzzer harness: the JSON reader behind `shadecalc bench --compare` (src/util/json.h)
 * accepts or refuses any input without crashing, leaking or reading past its end; an accepted
 * document's members can be looked up. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "util/json.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size ? size : 1); /* no NUL after the input: the reader must not need one */
    if (!text)
        return 0;
    memcpy(text, data, size);
    char err[160];
    sc_json *v = sc_json_parse(text, size, err, sizeof err);
    if (v) {
        const sc_json *rows = sc_json_member(v, "rows");
        for (const sc_json *r = rows ? rows->child : NULL; r; r = r->next)
            (void)sc_json_member(r, "ns_per_elem");
    } else if (strncmp(err, "line ", 5) != 0) {
        abort(); /* every refusal names its place */
    }
    sc_json_free(v);
    free(text);
    return 0;
}
