/* Double references, input generators and test parameters of the attenuation, spot and BRDF
 * batch kernels. */
#ifndef SHADECALC_BATCH_REFERENCE_LIGHT_H
#define SHADECALC_BATCH_REFERENCE_LIGHT_H

#include "shadecalc/batch.h"

#endif
