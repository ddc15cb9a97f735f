/*
 * shadecalc/light.h — light sources, distance attenuation and spotlight functions (docs/formulas.md §2–§4).
 *
 *   sc_atten, sc_atten_eval        f_d(r): none, inverse-square, clq, window, pixar,
 *                                  windowed inverse-square (UE4/Filament)
 *   sc_spot, sc_spot_eval          I_L(l)/I_Lmax from cos θ_s: opengl, directx, smoothstep (pbrt)
 *   sc_light, sc_light_eval        l and E_L at a surface point: directional, point, spot; for
 *                                  the area lights (sphere, tube, disk, rect) those of their
 *                                  point-light stand-in (shadecalc/area.h evaluates them)
 *   sc_light_validate              the parameter domains of docs/formulas.md §3–§5, as a message
 *
 * Every function takes the precision p (shadecalc/precision.h): SC_DOUBLE is the reference;
 * in highp and mediump each named intermediate quantity is rounded to the precision and the
 * transcendental functions are the precision's built-ins (shadecalc/pmath.h).
 *
 * Edges (docs/formulas.md §3): denominators of inverse-square and clq below 1e-4 are raised to 1e-4
 * (Filament's ε², so r = 0 is finite), and where they overflow the precision they are formed in
 * double (1/r² of highp r = 1e20 is 1e-40, not 0); distances and directions are scaled by a
 * power of two where their squared length would overflow or underflow; window with r_start = r_end is a step (1 for
 * r <= r_start); pixar with f_c = f_max is the constant f_max inside r_c; a point on a point or
 * spot light (r = 0) takes l = n. Spot (docs/formulas.md §4): opengl is 1 for cutoff 180°, else
 * max(cos θ_s, 0)^exp inside the inclusive cone; directx and smoothstep with inner = outer are
 * a hard edge at the cone (1 inside, inclusive). pow(0, 0) is 1 throughout.
 */
#ifndef SHADECALC_LIGHT_H
#define SHADECALC_LIGHT_H

#include <stddef.h>

#include "shadecalc/api.h"
#include "shadecalc/precision.h"

SC_BEGIN_DECLS

typedef enum {
    SC_ATTEN_NONE,
    SC_ATTEN_INVERSE_SQUARE,
    SC_ATTEN_CLQ,
    SC_ATTEN_WINDOW,
    SC_ATTEN_PIXAR,
    SC_ATTEN_WINDOWED /* (saturate(1 − (r/r_max)^4))^2 / max(r², 1e-4) */
} sc_atten_kind;

typedef struct {
    sc_atten_kind kind;
    double sc, sl, sq;           /* clq: 1/(s_c + s_l r + s_q r²) */
    double r_start, r_end;       /* window */
    double f_max, f_c, r_c, s_e; /* pixar (Barzel 1997); k0 = ln(f_c/f_max), k1 = s_e/k0 */
    double r_max;                /* windowed inverse-square */
} sc_atten;

typedef enum { SC_SPOT_OPENGL, SC_SPOT_DIRECTX, SC_SPOT_SMOOTHSTEP } sc_spot_kind;

typedef struct {
    sc_spot_kind kind;
    double exponent;     /* opengl, directx */
    double cutoff;       /* opengl: θ_u in degrees, [0, 90] or 180 */
    double inner, outer; /* directx, smoothstep: half-angles θ_p <= θ_u in degrees */
} sc_spot;

typedef enum {
    SC_LIGHT_DIRECTIONAL,
    SC_LIGHT_POINT,
    SC_LIGHT_SPOT,
    SC_LIGHT_SPHERE, /* the area lights (docs/formulas.md §5): sc_light.area */
    SC_LIGHT_TUBE,
    SC_LIGHT_DISK,
    SC_LIGHT_RECT
} sc_light_kind;

/* How an area light's L_o is evaluated (shadecalc/area.h, docs/formulas.md §5). */
typedef enum {
    SC_AREA_REFERENCE,      /* the converging quadrature over the emitter, any BRDF */
    SC_AREA_REPRESENTATIVE, /* Karis 2013's representative point: sphere, tube */
    SC_AREA_POINT,          /* a point light at the centre with I = L_e · area */
    SC_AREA_LTC             /* linearly transformed cosines (Heitz et al. 2016): disk, rect */
} sc_area_method;

/* The emitter of an area light: a uniform, Lambertian emitter of radiance L_e
 * (sc_light.intensity) whose centre is sc_light.pos (sphere, disk, rect).
 *   sphere  radius
 *   tube    a capsule: the segment p0–p1 swept by a ball of `radius` (hemispherical ends)
 *   disk    radius, normal
 *   rect    corners pos ± edge1/2 ± edge2/2; its normal is edge1 × edge2 (normalized)
 * A one-sided disk or rect emits toward its normal only; two_sided toward both sides. */
typedef struct {
    sc_area_method method;
    double radius;             /* sphere, tube, disk (>= 0; 0 emits nothing) */
    double p0[3], p1[3];       /* tube */
    double normal[3];          /* disk */
    double edge1[3], edge2[3]; /* rect */
    int two_sided;             /* disk, rect (default 0) */
    int samples; /* reference: Gauss–Legendre nodes per panel and dimension, 2..512; 0 (the
                  * default) doubles them from 8 until the error estimate is below tol */
    double tol;  /* reference: relative error goal when samples = 0 (default 1e-9) */
} sc_area;

typedef struct {
    sc_light_kind kind;
    double dir[3];       /* directional: toward the light; spot: where the spot points */
    double pos[3];       /* point, spot */
    double intensity[3]; /* directional: E_L; point: I_L; spot: I_Lmax */
    /* Colours of the legacy models (ads, opengl, direct3d9): per-light ambient L_A,k (also used
     * by the docs/formulas.md §6 equation), diffuse and specular colours. */
    double ambient[3], diffuse[3], specular[3];
    double range; /* direct3d9: no light beyond this distance (default +Inf) */
    sc_atten atten;
    sc_spot spot;
    sc_area area; /* sphere, tube, disk, rect */
} sc_light;

/* Whether a kind is an area light (sphere, tube, disk, rect). */
int sc_light_is_area(sc_light_kind kind);

/* What a light gives at a surface point, with its intermediates (for --explain). */
typedef struct {
    double l[3];  /* unit vector toward the light */
    double r;     /* distance (0 for directional) */
    double f_d;   /* distance attenuation (1 for directional) */
    double spot;  /* spot factor (1 unless a spot) */
    double cos_s; /* cos θ_s (spot only) */
    double E[3];  /* E_L = intensity · f_d · spot */
} sc_light_sample;

/* Defaults: inverse-square attenuation, opengl spot with cutoff 180 (no cone), colours 1;
 * area lights: method reference, one-sided, samples 0 and tol 1e-9, normal (0, 0, -1). */
void sc_light_init(sc_light *light, sc_light_kind kind);

double sc_atten_eval(sc_prec p, const sc_atten *a, double r);
double sc_spot_eval(sc_prec p, const sc_spot *s, double cos_s);

/* l and E_L of `light` at point `pos` with unit normal n (used only when pos is on the light).
 * An area light gives those of its point-light stand-in: a point light at its centre (a
 * tube's: the midpoint of p0–p1) with I = L_e · sc_area_extent (shadecalc/area.h). */
void sc_light_eval(sc_prec p, const sc_light *light, const double pos[3], const double n[3],
                   sc_light_sample *out);

/* a·b rounded to p, except that a zero factor gives 0 even against an infinite one: a light
 * that does not reach a point (f_d, spot, f or cos̄θ_i = 0) adds nothing, however bright — the
 * shading equation never makes 0·∞ = NaN of an overflowed intensity. */
double sc_mul_reach(sc_prec p, double a, double b);

/* 0 if the parameters are inside their domains (docs/formulas.md §3–§5), else -1 with a message naming the
 * key and its valid range ("cutoff=120: spot=opengl takes 0..90 or 180"). Area lights: radius
 * >= 0, a disk's normal not zero, a rect's edges neither zero nor parallel, samples 0 or
 * 2..512, tol in (0, 1), and a method that applies to the kind (sc_area_method_applies). */
int sc_light_validate(const sc_light *light, char *msg, size_t size);

/* Named parameters, for range checks: v[0..n-1] are the values of key. */
typedef struct {
    const char *key;
    const double *v;
    int n;
} sc_param;

/* 0 if every value rounds to a finite value in precision p (lowp saturates: always), else -1
 * with "KEY=VALUE: beyond the highp range (|x| <= 3.4028235e+38)" for the first that does not. */
int sc_params_in_range(sc_prec p, const sc_param *params, int count, char *msg, size_t size);

/* sc_params_in_range over every numeric parameter of a light that its evaluation rounds to p
 * (intensity and colours, pos, dir, attenuation and spot parameters; range, cutoff and the
 * cone angles are compared in double). */
int sc_light_check_range(sc_prec p, const sc_light *light, char *msg, size_t size);

SC_END_DECLS

#endif
