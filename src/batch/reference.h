/* The double-precision references and input generators of the batch table (src/batch/). */
#ifndef SHADECALC_BATCH_REFERENCE_H
#define SHADECALC_BATCH_REFERENCE_H

#include "shadecalc/batch.h"
#include "shadecalc/shade.h"

/* clang-format off */
#define SC_BATCH_REFS(X)                                                                          \
    X(exp2) X(exp) X(log2) X(log) X(pow) X(inversesqrt) X(sqrt) X(dot) X(reflect) X(normalize)    \
    X(length) X(shade)
#define SC_DECLARE_REF(name) void sc_batch_ref_##name(const sc_batch_args *a, size_t i, double *out);
SC_BATCH_REFS(SC_DECLARE_REF)
/* clang-format on */

/* sc_shade of scene s (double) at element i of a's n, v, p: out[0..2] the radiance, out[3]
 * the ambient term's largest component, terms (s->n_lights of them) each light's; -1 where n
 * or v is zero (out: the ambient term). */
int sc_batch_shade_at(const sc_scene *s, const sc_batch_args *a, size_t i, double out[4],
                      sc_light_terms *terms);

void sc_batch_gen_pair(uint64_t *rng, float *in);    /* two vectors of magnitude 2^±8 */
void sc_batch_gen_reflect(uint64_t *rng, float *in); /* I of magnitude 2^±8, N unit */
void sc_batch_gen_vector(uint64_t *rng, float *in);  /* one vector of magnitude 2^±60 */
void sc_batch_gen_shade(uint64_t *rng, float *in); /* n, v (|cos θ_o| >= 2^-6), p in [−3, 3]³ */

/* The scenes of the tests and of `shadecalc bench`: n_dir directional, n_point point and n_spot
 * spot lights (the three spot kinds in turn, cones of 25° to 40°) around +y, the BRDF's
 * defaults (brdf.h: m 32, α 0.3, f0 0.04) with diff 0.8/0.5/0.2, spec 0.2 (cook-torrance 1),
 * ambient 0.02. lights holds the lights out points to. */
void sc_batch_example_scene(sc_brdf_kind brdf, int n_dir, int n_point, int n_spot,
                            sc_light lights[SC_BATCH_MAX_LIGHTS], sc_scene *out);

#endif
