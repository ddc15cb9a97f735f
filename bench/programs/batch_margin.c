/* How close each batch kernel comes to its stated bound: every row of the table on the
 * instruction set the library chose, on N fresh inputs from seed S (the unit test uses its own
 * fixed sequence), printing the worst error as a fraction of the bound. A row near 1 is a bound
 * the next input sequence may break.
 *
 *   build/bench/batch_margin [SEED [N]]      (default seed 1, N 1000000) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/batch.h"

#include "batch/reference.h"

static int margin(const sc_batch_entry *e, uint64_t *rng, size_t n, float **in, float **out)
{
    sc_light lights[SC_BATCH_MAX_LIGHTS];
    sc_scene scene;
    char why[256];
    sc_batch_example_scene(SC_BRDF_COOK_TORRANCE, 1, 1, 3, lights, &scene);
    sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why, sizeof why);
    if (!plan) {
        fprintf(stderr, "batch_margin: %s\n", why);
        return 1;
    }
    for (size_t k = 0; k < n; k++) {
        float v[9];
        sc_batch_sample(e, rng, v);
        for (int j = 0; j < e->n_in; j++)
            in[j][k] = v[j];
    }
    sc_batch_args a = {{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]},
                       {out[0], out[1], out[2]},
                       n,
                       strcmp(e->kernel, "shade") == 0 ? (const void *)plan : e->params};
    e->fn(&a);
    sc_batch_error acc;
    sc_batch_error_init(&acc);
    sc_batch_error_of(e, &a, &acc);
    printf("%-16s %-9s %-7s %6.3f\n", e->kernel, e->tier, sc_isa_name(e->isa), acc.max_ratio);
    sc_batch_plan_free(plan);
    return acc.max_ratio > 1.0;
}

int main(int argc, char **argv)
{
    uint64_t rng = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    size_t n = argc > 2 ? strtoull(argv[2], NULL, 10) : 1000000;
    if (rng == 0 || n == 0) {
        fprintf(stderr, "usage: batch_margin [SEED>0 [N>0]]\n");
        return 2;
    }
    float *in[9], *out[3];
    for (int j = 0; j < 9; j++)
        in[j] = malloc(n * sizeof(float));
    for (int j = 0; j < 3; j++)
        out[j] = malloc(n * sizeof(float));
    for (int j = 0; j < 9; j++)
        if (!in[j] || (j < 3 && !out[j])) {
            fprintf(stderr, "batch_margin: out of memory\n");
            return 1;
        }
    int broken = 0;
    printf("%-16s %-9s %-7s %6s\n", "kernel", "tier", "isa", "worst/bound");
    for (int i = 0; i < sc_batch_count; i++)
        if (sc_batch_table[i].isa == sc_isa_active())
            broken += margin(&sc_batch_table[i], &rng, n, in, out);
    for (int j = 0; j < 9; j++)
        free(in[j]);
    for (int j = 0; j < 3; j++)
        free(out[j]);
    return broken ? 1 : 0;
}
