/* Helpers shared by the files of src/sweep/. */
#ifndef SHADECALC_SWEEP_INTERNAL_H
#define SHADECALC_SWEEP_INTERNAL_H

#include <stddef.h>

/* Length of the identifier at s ([A-Za-z_][A-Za-z0-9_]*), 0 if none. */
size_t sc_sweep_identifier_length(const char *s);

#endif
