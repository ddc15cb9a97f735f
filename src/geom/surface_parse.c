/* The surface spec parser (shadecalc/surface.h): "sphere r=1", "torus R=1 r=0.3", "plane",
 * "cylinder r=1 h=2", "user x=EXPR y=EXPR z=EXPR". */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/geom_internal.h"

/* A built-in: its name, its parameters' names and defaults. */
typedef struct {
    const char *name;
    surface_kind kind;
    const char *keys[2];
    double defaults[2];
    int closed_u, closed_v;
} builtin_surface;

static const builtin_surface builtins[] = {
    {"sphere", SURFACE_SPHERE, {"r", NULL}, {1.0, 0.0}, 1, 0},
    {"torus", SURFACE_TORUS, {"R", "r"}, {1.0, 0.3}, 1, 1},
    {"plane", SURFACE_PLANE, {"size", NULL}, {2.0, 0.0}, 0, 0},
    {"cylinder", SURFACE_CYLINDER, {"r", "h"}, {1.0, 2.0}, 1, 0},
};
enum { N_BUILTINS = (int)(sizeof builtins / sizeof builtins[0]) };

static const char *skip_space(const char *p)
{
    while (isspace((unsigned char)*p))
        p++;
    return p;
}

static size_t word_length(const char *p)
{
    size_t n = 0;
    while (p[n] && !isspace((unsigned char)p[n]))
        n++;
    return n;
}

/* The whole of src[0 .. n) as a finite number > 0. */
static int parse_positive(const char *src, size_t n, double *out)
{
    char number[64], *end;
    if (n == 0 || n >= sizeof number)
        return -1;
    memcpy(number, src, n);
    number[n] = '\0';
    *out = strtod(number, &end);
    return *end == '\0' && isfinite(*out) && *out > 0.0 ? 0 : -1;
}

/* The index of b's parameter named word[0 .. n), or -1. */
static int parameter_index(const builtin_surface *b, const char *word, size_t n)
{
    for (int k = 0; k < 2 && b->keys[k]; k++)
        if (strlen(b->keys[k]) == n && strncmp(word, b->keys[k], n) == 0)
            return k;
    return -1;
}

/* The parameter `word` (len bytes, "KEY=NUMBER") of built-in b into values[]. */
static int parse_parameter(const builtin_surface *b, const char *word, size_t len, double *values,
                           int *seen, char *err, size_t errsize)
{
    const char *eq = memchr(word, '=', len);
    int k = eq ? parameter_index(b, word, (size_t)(eq - word)) : -1;
    if (k < 0) {
        snprintf(err, errsize, "surface %s: unknown parameter '%.*s' (expected %s=NUMBER%s%s%s)",
                 b->name, (int)len, word, b->keys[0], b->keys[1] ? ", " : "",
                 b->keys[1] ? b->keys[1] : "", b->keys[1] ? "=NUMBER" : "");
        return -1;
    }
    if (seen[k]) {
        snprintf(err, errsize, "surface %s: '%s' given twice", b->name, b->keys[k]);
        return -1;
    }
    if (parse_positive(eq + 1, len - (size_t)(eq - word) - 1, &values[k]) < 0) {
        snprintf(err, errsize, "surface %s: '%.*s': expected a finite number > 0", b->name,
                 (int)len, word);
        return -1;
    }
    seen[k] = 1;
    return 0;
}

static sc_surface *parse_builtin(const builtin_surface *b, const char *rest, char *err,
                                 size_t errsize)
{
    double values[2] = {b->defaults[0], b->defaults[1]};
    int seen[2] = {0, 0};
    for (const char *p = skip_space(rest); *p; p = skip_space(p)) {
        size_t len = word_length(p);
        if (parse_parameter(b, p, len, values, seen, err, errsize) < 0)
            return NULL;
        p += len;
    }
    if (b->kind == SURFACE_TORUS && !(values[1] < values[0])) {
        snprintf(err, errsize, "surface torus: r=%g must be below R=%g (a ring torus)", values[1],
                 values[0]);
        return NULL;
    }
    sc_surface *s = calloc(1, sizeof *s);
    if (s == NULL) {
        snprintf(err, errsize, "surface: out of memory");
        return NULL;
    }
    *s = (sc_surface){b->kind, values[0], values[1], {NULL, NULL, NULL}, b->closed_u, b->closed_v};
    return s;
}

/* ---- user x=EXPR y=EXPR z=EXPR ---- */

/* Whether p (inside spec) starts a key "x=", "y=" or "z=" at the start of a word. */
static int is_key(const char *spec, const char *p)
{
    return (p == spec || isspace((unsigned char)p[-1])) && (*p == 'x' || *p == 'y' || *p == 'z') &&
           p[1] == '=';
}

static int compile_coordinate(sc_surface *s, int k, const char *src, size_t len, char *err,
                              size_t errsize)
{
    static const sc_expr_input uv[2] = {{"u", SC_FLOAT}, {"v", SC_FLOAT}};
    char *text = malloc(len + 1);
    sc_expr_error e = {0, ""};
    if (text == NULL) {
        snprintf(err, errsize, "surface: out of memory");
        return -1;
    }
    memcpy(text, src, len);
    text[len] = '\0';
    s->xyz[k] = sc_expr_compile(text, uv, 2, &e);
    if (s->xyz[k] == NULL)
        snprintf(err, errsize, "surface user: %c=%s: column %d: %s", "xyz"[k], text, e.column,
                 e.message);
    else if (sc_expr_result_type(s->xyz[k]) != SC_FLOAT)
        snprintf(err, errsize, "surface user: %c=%s: is %s, expected float", "xyz"[k], text,
                 sc_type_name(sc_expr_result_type(s->xyz[k])));
    free(text);
    return s->xyz[k] && sc_expr_result_type(s->xyz[k]) == SC_FLOAT ? 0 : -1;
}

/* Each key's expression runs from after "K=" to the next key (trailing space dropped). */
static int parse_user_keys(sc_surface *s, const char *spec, const char *p, char *err,
                           size_t errsize)
{
    p = skip_space(p);
    while (*p) {
        if (!is_key(spec, p)) {
            snprintf(err, errsize, "surface user: '%.*s': expected x=EXPR y=EXPR z=EXPR",
                     (int)word_length(p), p);
            return -1;
        }
        int k = *p - 'x';
        const char *start = p + 2, *end = start;
        while (*end && !is_key(spec, end))
            end++;
        p = end;
        while (end > start && isspace((unsigned char)end[-1]))
            end--;
        if (s->xyz[k]) {
            snprintf(err, errsize, "surface user: '%c=' given twice", "xyz"[k]);
            return -1;
        }
        if (compile_coordinate(s, k, start, (size_t)(end - start), err, errsize) < 0)
            return -1;
    }
    for (int k = 0; k < 3; k++)
        if (s->xyz[k] == NULL) {
            snprintf(err, errsize, "surface user: missing %c=EXPR", "xyz"[k]);
            return -1;
        }
    return 0;
}

static sc_surface *parse_user(const char *spec, const char *rest, char *err, size_t errsize)
{
    sc_surface *s = calloc(1, sizeof *s);
    if (s == NULL) {
        snprintf(err, errsize, "surface: out of memory");
        return NULL;
    }
    s->kind = SURFACE_USER;
    if (parse_user_keys(s, spec, rest, err, errsize) < 0) {
        sc_surface_free(s);
        return NULL;
    }
    sc_surface_detect_closed(s);
    return s;
}

sc_surface *sc_surface_parse(const char *spec, char *err, size_t errsize)
{
    const char *p = skip_space(spec);
    size_t len = word_length(p);
    for (int i = 0; i < N_BUILTINS; i++)
        if (strlen(builtins[i].name) == len && strncmp(p, builtins[i].name, len) == 0)
            return parse_builtin(&builtins[i], p + len, err, errsize);
    if (len == 4 && strncmp(p, "user", 4) == 0)
        return parse_user(spec, p + len, err, errsize);
    snprintf(err, errsize,
             "surface '%.*s': unknown (expected sphere, torus, plane, cylinder or user)", (int)len,
             p);
    return NULL;
}
