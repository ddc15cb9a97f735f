/* Parsing of light and model specs (shadecalc/scene.h): "KIND key=value ...", driven by one
 * table of keys per spec type. */
#include "shadecalc/scene.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/brdf_file.h"
#include "util/text.h"

enum { MAX_ITEM = 256, MAX_WRITES = 40, SHOWN = 80 };

typedef enum { V_NUMBER, V_COLOUR, V_VECTOR, V_ENUM, V_FLAG, V_INT } value_kind;

/* A key: where its value goes (an offset into sc_light or sc_model), its type, and which kinds
 * accept it (bit k for kind k). */
typedef struct {
    const char *key;
    value_kind kind;
    size_t offset;
    unsigned kinds;
    const char *const *names; /* V_ENUM: the accepted words, index = value */
    const char *help;         /* what it accepts, for messages */
} key_def;

/* ---- values ---- */

static int parse_numbers(const char *s, double *out, int n)
{
    const char *p = s;
    for (int i = 0; i < n; i++) {
        char *end;
        out[i] = strtod(p, &end);
        if (end == p || !isfinite(out[i]))
            return -1;
        p = end;
        if (i + 1 < n) {
            if (*p != ',')
                return -1;
            p++;
        }
    }
    return *p == '\0' ? 0 : -1;
}

int sc_parse_vector3(const char *s, double out[3]) { return parse_numbers(s, out, 3); }

int sc_parse_colour(const char *s, double out[3])
{
    if (parse_numbers(s, out, 1) == 0) {
        out[1] = out[2] = out[0];
        return 0;
    }
    return parse_numbers(s, out, 3);
}

static int word_index(const char *const *names, const char *word)
{
    for (int i = 0; names[i]; i++)
        if (strcmp(names[i], word) == 0)
            return i;
    return -1;
}

/* The accepted words, "a|b|c", into buf. */
static const char *word_list(const char *const *names, char *buf, size_t size)
{
    buf[0] = '\0';
    for (int i = 0; names[i]; i++) {
        size_t len = strlen(buf);
        snprintf(buf + len, size - len, "%s%s", i ? "|" : "", names[i]);
    }
    return buf;
}

static int fail(char *err, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, size, fmt, ap);
    va_end(ap);
    return -1;
}

/* Stores `value` into the field of `k` in `target`. */
static int store(const key_def *k, void *target, const char *value, const char *what, char *err,
                 size_t size)
{
    char *field = (char *)target + k->offset;
    double d[3];
    int ok = 0;
    switch (k->kind) {
    case V_NUMBER:
        ok = parse_numbers(value, d, 1) == 0;
        if (ok)
            memcpy(field, d, sizeof(double));
        break;
    case V_INT: {
        int i = 0;
        ok = parse_numbers(value, d, 1) == 0 && d[0] == floor(d[0]) && fabs(d[0]) <= 1e9;
        if (ok)
            i = (int)d[0];
        memcpy(field, &i, sizeof i);
        break;
    }
    case V_COLOUR:
    case V_VECTOR:
        ok = (k->kind == V_COLOUR ? sc_parse_colour(value, d) : sc_parse_vector3(value, d)) == 0;
        if (ok)
            memcpy(field, d, 3 * sizeof(double));
        break;
    case V_FLAG:
        ok = strcmp(value, "0") == 0 || strcmp(value, "1") == 0 || strcmp(value, "on") == 0 ||
             strcmp(value, "off") == 0;
        if (ok) {
            int on = value[0] == '1' || strcmp(value, "on") == 0;
            memcpy(field, &on, sizeof on);
        }
        break;
    case V_ENUM: {
        int i = word_index(k->names, value);
        ok = i >= 0;
        if (ok)
            memcpy(field, &i, sizeof i);
        break;
    }
    }
    if (ok)
        return 0;
    char words[160], shown[SHOWN];
    const char *near = k->kind == V_ENUM ? sc_suggest_among(value, k->names) : NULL;
    return fail(err, size, "%s: %s=%s: expected %s%s%s%s", what, k->key,
                sc_escape(value, shown, sizeof shown),
                k->kind == V_ENUM ? word_list(k->names, words, sizeof words) : k->help,
                near ? " (did you mean '" : "", near ? near : "", near ? "'?)" : "");
}

/* ---- items ---- */

typedef struct {
    char key[MAX_ITEM], value[MAX_ITEM];
} item;

/* Splits "key=value"; -1 if it has no '=' or is too long. */
static int split_item(const char *tok, size_t len, item *out)
{
    const char *eq = memchr(tok, '=', len);
    if (!eq || eq == tok || len >= MAX_ITEM)
        return -1;
    snprintf(out->key, sizeof out->key, "%.*s", (int)(eq - tok), tok);
    snprintf(out->value, sizeof out->value, "%.*s", (int)(len - (size_t)(eq - tok) - 1), eq + 1);
    return 0;
}

/* Calls `apply` for each key=value item after the kind; stops at the first error. */
static int for_each_item(const char *rest, const char *what, char *err, size_t size,
                         int (*apply)(void *ctx, const item *it), void *ctx)
{
    const char *p = rest;
    for (;;) {
        p += strspn(p, " \t");
        if (*p == '\0')
            return 0;
        size_t len = strcspn(p, " \t");
        item it;
        char shown[SHOWN];
        if (split_item(p, len, &it) < 0)
            return fail(err, size, "%s: '%s': expected key=value", what,
                        sc_escape_n(p, len, shown, sizeof shown));
        if (apply(ctx, &it) < 0)
            return -1;
        p += len;
    }
}

/* The kind word at the start of spec, into buf; the rest in *rest. */
static int kind_word(const char *spec, char *buf, size_t size, const char **rest)
{
    const char *p = spec + strspn(spec, " \t");
    size_t len = strcspn(p, " \t");
    if (len == 0 || len >= size)
        return -1;
    memcpy(buf, p, len);
    buf[len] = '\0';
    *rest = p + len;
    return 0;
}

static const key_def *find_key(const key_def *keys, const char *key)
{
    for (; keys->key; keys++)
        if (strcmp(keys->key, key) == 0)
            return keys;
    return NULL;
}

/* Another name a user may reach for, and the key it means. */
static const struct {
    const char *alias, *key;
} synonyms[] = {
    {"shininess", "m"},  {"exponent", "m"},    {"exponent", "exp"},    {"roughness", "alpha"},
    {"intensity", "I"},  {"position", "pos"},  {"direction", "dir"},   {"attenuation", "atten"},
    {"color", "diff"},   {"colour", "diff"},   {"ambient", "amb"},     {"specular", "spec"},
    {"diffuse", "diff"}, {"falloff", "exp"},   {"fresnel", "F"},       {"ndf", "D"},
    {"radiance", "L"},   {"centre", "center"}, {"position", "center"}, {"nodes", "samples"},
};

/* The key of `keys` (one that `kind` accepts) closest to the unknown `key`, by name or by a
 * synonym's name, or NULL. */
static const char *closest_key(const key_def *keys, unsigned kind, const char *key)
{
    enum { N_SYNONYMS = sizeof synonyms / sizeof synonyms[0] };
    const char *meaning[N_SYNONYMS] = {NULL};
    sc_suggestion s;
    sc_suggest_init(&s, key);
    for (size_t i = 0; i < N_SYNONYMS; i++) {
        const key_def *k = find_key(keys, synonyms[i].key);
        if (k && (k->kinds & kind) && strcmp(key, synonyms[i].alias) == 0)
            return k->key;
        if (k && (k->kinds & kind)) {
            meaning[i] = k->key;
            sc_suggest_consider(&s, synonyms[i].alias);
        }
    }
    for (const key_def *k = keys; k->key; k++)
        if (k->kinds & kind)
            sc_suggest_consider(&s, k->key);
    const char *best = sc_suggest_best(&s);
    for (size_t i = 0; best && i < N_SYNONYMS; i++)
        if (best == synonyms[i].alias && meaning[i])
            return meaning[i];
    return best;
}

/* "unknown key 'K'" with what it may have meant; -1. */
static int fail_key(char *err, size_t size, const char *what, const key_def *keys, unsigned kind,
                    const char *key)
{
    char shown[SHOWN];
    const key_def *other = find_key(keys, key);
    const char *near = other ? NULL : closest_key(keys, kind, key);
    if (other)
        return fail(err, size, "%s: unknown key '%s' (a key of other kinds)", what, key);
    return fail(err, size, "%s: unknown key '%s'%s%s%s", what, sc_escape(key, shown, sizeof shown),
                near ? " (did you mean '" : "", near ? near : "", near ? "='?)" : "");
}

/* "unknown kind 'K' (a|b|c)" with the closest kind first; -1. */
static int fail_kind(char *err, size_t size, const char *what, const char *const *kinds,
                     const char *kind)
{
    char shown[SHOWN], words[160];
    const char *near = sc_suggest_among(kind, kinds);
    return fail(err, size, "%s: unknown kind '%s' (%s%s%s%s)", what,
                sc_escape(kind, shown, sizeof shown), near ? "did you mean '" : "",
                near ? near : "", near ? "'? " : "", word_list(kinds, words, sizeof words));
}

/* The fields a spec has set, to refuse a second value for one (`m=32 m=64`, `alpha=` with
 * `ay=`, `inner=` with `theta=`). */
typedef struct {
    struct {
        size_t offset;
        const char *key;
    } w[MAX_WRITES];
    int n;
} write_log;

/* Records that `key` sets the field at `offset`; -1 with the message if one already was. */
static int log_write(write_log *log, size_t offset, const char *key, const char *what, char *err,
                     size_t size)
{
    for (int i = 0; i < log->n; i++) {
        if (log->w[i].offset != offset)
            continue;
        if (strcmp(log->w[i].key, key) == 0)
            return fail(err, size, "%s: %s= is given twice", what, key);
        return fail(err, size, "%s: %s= contradicts %s= (both set the same parameter)", what, key,
                    log->w[i].key);
    }
    if (log->n < MAX_WRITES) {
        log->w[log->n].offset = offset;
        log->w[log->n++].key = key;
    }
    return 0;
}

/* A key that has an effect only for some values of another (sc= only with atten=clq). */
typedef struct {
    const char *key;
    size_t selector; /* offset of the int field that decides */
    unsigned values; /* bit v: the key has an effect when that field is v */
    const char *selector_key;
    const char *const *names; /* the selector's values, index = value */
} key_need;

/* Appends "K= has no effect with S=V" to warn for each key of the log that `needs` says the
 * spec's choices ignore; 1 if any, else 0. */
static int ignored_keys(const write_log *log, const key_need *needs, size_t n_needs,
                        const void *target, const char *what, char *warn, size_t size)
{
    int any = 0;
    for (int i = 0; i < log->n; i++)
        for (size_t j = 0; j < n_needs; j++) {
            const key_need *k = &needs[j];
            int value;
            memcpy(&value, (const char *)target + k->selector, sizeof value);
            if (strcmp(k->key, log->w[i].key) != 0 || (k->values >> value & 1u))
                continue;
            size_t len = strlen(warn);
            snprintf(warn + len, size - len, "%s%s: %s= has no effect with %s=%s", any ? "; " : "",
                     what, k->key, k->selector_key, k->names[value]);
            any = 1;
        }
    return any;
}

/* ---- lights ---- */

static const char *const light_kinds[] = {"directional", "point", "spot", "sphere",
                                          "tube",        "disk",  "rect", NULL};
static const char *const atten_names[] = {"none",  "inverse-square", "clq", "window",
                                          "pixar", "windowed",       NULL};
static const char *const spot_names[] = {"opengl", "directx", "smoothstep", NULL};
static const char *const method_names[] = {"reference", "representative-point", "point", "ltc",
                                           NULL};

/* What a light spec sets: the light, and a rect's size form (normal= with width=, height=,
 * tangent=), which sc_light_parse turns into its edges. */
typedef struct {
    sc_light light;
    double width, height, tangent[3];
} light_spec;

#define L(field) offsetof(light_spec, light.field)
#define S(field) offsetof(light_spec, field)
enum { DIR = 1, PNT = 2, SPT = 4, SPH = 8, TUB = 16, DSK = 32, RCT = 64 };
enum { POINTLIKE = DIR | PNT | SPT, AREA = SPH | TUB | DSK | RCT, ANY = POINTLIKE | AREA };
/* clang-format off */
static const key_def light_keys[] = {
    {"I", V_COLOUR, L(intensity), POINTLIKE, NULL, "a colour (1 or 3 numbers)"},
    {"E", V_COLOUR, L(intensity), POINTLIKE, NULL, "a colour (1 or 3 numbers)"},
    {"L", V_COLOUR, L(intensity), AREA, NULL, "a colour (1 or 3 numbers)"},
    {"amb", V_COLOUR, L(ambient), ANY, NULL, "a colour (1 or 3 numbers)"},
    {"diff", V_COLOUR, L(diffuse), POINTLIKE, NULL, "a colour (1 or 3 numbers)"},
    {"spec", V_COLOUR, L(specular), POINTLIKE, NULL, "a colour (1 or 3 numbers)"},
    {"dir", V_VECTOR, L(dir), DIR | SPT, NULL, "a vector X,Y,Z"},
    {"pos", V_VECTOR, L(pos), PNT | SPT, NULL, "a point X,Y,Z"},
    {"atten", V_ENUM, L(atten.kind), PNT | SPT, atten_names, NULL},
    {"sc", V_NUMBER, L(atten.sc), PNT | SPT, NULL, "a number"},
    {"sl", V_NUMBER, L(atten.sl), PNT | SPT, NULL, "a number"},
    {"sq", V_NUMBER, L(atten.sq), PNT | SPT, NULL, "a number"},
    {"rstart", V_NUMBER, L(atten.r_start), PNT | SPT, NULL, "a number"},
    {"rend", V_NUMBER, L(atten.r_end), PNT | SPT, NULL, "a number"},
    {"fmax", V_NUMBER, L(atten.f_max), PNT | SPT, NULL, "a number"},
    {"fc", V_NUMBER, L(atten.f_c), PNT | SPT, NULL, "a number"},
    {"rc", V_NUMBER, L(atten.r_c), PNT | SPT, NULL, "a number"},
    {"se", V_NUMBER, L(atten.s_e), PNT | SPT, NULL, "a number"},
    {"rmax", V_NUMBER, L(atten.r_max), PNT | SPT, NULL, "a number"},
    {"range", V_NUMBER, L(range), PNT | SPT, NULL, "a number"},
    {"spot", V_ENUM, L(spot.kind), SPT, spot_names, NULL},
    {"cutoff", V_NUMBER, L(spot.cutoff), SPT, NULL, "an angle in degrees"},
    {"exp", V_NUMBER, L(spot.exponent), SPT, NULL, "a number"},
    {"inner", V_NUMBER, L(spot.inner), SPT, NULL, "a half-angle in degrees"},
    {"outer", V_NUMBER, L(spot.outer), SPT, NULL, "a half-angle in degrees"},
    {"theta", V_NUMBER, L(spot.inner), SPT, NULL, "a full cone angle in degrees"},
    {"phi", V_NUMBER, L(spot.outer), SPT, NULL, "a full cone angle in degrees"},
    {"center", V_VECTOR, L(pos), SPH | DSK | RCT, NULL, "a point X,Y,Z"},
    {"radius", V_NUMBER, L(area.radius), SPH | TUB | DSK, NULL, "a number"},
    {"p0", V_VECTOR, L(area.p0), TUB, NULL, "a point X,Y,Z"},
    {"p1", V_VECTOR, L(area.p1), TUB, NULL, "a point X,Y,Z"},
    {"normal", V_VECTOR, L(area.normal), DSK | RCT, NULL, "a vector X,Y,Z"},
    {"edge1", V_VECTOR, L(area.edge1), RCT, NULL, "a vector X,Y,Z"},
    {"edge2", V_VECTOR, L(area.edge2), RCT, NULL, "a vector X,Y,Z"},
    {"width", V_NUMBER, S(width), RCT, NULL, "a number"},
    {"height", V_NUMBER, S(height), RCT, NULL, "a number"},
    {"tangent", V_VECTOR, S(tangent), RCT, NULL, "a vector X,Y,Z"},
    {"two-sided", V_FLAG, L(area.two_sided), DSK | RCT, NULL, "0 or 1"},
    {"method", V_ENUM, L(area.method), AREA, method_names, NULL},
    {"samples", V_INT, L(area.samples), AREA, NULL, "an integer"},
    {"tol", V_NUMBER, L(area.tol), AREA, NULL, "a number"},
    {NULL, V_NUMBER, 0, 0, NULL, NULL},
};
/* clang-format on */

static const char *const flag_names[] = {"0", "1", NULL};
enum {
    CLQ = 1u << SC_ATTEN_CLQ,
    WIN = 1u << SC_ATTEN_WINDOW,
    PIX = 1u << SC_ATTEN_PIXAR,
    WDW = 1u << SC_ATTEN_WINDOWED,
    GL = 1u << SC_SPOT_OPENGL,
    DX = 1u << SC_SPOT_DIRECTX,
    SMOOTH = 1u << SC_SPOT_SMOOTHSTEP,
    REF = 1u << SC_AREA_REFERENCE
};
static const key_need light_needs[] = {
    {"sc", L(atten.kind), CLQ, "atten", atten_names},
    {"sl", L(atten.kind), CLQ, "atten", atten_names},
    {"sq", L(atten.kind), CLQ, "atten", atten_names},
    {"rstart", L(atten.kind), WIN, "atten", atten_names},
    {"rend", L(atten.kind), WIN, "atten", atten_names},
    {"fmax", L(atten.kind), PIX, "atten", atten_names},
    {"fc", L(atten.kind), PIX, "atten", atten_names},
    {"rc", L(atten.kind), PIX, "atten", atten_names},
    {"se", L(atten.kind), PIX, "atten", atten_names},
    {"rmax", L(atten.kind), WDW, "atten", atten_names},
    {"cutoff", L(spot.kind), GL, "spot", spot_names},
    {"exp", L(spot.kind), GL | DX, "spot", spot_names},
    {"inner", L(spot.kind), DX | SMOOTH, "spot", spot_names},
    {"outer", L(spot.kind), DX | SMOOTH, "spot", spot_names},
    {"theta", L(spot.kind), DX | SMOOTH, "spot", spot_names},
    {"phi", L(spot.kind), DX | SMOOTH, "spot", spot_names},
    {"samples", L(area.method), REF, "method", method_names},
    {"tol", L(area.method), REF, "method", method_names},
};

typedef struct {
    light_spec spec;
    char what[40];
    write_log log;
    char *err;
    size_t size;
} light_ctx;

static int is_negative(const double c[3]) { return c[0] < 0 || c[1] < 0 || c[2] < 0; }

static int apply_light_item(void *vctx, const item *it)
{
    light_ctx *c = vctx;
    unsigned kind = 1u << c->spec.light.kind;
    const key_def *k = find_key(light_keys, it->key);
    if (!k || !(k->kinds & kind))
        return fail_key(c->err, c->size, c->what, light_keys, kind, it->key);
    if (log_write(&c->log, k->offset, k->key, c->what, c->err, c->size) < 0 ||
        store(k, &c->spec, it->value, c->what, c->err, c->size) < 0)
        return -1;
    if (k->kind == V_COLOUR && is_negative((const double *)((char *)&c->spec + k->offset)))
        return fail(c->err, c->size, "%s: %s=%s: must not be negative", c->what, k->key, it->value);
    if (strcmp(k->key, "theta") == 0) /* Direct3D 9 full cone angles: halved */
        c->spec.light.spot.inner /= 2.0;
    if (strcmp(k->key, "phi") == 0)
        c->spec.light.spot.outer /= 2.0;
    return 0;
}

static int logged(const write_log *log, size_t offset)
{
    for (int i = 0; i < log->n; i++)
        if (log->w[i].offset == offset)
            return 1;
    return 0;
}

/* The keys each kind must have: "missing KEY=..." for the first absent one. */
static int check_required(const light_ctx *c, char *err, size_t size)
{
    static const struct {
        unsigned kinds;
        size_t offset;
        const char *item;
    } required[] = {
        {PNT | SPT, L(pos), "pos=X,Y,Z"},
        {DIR | SPT, L(dir), "dir=X,Y,Z"},
        {SPH | DSK | RCT, L(pos), "center=X,Y,Z"},
        {TUB, L(area.p0), "p0=X,Y,Z"},
        {TUB, L(area.p1), "p1=X,Y,Z"},
        {SPH | TUB | DSK, L(area.radius), "radius=R"},
        {DSK, L(area.normal), "normal=X,Y,Z"},
    };
    unsigned kind = 1u << c->spec.light.kind;
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++)
        if ((required[i].kinds & kind) && !logged(&c->log, required[i].offset))
            return fail(err, size, "%s: missing %s", c->what, required[i].item);
    return 0;
}

/* A rect from edge1= and edge2=, or from normal=, width=, height= (and tangent=, the direction
 * of its width; default sc_frame_make's): edge1 = width·t, edge2 = height·(n × t). */
static int rect_edges(light_ctx *c, char *err, size_t size)
{
    const write_log *log = &c->log;
    int edges = logged(log, L(area.edge1)) || logged(log, L(area.edge2));
    int sized = logged(log, L(area.normal)) || logged(log, S(width)) || logged(log, S(height)) ||
                logged(log, S(tangent));
    if (edges && sized)
        return fail(err, size, "%s: give edge1=, edge2= or normal=, width=, height=, not both",
                    c->what);
    if (edges)
        return logged(log, L(area.edge1)) && logged(log, L(area.edge2))
                   ? 0
                   : fail(err, size, "%s: missing %s", c->what,
                          logged(log, L(area.edge1)) ? "edge2=X,Y,Z" : "edge1=X,Y,Z");
    if (!logged(log, L(area.normal)) || !logged(log, S(width)) || !logged(log, S(height)))
        return fail(err, size, "%s: missing edge1=, edge2= (or normal=, width=, height=)", c->what);
    const light_spec *s = &c->spec;
    if (!(s->width > 0.0 && s->height > 0.0))
        return fail(err, size, "%s: width=%g height=%g: a degenerate rectangle (each must be > 0)",
                    c->what, s->width, s->height);
    sc_frame f;
    if (sc_frame_make(s->light.area.normal, logged(log, S(tangent)) ? s->tangent : NULL, &f) < 0)
        return fail(err, size, "%s: normal= must not be zero nor parallel to tangent=", c->what);
    for (int i = 0; i < 3; i++) {
        c->spec.light.area.edge1[i] = s->width * f.t[i];
        c->spec.light.area.edge2[i] = s->height * f.b[i];
    }
    return 0;
}

int sc_light_parse(const char *spec, sc_light *out, char *err, size_t size)
{
    char kind[32];
    const char *rest = NULL;
    int has_kind = kind_word(spec, kind, sizeof kind, &rest) == 0;
    int k = has_kind ? word_index(light_kinds, kind) : -1;
    if (k < 0)
        return fail_kind(err, size, "light", light_kinds, has_kind ? kind : "");
    light_ctx c = {.err = err, .size = size};
    sc_light_init(&c.spec.light, (sc_light_kind)k);
    snprintf(c.what, sizeof c.what, "light %s", kind);
    char msg[160];
    int status = for_each_item(rest, c.what, err, size, apply_light_item, &c);
    if (status == 0)
        status = check_required(&c, err, size);
    if (status == 0 && k == SC_LIGHT_RECT)
        status = rect_edges(&c, err, size);
    if (status == 0 && sc_light_validate(&c.spec.light, msg, sizeof msg) < 0)
        status = fail(err, size, "%s: %s", c.what, msg);
    if (status == 0) {
        err[0] = '\0';
        status = ignored_keys(&c.log, light_needs, sizeof light_needs / sizeof light_needs[0],
                              &c.spec, c.what, err, size);
    }
    *out = c.spec.light;
    return status;
}

/* ---- models ---- */

static const char *const model_kinds[] = {
    "lambert",       "phong", "blinn-phong", "ward",      "oren-nayar",
    "cook-torrance", "ads",   "opengl",      "direct3d9", NULL};
static const char *const ndf_names[] = {"beckmann", "ggx", NULL};
static const char *const g_names[] = {"cook-torrance", "smith", "smith-correlated", NULL};
static const char *const f_names[] = {"schlick", "exact", "none", NULL};

#define M(field) offsetof(sc_model, field)
enum { LAM = 1, PHO = 2, BLI = 4, WAR = 8, ORN = 16, CTO = 32, ADS = 64, OGL = 128, D3D = 256 };
enum { BRDFS = 63, LEGACY = ADS | OGL | D3D, FIXED = OGL | D3D };
/* clang-format off */
static const key_def model_keys[] = {
    {"diff", V_COLOUR, M(brdf.diff), 511, NULL, "a colour (1 or 3 numbers)"},
    {"albedo", V_COLOUR, M(brdf.diff), ORN, NULL, "a colour (1 or 3 numbers)"},
    {"spec", V_COLOUR, M(brdf.spec), 511 & ~(LAM | ORN), NULL, "a colour (1 or 3 numbers)"},
    {"amb", V_COLOUR, M(brdf.amb), 511, NULL, "a colour (1 or 3 numbers)"},
    {"m", V_NUMBER, M(brdf.m), PHO | BLI | LEGACY, NULL, "a number"},
    {"alpha", V_NUMBER, M(brdf.ax), WAR | CTO, NULL, "a number"},
    {"perceptual", V_NUMBER, M(brdf.ax), WAR | CTO, NULL, "a number"},
    {"ax", V_NUMBER, M(brdf.ax), WAR | CTO, NULL, "a number"},
    {"ay", V_NUMBER, M(brdf.ay), WAR | CTO, NULL, "a number"},
    {"sigma", V_NUMBER, M(brdf.sigma), ORN, NULL, "an angle in degrees"},
    {"D", V_ENUM, M(brdf.D), CTO, ndf_names, NULL},
    {"G", V_ENUM, M(brdf.G), CTO, g_names, NULL},
    {"F", V_ENUM, M(brdf.F), CTO, f_names, NULL},
    {"f0", V_COLOUR, M(brdf.f0), CTO, NULL, "a colour (1 or 3 numbers)"},
    {"ior", V_NUMBER, M(brdf.ior), CTO, NULL, "a number"},
    {"emission", V_COLOUR, M(emission), FIXED, NULL, "a colour (1 or 3 numbers)"},
    {"local-viewer", V_FLAG, M(local_viewer), FIXED, NULL, "0 or 1"},
    {"viewer", V_VECTOR, M(viewer_dir), FIXED, NULL, "a vector X,Y,Z"},
    {"clamp", V_FLAG, M(clamp), FIXED, NULL, "0 or 1"},
    {"separate-specular", V_FLAG, M(separate_specular), OGL, NULL, "0 or 1"},
    {NULL, V_NUMBER, 0, 0, NULL, NULL},
};
/* clang-format on */

static const char *const ads_forms[] = {"lambert", "phong", "blinn-phong", NULL};

enum { SCHLICK = 1u << 0, EXACT = 1u << 1, NOT_LOCAL = 1u << 0 };
static const key_need model_needs[] = {
    {"f0", M(brdf.F), SCHLICK, "F", f_names},
    {"ior", M(brdf.F), EXACT, "F", f_names},
    {"viewer", M(local_viewer), NOT_LOCAL, "local-viewer", flag_names},
};

typedef struct {
    sc_model *model;
    int kind; /* index in model_kinds */
    char what[40];
    write_log log;
    char *err;
    size_t size;
} model_ctx;

/* form= : the model's own variant names (sc_brdf_form_name), or the ADS forms. */
static int apply_form(model_ctx *c, const char *value)
{
    char words[96] = "", shown[SHOWN];
    if (log_write(&c->log, M(brdf.form), "form", c->what, c->err, c->size) < 0)
        return -1;
    value = sc_escape(value, shown, sizeof shown);
    if (c->kind == 6) {
        int i = word_index(ads_forms, value);
        if (i < 0)
            return fail(c->err, c->size, "%s: form=%s: expected %s", c->what, value,
                        word_list(ads_forms, words, sizeof words));
        c->model->ads_form = (sc_ads_form)i;
        return 0;
    }
    sc_brdf_kind bk = c->model->brdf.kind;
    for (int f = 0; c->kind < 6 && sc_brdf_form_name(bk, f); f++) {
        if (strcmp(sc_brdf_form_name(bk, f), value) == 0) {
            c->model->brdf.form = f;
            return 0;
        }
        size_t len = strlen(words);
        snprintf(words + len, sizeof words - len, "%s%s", f ? "|" : "", sc_brdf_form_name(bk, f));
    }
    return fail(c->err, c->size, "%s: form=%s: expected %s", c->what, value,
                words[0] ? words : "no form= (this model has one form)");
}

static int apply_model_item(void *vctx, const item *it)
{
    model_ctx *c = vctx;
    if (strcmp(it->key, "form") == 0)
        return apply_form(c, it->value);
    unsigned kind = 1u << c->kind;
    const key_def *k = find_key(model_keys, it->key);
    if (!k || !(k->kinds & kind))
        return fail_key(c->err, c->size, c->what, model_keys, kind, it->key);
    int sets_ay = strcmp(k->key, "alpha") == 0 || strcmp(k->key, "perceptual") == 0;
    if (log_write(&c->log, k->offset, k->key, c->what, c->err, c->size) < 0 ||
        (sets_ay && log_write(&c->log, M(brdf.ay), k->key, c->what, c->err, c->size) < 0) ||
        store(k, c->model, it->value, c->what, c->err, c->size) < 0)
        return -1;
    sc_brdf *b = &c->model->brdf;
    if (strcmp(k->key, "alpha") == 0)
        b->ay = b->ax;
    if (strcmp(k->key, "perceptual") == 0) /* Disney/UE4/Filament: α = r² */
        b->ay = b->ax = b->ax * b->ax;
    if (strcmp(k->key, "sigma") == 0)
        b->sigma *= 3.14159265358979323846 / 180.0;
    return 0;
}

static void init_model(sc_model *m, int kind)
{
    static const sc_model_kind legacy[] = {SC_MODEL_ADS, SC_MODEL_OPENGL, SC_MODEL_D3D9};
    sc_model_init(m, kind < 6 ? SC_MODEL_BRDF : legacy[kind - 6]);
    if (kind < 6)
        sc_brdf_init(&m->brdf, (sc_brdf_kind)kind);
}

/* ---- file=PATH NAME=VALUE ... (shadecalc/brdf_file.h) ---- */

typedef struct {
    sc_brdf *brdf;
    unsigned long set; /* bit i: parameter i was given */
    char *err;
    size_t size;
} file_ctx;

static int apply_file_item(void *vctx, const item *it)
{
    file_ctx *c = vctx;
    if (sc_brdf_file_set(c->brdf, it->key, it->value, c->err, c->size) < 0)
        return -1;
    const sc_brdf_param *params;
    int i = 0, n = sc_brdf_file_params(c->brdf->file, &params);
    while (i < n && strcmp(params[i].name, it->key) != 0)
        i++;
    if (c->set & 1ul << i)
        return fail(c->err, c->size, "%s: %s= is given twice", sc_brdf_file_name(c->brdf->file),
                    it->key);
    c->set |= 1ul << i;
    return 0;
}

/* A spec whose first item is file=PATH: the file's BRDF, then its parameters' values. */
static int parse_file_model(const char *spec, sc_model *out, char *err, size_t size)
{
    char path[MAX_ITEM], what[MAX_ITEM + 16], shown[SHOWN];
    size_t len = strcspn(spec, " \t");
    if (len >= sizeof path)
        return fail(err, size, "brdf %s: the path is too long",
                    sc_escape_n(spec, len, shown, sizeof shown));
    snprintf(path, sizeof path, "%.*s", (int)len, spec);
    const char *rest = spec + len;
    snprintf(what, sizeof what, "brdf file=%s", path);
    sc_model_init(out, SC_MODEL_BRDF);
    const sc_brdf_file *f = sc_brdf_file_load(path, err, size);
    if (!f)
        return -1;
    sc_brdf_file_defaults(f, &out->brdf);
    file_ctx c = {.brdf = &out->brdf, .err = err, .size = size};
    if (for_each_item(rest, what, err, size, apply_file_item, &c) < 0)
        return -1;
    err[0] = '\0';
    return 0;
}

int sc_model_parse(const char *spec, sc_model *out, char *err, size_t size)
{
    char kind[32];
    const char *rest = NULL, *first = spec + strspn(spec, " \t");
    if (strncmp(first, "file=", 5) == 0)
        return parse_file_model(first + 5, out, err, size);
    int has_kind = kind_word(spec, kind, sizeof kind, &rest) == 0;
    int k = has_kind ? word_index(model_kinds, kind) : -1;
    if (k < 0)
        return fail_kind(err, size, "brdf", model_kinds, has_kind ? kind : "");
    init_model(out, k);
    model_ctx c = {.model = out, .kind = k, .err = err, .size = size};
    snprintf(c.what, sizeof c.what, "brdf %s", kind);
    if (for_each_item(rest, c.what, err, size, apply_model_item, &c) < 0)
        return -1;
    char msg[160];
    if (sc_brdf_validate(&out->brdf, msg, sizeof msg) < 0)
        return fail(err, size, "%s: %s", c.what, msg);
    err[0] = '\0';
    return ignored_keys(&c.log, model_needs, sizeof model_needs / sizeof model_needs[0], out,
                        c.what, err, size);
}
