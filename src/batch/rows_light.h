/* Rows of the batch table for the attenuation, spot and BRDF kernels (included inside the array
 * of src/batch/table.c: ROWS(...) and ROWS_P(...) lines only). */
#define ATTEN_P &sc_batch_test_atten
#define SPOT_P &sc_batch_test_spot
#define BRDF_P &sc_batch_test_brdf
#define R_RANGE 0, 1000, 0, 0, NULL
#define COS_RANGE -1, 1, 0, 0, NULL
#define BRDF_DOM                                                                                   \
    "l, v, n nonzero, |n.l|, |n.v| >= 2^-6 |n||l|, |n||v|; alpha >= 0.2 (anisotropic Beckmann "    \
    ">= 0.35), m <= 200, ior >= 1; "                                                               \
    "error relative, plus 2^-20 x scale"
ROWS_P(atten_none, u1, 1, 1, 0.5, 0, 0, "all r", R_RANGE, 0, ATTEN_P)
ROWS_P(atten_invsq, u2, 1, 1, 2, 0, 0, "0 <= r <= 1000", R_RANGE, 4, ATTEN_P)
ROWS_P(atten_clq, u3, 1, 1, 3, 0, 0, "0 <= r <= 1000", R_RANGE, 6, ATTEN_P)
ROWS_P(atten_window, u2, 1, 1, 2, 0, 0, "0 <= r <= 1000", R_RANGE, 6, ATTEN_P)
ROWS_P(atten_pixar, u4, 1, 1, 4, 0, 0, "0 <= r <= 1000", R_RANGE, 140, ATTEN_P)
ROWS_P(atten_pixar, bits12, 1, 1, 0, B12, 0, "0 <= r <= 1000", R_RANGE, 40, ATTEN_P)
ROWS_P(atten_windowed, u12, 1, 1, 12, 0, 0, "0 <= r <= 1000", R_RANGE, 12, ATTEN_P)
ROWS_P(spot_opengl, u1, 1, 1, 1, 0, 0, "-1 <= cos <= 1", COS_RANGE, 70, SPOT_P)
ROWS_P(spot_opengl, bits12, 1, 1, 0, B12, 0, "-1 <= cos <= 1", COS_RANGE, 30, SPOT_P)
ROWS_P(spot_directx, u16, 1, 1, 16, 0, 0,
       "-1 <= cos <= 1, exponent <= 8 (error (1 + 1.5 exponent) ULP)", COS_RANGE, 75, SPOT_P)
ROWS_P(spot_directx, bits12, 1, 1, 0, B12, 0x1p-125,
       "-1 <= cos <= 1 (results below 2^-125 flush to 0)", COS_RANGE, 35, SPOT_P)
ROWS_P(spot_smoothstep, u8, 1, 1, 8, 0, 0, "-1 <= cos <= 1", COS_RANGE, 10, SPOT_P)
ROWS_P(brdf, bits16, 9, 3, 0, 0x1p-16, 0x1p-20, BRDF_DOM, VEC(sc_batch_gen_brdf), 80, BRDF_P)
ROWS_P(brdf, bits12, 9, 3, 0, B12, B12, "as bits16", VEC(sc_batch_gen_brdf), 80, BRDF_P)
#define AREA_DOM(what)                                                                             \
    "n, v nonzero, |n.v| >= 2^-6 |n||v|, p in [-3, 3]^3 (" what "); error against the double "     \
    "approximation, absolute: the bound x scale, scale = max L_e (c_diff + c_spec); next to the "  \
    "emitter's surface, plus the change one ulp of p makes there"
ROWS_P(area_sphere, accurate, 9, 3, 0, 0, 0x1p-15, AREA_DOM("representative point, sphere R 0.6"),
       VEC(sc_batch_gen_shade), 300, &sc_batch_test_area_sphere)
ROWS_P(area_tube, accurate, 9, 3, 0, 0, 0x1p-13, AREA_DOM("representative point, tube R 0.25"),
       VEC(sc_batch_gen_shade), 300, &sc_batch_test_area_tube)
ROWS_P(area_disk, accurate, 9, 3, 0, 0, 0x1p-14,
       AREA_DOM("LTC, one-sided disk R 0.8, its 64-gon; GGX alpha >= 0.1"), VEC(sc_batch_gen_shade),
       8000, &sc_batch_test_area_disk)
ROWS_P(area_rect, accurate, 9, 3, 0, 0, 0x1p-14, AREA_DOM("LTC, two-sided rect; GGX alpha >= 0.1"),
       VEC(sc_batch_gen_shade), 600, &sc_batch_test_area_rect)
