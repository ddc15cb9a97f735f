/* The shading kernel through a plan for each BRDF model a scene can name, one directional light,
 * on every tier and instruction set of this CPU: ns per element (the best of R calls on 4096
 * random points drawn as the bench's). `shadecalc bench shade` times the scenes its plain-loop peers
 * also compute (lambert, Blinn-Phong, GGX); this times the models beyond them.
 *
 *   build/bench/plan_models [R]      (R in 1..100000, default 300; CSV on stdout) */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "shadecalc/batch.h"
#include "shadecalc/scene.h"

enum { N = 4096 };

static const char *const models[] = {"lambert",
                                     "blinn-phong m=32 spec=0.4",
                                     "phong m=20 spec=0.3",
                                     "oren-nayar sigma=30 form=full",
                                     "ward alpha=0.3 spec=0.3",
                                     "ward ax=0.2 ay=0.5 spec=0.3",
                                     "cook-torrance alpha=0.3 f0=0.04",
                                     "cook-torrance D=beckmann G=cook-torrance alpha=0.3",
                                     "cook-torrance D=beckmann G=smith alpha=0.3",
                                     "cook-torrance D=beckmann G=smith ax=0.2 ay=0.5"};
static const char *const tiers[] = {"accurate", "bits12"};

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

/* 4096 elements of the shading kernel's inputs as `shadecalc bench shade` draws them
 * (sc_batch_sample) */
static int random_points(float in[9][N])
{
    const sc_batch_entry *e = sc_batch_find("shade", "accurate", SC_ISA_SCALAR);
    if (!e)
        return -1;
    uint64_t rng = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < N; i++) {
        float element[9];
        sc_batch_sample(e, &rng, element);
        for (int j = 0; j < 9; j++)
            in[j][i] = element[j];
    }
    return 0;
}

/* the best of `repeat` calls, ns per element */
static double best_ns(const sc_batch_plan *plan, float in[9][N], float out[3][N], int repeat)
{
    const float *ins[9];
    float *outs[3];
    for (int j = 0; j < 9; j++)
        ins[j] = in[j];
    for (int j = 0; j < 3; j++)
        outs[j] = out[j];
    double best = INFINITY;
    for (int k = 0; k < repeat; k++) {
        double t0 = now_ns();
        sc_batch_plan_shade(plan, ins, outs, N);
        double t = now_ns() - t0;
        best = t < best ? t : best;
    }
    return best / N;
}

int main(int argc, char **argv)
{
    char *end = NULL;
    long repeat = argc > 1 ? strtol(argv[1], &end, 10) : 300;
    if (argc > 2 || repeat < 1 || repeat > 100000 || (end && *end)) {
        fprintf(stderr, "usage: plan_models [R]\n");
        return 2;
    }
    static float in[9][N], out[3][N];
    sc_light light;
    char err[256];
    if (random_points(in) != 0) {
        fprintf(stderr, "plan_models: no shade kernel in the table\n");
        return 1;
    }
    if (sc_light_parse("directional dir=-1,-1,2 E=0.7", &light, err, sizeof err) != 0) {
        fprintf(stderr, "plan_models: %s\n", err);
        return 1;
    }
    printf("model,isa,tier,ns_per_elem\n");
    for (size_t m = 0; m < sizeof models / sizeof models[0]; m++) {
        sc_scene scene = {&light, 1, {0}, {0.05, 0.05, 0.05}};
        if (sc_model_parse(models[m], &scene.model, err, sizeof err) != 0) {
            fprintf(stderr, "plan_models: %s: %s\n", models[m], err);
            return 1;
        }
        for (int isa = 0; isa < SC_ISA_COUNT; isa++)
            for (size_t t = 0; t < sizeof tiers / sizeof tiers[0] && sc_isa_supported((sc_isa)isa);
                 t++) {
                sc_batch_plan *plan = sc_batch_plan_compile(&scene, tiers[t], (sc_isa)isa, err,
                                                            sizeof err);
                if (!plan) {
                    fprintf(stderr, "plan_models: %s %s: %s\n", models[m], tiers[t], err);
                    return 1;
                }
                printf("\"%s\",%s,%s,%.4f\n", models[m], sc_isa_name((sc_isa)isa), tiers[t],
                       best_ns(plan, in, out, (int)repeat));
                sc_batch_plan_free(plan);
            }
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "plan_models: writing the CSV: %s\n", strerror(errno));
        return 1;
    }
    return 0;
}
