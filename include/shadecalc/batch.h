/*
 * shadecalc/batch.h — structure-of-arrays kernels over n elements, in named accuracy tiers,
 * for each instruction set, chosen at run time.
 *
 *   sc_isa, sc_isa_name, sc_isa_parse   scalar, sse4.1, avx2, avx512
 *   sc_isa_supported                    compiled in and supported by this CPU
 *   sc_isa_active, sc_isa_set           the instruction set the sc_batch_* calls use: the best
 *                                       supported one, or SHADECALC_ISA=scalar|sse4.1|avx2|avx512
 *   sc_batch_table, sc_batch_count      every kernel × tier × instruction set with its stated
 *                                       bound and input domain (the table that drives dispatch,
 *                                       `shadecalc bench`, its --list and the man page)
 *   sc_batch_find                       one entry of the table
 *   sc_batch_sample                     random inputs in an entry's domain (tests, bench)
 *   sc_batch_error_of                   max/mean ULP, max relative/absolute error, bound ratio
 *   sc_batch_scene_example              the standard scenes of the tests and the bench
 *   sc_batch_run                        run a kernel by name and tier on the active ISA
 *   sc_batch_plan_compile, _shade, _free a scene of shade.h compiled once for the shading
 *                                       kernel: its uniforms and its function, or why not
 *
 * Tiers name their worst-case error like SLEEF's _u10/_u35: `u1` (<= 1 ULP against the double
 * reference: the accurate tier, the algorithm of the scalar highp built-ins), `u4`, `bits12`
 * (relative error <= 2^-12), `bits8` (<= 2^-8). Inputs and outputs are separate float arrays, any
 * n, aligned as floats (4 bytes; nothing stricter is needed); outputs may not alias inputs. A
 * kernel computes only the terms it names.
 * One-input kernels write outputs of 2^21 elements or more with non-temporal stores (past the
 * caches: the output line is not read before it is written).
 */
#ifndef SHADECALC_BATCH_H
#define SHADECALC_BATCH_H

#include <stddef.h>
#include <stdint.h>

#include "shadecalc/shade.h"
#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef enum { SC_ISA_SCALAR, SC_ISA_SSE41, SC_ISA_AVX2, SC_ISA_AVX512, SC_ISA_COUNT } sc_isa;

const char *sc_isa_name(sc_isa isa);
/* 0 on success, -1 on an unknown name */
int sc_isa_parse(const char *name, sc_isa *out);
int sc_isa_supported(sc_isa isa);
/* The instruction set sc_batch_run uses: chosen once, from SHADECALC_ISA when set to a
 * supported one, else the best supported. Both functions may be called from any thread. */
sc_isa sc_isa_active(void);
/* Overrides the choice (--isa); -1 if isa is not supported here. */
int sc_isa_set(sc_isa isa);

/* ---- shading uniforms (what a plan compiles a scene into; the tests and the bench also build
 * them directly) ---- */

enum { SC_BATCH_MAX_LIGHTS = 64 }; /* more: split the set, amb_term 0 in all parts but one */

typedef enum { SC_BATCH_DIRECTIONAL, SC_BATCH_POINT, SC_BATCH_SPOT } sc_batch_light_kind;
typedef enum {
    SC_BATCH_SPOT_OPENGL,
    SC_BATCH_SPOT_DIRECTX,
    SC_BATCH_SPOT_SMOOTHSTEP
} sc_batch_spot;

/* A light as light.h computes it: directional (E_L), point and spot (I_L with inverse-square
 * falloff 1/max(r², 10^-4); at r = 0, l = n). Spot factor of cos θ_s = −l·dir (docs/formulas.md §4):
 * opengl cos_s^exponent where cos θ_s >= cos_outer (cos_outer <= −1: a cutoff of 180°, factor
 * 1); directx and smoothstep 1 inside cos_inner, 0 outside cos_outer, between them the ramp
 * t = (cos θ_s − cos_outer)/(cos_inner − cos_outer) to the exponent, or t²(3 − 2t). */
typedef struct {
    sc_batch_light_kind kind;
    float dir[3];   /* directional: unit vector toward the light; spot: unit axis it points along */
    float pos[3];   /* point, spot */
    float color[3]; /* E_L (directional) or I_L (point, spot) */
    sc_batch_spot spot;
    float cos_outer, cos_inner, exponent; /* spot: cosines of the half-angles */
} sc_batch_light;

typedef enum { SC_BATCH_LAMBERT, SC_BATCH_BLINN_PHONG, SC_BATCH_GGX } sc_batch_brdf;

/* The shading equation of docs/formulas.md §6 with one BRDF, L = c_amb ⊙ L_A + Σ_k f(l_k, v) ⊙ E_k cos θ_i:
 * lambert c_diff/π; blinn-phong (normalized) c_diff/π + c_spec (m+8)/(8π) (n·h)^m, m >= 1;
 * ggx c_diff/π + c_spec D_GGX V_Smith-correlated F_Schlick(f0) (the cook-torrance model of
 * brdf.h with D=ggx G=smith-correlated F=schlick). f = 0 where n·l <= 0 or n·v <= 0; a point
 * light at the shading point lights nothing. The kernel computes only what the scene names: a
 * directional light costs no distance, falloff or spot factor, a point light no spot factor, a
 * lambert scene no specular lobe. */
typedef struct {
    sc_batch_light lights[SC_BATCH_MAX_LIGHTS];
    int n_lights;
    sc_batch_brdf brdf;
    float diff[3], spec[3], amb_term[3]; /* amb_term = c_amb ⊙ L_A */
    float m, alpha, f0;
} sc_batch_scene;

/* The scenes of the tests and of `shadecalc bench`: n_dir directional, n_point point and n_spot
 * spot lights (the three spot kinds in turn) around +y, diff 0.8/0.5/0.2, spec 0.2 (ggx: 1),
 * m 32, α 0.3, f0 0.04, ambient 0.02. */
void sc_batch_scene_example(sc_batch_brdf brdf, int n_dir, int n_point, int n_spot,
                            sc_batch_scene *out);
const char *sc_batch_brdf_name(sc_batch_brdf brdf);

/* ---- light function and BRDF parameters ---- */

/* atten_<function> (docs/formulas.md §3, light.h): each kernel reads the fields of its function. */
typedef struct {
    float sc, sl, sq;           /* clq: 1 / max(s_c + s_l r + s_q r², 10^-4) */
    float r_start, r_end;       /* window: 0 <= r_start <= r_end (equal: a step) */
    float f_max, f_c, r_c, s_e; /* pixar (Barzel 1997): 0 < f_c <= f_max, r_c, s_e > 0 */
    float r_max;                /* windowed inverse-square: r_max > 0 */
} sc_batch_atten_params;

/* spot_<function> (docs/formulas.md §4), angles in degrees. */
typedef struct {
    float exponent;     /* opengl, directx: >= 0 */
    float cutoff;       /* opengl: 0..90, or 180 (no cone) */
    float inner, outer; /* directx, smoothstep: 0 <= inner <= outer <= 180 */
} sc_batch_spot_params;

/* brdf (docs/formulas.md §6, brdf.h), isotropic: one roughness α for Ward and Cook–Torrance. */
typedef struct {
    int model;                     /* sc_brdf_kind (brdf.h); out of range: lambert */
    int form;                      /* the model's variant: SC_PHONG_*, SC_BLINN_*, SC_WARD_*,
                                      SC_OREN_*, SC_CT_* of brdf.h */
    int cos;                       /* nonzero: the kernel returns f·cos θ_i, not f */
    int D, G, F;                   /* cook-torrance: sc_ndf, sc_masking, sc_fresnel (brdf.h) */
    float diff[3], spec[3], f0[3]; /* c_diff (oren-nayar: ρ), c_spec, Schlick's F0 */
    float m;                       /* phong, blinn-phong exponent, >= 0 */
    float alpha;                   /* ward, cook-torrance roughness (taken >= 10^-4) */
    float sigma;                   /* oren-nayar σ, radians */
    float ior;                     /* exact Fresnel η >= 1 (η < 1 runs, but near the critical
                                      angle F's infinite slope defeats every float tier) */
} sc_batch_brdf_params;

/* ---- kernels ---- */

/* Arguments of every kernel: in[i] are the input arrays, out[j] the output arrays, scene the
 * shading uniforms (NULL for the others). Inputs by kernel:
 *   exp2 exp log2 log inversesqrt sqrt   x                  out: value
 *   sin cos acos                         x                  out: value
 *   pow                                  x y                out: value
 *   atan2                                y x                out: value
 *   dot                                  ax ay az bx by bz  out: value
 *   reflect                              Ix Iy Iz Nx Ny Nz  out: x y z
 *   normalize                            x y z              out: x y z
 *   length                               x y z              out: value
 *   shade                                nx ny nz vx vy vz px py pz (n, v need not be unit;
 *                                        p is read only for point lights)   out: r g b
 *   atten_none atten_invsq atten_clq     r (distance)       out: f_d
 *   atten_window atten_pixar atten_windowed                 params: sc_batch_atten_params
 *   spot_opengl spot_directx             cos θ_s            out: spot factor
 *   spot_smoothstep                                         params: sc_batch_spot_params
 *   brdf                                 lx ly lz vx vy vz nx ny nz (toward the light, the
 *                                        viewer; the normal; need not be unit)
 *                                        out: r g b (f, or f·cos θ_i; 0 below the horizon)
 *                                        params: sc_batch_brdf_params */
typedef struct {
    const float *in[9];
    float *out[3];
    size_t n;
    const sc_batch_scene *scene;
    const void *params; /* the kernel's parameters, of the type its documentation names */
} sc_batch_args;

typedef void (*sc_batch_fn)(const sc_batch_args *a);

/* The double-precision reference of a kernel for element i: out[j] gets output j, and
 * out[n_out] the scale of the absolute error allowance (1 where the bound is relative only). */
typedef void (*sc_batch_ref_fn)(const sc_batch_args *a, size_t i, double *out);

/* Random inputs in the kernel's domain for one element (in[0..n_in−1]). */
typedef void (*sc_batch_gen_fn)(uint64_t *rng, float *in);

typedef struct {
    const char *kernel; /* "pow", "normalize", "shade" */
    const char *tier;   /* "u1", "u4", "bits12", "bits8", …: the name states the bound */
    sc_isa isa;
    sc_batch_fn fn;
    sc_batch_ref_fn ref;
    int n_in, n_out;
    double bound_ulp;    /* the stated bound in ULP, or 0 when stated as relative error */
    double bound_rel;    /* the stated bound as relative error, or 0 */
    double bound_abs;    /* besides: absolute error allowed, times the reference's scale */
    const char *domain;  /* the input domain, as the man page states it */
    double lo[2], hi[2]; /* random inputs for x and y (one-argument kernels), or: */
    sc_batch_gen_fn gen; /* the generator of vector inputs (NULL for x, y kernels) */
    double ops;          /* AVX2 arithmetic instructions per vector of 8 elements (roofline) */
    const void *params;  /* the parameters the tests and the bench run it with, or NULL */
} sc_batch_entry;

extern const sc_batch_entry sc_batch_table[];
extern const int sc_batch_count;

/* One random element of e's inputs in its stated domain (magnitude-biased or uniform). */
void sc_batch_sample(const sc_batch_entry *e, uint64_t *rng, float *in);

/* ---- accuracy ---- */

typedef struct {
    double max_ratio;        /* the worst error as a fraction of the stated bound (> 1: broken) */
    size_t worst;            /* the element where it occurred */
    double max_ulp, sum_ulp; /* ULPs of binary32 at the reference, over finite errors */
    long count;              /* outputs counted in sum_ulp */
    double max_rel, max_abs;
} sc_batch_error;

void sc_batch_error_init(sc_batch_error *acc);
/* Adds element i of a finished run of e (a->out filled) to acc; returns its bound ratio. The
 * pow u1 row counts only normal-float results (its stated domain). */
double sc_batch_error_element(const sc_batch_entry *e, const sc_batch_args *a, size_t i,
                              sc_batch_error *acc);
/* The same with the reference already computed (ref: e->ref's n_out + 1 values). */
double sc_batch_error_against(const sc_batch_entry *e, const sc_batch_args *a, size_t i,
                              const double *ref, sc_batch_error *acc);
/* All a->n elements. */
void sc_batch_error_of(const sc_batch_entry *e, const sc_batch_args *a, sc_batch_error *acc);

/* The entry for kernel × tier × isa, or NULL. */
const sc_batch_entry *sc_batch_find(const char *kernel, const char *tier, sc_isa isa);

/* Runs kernel × tier on the active instruction set (falling back to the best one that has
 * it, then scalar). Returns 0, or -1 if no such kernel or tier. */
int sc_batch_run(const char *kernel, const char *tier, const sc_batch_args *a);

/* ---- scene plans ---- */

/* A scene compiled for the shading kernel: the float uniforms of sc_batch_scene computed once
 * from the double description (shade.h), and the kernel of a tier on an instruction set
 * resolved once. Immutable: any number of threads may shade through one plan. */
typedef struct sc_batch_plan sc_batch_plan;

/* Compiles scene for tier (accurate, bits12, bits8) on isa (else the best supported set below
 * it that has the tier). NULL with the reason in why when the kernel does not compute the
 * scene: a legacy model, a BRDF or variant it lacks (it has lambert, normalized blinn-phong
 * with m >= 1, and cook-torrance walter GGX/smith-correlated/schlick with isotropic α >= 10^-4
 * and grey F0), a falloff other than inverse-square (point, spot) or none (directional), a
 * range, more than SC_BATCH_MAX_LIGHTS lights, an unknown tier; or out of memory. */
sc_batch_plan *sc_batch_plan_compile(const sc_scene *scene, const char *tier, sc_isa isa, char *why,
                                     size_t size);
void sc_batch_plan_free(sc_batch_plan *plan);

/* The table entry (kernel, tier, instruction set, bound) the plan runs. */
const sc_batch_entry *sc_batch_plan_entry(const sc_batch_plan *plan);

/* The shade kernel's inputs (n, v, p as nine arrays) and outputs (r, g, b) for n points. */
void sc_batch_plan_shade(const sc_batch_plan *plan, const float *const in[9], float *const out[3],
                         size_t n);

SC_END_DECLS

#endif
