/*
 * shadecalc/brdf.h — the BRDFs of the lecture and their variants (docs/formulas.md §6; §6.1–§6.6).
 *
 *   sc_brdf, sc_brdf_init      a model, its variant (form) and parameters
 *   sc_brdf_eval               f(l, v) as RGB, with its terms (diffuse, specular, D, F, G)
 *   sc_brdf_eval_many          the same at many points (a BRDF file's shader in blocks)
 *   sc_frame_make              an orthonormal frame (t, b, n) from n and an optional tangent
 *   sc_brdf_validate           the parameter domains, as a message
 *   sc_brdf_kind_name, sc_brdf_form_name
 *
 * f never contains cos θ_i (docs/formulas.md §1). f is 0 when l or v is below the horizon
 * (n·l <= 0 or n·v <= 0). Directions are unit vectors toward the light (l) and the viewer (v).
 *
 * Models and forms (diffuse part c_diff/π unless noted; m the exponent):
 *   lambert                       c_diff/π
 *   phong        original         c_spec (cos̄α_r)^m / (π cos θ_i)          (Phong 1975)
 *                modified         c_spec (cos̄α_r)^m / π                   (Lewis 1994)
 *                normalized       c_spec (m+2)/(2π) (cos̄α_r)^m           (Lafortune–Willems 1994)
 *   blinn-phong  normalized       c_spec (m+8)/(8π) (cos̄θ_h)^m           (RTR3 §7.6)
 *                plain            c_spec (cos̄θ_h)^m                       (Blinn 1977)
 *   ward         1992 | duer | gmd   ρ_d/π + ρ_s E / (4π α_x α_y √(cos θ_i cos θ_o)) |
 *                                  … / (4π α_x α_y cos θ_i cos θ_o) | E (h·h) / (π α_x α_y (h·n)^4)
 *   oren-nayar   qualitative | full  (Oren–Nayar 1994, σ in radians, ρ = albedo)
 *   cook-torrance walter | 1982   c_diff/π + D F G / (4 cos θ_i cos θ_o); 1982 as printed is 4×
 *                D beckmann|ggx, G cook-torrance|smith|smith-correlated, F schlick|exact|none
 *   file         f = BRDF(L, V, N, X, Y) of a .brdf file's GLSL (shadecalc/brdf_file.h)
 *
 * Guards (each documented in the man page): divisions by cos θ_i, cos θ_o take them at least
 * 1e-6; α is at least 1e-4 (pbrt); h = n when l = −v (docs/formulas.md §1); pow(0, 0) = 1; Ward's exponent
 * is evaluated first so that exp(−∞) = 0 never meets an infinite prefactor.
 */
#ifndef SHADECALC_BRDF_H
#define SHADECALC_BRDF_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

typedef enum {
    SC_BRDF_LAMBERT,
    SC_BRDF_PHONG,
    SC_BRDF_BLINN_PHONG,
    SC_BRDF_WARD,
    SC_BRDF_OREN_NAYAR,
    SC_BRDF_COOK_TORRANCE,
    SC_BRDF_FILE /* a BRDF written in GLSL (shadecalc/brdf_file.h) */
} sc_brdf_kind;

/* Variants (sc_brdf.form), by model, in the order sc_brdf_form_name lists them. */
enum { SC_PHONG_ORIGINAL, SC_PHONG_MODIFIED, SC_PHONG_NORMALIZED };
enum { SC_BLINN_NORMALIZED, SC_BLINN_PLAIN };
enum { SC_WARD_1992, SC_WARD_DUER, SC_WARD_GMD };
enum { SC_OREN_QUALITATIVE, SC_OREN_FULL };
enum { SC_CT_WALTER, SC_CT_1982 };

typedef enum { SC_D_BECKMANN, SC_D_GGX } sc_ndf;
typedef enum { SC_G_VCAVITY, SC_G_SMITH, SC_G_SMITH_CORRELATED } sc_masking;
typedef enum { SC_F_SCHLICK, SC_F_EXACT, SC_F_NONE } sc_fresnel;

/* A compiled .brdf file (shadecalc/brdf_file.h). */
typedef struct sc_brdf_file sc_brdf_file;

enum { SC_BRDF_FILE_MAX_PARAMS = 32, SC_BRDF_FILE_MAX_VALUES = 3 * SC_BRDF_FILE_MAX_PARAMS };

typedef struct {
    sc_brdf_kind kind;
    int form;
    double diff[3]; /* c_diff, ρ_d; oren-nayar: ρ */
    double spec[3]; /* c_spec, ρ_s */
    double amb[3];  /* c_amb, the material's ambient colour (docs/formulas.md §6) */
    double m;       /* phong and blinn-phong exponent */
    double ax, ay;  /* roughness α (ward, cook-torrance); ax = ay when isotropic */
    double sigma;   /* oren-nayar σ in radians */
    sc_ndf D;
    sc_masking G;
    sc_fresnel F;
    double f0[3]; /* schlick F0 */
    double ior;   /* exact Fresnel: relative index of refraction η */
    /* SC_BRDF_FILE: the file (shared, never freed by sc_brdf) and its parameters' values */
    const sc_brdf_file *file;
    double file_values[SC_BRDF_FILE_MAX_VALUES];
} sc_brdf;

/* Orthonormal frame: n unit normal, t tangent (t ⟂ n), b = n × t. */
typedef struct {
    double n[3], t[3], b[3];
} sc_frame;

/* The terms behind one value of f (for --explain); D, G, F are 0 where a model has none. */
typedef struct {
    double f[3];        /* the BRDF */
    double diffuse[3];  /* its diffuse part */
    double specular[3]; /* its specular part */
    double D, G, F[3];
    double cos_i, cos_o, cos_h;
} sc_brdf_terms;

/* Defaults: c_diff 0.8; c_spec 0.2 (0 for lambert and oren-nayar, 1 for cook-torrance, whose
 * colour is F0); m 32; α 0.3; σ 0; GGX + Smith height-correlated + Schlick with F0 0.04; η 1.5;
 * c_amb 0; forms: phong normalized, blinn-phong normalized, ward 1992, oren-nayar qualitative,
 * cook-torrance walter. */
void sc_brdf_init(sc_brdf *b, sc_brdf_kind kind);

/* Builds the frame from a normal and a tangent hint (NULL: e_x, or e_y where |n_x| >=
 * 2 max(|n_y|, |n_z|), decided on n as given; the batch kernels choose alike); normalizes both.
 * Returns -1 if n is zero or the tangent is parallel to n. */
int sc_frame_make(const double n[3], const double *tangent, sc_frame *out);

void sc_brdf_eval(sc_prec p, const sc_brdf *b, const sc_frame *frame, const double l[3],
                  const double v[3], sc_brdf_terms *out);

/* One point of sc_brdf_eval_many: its frame (often shared by many points) and l, v. */
typedef struct {
    const sc_frame *frame;
    double l[3], v[3];
} sc_brdf_point;

/* out[i] = sc_brdf_eval(p, b, pts[i].frame, pts[i].l, pts[i].v) for i < n, bit for bit; a BRDF
 * file's shader runs over the points above the horizon in blocks (sc_brdf_file_eval_many).
 * Returns n, or for a BRDF file whose shader failed, the index of the point whose evaluation
 * failed first (0 if it had failed before the call). */
int sc_brdf_eval_many(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                      sc_brdf_terms *out);

int sc_brdf_validate(const sc_brdf *b, char *msg, size_t size);

/* 0 if every numeric parameter is finite in precision p, else -1 with a message naming the key
 * (sc_params_in_range, shadecalc/light.h). */
int sc_brdf_check_range(sc_prec p, const sc_brdf *b, char *msg, size_t size);

const char *sc_brdf_kind_name(sc_brdf_kind kind);
/* The name of form `form` of a model ("normalized"), or NULL past the last. */
const char *sc_brdf_form_name(sc_brdf_kind kind, int form);

SC_END_DECLS

#endif
