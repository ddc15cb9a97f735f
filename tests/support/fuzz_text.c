/* tests/support/fuzz_text.h */
#include <stdlib.h>
#include <string.h>

#include "tests/support/fuzz_text.h"

char *fuzz_text(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (text) {
        memcpy(text, data, size);
        text[size] = '\0';
    }
    return text;
}
