/* libFuzzer harness: the light and model spec parsers (shadecalc/scene.h) accept or reject any
 * input without crashing; an accepted spec shades to a value that is never NaN. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "shadecalc/scene.h"
#include "tests/support/fuzz_text.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *spec = fuzz_text(data, size);
    if (!spec)
        return 0;
    char err[256];
    sc_light light;
    sc_model model;
    int light_ok = sc_light_parse(spec, &light, err, sizeof err) >= 0;
    int model_ok = sc_model_parse(spec, &model, err, sizeof err) >= 0;
    if (light_ok || model_ok) {
        if (!light_ok)
            sc_light_init(&light, SC_LIGHT_DIRECTIONAL);
        if (!model_ok)
            sc_model_init(&model, SC_MODEL_BRDF);
        if (sc_light_is_area(light.kind) && (light.area.samples == 0 || light.area.samples > 16))
            light.area.samples = 16; /* each input fast: the node count is not what is fuzzed */
        sc_scene scene = {&light, 1, model, {0.1, 0.1, 0.1}};
        sc_shade_point at = {.pos = {0, 0, 0}, .v = {0, 0.6, 0.8}};
        const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
        sc_frame_make(n, t, &at.frame);
        sc_shade_result r = {.per_light = NULL};
        sc_shade(SC_DOUBLE, &scene, &at, &r);
        int file = model.kind == SC_MODEL_BRDF && model.brdf.kind == SC_BRDF_FILE;
        if (!file && (isnan(r.L[0]) || isnan(r.L[1]) || isnan(r.L[2])))
            abort(); /* validated specs never give NaN (a BRDF file's GLSL may: IEEE 754) */
    }
    free(spec);
    return 0;
}
