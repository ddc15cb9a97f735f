/*
 * shadecalc/shadecalc.h — the whole public API in one include.
 *
 * Includes every header of include/shadecalc/ (each can also be included alone); the manual
 * page shadecalc(3) describes them by group. Link with `pkg-config --libs shadecalc`.
 */
#ifndef SHADECALC_SHADECALC_H
#define SHADECALC_SHADECALC_H

#include "shadecalc/accuracy.h"
#include "shadecalc/area.h"
#include "shadecalc/batch.h"
#include "shadecalc/brdf.h"
#include "shadecalc/brdf_file.h"
#include "shadecalc/check.h"
#include "shadecalc/expr.h"
#include "shadecalc/file.h"
#include "shadecalc/glsl.h"
#include "shadecalc/glsl_int.h"
#include "shadecalc/image.h"
#include "shadecalc/lang.h"
#include "shadecalc/light.h"
#include "shadecalc/mat.h"
#include "shadecalc/mesh.h"
#include "shadecalc/plot.h"
#include "shadecalc/pmath.h"
#include "shadecalc/precision.h"
#include "shadecalc/render.h"
#include "shadecalc/scene.h"
#include "shadecalc/shade.h"
#include "shadecalc/surface.h"
#include "shadecalc/sweep.h"
#include "shadecalc/transform.h"
#include "shadecalc/vec.h"
#include "shadecalc/version.h"

#endif
