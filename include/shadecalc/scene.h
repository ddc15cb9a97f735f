/*
 * shadecalc/scene.h — the text form of lights and models, as the command line and scene files
 * write them (`shadecalc shade --light SPEC --brdf SPEC`; the man page's SPEC GRAMMAR).
 *
 *   sc_light_parse        "point pos=0,5,0 I=100 atten=pixar fmax=2 fc=1 rc=1 se=2"
 *   sc_model_parse        "cook-torrance diff=0.5,0.1,0.1 f0=0.04 alpha=0.3 D=ggx"
 *   sc_parse_colour       "0.5" or "1,0.5,0.25"
 *   sc_parse_vector3      "0,1,0"
 *
 * A spec is a kind, then whitespace-separated key=value items; vectors are comma lists of three
 * numbers, colours one number (grey) or three. Every error names the item and what it accepts,
 * and the parameter domains are checked (sc_light_validate, sc_brdf_validate).
 */
#ifndef SHADECALC_SCENE_H
#define SHADECALC_SCENE_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/shade.h"

SC_BEGIN_DECLS

/* Returns 0; or 1 when the spec is valid but a key has no effect under its other choices, with
 * the warning in err ("light spot: inner= has no effect with spot=opengl"); or -1 with the error
 * in err ("light point: missing pos=..."). A key given twice, two keys that set the same
 * parameter (alpha= and ay=, inner= and theta=) and a negative light colour are errors; an
 * unknown kind or key names the closest valid one. */
int sc_light_parse(const char *spec, sc_light *out, char *err, size_t size);
int sc_model_parse(const char *spec, sc_model *out, char *err, size_t size);

/* 0 on success; -1 if s is not what it should be. */
int sc_parse_colour(const char *s, double out[3]);
int sc_parse_vector3(const char *s, double out[3]);

SC_END_DECLS

#endif
