/* The .brdf file format of BRDF Explorer (shadecalc/brdf_file.h): the header line, the
 * sections, the parameter lines. Stricter than BRDF Explorer, which skips what it does not
 * understand: anything unexpected is an error naming the line. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brdf/brdf_file_internal.h"

enum { MAX_TOKENS = 8, MAX_TOKEN = 64 };

typedef enum { OUTSIDE, PARAMETERS, SHADER, IGNORED } section;
static const char *const section_names[] = {"", "parameters", "shader", "isFunc"};

typedef struct {
    sc_brdf_file *f;
    const char *name;
    int line;
    section in;
    int opened_at; /* line of the open section's ::begin */
    int seen[4];   /* line of each section's ::begin (0: none yet) */
    char *err;
    size_t size;
} split_state;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static int
fail(const split_state *s, const char *fmt, ...)
{
    int n = snprintf(s->err, s->size, "%s:%d: ", s->name, s->line);
    va_list ap;
    va_start(ap, fmt);
    if (n >= 0 && (size_t)n < s->size)
        vsnprintf(s->err + n, s->size - (size_t)n, fmt, ap);
    va_end(ap);
    return -1;
}

/* Splits a line into blank-separated tokens, up to a comment (`#` or `//`); -1 if a token is
 * too long or there are too many. */
static int tokenize(const char *line, char tok[MAX_TOKENS][MAX_TOKEN], int *n)
{
    *n = 0;
    for (const char *p = line;;) {
        p += strspn(p, " \t");
        if (*p == '\0' || *p == '#' || (p[0] == '/' && p[1] == '/'))
            return 0;
        size_t len = strcspn(p, " \t");
        if (len >= MAX_TOKEN || *n == MAX_TOKENS)
            return -1;
        memcpy(tok[*n], p, len);
        tok[(*n)++][len] = '\0';
        p += len;
    }
}

static int parse_finite(const char *s, double *out)
{
    char *end;
    *out = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*out) ? 0 : -1;
}

static int is_identifier(const char *s)
{
    if (!isalpha((unsigned char)s[0]) && s[0] != '_')
        return 0;
    for (; *s; s++)
        if (!isalnum((unsigned char)*s) && *s != '_')
            return 0;
    return 1;
}

static int parse_bool(const char *s, double *out)
{
    int on = strcmp(s, "1") == 0 || strcmp(s, "true") == 0;
    if (!on && strcmp(s, "0") != 0 && strcmp(s, "false") != 0)
        return -1;
    *out = on;
    return 0;
}

/* The values after the name: MIN MAX DEFAULT (float), 0|1 (bool), R G B (color). */
static int parameter_values(const split_state *s, sc_brdf_param *prm, char tok[][MAX_TOKEN], int n)
{
    static const int counts[] = {5, 3, 5};
    static const char *const forms[] = {"float NAME MIN MAX DEFAULT", "bool NAME 0|1",
                                        "color NAME R G B"};
    if (n != counts[prm->type])
        return fail(s, "expected '%s' (%d values after the name, not %d)", forms[prm->type],
                    counts[prm->type] - 2, n - 2);
    if (prm->type == SC_BRDF_PARAM_BOOL) {
        if (parse_bool(tok[2], &prm->def[0]) < 0)
            return fail(s, "bool %s: '%s' is not 0 or 1", prm->name, tok[2]);
        return 0;
    }
    double x[3];
    for (int i = 0; i < 3; i++)
        if (parse_finite(tok[2 + i], &x[i]) < 0)
            return fail(s, "%s %s: '%s' is not a finite number", tok[0], prm->name, tok[2 + i]);
    if (prm->type == SC_BRDF_PARAM_COLOR) {
        memcpy(prm->def, x, sizeof x);
        return 0;
    }
    if (!(x[0] <= x[1]))
        return fail(s, "float %s: MIN %s is above MAX %s", prm->name, tok[2], tok[3]);
    if (!(x[0] <= x[2] && x[2] <= x[1]))
        return fail(s, "float %s: the default %s is outside MIN..MAX %s..%s", prm->name, tok[4],
                    tok[2], tok[3]);
    prm->min = x[0];
    prm->max = x[1];
    prm->def[0] = x[2];
    return 0;
}

static int parameter_line(split_state *s, const char *line)
{
    static const char *const types[] = {"float", "bool", "color", NULL};
    char tok[MAX_TOKENS][MAX_TOKEN];
    int n;
    if (tokenize(line, tok, &n) < 0)
        return fail(s, "not a parameter line (a token over %d bytes, or over %d tokens)",
                    MAX_TOKEN - 1, MAX_TOKENS);
    if (n == 0)
        return 0;
    int type = 0;
    while (types[type] && strcmp(types[type], tok[0]) != 0)
        type++;
    if (!types[type])
        return fail(s, "unknown parameter type '%s' (expected float, bool or color)", tok[0]);
    if (n < 2 || !is_identifier(tok[1]))
        return fail(s, "%s: expected a GLSL name after the type", tok[0]);
    sc_brdf_file *f = s->f;
    for (int i = 0; i < f->n_params; i++)
        if (strcmp(f->params[i].name, tok[1]) == 0)
            return fail(s, "parameter '%s' is already declared on line %d", tok[1],
                        f->params[i].line);
    if (f->n_params == SC_BRDF_FILE_MAX_PARAMS)
        return fail(s, "too many parameters (at most %d)", SC_BRDF_FILE_MAX_PARAMS);
    sc_brdf_param *prm = &f->params[f->n_params];
    memset(prm, 0, sizeof *prm);
    memcpy(prm->name, tok[1], strlen(tok[1]) + 1);
    prm->type = (sc_brdf_param_type)type;
    prm->line = s->line;
    prm->offset = f->n_values;
    if (parameter_values(s, prm, tok, n) < 0)
        return -1;
    f->n_params++;
    f->n_values += prm->type == SC_BRDF_PARAM_COLOR ? 3 : 1;
    return 0;
}

static section section_named(const char *word)
{
    for (int i = PARAMETERS; i <= IGNORED; i++)
        if (strcmp(word, section_names[i]) == 0)
            return (section)i;
    return OUTSIDE;
}

/* `::begin NAME` or `::end NAME`. */
static int section_line(split_state *s, const char *line)
{
    char tok[MAX_TOKENS][MAX_TOKEN];
    int n;
    if (tokenize(line, tok, &n) < 0 || n != 2)
        return fail(s, "expected '::begin NAME' or '::end NAME'");
    section named = section_named(tok[1]);
    if (strcmp(tok[0], "::begin") == 0) {
        if (s->in != OUTSIDE)
            return fail(s, "::begin %s inside the '%s' section opened on line %d", tok[1],
                        section_names[s->in], s->opened_at);
        if (named == OUTSIDE)
            return fail(s, "unknown section '%s' (expected parameters or shader)", tok[1]);
        if (s->seen[named])
            return fail(s, "a second '%s' section (the first opens on line %d)", tok[1],
                        s->seen[named]);
        s->in = named;
        s->opened_at = s->seen[named] = s->line;
        return 0;
    }
    if (strcmp(tok[0], "::end") != 0)
        return fail(s, "unknown directive '%s' (expected ::begin or ::end)", tok[0]);
    if (s->in == OUTSIDE)
        return fail(s, "::end %s outside any section", tok[1]);
    if (named != s->in)
        return fail(s, "::end %s does not close the '%s' section opened on line %d", tok[1],
                    section_names[s->in], s->opened_at);
    s->in = OUTSIDE;
    return 0;
}

/* The first line: `analytic` (BRDF Explorer's other types are measured data). */
static int header_line(split_state *s, const char *line)
{
    char tok[MAX_TOKENS][MAX_TOKEN];
    int n;
    if (tokenize(line, tok, &n) == 0 && n >= 1 && strcmp(tok[0], "analytic") == 0)
        return 0;
    return fail(s, "the first line must be 'analytic' (a BRDF Explorer analytic BRDF)");
}

/* One line of the file; shader lines are copied to *out, others leave it empty. */
static int split_line(split_state *s, const char *line, char **out)
{
    const char *text = line + strspn(line, " \t");
    if (s->line == 1)
        return header_line(s, line);
    if (text[0] == '#') /* a comment everywhere, the shader included, as in BRDF Explorer */
        return 0;
    if (strncmp(text, "::", 2) == 0)
        return section_line(s, text);
    switch (s->in) {
    case PARAMETERS: return parameter_line(s, text);
    case SHADER: *out += sprintf(*out, "%s", line); return 0;
    case IGNORED: return 0;
    default:
        if (text[0] == '\0' || (text[0] == '/' && text[1] == '/'))
            return 0;
        return fail(s, "text outside a section (sections: ::begin parameters, ::begin shader)");
    }
}

int sc_brdf_file_split(const char *text, sc_brdf_file *f, char **glsl, int *shader_line, char *err,
                       size_t size)
{
    split_state s = {.f = f, .name = f->name, .err = err, .size = size};
    size_t len = strlen(text);
    char *out = malloc(len + 2), *line = malloc(len + 1);
    *glsl = out;
    if (!out || !line) {
        free(line);
        snprintf(err, size, "%s: out of memory", f->name);
        return -1;
    }
    *out = '\0';
    int status = 0;
    for (const char *p = text; status == 0 && (*p || s.line == 0);) {
        size_t n = strcspn(p, "\n");
        memcpy(line, p, n);
        line[n - (n > 0 && p[n - 1] == '\r')] = '\0';
        s.line++;
        status = split_line(&s, line, &out);
        *out++ = '\n';
        *out = '\0';
        p += n + (p[n] == '\n');
    }
    free(line);
    if (status == 0 && s.in != OUTSIDE) {
        s.line = s.opened_at;
        status = fail(&s, "the '%s' section opened here has no ::end %s", section_names[s.in],
                      section_names[s.in]);
    }
    if (status == 0 && !s.seen[SHADER]) {
        s.line = s.line > 0 ? s.line : 1;
        status = fail(&s, "no '::begin shader' section (the GLSL defining vec3 BRDF(vec3 L, "
                          "vec3 V, vec3 N, vec3 X, vec3 Y))");
    }
    *shader_line = s.seen[SHADER];
    return status;
}
