/* image/half.h — float to binary16 over arrays (private to src/image).
 *
 * The same bits as sc_half_from_double (shadecalc/precision.h) for every float: round to
 * nearest even, subnormal halves, beyond ±65504 ±Inf, every NaN the quiet NaN 0x7e00 with the
 * input's sign. With F16C (x86-64, checked at run time) eight at a time by the hardware
 * conversion (VCVTPS2PH, rounding to nearest even), NaNs made canonical first; otherwise, and
 * for the tail, the software conversion. */
#ifndef SHADECALC_IMAGE_HALF_H
#define SHADECALC_IMAGE_HALF_H

#include <stddef.h>
#include <stdint.h>

/* out[i] = binary16 of in[i], i < n. force_software: the software path even where F16C is
 * present (the tests compare both). */
void image_halves_from_floats(const float *in, uint16_t *out, size_t n, int force_software);

#endif
