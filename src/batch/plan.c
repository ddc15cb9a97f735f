/* Scene plans (shadecalc/batch.h): a scene of shade.h compiled once into the shading kernel's
 * float uniforms and the kernel's function for a tier and an instruction set, or the reason
 * the kernel does not compute it. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "shadecalc/batch.h"

struct sc_batch_plan {
    sc_batch_scene uniforms;
    const sc_batch_entry *entry; /* the kernel × tier × instruction set it runs */
};

static int refuse(char *why, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Writes the reason and returns 0 (not computed by the kernel). */
static int refuse(char *why, size_t size, const char *fmt, ...)
{
    if (why && size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, size, fmt, ap);
        va_end(ap);
    }
    return 0;
}

static int same3(const double v[3]) { return v[0] == v[1] && v[1] == v[2]; }

/* The cook-torrance variant the kernel computes: Walter's form with GGX, Smith
 * height-correlated masking and Schlick's Fresnel with a grey F0, isotropic, α >= 10^-4. */
static int ggx_fits(const sc_brdf *b, char *why, size_t size)
{
    if (b->form != SC_CT_WALTER || b->D != SC_D_GGX || b->G != SC_G_SMITH_CORRELATED ||
        b->F != SC_F_SCHLICK)
        return refuse(why, size,
                      "cook-torrance: the kernel computes form=walter D=ggx "
                      "G=smith-correlated F=schlick only");
    if (b->ax != b->ay)
        return refuse(why, size, "cook-torrance: anisotropic roughness (ax=%g ay=%g)", b->ax,
                      b->ay);
    if (!(b->ax >= 1e-4))
        return refuse(why, size, "cook-torrance: alpha=%g below 1e-4", b->ax);
    if (!same3(b->f0))
        return refuse(why, size, "cook-torrance: F0 is not grey (%g,%g,%g)", b->f0[0], b->f0[1],
                      b->f0[2]);
    return 1;
}

static int brdf_fits(const sc_brdf *b, sc_batch_scene *out, char *why, size_t size)
{
    switch (b->kind) {
    case SC_BRDF_LAMBERT: out->brdf = SC_BATCH_LAMBERT; return 1;
    case SC_BRDF_BLINN_PHONG:
        out->brdf = SC_BATCH_BLINN_PHONG;
        if (b->form != SC_BLINN_NORMALIZED)
            return refuse(why, size, "blinn-phong: the kernel computes form=normalized only");
        if (!(b->m >= 1.0))
            return refuse(why, size, "blinn-phong: m=%g below 1", b->m);
        return 1;
    case SC_BRDF_COOK_TORRANCE: out->brdf = SC_BATCH_GGX; return ggx_fits(b, why, size);
    default:
        return refuse(why, size,
                      "brdf %s: the kernel computes lambert, blinn-phong and "
                      "cook-torrance (GGX)",
                      sc_brdf_kind_name(b->kind));
    }
}

/* The spot of a light as the kernel's uniforms: cosines of the half-angles. */
static void spot_uniforms(const sc_spot *spot, sc_batch_light *out)
{
    static const sc_batch_spot kinds[] = {SC_BATCH_SPOT_OPENGL, SC_BATCH_SPOT_DIRECTX,
                                          SC_BATCH_SPOT_SMOOTHSTEP};
    const double radians = 0.017453292519943295;
    out->spot = kinds[spot->kind];
    out->exponent = (float)spot->exponent;
    if (spot->kind == SC_SPOT_OPENGL) {
        out->cos_outer = spot->cutoff == 180.0 ? -2.0f : (float)cos(spot->cutoff * radians);
        return;
    }
    out->cos_outer = (float)cos(spot->outer * radians);
    out->cos_inner = (float)cos(spot->inner * radians);
}

static void unit_float(const double v[3], float out[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; c++)
        out[c] = (float)(len > 0.0 ? v[c] / len : 0.0);
}

/* Directional lights, and point and spot lights with inverse-square falloff (the kernel's
 * 1/max(r², 10^-4) is light.h's), without a range. */
static int light_fits(const sc_light *l, int k, sc_batch_light *out, char *why, size_t size)
{
    static const sc_batch_light_kind kinds[] = {SC_BATCH_DIRECTIONAL, SC_BATCH_POINT,
                                                SC_BATCH_SPOT};
    int directional = l->kind == SC_LIGHT_DIRECTIONAL;
    if (sc_light_is_area(l->kind))
        return refuse(why, size, "light %d: area lights are not in the kernel", k + 1);
    if (isfinite(l->range))
        return refuse(why, size, "light %d: a range (direct3d9) is not in the kernel", k + 1);
    if (l->atten.kind != (directional ? SC_ATTEN_NONE : SC_ATTEN_INVERSE_SQUARE))
        return refuse(why, size,
                      "light %d: the kernel's falloff is inverse-square for point "
                      "and spot lights, none for directional ones",
                      k + 1);
    out->kind = kinds[l->kind];
    unit_float(l->dir, out->dir);
    for (int c = 0; c < 3; c++) {
        out->pos[c] = (float)l->pos[c];
        out->color[c] = (float)l->intensity[c];
    }
    if (l->kind == SC_LIGHT_SPOT)
        spot_uniforms(&l->spot, out);
    return 1;
}

/* The kernel's uniforms of s: 1, or 0 with the reason. The per-light ambient terms
 * c_amb ⊙ L_A,k join the global one. */
static int uniforms_of(const sc_scene *s, sc_batch_scene *out, char *why, size_t size)
{
    const sc_brdf *b = &s->model.brdf;
    if (s->model.kind != SC_MODEL_BRDF)
        return refuse(why, size,
                      "the legacy models (ads, opengl, direct3d9) are not in the "
                      "kernel");
    if (s->n_lights > SC_BATCH_MAX_LIGHTS)
        return refuse(why, size, "%d lights: the kernel takes at most %d", s->n_lights,
                      SC_BATCH_MAX_LIGHTS);
    if (!brdf_fits(b, out, why, size))
        return 0;
    double ambient[3] = {s->ambient[0], s->ambient[1], s->ambient[2]};
    for (int k = 0; k < s->n_lights; k++) {
        if (!light_fits(&s->lights[k], k, &out->lights[k], why, size))
            return 0;
        for (int c = 0; c < 3; c++)
            ambient[c] += s->lights[k].ambient[c];
    }
    out->n_lights = s->n_lights;
    for (int c = 0; c < 3; c++) {
        out->diff[c] = (float)b->diff[c];
        out->spec[c] = (float)b->spec[c];
        out->amb_term[c] = (float)(b->amb[c] * ambient[c]);
    }
    out->m = (float)b->m;
    out->alpha = (float)b->ax;
    out->f0 = (float)b->f0[0];
    return 1;
}

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
        refuse(why, size, "tier %s: the shading kernel's tiers are accurate, bits12, bits8", tier);
        return NULL;
    }
    sc_batch_plan *plan = calloc(1, sizeof *plan);
    if (!plan) {
        refuse(why, size, "out of memory");
        return NULL;
    }
    plan->entry = e;
    if (!uniforms_of(scene, &plan->uniforms, why, size)) {
        free(plan);
        return NULL;
    }
    return plan;
}

void sc_batch_plan_free(sc_batch_plan *plan) { free(plan); }

const sc_batch_entry *sc_batch_plan_entry(const sc_batch_plan *plan) { return plan->entry; }

void sc_batch_plan_shade(const sc_batch_plan *plan, const float *const in[9], float *const out[3],
                         size_t n)
{
    sc_batch_args a = {{in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]},
                       {out[0], out[1], out[2]},
                       n,
                       &plan->uniforms,
                       NULL};
    plan->entry->fn(&a);
}
