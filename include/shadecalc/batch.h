/*
 * shadecalc/batch.h — structure-of-arrays kernels over n elements, in named accuracy tiers,
 * for each instruction set, chosen at run time.
 *
 *   sc_isa, sc_isa_name, sc_isa_parse   scalar, sse4.1, avx2
 *   sc_isa_supported                    compiled in and supported by this CPU
 *   sc_isa_active, sc_isa_set           the instruction set the sc_batch_* calls use: the best
 *                                       supported one, or SHADECALC_ISA=scalar|sse4.1|avx2
 *   sc_batch_table, sc_batch_count      every kernel × tier × instruction set with its stated
 *                                       bound and input domain (the table that drives dispatch,
 *                                       `shadecalc bench`, its --list and the man page)
 *   sc_batch_find                       one entry of the table
 *   sc_batch_run                        run a kernel by name and tier on the active ISA
 *
 * Tiers name their worst-case error like SLEEF's _u10/_u35: `u1` (<= 1 ULP against the double
 * reference: the accurate tier, the algorithm of the scalar highp built-ins), `u4`, `bits12`
 * (relative error <= 2^-12), `bits8` (<= 2^-8). Inputs and outputs are separate float arrays, any
 * n, any alignment; outputs may not alias inputs. A kernel computes only the terms it names.
 */
#ifndef SHADECALC_BATCH_H
#define SHADECALC_BATCH_H

#include <stddef.h>

typedef enum { SC_ISA_SCALAR, SC_ISA_SSE41, SC_ISA_AVX2, SC_ISA_COUNT } sc_isa;

const char *sc_isa_name(sc_isa isa);
/* 0 on success, -1 on an unknown name */
int sc_isa_parse(const char *name, sc_isa *out);
int sc_isa_supported(sc_isa isa);
/* The instruction set sc_batch_run uses: chosen once, from SHADECALC_ISA when set to a
 * supported one, else the best supported. */
sc_isa sc_isa_active(void);
/* Overrides the choice (--isa); -1 if isa is not supported here. */
int sc_isa_set(sc_isa isa);

/* ---- shading uniforms ---- */

enum { SC_BATCH_MAX_LIGHTS = 8 };

typedef enum { SC_BATCH_DIRECTIONAL, SC_BATCH_POINT } sc_batch_light_kind;

typedef struct {
    sc_batch_light_kind kind;
    float dir[3];       /* directional: unit vector toward the light */
    float pos[3];       /* point */
    float color[3];     /* E_L (directional) or I_L (point, times 1/max(r², 1e-4)) */
} sc_batch_light;

typedef enum { SC_BATCH_LAMBERT, SC_BATCH_BLINN_PHONG, SC_BATCH_GGX } sc_batch_brdf;

/* The shading equation of SPEC §6 with one BRDF: lambert c_diff/π; blinn-phong normalized
 * c_diff/π + c_spec (m+8)/(8π) (n·h)^m; ggx c_diff/π + D_GGX·G_Smith-correlated·F_Schlick /
 * (4 n·l n·v) with α, F0. Ambient: c_amb ⊙ L_A. */
typedef struct {
    sc_batch_light lights[SC_BATCH_MAX_LIGHTS];
    int n_lights;
    sc_batch_brdf brdf;
    float diff[3], spec[3], amb_term[3]; /* amb_term = c_amb ⊙ L_A */
    float m, alpha, f0;
} sc_batch_scene;

/* ---- kernels ---- */

/* Arguments of every kernel: in[i] are the input arrays (for shading: nx ny nz vx vy vz px py
 * pz), out[j] the output arrays, scene the shading uniforms (NULL otherwise). */
typedef struct {
    const float *in[9];
    float *out[3];
    size_t n;
    const sc_batch_scene *scene;
} sc_batch_args;

typedef void (*sc_batch_fn)(const sc_batch_args *a);

/* The double-precision reference of a kernel for element i: out[j] gets output j. */
typedef void (*sc_batch_ref_fn)(const sc_batch_args *a, size_t i, double *out);

typedef struct {
    const char *kernel; /* "pow", "normalize", "shade-blinn-phong" */
    const char *tier;   /* "u1", "u4", "bits12", "bits8" */
    sc_isa isa;
    sc_batch_fn fn;
    sc_batch_ref_fn ref;
    int n_in, n_out;
    double bound_ulp;   /* the stated bound in ULP, or 0 when stated as relative error */
    double bound_rel;   /* the stated bound as relative error, or 0 */
    double bound_abs;   /* absolute error allowed besides (results near 0 of sums), or 0 */
    const char *domain; /* the input domain, as the man page states it */
    double lo[2], hi[2];/* random inputs for the test and the bench: in[0], in[1] ranges */
    double ops;         /* arithmetic operations per element (for the roofline) */
} sc_batch_entry;

extern const sc_batch_entry sc_batch_table[];
extern const int sc_batch_count;

/* The entry for kernel × tier × isa, or NULL. */
const sc_batch_entry *sc_batch_find(const char *kernel, const char *tier, sc_isa isa);

/* Runs kernel × tier on the active instruction set (falling back to the best one that has
 * it, then scalar). Returns 0, or -1 if no such kernel or tier. */
int sc_batch_run(const char *kernel, const char *tier, const sc_batch_args *a);

#endif
