/* The fuzz harnesses' input as text. */
#ifndef SHADECALC_TESTS_FUZZ_TEXT_H
#define SHADECALC_TESTS_FUZZ_TEXT_H

#include <stddef.h>
#include <stdint.h>

/* data[0..size) and a NUL, in memory the caller frees; NULL when out of memory */
char *fuzz_text(const uint8_t *data, size_t size);

#endif
