/* Double references and input generators of the sin, cos, acos, atan2 batch kernels. */
#ifndef SHADECALC_BATCH_REFERENCE_TRIG_H
#define SHADECALC_BATCH_REFERENCE_TRIG_H

#include "shadecalc/batch.h"

#endif
