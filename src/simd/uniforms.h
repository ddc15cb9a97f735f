/* src/simd/uniforms.h — the float uniforms the batch kernels read (private to the library).
 *
 * The kernels take the double model types of light.h, brdf.h and shade.h; src/batch/uniforms.c
 * turns them into these once — per call for the attenuation, spot and BRDF kernels, once per
 * plan for the shading kernel (src/batch/plan.c) — so that the lanes read floats only. */
#ifndef SHADECALC_SIMD_UNIFORMS_H
#define SHADECALC_SIMD_UNIFORMS_H

#include <stddef.h>

#include "shadecalc/batch.h"
#include "shadecalc/shade.h"

enum { SC_LTC_ROW = 6, SC_LTC_ROWS = 32 }; /* fields per row, rows: light/ltc.h's table */

/* An attenuation or spot function: six constants, named by the setup of each kind. */
typedef struct {
    float k[6];
} sc_func_uniforms;

/* The constants of attenuation function `kind` from a's parameters (a->kind is not read):
 *   clq       sc sl sq
 *   window    r_start r_end w·s 1/(w·s) s w, w = r_end − r_start rounded to float, s the
 *             power of 2 that puts w·s in [1, 2), at most 2^126 (w·s >= 2^-23), 1/(w·s)
 *             rounded once; the step w = 0 has s = 1, 1/(w·s) = 0 and w = 1 (a ramp of 0/1)
 *   pixar     f_c r_c s_e f_max k0 −k1, k0 = ln(f_c/f_max), k1 = s_e/k0 (flat: k0 = 0)
 *   windowed  r_max r_max² 1/r_max^4                                     others: none */
void sc_uniforms_atten(const sc_atten *a, sc_atten_kind kind, sc_func_uniforms *u);

/* The constants of spot function `kind` from s (s->kind is not read):
 *   opengl               cos θ_u (rounded up), exponent, 1 for no cone (cutoff 180)
 *   directx, smoothstep  cos θ_p (rounded up), cos θ_u (rounded down) as hi + lo,
 *                        1/(cos θ_p − cos θ_u) (0 for a hard edge), exponent
 * The cosines are rounded toward the inside of each test, so that the comparisons of a float
 * cos θ_s decide as in double. */
void sc_uniforms_spot(const sc_spot *s, sc_spot_kind kind, sc_func_uniforms *u);

/* Integer lobe exponents up to this are raised by binary powering (the shading kernel's own
 * lobes in its accurate tier stop at 64: see src/simd/shade_impl.h). */
enum { SC_LOBE_INT_MAX = 256 };

/* A BRDF: f_c = w_0 col[0][c] + w_1 col[1][c] + w_2 col[2][c] with weights the model computes. */
typedef struct {
    sc_brdf_kind model;
    int form, D, G, F;
    int aniso;       /* ward, cook-torrance with α_x != α_y: the lanes build the tangent frame */
    float col[3][3]; /* the colour vectors */
    float k[4];      /* the model's constants, named by sc_uniforms_brdf */
    float m, a2;     /* exponent; α_x α_y */
    float ax, ay;    /* α (>= 10^-4) */
    /* the cosine lobe's exponent (phong m, blinn-phong m/2) when an integer in
     * 1..SC_LOBE_INT_MAX, else 0, and 2^(−100/lobe_m): in the fast tiers bases below it give 0 */
    unsigned lobe_m;
    float lobe_cutoff;
} sc_brdf_uniforms;

void sc_uniforms_brdf(const sc_brdf *b, sc_brdf_uniforms *u);

/* The lobe the shading kernel computes for a scene's BRDF: none (lambert); its own Blinn-Phong
 * (either form) and GGX (walter, smith-correlated, Schlick with a grey F0, isotropic); or the
 * BRDF kernel's model functions (every other model, form and anisotropic roughness). */
typedef enum { SC_LOBE_NONE, SC_LOBE_BLINN, SC_LOBE_GGX, SC_LOBE_MODEL } sc_lobe;

/* An area light by its approximation (docs/formulas.md §5.3): sphere and tube by the
 * representative point, disk and rect by LTC (method=point is a point light; reference is
 * refused). Rect and disk are both a convex polygon of vertices centre + c_k e1 + s_k e2
 * (sc_area_ring_*: a rect's 4 corners, the disk's 64-gon of equal area). */
typedef struct {
    float centre[3]; /* sphere, disk, rect: the centre; tube: the midpoint of p0–p1 */
    float radius;
    float p0[3], axis[3]; /* tube: p0 and p1 − p0 */
    float line;           /* tube: its cylinder's 2Rℓ, ℓ = |p1 − p0| */
    float half_along;     /* the half-width along the emitter, R (a tube: R + ℓ/2), for α' */
    float e1[3], e2[3];   /* rect: edge1, edge2; disk: its polygon's radius times two axes */
    float normal[3];      /* disk, rect: the emitting side (rect: edge1 × edge2) */
    int two_sided;
} sc_area_uniforms;

/* c_k and s_k of the polygon of sc_area_uniforms: rect (4 corners) and disk (64-gon). */
extern const float sc_area_ring_rect[2][4];
extern const float sc_area_ring_disk[2][64];

typedef struct {
    sc_light_kind kind;
    sc_atten_kind atten; /* point, spot */
    sc_spot_kind spot;
    float dir[3];   /* directional: unit, toward the light; spot: unit axis */
    float pos[3];   /* point, spot */
    float color[3]; /* E_L or I_L */
    sc_func_uniforms atten_u, spot_u;
    sc_area_uniforms area; /* sphere, tube, disk, rect (color: L_e) */
} sc_light_uniforms;

/* The shading kernel's straight-line variants: 1..SC_SHADE_FIXED_MAX lights, all directional,
 * all point or all spot lights (of any spot kinds), these two with inverse-square falloff,
 * with the kernel's own lobes. Variant 0 is the generic loop; variant 1 + 4 s + (count − 1)
 * is count lights of shape s. */
enum { SC_SHAPE_DIRECTIONAL, SC_SHAPE_POINT, SC_SHAPE_SPOT, SC_SHAPES };
enum { SC_SHADE_FIXED_MAX = 4, SC_SHADE_VARIANTS = 1 + SC_SHAPES * SC_SHADE_FIXED_MAX };

typedef struct {
    sc_light_uniforms lights[SC_BATCH_MAX_LIGHTS];
    int n_lights;
    sc_lobe lobe;
    float diff_pi[3], spec[3], amb_term[3]; /* c_diff/π, c_spec, c_amb ⊙ (L_A + Σ L_A,k) */
    float lobe_k;                           /* blinn-phong: (m+8)/(8π) or 1 */
    float m, alpha, f0;                     /* blinn-phong m; ggx α (>= 10^-4), grey F0 */
    unsigned lobe_m;                        /* m when an integer in 1..SC_LOBE_INT_MAX, else 0 */
    float lobe_cutoff;                      /* 2^(−100/m): bases below it give 0 */
    sc_brdf_uniforms brdf;                  /* SC_LOBE_MODEL */
    int variant;                            /* the kernel's variant for the scene's lights */
    /* LTC (disk and rect lights): c_spec ⊙ F0 and c_spec ⊙ (1 − F0) (0 for lambert), and the
     * table of light/ltc.h interpolated at the scene's α once: per cos θ_v row, M⁻¹'s m00,
     * m02, m11, m20, A and B */
    float ltc_sa[3], ltc_sb[3];
    float ltc_rows[SC_LTC_ROWS][SC_LTC_ROW];
} sc_shade_uniforms;

/* The uniforms of scene: 0, or -1 with why naming the model, light or form the kernels do not
 * cover. */
int sc_uniforms_shade(const sc_scene *scene, sc_shade_uniforms *u, char *why, size_t size);

/* The uniforms a plan holds (the shade kernels' params is a plan). */
const sc_shade_uniforms *sc_batch_plan_uniforms(const sc_batch_plan *plan);

#endif
