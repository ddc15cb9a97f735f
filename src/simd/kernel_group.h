/* One group of the batch kernels, for the instruction set whose vector helpers (vec.h) the file
 * included first: each instruction set's folder has a file per group, which defines
 * SC_KERNEL_GROUP and includes this header. The shading kernel was nine tenths of the compile
 * time of the whole (gcc 12 -O2: 48 of 52 s of CPU for AVX2, then with a third tier, bits8), so
 * each of its tiers has a file of its own (shade_accurate.c, shade_bits12.c) and every other
 * kernel is in kernels.c: a build compiles them in parallel, a fraction of a minute each.
 *
 * Every file includes every header: each builds on those before it, and the shading kernel calls
 * the area lights' term. The kernels a file does not define are static inline (KERNEL,
 * src/simd/kernels_impl.h) and never called, so neither compiler generates code for them;
 * scene_impl.h instantiates the shading kernel of the file's tier only. */

#define SC_GROUP_KERNELS 1        /* all but the shading kernel */
#define SC_GROUP_SHADE_ACCURATE 2 /* the shading kernel, one tier per file */
#define SC_GROUP_SHADE_BITS12 3

/* the scope of every kernel but the shading one (KERNEL, src/simd/kernels_impl.h) */
#if SC_KERNEL_GROUP == SC_GROUP_KERNELS
#define SC_GROUP_SCOPE
#else
#define SC_GROUP_SCOPE static inline
#endif

#define SC_KERNEL_SCOPE SC_GROUP_SCOPE
#include "simd/kernels_impl.h"
#include "simd/shade_impl.h"
#include "simd/trig_impl.h"
#include "simd/light_impl.h"
#undef SC_KERNEL_SCOPE
#define SC_KERNEL_SCOPE
#include "simd/scene_impl.h"
#undef SC_KERNEL_SCOPE
#define SC_KERNEL_SCOPE SC_GROUP_SCOPE
#include "simd/area_impl.h"
