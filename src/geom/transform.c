/* Transforms from text and the normal matrix with the rigid shortcut (shadecalc/transform.h). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/transform.h"

enum { MAX_ARGS = 16 };

static const char *skip_space(const char *p)
{
    while (isspace((unsigned char)*p))
        p++;
    return p;
}

/* Up to `max` finite numbers separated by commas, ending at `close` (or the end of the string
 * when close is 0); their count, or -1. *p moves past the list (and the `close`). */
static int parse_numbers(const char **p, char close, double *out, int max)
{
    int n = 0;
    const char *s = skip_space(*p);
    if (close && *s == close) {
        *p = s + 1;
        return 0;
    }
    for (;;) {
        char *end;
        if (n == max)
            return -1;
        out[n] = strtod(s, &end);
        if (end == s || !isfinite(out[n]))
            return -1;
        n++;
        s = skip_space(end);
        if (*s != ',')
            break;
        s++;
    }
    if (*s != close)
        return -1;
    *p = close ? s + 1 : s;
    return n;
}

static int name_is(const char *name, size_t len, const char *want)
{
    return len == strlen(want) && strncmp(name, want, len) == 0;
}

/* One factor name(args): its matrix, or -1. */
static int make_factor(const char *name, size_t len, const double *a, int n, sc_dmat4 *out)
{
    if (name_is(name, len, "translate") && n == 3)
        *out = sc_dmat4_translate(a[0], a[1], a[2]);
    else if (name_is(name, len, "scale") && n == 3)
        *out = sc_dmat4_scale(a[0], a[1], a[2]);
    else if (name_is(name, len, "scale") && n == 1)
        *out = sc_dmat4_scale(a[0], a[0], a[0]);
    else if (name_is(name, len, "rotate") && n == 4 && (a[1] != 0.0 || a[2] != 0.0 || a[3] != 0.0))
        *out = sc_dmat4_rotate(a[0], a[1], a[2], a[3]);
    else if (name_is(name, len, "identity") && n == 0)
        *out = sc_dmat4_identity();
    else
        return -1;
    return 0;
}

static int factor_error(const char *start, const char *p, char *err, size_t errsize)
{
    int len = (int)strcspn(p, "*");
    snprintf(err, errsize,
             "matrix: '%.*s' at column %d: expected translate(x,y,z), scale(x,y,z), scale(s), "
             "rotate(deg,x,y,z) with a nonzero axis, or identity()",
             len, p, (int)(p - start) + 1);
    return -1;
}

static int parse_chain(const char *spec, sc_dmat4 *out, char *err, size_t errsize)
{
    sc_dmat4 product = sc_dmat4_identity();
    const char *p = skip_space(spec);
    for (;;) {
        const char *name = p, *q;
        double args[MAX_ARGS];
        sc_dmat4 factor;
        while (isalpha((unsigned char)*p))
            p++;
        size_t len = (size_t)(p - name);
        q = skip_space(p);
        int n = -1;
        if (*q == '(') {
            q++;
            n = parse_numbers(&q, ')', args, 4);
        }
        if (n < 0 || make_factor(name, len, args, n, &factor) < 0)
            return factor_error(spec, name, err, errsize);
        product = sc_dmat4_mul(product, factor);
        p = skip_space(q);
        if (*p == '\0')
            break;
        if (*p != '*') {
            snprintf(err, errsize, "matrix: '%s' at column %d: expected '*' between factors", p,
                     (int)(p - spec) + 1);
            return -1;
        }
        p = skip_space(p + 1);
    }
    *out = product;
    return 0;
}

int sc_transform_parse(const char *spec, sc_dmat4 *out, char *err, size_t errsize)
{
    const char *p = skip_space(spec);
    if (isalpha((unsigned char)*p))
        return parse_chain(spec, out, err, errsize);
    sc_dmat4 m;
    if (parse_numbers(&p, '\0', m.m, 16) != 16) {
        snprintf(err, errsize,
                 "matrix: '%s': expected 16 finite numbers separated by commas (column-major) "
                 "or a chain like scale(1,2,3)*rotate(30,0,1,0)*translate(1,2,3)",
                 spec);
        return -1;
    }
    *out = m;
    return 0;
}

/* transform.h: M₃ is orthogonal when every entry of M₃ᵀM₃ − I is within 32ε. */
static int is_orthogonal(const sc_dmat3 *m3)
{
    sc_dmat3 gram = sc_dmat3_mul(sc_dmat3_transpose(*m3), *m3);
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++)
            if (!(fabs(gram.m[3 * c + r] - (r == c)) <= 32.0 * 0x1p-53))
                return 0;
    return 1;
}

int sc_normal_matrix(const sc_dmat4 *m, sc_dmat3 *out, int *rigid)
{
    sc_dmat3 m3;
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++)
            m3.m[3 * c + r] = m->m[4 * c + r];
    *rigid = is_orthogonal(&m3);
    if (*rigid) {
        *out = m3;
        return 0;
    }
    return sc_dmat3_normal_matrix(m, out);
}
