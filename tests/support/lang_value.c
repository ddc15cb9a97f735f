/* tests/support/lang_value.h */
#include <math.h>
#include <string.h>

#include "tests/support/lang_value.h"

int lang_value_keep(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    lang_value_pick *pick = user;
    (void)text, (void)len, (void)line;
    if (pick->seen++ == pick->value)
        memcpy(pick->out, v->v, (size_t)sc_ltype_size(v->type) * sizeof(double));
    return 0;
}

int lang_same_bits(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}
