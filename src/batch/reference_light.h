/* Double references, input generators and test parameters of the attenuation, spot and BRDF
 * batch kernels. */
#ifndef SHADECALC_BATCH_REFERENCE_LIGHT_H
#define SHADECALC_BATCH_REFERENCE_LIGHT_H

#include "batch/reference.h"
#include "shadecalc/batch.h"
#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

/* clang-format off */
#define SC_BATCH_REFS_LIGHT(X)                                                                    \
    X(atten_none) X(atten_invsq) X(atten_clq) X(atten_window) X(atten_pixar) X(atten_windowed)   \
    X(spot_opengl) X(spot_directx) X(spot_smoothstep) X(brdf) X(area_sphere) X(area_tube)         \
    X(area_disk) X(area_rect)
SC_BATCH_REFS_LIGHT(SC_DECLARE_REF)
/* clang-format on */

/* l, v, n in random directions, magnitudes 2^±30, |cos θ_i|, |cos θ_o| >= 2^-6 (most above
 * the horizon) */
void sc_batch_gen_brdf(uint64_t *rng, float *in);

/* The parameters of the table's rows (the tests and the bench). */
extern const sc_atten sc_batch_test_atten;
extern const sc_spot sc_batch_test_spot;
/* cook-torrance GGX, Smith height-correlated, Schlick: the model with the most terms (the
 * others are tested in tests/unit/test_batch_light.c) */
extern const sc_brdf sc_batch_test_brdf;

/* The area kernels' scenes: one light each, sphere and tube by the representative point with
 * GGX (a grey F0: the kernel's own lobe), a one-sided disk and a two-sided rect by LTC with
 * GGX (F0 per channel) */
extern const sc_scene sc_batch_test_area_sphere, sc_batch_test_area_tube, sc_batch_test_area_disk,
    sc_batch_test_area_rect;

#endif
