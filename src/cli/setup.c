/* Building a shading setup from options and scene files (setup.h). */
#include "cli/setup.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/line_reader.h"
#include "util/text.h"

static int is_zero(const double v[3]) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

void setup_init(shade_setup *s)
{
    memset(s, 0, sizeof *s);
    sc_model_init(&s->model, SC_MODEL_BRDF);
    s->n[2] = 1.0;
    s->v[2] = 1.0;
}

int setup_add_light(shade_setup *s, const char *spec, const char *where)
{
    char err[256];
    if (s->n_lights == SETUP_MAX_LIGHTS) {
        sc_error("%stoo many lights (at most %d)", where, SETUP_MAX_LIGHTS);
        return SC_EXIT_USAGE;
    }
    int parsed = sc_light_parse(spec, &s->lights[s->n_lights], err, sizeof err);
    if (parsed < 0) {
        sc_error("%s%s", where, err);
        return SC_EXIT_USAGE;
    }
    if (parsed > 0)
        sc_warning("%s%s", where, err);
    s->n_lights++;
    return SC_EXIT_OK;
}

int setup_set_model(shade_setup *s, const char *spec, const char *where)
{
    char err[512];
    int parsed = sc_model_parse(spec, &s->model, err, sizeof err);
    if (parsed < 0) {
        sc_error("%s%s", where, err);
        return SC_EXIT_USAGE;
    }
    if (parsed > 0)
        sc_warning("%s%s", where, err);
    s->have_model = 1;
    return SC_EXIT_OK;
}

const char *setup_geometry_name(int c)
{
    static const char *const names[] = {"n", "v", "p", "eye", "tangent"};
    return names[c - SETUP_OPT_N];
}

int setup_set_value(shade_setup *s, const char *name, const char *value, const char *where)
{
    static const char *const names[] = {"ambient", "n", "v", "p", "eye", "tangent"};
    double *fields[] = {s->ambient, s->n, s->v, s->p, s->eye, s->tangent};
    int *flags[] = {NULL, NULL, &s->have_v, NULL, &s->have_eye, &s->have_tangent};
    static const int must_not_be_zero[] = {0, 1, 1, 0, 0, 1};
    for (int i = 0; i < 6; i++) {
        if (strcmp(name, names[i]) != 0)
            continue;
        int bad = i == 0 ? sc_parse_colour(value, fields[i]) : sc_parse_vector3(value, fields[i]);
        const char *dashes = where[0] ? "" : "--"; /* a scene file's items have none */
        if (bad) {
            sc_error("%s%s%s %s: expected %s", where, dashes, name, value,
                     i == 0 ? "a colour R,G,B (or one number)" : "three numbers X,Y,Z");
            return SC_EXIT_USAGE;
        }
        if (must_not_be_zero[i] && is_zero(fields[i])) {
            sc_error("%s%s%s %s: must not be the zero vector", where, dashes, name, value);
            return SC_EXIT_USAGE;
        }
        if (flags[i])
            *flags[i] = 1;
        return SC_EXIT_OK;
    }
    static const char *const items[] = {"light", "brdf", "ambient", "n", "v",
                                        "p",     "eye",  "tangent", NULL};
    const char *best = sc_suggest_among(name, items);
    sc_error("%sunknown item '%s'%s%s%s", where, name, best ? " (did you mean '" : "",
             best ? best : "", best ? "'?)" : "");
    return SC_EXIT_USAGE;
}

/* One line of a scene file: "WORD rest". */
static int apply_line(shade_setup *s, char *line, const char *where)
{
    char *word = line + strspn(line, " \t");
    size_t len = strcspn(word, " \t");
    char *rest = word + len;
    rest += strspn(rest, " \t");
    word[len] = '\0';
    if (strcmp(word, "light") == 0)
        return setup_add_light(s, rest, where);
    if (strcmp(word, "brdf") == 0)
        return setup_set_model(s, rest, where);
    return setup_set_value(s, word, rest, where);
}

/* The text of a line without its comment ('#' to the end) and surrounding blanks. */
static char *line_text(char *line)
{
    line[strcspn(line, "#\r\n")] = '\0';
    size_t len = strlen(line);
    while (len > 0 && (line[len - 1] == ' ' || line[len - 1] == '\t'))
        line[--len] = '\0';
    return line + strspn(line, " \t");
}

/* Scene files are small: a bound on what is read keeps /dev/zero or an endless stream from
 * filling memory or running forever. */
enum { SCENE_MAX_LINE = 64 * 1024, SCENE_MAX_SIZE = 16 * 1024 * 1024 };

int setup_load_file(shade_setup *s, const char *path)
{
    int from_stdin = strcmp(path, "-") == 0;
    const char *name = from_stdin ? "standard input" : path;
    FILE *f = from_stdin ? stdin : fopen(path, "r");
    if (!f) {
        sc_error("%s: %s", path, strerror(errno));
        return SC_EXIT_RUNTIME;
    }
    line_reader r;
    if (line_reader_init(&r, f, SCENE_MAX_LINE, SCENE_MAX_SIZE) < 0) {
        if (!from_stdin)
            fclose(f);
        sc_error("%s: out of memory", name);
        return SC_EXIT_RUNTIME;
    }
    char where[512];
    int status = SC_EXIT_OK;
    line_status ls;
    while (status == SC_EXIT_OK && (ls = line_reader_next(&r)) != LINE_END) {
        snprintf(where, sizeof where, "%s:%ld: ", name, r.number);
        if (ls != LINE_OK) {
            status = line_reader_report(&r, ls, name, where);
            continue;
        }
        char *text = line_text(r.line);
        if (*text != '\0')
            status = apply_line(s, text, where);
    }
    line_reader_free(&r);
    if (!from_stdin)
        fclose(f);
    return status;
}

static int unit(const double in[3], double out[3], const char *what)
{
    double len = sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2]);
    if (!(len > 0.0) || !isfinite(len)) {
        sc_error("%s %g,%g,%g: must not be the zero vector", what, in[0], in[1], in[2]);
        return SC_EXIT_USAGE;
    }
    for (int c = 0; c < 3; c++)
        out[c] = in[c] / len;
    return SC_EXIT_OK;
}

int setup_point(const shade_setup *s, sc_shade_point *out)
{
    memset(out, 0, sizeof *out);
    memcpy(out->pos, s->p, sizeof out->pos);
    double to_eye[3];
    for (int c = 0; c < 3; c++)
        to_eye[c] = s->eye[c] - s->p[c];
    int status = s->have_eye && !s->have_v ? unit(to_eye, out->v, "--eye minus --p")
                                           : unit(s->v, out->v, "--v");
    if (status != SC_EXIT_OK)
        return status;
    double n[3];
    if ((status = unit(s->n, n, "--n")) != SC_EXIT_OK)
        return status;
    if (sc_frame_make(n, s->have_tangent ? s->tangent : NULL, &out->frame) < 0) {
        sc_error("--tangent %g,%g,%g: must not be zero or parallel to the normal", s->tangent[0],
                 s->tangent[1], s->tangent[2]);
        return SC_EXIT_USAGE;
    }
    const sc_brdf *b = &s->model.brdf;
    if (s->model.kind == SC_MODEL_BRDF && b->ax != b->ay && !s->have_tangent &&
        (b->kind == SC_BRDF_WARD || b->kind == SC_BRDF_COOK_TORRANCE)) {
        sc_error("brdf %s: anisotropic roughness (ax=%g ay=%g) needs --tangent X,Y,Z",
                 sc_brdf_kind_name(b->kind), b->ax, b->ay);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

/* An area light needs a BRDF its method takes (shadecalc/area.h). */
static int check_area(const shade_setup *s, int k, char *msg, size_t size)
{
    const sc_light *l = &s->lights[k];
    if (!sc_light_is_area(l->kind))
        return 0;
    if (s->model.kind != SC_MODEL_BRDF) {
        snprintf(msg, size,
                 "area lights need a BRDF (--brdf lambert, cook-torrance, ...), not a "
                 "legacy lighting model");
        return -1;
    }
    return sc_area_method_applies(l->kind, l->area.method, &s->model.brdf, msg, size);
}

int setup_check_range(const shade_setup *s, sc_prec p)
{
    char msg[160];
    for (int k = 0; k < s->n_lights; k++)
        if (sc_light_check_range(p, &s->lights[k], msg, sizeof msg) < 0 ||
            check_area(s, k, msg, sizeof msg) < 0) {
            sc_error("light %d: %s", k + 1, msg);
            return SC_EXIT_USAGE;
        }
    const sc_param point[] = {{"emission", s->model.emission, 3},
                              {"--ambient", s->ambient, 3},
                              {"--n", s->n, 3},
                              {"--v", s->v, 3},
                              {"--p", s->p, 3},
                              {"--eye", s->eye, 3},
                              {"--tangent", s->tangent, 3}};
    if (sc_brdf_check_range(p, &s->model.brdf, msg, sizeof msg) < 0 ||
        sc_params_in_range(p, point, (int)(sizeof point / sizeof point[0]), msg, sizeof msg) < 0) {
        sc_error("%s", msg);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}
