/* A shading setup as the command line builds it (shade, and later sweep and render): lights,
 * model, ambient, geometry, from options and scene files. */
#ifndef SHADECALC_CLI_SETUP_H
#define SHADECALC_CLI_SETUP_H

#include "shadecalc/scene.h"

enum { SETUP_MAX_LIGHTS = 64 };

/* The command-line options of a setup, shared by shade and sweep (struct option entries):
 * -l --light, -b --brdf, -a --ambient, -s --scene, and the geometry --n --v --p --eye
 * --tangent as SETUP_OPT_N.. in that order (setup_geometry_name), followed by the command's
 * own options from SETUP_OPT_END. */
enum {
    SETUP_OPT_N = 256,
    SETUP_OPT_V,
    SETUP_OPT_P,
    SETUP_OPT_EYE,
    SETUP_OPT_TANGENT,
    SETUP_OPT_END
};
#define SETUP_LONG_OPTIONS                                                                         \
    {"light", required_argument, NULL, 'l'}, {"brdf", required_argument, NULL, 'b'},               \
        {"ambient", required_argument, NULL, 'a'}, {"scene", required_argument, NULL, 's'},        \
        {"n", required_argument, NULL, SETUP_OPT_N}, {"v", required_argument, NULL, SETUP_OPT_V},  \
        {"p", required_argument, NULL, SETUP_OPT_P},                                               \
        {"eye", required_argument, NULL, SETUP_OPT_EYE},                                           \
    {                                                                                              \
        "tangent", required_argument, NULL, SETUP_OPT_TANGENT                                      \
    }

/* The setup_set_value name of geometry option c (SETUP_OPT_N..SETUP_OPT_TANGENT) */
const char *setup_geometry_name(int c);

typedef struct {
    sc_light lights[SETUP_MAX_LIGHTS];
    int n_lights;
    sc_model model;
    int have_model;
    double ambient[3];
    double n[3], v[3], p[3], eye[3], tangent[3];
    int have_v, have_eye, have_tangent;
} shade_setup;

void setup_init(shade_setup *s);

/* Each applies one item (`what` names it in messages) and returns an exit status: OK, or USAGE
 * after printing the error. */
int setup_add_light(shade_setup *s, const char *spec, const char *where);
int setup_set_model(shade_setup *s, const char *spec, const char *where);
/* name is one of ambient n v p eye tangent; value the option's argument */
int setup_set_value(shade_setup *s, const char *name, const char *value, const char *where);

/* Reads a scene file: lines `light SPEC`, `brdf SPEC`, `ambient C`, `n|v|p|eye|tangent X,Y,Z`,
 * `#` comments. Exit status as above; RUNTIME if the file cannot be read; USAGE for a line
 * over 64 KiB, a NUL byte or a file over 16 MiB. */
int setup_load_file(shade_setup *s, const char *path);

/* The shading point: n, v (from --v or from --eye and --p) and the frame. USAGE on a zero
 * vector or a tangent parallel to n. */
int setup_point(const shade_setup *s, sc_shade_point *out);

/* USAGE (after the error) if a number of the setup is beyond the range of precision p
 * ("light 1: I=1e+39: beyond the highp range ..."): it would round to inf; or if an area light
 * meets a model its method does not take (a legacy model; method=ltc with a BRDF other than
 * lambert or GGX cook-torrance). */
int setup_check_range(const shade_setup *s, sc_prec p);

#endif
