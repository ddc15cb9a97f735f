/* Parametric surfaces and their exact normals (shadecalc/surface.h, docs/formulas.md §7): the built-ins in
 * closed form, user surfaces by dual numbers through the expression evaluator. */
#include <math.h>
#include <stdlib.h>

#include "geom/geom_internal.h"
#include "shadecalc/expr.h"

static const double TWO_PI = 6.28318530717958647692, PI = 3.14159265358979323846;

/* sin and cos of 2π·t, exact at multiples of ¼ turn: t is reduced to r ∈ [0, ¼) (exactly, by
 * Sterbenz) and the quadrant applied by symmetry, so the built-ins' seams and poles are exact. */
static void sincos_turns(double t, double *s, double *c)
{
    if (!isfinite(t)) {
        *s = *c = NAN;
        return;
    }
    t -= floor(t);
    if (t >= 1.0) /* a tiny negative t rounds up to 1: the same as 0 */
        t = 0.0;
    int quadrant = (int)(4.0 * t);
    double r = TWO_PI * (t - quadrant / 4.0), sr = sin(r), cr = cos(r);
    static const double sin_of[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}; /* (sr, cr) weights */
    *s = sin_of[quadrant][0] * sr + sin_of[quadrant][1] * cr;
    *c = sin_of[quadrant][0] * cr - sin_of[quadrant][1] * sr;
}

/* ---- the built-ins in closed form (φ = 2πu; θ = πv or ψ = 2πv) ---- */

static void set3(double *d, double x, double y, double z)
{
    d[0] = x;
    d[1] = y;
    d[2] = z;
}

/* S = R(sin θ cos φ, sin θ sin φ, −cos θ). */
static void sphere(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    double sf, cf, st, ct, r = s->a;
    sincos_turns(u, &sf, &cf);
    sincos_turns(v / 2.0, &st, &ct);
    set3(o->p, r * st * cf, r * st * sf, -r * ct);
    set3(o->dpdu, -TWO_PI * r * st * sf, TWO_PI * r * st * cf, 0.0);
    set3(o->dpdv, PI * r * ct * cf, PI * r * ct * sf, PI * r * st);
}

/* S = ((A + B cos ψ) cos φ, (A + B cos ψ) sin φ, B sin ψ). */
static void torus(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    double sf, cf, sp, cp, ring;
    sincos_turns(u, &sf, &cf);
    sincos_turns(v, &sp, &cp);
    ring = s->a + s->b * cp;
    set3(o->p, ring * cf, ring * sf, s->b * sp);
    set3(o->dpdu, -TWO_PI * ring * sf, TWO_PI * ring * cf, 0.0);
    set3(o->dpdv, -TWO_PI * s->b * sp * cf, -TWO_PI * s->b * sp * sf, TWO_PI * s->b * cp);
}

/* S = (L(u − ½), L(v − ½), 0). */
static void plane(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    set3(o->p, s->a * (u - 0.5), s->a * (v - 0.5), 0.0);
    set3(o->dpdu, s->a, 0.0, 0.0);
    set3(o->dpdv, 0.0, s->a, 0.0);
}

/* S = (R cos φ, R sin φ, H(v − ½)). */
static void cylinder(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    double sf, cf;
    sincos_turns(u, &sf, &cf);
    set3(o->p, s->a * cf, s->a * sf, s->b * (v - 0.5));
    set3(o->dpdu, -TWO_PI * s->a * sf, TWO_PI * s->a * cf, 0.0);
    set3(o->dpdv, 0.0, 0.0, s->b);
}

/* S = (x(u,v), y(u,v), z(u,v)) with ∂/∂u, ∂/∂v by forward-mode AD. */
static void user(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    sc_dual_value in[2] = {{{SC_FLOAT, {u}}, {{SC_FLOAT, {1.0}}, {SC_FLOAT, {0.0}}}},
                           {{SC_FLOAT, {v}}, {{SC_FLOAT, {0.0}}, {SC_FLOAT, {1.0}}}}};
    for (int k = 0; k < 3; k++) {
        sc_dual_value c = sc_expr_eval_dual(s->xyz[k], in);
        o->p[k] = c.x.v[0];
        o->dpdu[k] = c.d[0].v[0];
        o->dpdv[k] = c.d[1].v[0];
    }
}

static void point_and_derivatives(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    switch (s->kind) {
    case SURFACE_SPHERE: sphere(s, u, v, o); break;
    case SURFACE_TORUS: torus(s, u, v, o); break;
    case SURFACE_PLANE: plane(s, u, v, o); break;
    case SURFACE_CYLINDER: cylinder(s, u, v, o); break;
    default: user(s, u, v, o); break;
    }
}

/* ---- the normal ---- */

/* The unit normal ∂S/∂u × ∂S/∂v / ‖…‖ into n; −1 (n untouched) if the cross product vanished:
 * zero, not finite, or within its rounding error 8ε‖∂S/∂u‖‖∂S/∂v‖ (the directions parallel). */
static int unit_cross(const double *a, const double *b, double *n)
{
    /* each scaled to unit size first: a user surface scaled by 1e200 has derivatives whose
     * cross product would overflow (1e-200: underflow) */
    sc_dvec3 da = sc_dvec3_unit_scaled(sc_dvec3_from(a));
    sc_dvec3 db = sc_dvec3_unit_scaled(sc_dvec3_from(b)), c = sc_dvec3_cross(da, db);
    double len = sc_dvec3_length(c),
           bound = 8.0 * 0x1p-53 * sc_dvec3_length(da) * sc_dvec3_length(db);
    if (!(len > bound) || !isfinite(len))
        return -1;
    set3(n, c.x / len, c.y / len, c.z / len);
    return 0;
}

/* The derivatives whose cross product is the normal: a built-in's of the same surface scaled by
 * a power of two to unit size (its normal does not change; sphere r=1e308 has ∂S/∂u beyond
 * the double range, r=1e-308 a cross product below it); a user surface's own. */
static void normal_derivatives(const sc_surface *s, double u, double v, sc_surface_point *o)
{
    sc_surface unit = *s;
    if (s->kind != SURFACE_USER) {
        double big = fmax(fabs(s->a), fabs(s->b));
        int k = big > 0.0 && isfinite(big) ? ilogb(big) : 0;
        unit.a = ldexp(s->a, -k);
        unit.b = ldexp(s->b, -k);
    }
    point_and_derivatives(&unit, u, v, o);
}

/* One step of δ toward ½ (down from ½ itself). */
static double toward_centre(double t, double delta) { return t < 0.5 ? t + delta : t - delta; }

/* surface.h: the limit of the normal from inside, the normal a step δ = 2⁻³⁰, 2⁻²⁰, 2⁻¹⁰
 * toward the centre of the parameter square; (0, 0, 1) if all of them are degenerate too. */
static void fallback_normal(const sc_surface *s, double u, double v, double *n)
{
    static const double steps[] = {0x1p-30, 0x1p-20, 0x1p-10};
    for (int i = 0; i < 3; i++) {
        sc_surface_point q;
        normal_derivatives(s, toward_centre(u, steps[i]), toward_centre(v, steps[i]), &q);
        if (unit_cross(q.dpdu, q.dpdv, n) == 0)
            return;
    }
    set3(n, 0.0, 0.0, 1.0);
}

void sc_surface_eval(const sc_surface *s, double u, double v, sc_surface_point *out)
{
    sc_surface_point d;
    point_and_derivatives(s, u, v, out);
    normal_derivatives(s, u, v, &d);
    out->degenerate = unit_cross(d.dpdu, d.dpdv, out->n) != 0;
    if (out->degenerate)
        fallback_normal(s, u, v, out->n);
}

int sc_surface_closed_u(const sc_surface *s) { return s->closed_u; }
int sc_surface_closed_v(const sc_surface *s) { return s->closed_v; }

/* surface.h: a user surface is closed in u if S(0,t) = S(1,t) at t = 0, ⅛, ..., 1 within 1e-9
 * of its size (the largest coordinate seen); `along_v` tests S(t,0) = S(t,1) instead. */
static int samples_match(const sc_surface *s, int along_v)
{
    double size = 0.0, worst = 0.0;
    for (int i = 0; i <= 8; i++) {
        sc_surface_point a, b;
        double t = i / 8.0;
        point_and_derivatives(s, along_v ? t : 0.0, along_v ? 0.0 : t, &a);
        point_and_derivatives(s, along_v ? t : 1.0, along_v ? 1.0 : t, &b);
        for (int k = 0; k < 3; k++) {
            size = fmax(size, fmax(fabs(a.p[k]), fabs(b.p[k])));
            worst = fmax(worst, fabs(a.p[k] - b.p[k]));
        }
    }
    return worst <= 1e-9 * size;
}

void sc_surface_detect_closed(sc_surface *s)
{
    s->closed_u = samples_match(s, 0);
    s->closed_v = samples_match(s, 1);
}

void sc_surface_free(sc_surface *s)
{
    if (s == NULL)
        return;
    for (int k = 0; k < 3; k++)
        sc_expr_free(s->xyz[k]);
    free(s);
}
