/* `$name` substitution of sweep variables into spec strings (shadecalc/sweep.h). */
#include "shadecalc/sweep.h"
#include "sweep/sweep_internal.h"

#include <string.h>

/* The variable named at s ($ already skipped): NAME or {NAME}. Sets *used to the characters
 * consumed; returns its index, or -1 with err. */
static int variable_at(const char *s, const sc_sweep_grid *g, size_t *used, char *err,
                       size_t errsize)
{
    int braced = s[0] == '{';
    size_t len = sc_sweep_identifier_length(s + braced);
    if (len == 0 || (braced && s[1 + len] != '}')) {
        snprintf(err, errsize, "'$%.20s': expected $NAME or ${NAME}", s);
        return -1;
    }
    char name[SC_SWEEP_NAME_MAX];
    if (len >= sizeof name) {
        snprintf(err, errsize, "'$%.*s': unknown variable", (int)len, s + braced);
        return -1;
    }
    memcpy(name, s + braced, len);
    name[len] = '\0';
    int k = sc_sweep_grid_find(g, name);
    if (k < 0)
        snprintf(err, errsize, "'$%s': unknown variable (give it with --var %s=...)", name, name);
    *used = len + 2 * (size_t)braced;
    return k;
}

int sc_sweep_substitute(const char *text, const sc_sweep_grid *g, const double *values, char *out,
                        size_t size, char *err, size_t errsize)
{
    size_t n = 0;
    for (const char *p = text; *p;) {
        char piece[64];
        size_t len = 1, used = 0;
        const char *from = p;
        if (*p == '$') {
            int k = variable_at(p + 1, g, &used, err, errsize);
            if (k < 0)
                return -1;
            sc_format_shortest(piece, sizeof piece, values[k], SC_DOUBLE);
            from = piece;
            len = strlen(piece);
            p += 1 + used;
        } else {
            p++;
        }
        if (n + len >= size) {
            snprintf(err, errsize, "'%.40s...': too long after substitution", text);
            return -1;
        }
        memcpy(out + n, from, len);
        n += len;
    }
    out[n] = '\0';
    return 0;
}
