/*
 * shadecalc/transform.h — 4×4 transforms written as text, and the normal matrix (docs/formulas.md §7).
 *
 *   sc_transform_parse   "scale(1,2,3)*rotate(30,0,1,0)*translate(1,2,3)", or 16 numbers
 *                        separated by commas (column-major, as GLSL's mat4(...)) -> sc_dmat4
 *   sc_normal_matrix     R = (M₃⁻¹)ᵀ of the upper-left 3×3, with the rigid-transform shortcut
 *
 * A chain is factors joined by '*', multiplied left to right (so the rightmost acts first on a
 * point, as in OpenGL): translate(x,y,z), scale(x,y,z), scale(s) (uniform), rotate(deg,x,y,z)
 * (counterclockwise by deg degrees about the axis, seen from its tip; the axis must be nonzero),
 * identity(). The matrices are shadecalc/mat.h's sc_dmat4_translate/_scale/_rotate; every
 * number must be finite. Spaces are allowed between tokens.
 *
 * The rigid shortcut: when M₃ is orthogonal (every entry of M₃ᵀM₃ − I within 32ε, ε = 2⁻⁵³:
 * rotations and reflections with any translation) R = M₃ exactly, with no inversion error.
 * Otherwise R = sc_dmat3_normal_matrix(M), and a singular M₃ (mat.h's relative rule) is
 * rejected.
 */
#ifndef SHADECALC_TRANSFORM_H
#define SHADECALC_TRANSFORM_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/mat.h"

SC_BEGIN_DECLS

/* 0, or -1 with a message naming the offending factor or number in err. */
int sc_transform_parse(const char *spec, sc_dmat4 *out, char *err, size_t errsize);

/* 0 with *rigid = 1 if the shortcut applied (else 0); -1 if M₃ is singular. */
int sc_normal_matrix(const sc_dmat4 *m, sc_dmat3 *out, int *rigid);

SC_END_DECLS

#endif
