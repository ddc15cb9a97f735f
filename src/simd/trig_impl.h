/* The sin, cos, acos, atan2 batch kernels, written once against the vector helpers and included
 * after src/simd/kernels_impl.h by each instruction set's file. */
