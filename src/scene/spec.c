/* Parsing of light and model specs (shadecalc/scene.h): "KIND key=value ...", driven by one
 * table of keys per spec type. */
#include "shadecalc/scene.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_ITEM = 256 };

typedef enum { V_NUMBER, V_COLOUR, V_VECTOR, V_ENUM, V_FLAG } value_kind;

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
    char words[160];
    return fail(err, size, "%s: %s=%s: expected %s", what, k->key, value,
                k->kind == V_ENUM ? word_list(k->names, words, sizeof words) : k->help);
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
        if (split_item(p, len, &it) < 0)
            return fail(err, size, "%s: '%.*s': expected key=value", what, (int)(len > 40 ? 40 : len), p);
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

/* ---- lights ---- */

static const char *const light_kinds[] = {"directional", "point", "spot", NULL};
static const char *const atten_names[] = {"none",  "inverse-square", "clq",
                                          "window", "pixar",         "windowed", NULL};
static const char *const spot_names[] = {"opengl", "directx", "smoothstep", NULL};

#define L(field) offsetof(sc_light, field)
enum { DIR = 1, PNT = 2, SPT = 4, ANY = 7 };
/* clang-format off */
static const key_def light_keys[] = {
    {"I", V_COLOUR, L(intensity), ANY, NULL, "a colour (1 or 3 numbers)"},
    {"E", V_COLOUR, L(intensity), ANY, NULL, "a colour (1 or 3 numbers)"},
    {"amb", V_COLOUR, L(ambient), ANY, NULL, "a colour (1 or 3 numbers)"},
    {"diff", V_COLOUR, L(diffuse), ANY, NULL, "a colour (1 or 3 numbers)"},
    {"spec", V_COLOUR, L(specular), ANY, NULL, "a colour (1 or 3 numbers)"},
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
    {NULL, V_NUMBER, 0, 0, NULL, NULL},
};
/* clang-format on */

typedef struct {
    sc_light *light;
    char what[40];
    unsigned seen_pos, seen_dir;
    char *err;
    size_t size;
} light_ctx;

static int apply_light_item(void *vctx, const item *it)
{
    light_ctx *c = vctx;
    const key_def *k = find_key(light_keys, it->key);
    if (!k || !(k->kinds & (1u << c->light->kind)))
        return fail(c->err, c->size, "%s: unknown key '%s'", c->what, it->key);
    if (store(k, c->light, it->value, c->what, c->err, c->size) < 0)
        return -1;
    c->seen_pos |= k->offset == L(pos);
    c->seen_dir |= k->offset == L(dir);
    if (strcmp(k->key, "theta") == 0) /* Direct3D 9 full cone angles: halved */
        c->light->spot.inner /= 2.0;
    if (strcmp(k->key, "phi") == 0)
        c->light->spot.outer /= 2.0;
    return 0;
}

int sc_light_parse(const char *spec, sc_light *out, char *err, size_t size)
{
    char kind[32], words[64];
    const char *rest = NULL;
    int has_kind = kind_word(spec, kind, sizeof kind, &rest) == 0;
    int k = has_kind ? word_index(light_kinds, kind) : -1;
    if (k < 0)
        return fail(err, size, "light: unknown kind '%s' (%s)", has_kind ? kind : "",
                    word_list(light_kinds, words, sizeof words));
    sc_light_init(out, (sc_light_kind)k);
    light_ctx c = {.light = out, .err = err, .size = size};
    snprintf(c.what, sizeof c.what, "light %s", kind);
    if (for_each_item(rest, c.what, err, size, apply_light_item, &c) < 0)
        return -1;
    if (out->kind != SC_LIGHT_DIRECTIONAL && !c.seen_pos)
        return fail(err, size, "%s: missing pos=X,Y,Z", c.what);
    if (out->kind != SC_LIGHT_POINT && !c.seen_dir)
        return fail(err, size, "%s: missing dir=X,Y,Z", c.what);
    char msg[160];
    if (sc_light_validate(out, msg, sizeof msg) < 0)
        return fail(err, size, "%s: %s", c.what, msg);
    return 0;
}

/* ---- models ---- */

static const char *const model_kinds[] = {"lambert",       "phong",      "blinn-phong",
                                          "ward",          "oren-nayar", "cook-torrance",
                                          "ads",           "opengl",     "direct3d9",
                                          NULL};
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

typedef struct {
    sc_model *model;
    int kind; /* index in model_kinds */
    char what[40];
    char *err;
    size_t size;
} model_ctx;

/* form= : the model's own variant names (sc_brdf_form_name), or the ADS forms. */
static int apply_form(model_ctx *c, const char *value)
{
    char words[96] = "";
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
    const key_def *k = find_key(model_keys, it->key);
    if (!k || !(k->kinds & (1u << c->kind)))
        return fail(c->err, c->size, "%s: unknown key '%s'", c->what, it->key);
    if (store(k, c->model, it->value, c->what, c->err, c->size) < 0)
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

int sc_model_parse(const char *spec, sc_model *out, char *err, size_t size)
{
    char kind[32], words[160];
    const char *rest = NULL;
    int has_kind = kind_word(spec, kind, sizeof kind, &rest) == 0;
    int k = has_kind ? word_index(model_kinds, kind) : -1;
    if (k < 0)
        return fail(err, size, "brdf: unknown kind '%s' (%s)", has_kind ? kind : "",
                    word_list(model_kinds, words, sizeof words));
    init_model(out, k);
    model_ctx c = {.model = out, .kind = k, .err = err, .size = size};
    snprintf(c.what, sizeof c.what, "brdf %s", kind);
    if (for_each_item(rest, c.what, err, size, apply_model_item, &c) < 0)
        return -1;
    char msg[160];
    if (sc_brdf_validate(&out->brdf, msg, sizeof msg) < 0)
        return fail(err, size, "%s: %s", c.what, msg);
    return 0;
}
