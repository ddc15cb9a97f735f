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
 *   sc_batch_run                        run a kernel by name and tier on the active ISA
 *   sc_batch_plan_compile, _shade, _free a scene of shade.h compiled once for the shading
 *                                       kernel: its uniforms and its function, or why not
 *
 * The kernels take the double model types of light.h, brdf.h and shade.h (there is no second,
 * float description of a light or a BRDF): each turns its parameters into float uniforms once
 * per call, a plan once per scene.
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

/* A plan takes at most this many lights (more: split the scene, ambient 0 in all parts but
 * one). */
enum { SC_BATCH_MAX_LIGHTS = 64 };

/* A scene compiled for the shading kernel (sc_batch_plan_compile below). */
typedef struct sc_batch_plan sc_batch_plan;

/* ---- kernels ---- */

/* Arguments of every kernel: in[i] are the input arrays, out[j] the output arrays, params the
 * kernel's parameters — the double model types of light.h, brdf.h and shade.h, turned into
 * float uniforms once per call (NULL for the kernels without). Inputs by kernel:
 *   exp2 exp log2 log inversesqrt sqrt   x                  out: value
 *   sin cos acos                         x                  out: value
 *   pow                                  x y                out: value
 *   atan2                                y x                out: value
 *   dot                                  ax ay az bx by bz  out: value
 *   reflect                              Ix Iy Iz Nx Ny Nz  out: x y z
 *   normalize                            x y z              out: x y z
 *   length                               x y z              out: value
 *   shade                                nx ny nz vx vy vz px py pz (n, v need not be unit;
 *                                        p is read only for point and spot lights)
 *                                        out: r g b   params: an sc_batch_plan (its uniforms;
 *                                        the entry's tier and instruction set)
 *   atten_none atten_invsq atten_clq     r (distance)       out: f_d
 *   atten_window atten_pixar atten_windowed                 params: sc_atten (the function's
 *                                                           fields; its kind is not read)
 *   spot_opengl spot_directx             cos θ_s            out: spot factor
 *   spot_smoothstep                                         params: sc_spot (angles in
 *                                                           degrees; its kind is not read)
 *   brdf                                 lx ly lz vx vy vz nx ny nz (toward the light, the
 *                                        viewer; the normal; need not be unit)
 *                                        out: r g b (f; 0 below the horizon)
 *                                        params: sc_brdf, any model, form and roughness; the
 *                                        tangent frame of anisotropic α is sc_frame_make's
 *                                        from n alone
 *   area_sphere area_tube area_disk      nx ny nz vx vy vz px py pz, as shade
 *   area_rect                            out: r g b   params: an sc_scene of one area light of
 *                                        that kind by its approximation (representative-point:
 *                                        sphere, tube; ltc: disk, rect), whose uniforms each
 *                                        call computes (the plans' area lanes; NaN outputs for
 *                                        a scene the kernels do not cover) */
typedef struct {
    const float *in[9];
    float *out[3];
    size_t n;
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

/* Compiles scene for tier (accurate, bits12) on isa (else the best supported set below
 * it that has the tier): every per-light and per-BRDF uniform in float, computed once; the
 * kernel and its variant resolved once — straight-line code for one to four lights that are all
 * directional, all point or all spot lights, these two with inverse-square falloff (with
 * lambert, blinn-phong or the
 * GGX of cook-torrance walter/smith-correlated/schlick with a grey F0), a loop over the lights
 * otherwise. NULL with the reason in why when the kernels do not cover the scene,
 * naming the model, light or form:
 *   - a legacy model (ads, opengl, direct3d9): the kernels compute the BRDF models only;
 *   - a light of a kind the kernels do not know ("light 2: light kind 9 not covered by the
 *     batch kernels"), or with a range (direct3d9);
 *   - an area light of method=reference (shade and check evaluate it), or by a method the
 *     scene's BRDF does not allow (representative-point takes lambert, blinn-phong and the
 *     kernel's own GGX; ltc what sc_area_method_applies allows);
 *   - more than SC_BATCH_MAX_LIGHTS lights; an unknown tier; out of memory.
 * Area lights run the generic loop: sphere and tube by the representative point, disk and rect
 * by LTC (src/simd/area_impl.h), method=point as the point light of its stand-in.
 * Every BRDF of brdf.h is covered — lambert, phong, blinn-phong, ward, oren-nayar and
 * cook-torrance in every form, D, G and F, isotropic or anisotropic — and every attenuation
 * and spot function of light.h. The plan keeps a copy of the scene (lights included): the
 * caller's may change or go. Immutable: any number of threads may shade through one plan. */
sc_batch_plan *sc_batch_plan_compile(const sc_scene *scene, const char *tier, sc_isa isa, char *why,
                                     size_t size);
void sc_batch_plan_free(sc_batch_plan *plan);

/* The table entry (kernel, tier, instruction set, bound) the plan runs. */
const sc_batch_entry *sc_batch_plan_entry(const sc_batch_plan *plan);

/* The plan's copy of its scene (the double reference of what it computes). */
const sc_scene *sc_batch_plan_scene(const sc_batch_plan *plan);

/* The shade kernel's inputs (n, v, p as nine arrays) and outputs (r, g, b) for n points. */
void sc_batch_plan_shade(const sc_batch_plan *plan, const float *const in[9], float *const out[3],
                         size_t n);

SC_END_DECLS

#endif
