/* The double references of the sin, cos, acos, atan2 batch kernels: libm's double functions on
 * the float inputs (within an ULP of binary64, far below the binary32 bounds they check). The
 * scale of the absolute allowance is 1: near the zeros of sin and cos the error of a float
 * reduction is absolute, and atan2's allowance is the flush to zero of results below 2^-126. */
#include <math.h>

#include "batch/reference_trig.h"

#define REF1(name)                                                                                 \
    void sc_batch_ref_##name(const sc_batch_args *a, size_t i, double *out)                        \
    {                                                                                              \
        out[0] = name((double)a->in[0][i]);                                                        \
        out[1] = 1.0;                                                                              \
    }
REF1(sin)
REF1(cos)
REF1(acos)

void sc_batch_ref_atan2(const sc_batch_args *a, size_t i, double *out)
{
    out[0] = atan2((double)a->in[0][i], (double)a->in[1][i]);
    out[1] = 1.0;
}
