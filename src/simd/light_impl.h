/* The attenuation, spot and BRDF batch kernels, written once against the vector helpers and
 * included after src/simd/shade_impl.h by each instruction set's file. */
