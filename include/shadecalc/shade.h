/*
 * shadecalc/shade.h — the shading equation (docs/formulas.md §6) and the fixed-function equations of
 * legacy APIs (docs/formulas.md §6.8), for any number of lights.
 *
 *   sc_model                what is evaluated at a point: a BRDF in the docs/formulas.md §6 equation, the
 *                           shader-literature ADS forms, OpenGL 1.x or Direct3D 9 lighting
 *   sc_scene                lights, a model, the global ambient L_A
 *   sc_shade                L_o at a point, with every intermediate per light (for --explain)
 *   sc_shade_many           the same at many points (a BRDF file's shader in blocks)
 *
 * docs/formulas.md §6:  L_o = c_amb ⊙ L_A + Σ_k [ c_amb ⊙ L_A,k + f(l_k, v) ⊙ E_L,k · cos̄θ_i,k ]
 *           where an area light's term is sc_area_eval's ∫ f L_e cos̄θ_i dω by its method
 *           (docs/formulas.md §5), rounded to the precision
 * ads:      L_o = k_a ⊙ (L_A + Σ_k L_A,k) + Σ_k att·spot·[ I⊙c_d,k ⊙ k_d (n·l)⁺ + I⊙c_s,k ⊙ k_s S ]
 *           with S = 0, (r·v)⁺^m or (n·h)⁺^m for the lambert, phong and blinn-phong forms and
 *           k_d, k_s, k_a, m the model's diff, spec, amb, m (the lecture's shader form: light
 *           colours separate from material colours, no 1/π)
 * opengl:   c = e + a_cm ⊙ a_cs + Σ att·spot·[ a_cm ⊙ a_cl + (n·l)⁺ d_cm ⊙ d_cl
 *                                              + [n·l > 0] (n·ĥ)⁺^srm s_cm ⊙ s_cl ]
 *           ĥ from l + v (local viewer) or l + the fixed viewer direction; colour clamp to
 *           [0, 1]; with separate specular the specular sum is clamped on its own and added
 * direct3d9: Ce + Ca ⊙ [Ga + Σ att·spot·La] + Σ att·spot·Cd ⊙ Ld (n·l)⁺
 *           + Cs ⊙ Σ att·spot·Ls (n·h)⁺^P, att = 0 beyond the light's range; local viewer by
 *           default; clamped to [0, 1]
 * In the legacy models a light's colours are its intensity times its amb, diff, spec colours.
 */
#ifndef SHADECALC_SHADE_H
#define SHADECALC_SHADE_H

#include "shadecalc/api.h"
#include "shadecalc/area.h"
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

SC_BEGIN_DECLS

typedef enum { SC_MODEL_BRDF, SC_MODEL_ADS, SC_MODEL_OPENGL, SC_MODEL_D3D9 } sc_model_kind;
typedef enum { SC_ADS_LAMBERT, SC_ADS_PHONG, SC_ADS_BLINN_PHONG } sc_ads_form;

typedef struct {
    sc_model_kind kind;
    /* SC_MODEL_BRDF: the BRDF. Legacy models use its diff, spec, amb (material colours) and m
     * (shininess). */
    sc_brdf brdf;
    sc_ads_form ads_form;
    double emission[3];    /* opengl e_cm, direct3d9 Ce */
    int local_viewer;      /* opengl: default 0; direct3d9: default 1 */
    double viewer_dir[3];  /* the fixed viewer direction when not local: (0, 0, 1) */
    int clamp;             /* opengl, direct3d9: clamp colours to [0, 1] (default 1) */
    int separate_specular; /* opengl GL_SEPARATE_SPECULAR_COLOR */
} sc_model;

typedef struct {
    const sc_light *lights;
    int n_lights;
    sc_model model;
    double ambient[3]; /* L_A (opengl a_cs, direct3d9 Ga) */
} sc_scene;

/* One light's share of L_o. An area light (SC_MODEL_BRDF only) fills `light` with its
 * point-light stand-in (sc_light_eval), `area` with its result and `brdf` at area.l. */
typedef struct {
    sc_light_sample light;
    sc_area_result area;
    sc_brdf_terms brdf; /* SC_MODEL_BRDF; legacy models fill cos_i, cos_h, diffuse, specular */
    double ambient[3];  /* its ambient term */
    double contribution[3];
} sc_light_terms;

typedef struct {
    double L[3];                     /* the result */
    double ambient[3];               /* the global ambient term */
    double primary[3], secondary[3]; /* opengl separate specular: the two colours */
    sc_light_terms *per_light;       /* filled when not NULL: n_lights entries */
} sc_shade_result;

/* Where to shade: position, unit normal, unit direction to the viewer, tangent (or NULL). */
typedef struct {
    double pos[3];
    sc_frame frame;
    double v[3];
} sc_shade_point;

/* Default model for a kind (opengl: local viewer off, clamp on; direct3d9: local viewer on). */
void sc_model_init(sc_model *m, sc_model_kind kind);

void sc_shade(sc_prec p, const sc_scene *scene, const sc_shade_point *at, sc_shade_result *out);
/* sc_shade at n points, bit for bit; with a BRDF file and no area light, f of each light at
 * every point is one sc_brdf_eval_many (the file's shader in blocks). */
void sc_shade_many(sc_prec p, const sc_scene *scene, int n, const sc_shade_point *at,
                   sc_shade_result *out);

SC_END_DECLS

#endif
