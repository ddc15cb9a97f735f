/* Scene plans (shadecalc/batch.h): a scene of shade.h compiled once into the shading kernel's
 * float uniforms (src/batch/uniforms.c) and the kernel of a tier on an instruction set, or the
 * reason the kernels do not cover it. A plan keeps a copy of the double scene: the reference
 * its tests and the bench measure it against. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "simd/uniforms.h"

struct sc_batch_plan {
    sc_shade_uniforms uniforms;
    const sc_batch_entry *entry; /* the kernel × tier × instruction set it runs */
    sc_scene scene;              /* the double description, its lights copied below */
    sc_light lights[SC_BATCH_MAX_LIGHTS];
};

/* The shading kernel of `tier` on isa, else on the best instruction set below it. */
static const sc_batch_entry *shade_kernel(const char *tier, sc_isa isa)
{
    for (int i = (int)isa; i >= 0; i--) {
        const sc_batch_entry *e = sc_batch_find("shade", tier, (sc_isa)i);
        if (e && sc_isa_supported((sc_isa)i))
            return e;
    }
    return NULL;
}

sc_batch_plan *sc_batch_plan_compile(const sc_scene *scene, const char *tier, sc_isa isa, char *why,
                                     size_t size)
{
    const sc_batch_entry *e = shade_kernel(tier, isa);
    if (!e) {
        snprintf(why, size, "tier %s: the shading kernel's tiers are accurate, bits12", tier);
        return NULL;
    }
    sc_batch_plan *plan = calloc(1, sizeof *plan);
    if (!plan) {
        snprintf(why, size, "out of memory");
        return NULL;
    }
    if (sc_uniforms_shade(scene, &plan->uniforms, why, size) != 0) {
        free(plan);
        return NULL;
    }
    plan->entry = e;
    plan->scene = *scene;
    if (scene->n_lights > 0)
        memcpy(plan->lights, scene->lights, (size_t)scene->n_lights * sizeof *scene->lights);
    plan->scene.lights = plan->lights;
    return plan;
}

void sc_batch_plan_free(sc_batch_plan *plan) { free(plan); }

const sc_batch_entry *sc_batch_plan_entry(const sc_batch_plan *plan) { return plan->entry; }

const sc_scene *sc_batch_plan_scene(const sc_batch_plan *plan) { return &plan->scene; }

const sc_shade_uniforms *sc_batch_plan_uniforms(const sc_batch_plan *plan)
{
    return &plan->uniforms;
}

void sc_batch_plan_shade(const sc_batch_plan *plan, const float *const in[9], float *const out[3],
                         size_t n)
{
    sc_batch_args a = {{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]},
                       {out[0], out[1], out[2]},
                       n,
                       plan};
    plan->entry->fn(&a);
}
