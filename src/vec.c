/* refract for the float vectors (shadecalc/vec.h): GLSL ES 3.00 §8.5, in the order of
 * shadecalc/pmath.h so that it matches `shadecalc eval` in highp bit for bit. */
#include "shadecalc/vec.h"

// clang-format off
#define SC_VEC_REFRACT_(c, k) eta * i.c - s * n.c
#define SC_VEC_ZERO_(c, k) 0.0f
// clang-format on

/* k = 1 − η·η·(1 − d·d) with d = dot(N, I); k < 0 is total internal reflection: the zero
 * vector. Otherwise η·I − (η·d + sqrt(k))·N. */
#define SC_VEC_DEFINE_REFRACT(T, EACH)                                                             \
    T T##_refract(T i, T n, float eta)                                                             \
    {                                                                                              \
        float d = T##_dot(n, i);                                                                   \
        float k = 1.0f - eta * eta * (1.0f - d * d);                                               \
        if (k < 0.0f)                                                                              \
            return (T){EACH(SC_VEC_ZERO_)};                                                        \
        float s = eta * d + sc_sqrtf(k);                                                           \
        return (T){EACH(SC_VEC_REFRACT_)};                                                         \
    }

SC_VEC_DEFINE_REFRACT(sc_vec2, SC_EACH2)
SC_VEC_DEFINE_REFRACT(sc_vec3, SC_EACH3)
SC_VEC_DEFINE_REFRACT(sc_vec4, SC_EACH4)
