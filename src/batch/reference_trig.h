/* Double references and input generators of the sin, cos, acos, atan2 batch kernels. */
#ifndef SHADECALC_BATCH_REFERENCE_TRIG_H
#define SHADECALC_BATCH_REFERENCE_TRIG_H

#include "shadecalc/batch.h"

/* libm's double sin, cos, acos, atan2 (inputs y, x) on the float inputs; scale 1 */
void sc_batch_ref_sin(const sc_batch_args *a, size_t i, double *out);
void sc_batch_ref_cos(const sc_batch_args *a, size_t i, double *out);
void sc_batch_ref_acos(const sc_batch_args *a, size_t i, double *out);
void sc_batch_ref_atan2(const sc_batch_args *a, size_t i, double *out);

#endif
