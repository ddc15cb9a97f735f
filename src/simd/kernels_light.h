/* The kernel_tier names of the attenuation, spot and BRDF batch kernels
 * (src/simd/light_impl.h). */
#ifndef SHADECALC_SIMD_KERNELS_LIGHT_H
#define SHADECALC_SIMD_KERNELS_LIGHT_H

/* clang-format off */
#define SC_BATCH_KERNELS_LIGHT(X)                                                                 \
    X(atten_none_u1) X(atten_invsq_u2) X(atten_clq_u3) X(atten_window_u2) X(atten_pixar_u4)       \
    X(atten_pixar_bits12) X(atten_windowed_u12) X(spot_opengl_u1) X(spot_opengl_bits12)           \
    X(spot_directx_u16) X(spot_directx_bits12) X(spot_smoothstep_u8) X(brdf_bits16)               \
    X(brdf_bits12) X(area_sphere_accurate) X(area_tube_accurate)                                 \
    X(area_disk_accurate) X(area_rect_accurate)
/* clang-format on */

#endif
