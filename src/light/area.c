/* Area lights (shadecalc/area.h, docs/formulas.md §5): the methods and what they share. The
 * reference is in area_reference.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "light/area_internal.h"

/* ---- vectors ---- */

double area_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double area_unit(const double a[3], double unit[3])
{
    double len = sqrt(area_dot(a, a));
    if (len > 0.0)
        for (int c = 0; c < 3; c++)
            unit[c] = a[c] / len;
    return len;
}

void area_cross(const double a[3], const double b[3], double out[3])
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
}

void area_perpendicular(const double w[3], double out[3])
{
    double axis[3] = {0.0, 0.0, 0.0};
    axis[fabs(w[0]) < 0.5 ? 0 : fabs(w[1]) < 0.5 ? 1 : 2] = 1.0;
    double t[3];
    area_cross(w, axis, t);
    area_unit(t, out);
}

/* ---- what the methods share ---- */

void area_add(area_integrand *g, const double l[3], double weight, double acc[3])
{
    sc_brdf_terms t;
    sc_brdf_eval(SC_DOUBLE, g->b, g->frame, l, g->v, &t);
    g->evaluations++;
    if (!(t.cos_i > 0.0))
        return;
    for (int c = 0; c < 3; c++)
        acc[c] += weight * t.f[c] * g->Le[c] * t.cos_i;
}

void area_centre(const sc_light *light, double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = light->kind == SC_LIGHT_TUBE ? 0.5 * (light->area.p0[c] + light->area.p1[c])
                                              : light->pos[c];
}

static double tube_length(const sc_light *light)
{
    const double *a = light->area.p0, *b = light->area.p1;
    return sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                (b[2] - a[2]) * (b[2] - a[2]));
}

double sc_area_extent(const sc_light *light)
{
    double R = light->area.radius, e[3];
    switch (light->kind) {
    case SC_LIGHT_TUBE: return 2.0 * R * tube_length(light) + AREA_PI * R * R;
    case SC_LIGHT_RECT:
        area_cross(light->area.edge1, light->area.edge2, e);
        return sqrt(area_dot(e, e));
    default: return AREA_PI * R * R;
    }
}

void sc_area_stand_in(const sc_light *light, sc_light *point)
{
    sc_light_init(point, SC_LIGHT_POINT);
    area_centre(light, point->pos);
    double extent = sc_area_extent(light);
    for (int c = 0; c < 3; c++) {
        point->intensity[c] = light->intensity[c] * extent;
        point->ambient[c] = light->ambient[c];
    }
}

static const char *const method_names[] = {"reference", "representative-point", "point", "ltc",
                                           NULL};

const char *sc_area_method_name(sc_area_method method)
{
    return (unsigned)method < sizeof method_names / sizeof method_names[0] ? method_names[method]
                                                                           : NULL;
}

/* The BRDFs the LTC fit is made for: Lambert, and isotropic GGX Cook–Torrance with Smith
 * height-correlated masking and Schlick's Fresnel (or none: F0 = 1). */
static int ltc_takes(const sc_brdf *b)
{
    if (b->kind == SC_BRDF_LAMBERT)
        return 1;
    return b->kind == SC_BRDF_COOK_TORRANCE && b->form == SC_CT_WALTER && b->D == SC_D_GGX &&
           b->G == SC_G_SMITH_CORRELATED && b->F != SC_F_EXACT && b->ax == b->ay;
}

int sc_area_method_applies(sc_light_kind kind, sc_area_method method, const sc_brdf *b, char *msg,
                           size_t size)
{
    /* the other methods take every BRDF (representative-point: docs/formulas.md §5.3) */
    if (method == SC_AREA_REPRESENTATIVE && kind != SC_LIGHT_SPHERE && kind != SC_LIGHT_TUBE) {
        snprintf(msg, size, "method=representative-point: sphere and tube lights only");
        return -1;
    }
    if (method == SC_AREA_REPRESENTATIVE && b && b->kind == SC_BRDF_FILE) {
        snprintf(msg, size,
                 "method=representative-point: not for a BRDF file (it lights the "
                 "diffuse and specular parts apart; a file gives f alone)");
        return -1;
    }
    if (method == SC_AREA_LTC && kind != SC_LIGHT_DISK && kind != SC_LIGHT_RECT) {
        snprintf(msg, size, "method=ltc: disk and rect lights only");
        return -1;
    }
    if (method == SC_AREA_LTC && b && !ltc_takes(b)) {
        snprintf(msg, size,
                 "method=ltc: not for brdf %s as given (ltc takes lambert, or cook-torrance with "
                 "D=ggx G=smith-correlated F=schlick|none and ax = ay)",
                 sc_brdf_kind_name(b->kind));
        return -1;
    }
    return 0;
}

/* ---- point ---- */

static void point_method(const sc_light *light, area_integrand *g, const double pos[3],
                         sc_area_result *out)
{
    sc_light point;
    sc_light_sample s;
    sc_brdf_terms t;
    sc_area_stand_in(light, &point);
    sc_light_eval(SC_DOUBLE, &point, pos, g->frame->n, &s);
    sc_brdf_eval(SC_DOUBLE, g->b, g->frame, s.l, g->v, &t);
    double cos_i = t.cos_i > 0.0 ? t.cos_i : 0.0;
    for (int c = 0; c < 3; c++)
        out->L[c] = sc_mul_reach(SC_DOUBLE, t.f[c] * cos_i, s.E[c]);
    memcpy(out->l, s.l, sizeof out->l);
    out->evaluations = 1;
}

/* ---- representative point (Karis 2013) ---- */

/* ∫ cos̄θ_i dω over a sphere seen at angle θ from the normal with sin σ = R/d, for σ < π/2
 * (Snyder 1996; Lagarde & de Rousiers 2014): π sin²σ cos θ when the sphere is wholly above the
 * horizon, else the horizon-clipped form. */
static double sphere_irradiance(double cos_theta, double sin2_sigma)
{
    if (cos_theta * cos_theta >= sin2_sigma)
        return cos_theta > 0.0 ? AREA_PI * sin2_sigma * cos_theta : 0.0;
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    double x = sqrt(1.0 / sin2_sigma - 1.0), y = -x * cos_theta / sin_theta;
    double s = sin_theta * sqrt(fmax(0.0, 1.0 - y * y));
    double e = (cos_theta * acos(y) - x * s) * sin2_sigma + atan2(s, x);
    return fmax(e, 0.0);
}

/* ∫ cos̄θ_i dω of a ball of radius R about c (π from inside or on it). */
static double ball_irradiance(const double c[3], double R, const double n[3])
{
    double d = sqrt(area_dot(c, c));
    if (d <= R)
        return AREA_PI;
    return sphere_irradiance(area_dot(n, c) / d, (R / d) * (R / d));
}

/* Whether pos is inside or on a sphere's ball or a tube's capsule (within R of the segment
 * p0–p1), where the whole sky above the horizon is the light (docs/formulas.md §5.1). */
static int inside_emitter(const sc_light *light, const double pos[3])
{
    double q[3], R = light->area.radius;
    area_centre(light, q);
    for (int i = 0; i < 3; i++)
        q[i] -= pos[i];
    if (light->kind == SC_LIGHT_TUBE) { /* q = p0 + t (p1 − p0) − pos, t the nearest in [0, 1] */
        double L0[3], Ld[3];
        for (int i = 0; i < 3; i++) {
            L0[i] = light->area.p0[i] - pos[i];
            Ld[i] = light->area.p1[i] - light->area.p0[i];
        }
        double dd = area_dot(Ld, Ld);
        double t = dd > 0.0 ? fmin(1.0, fmax(0.0, -area_dot(L0, Ld) / dd)) : 0.0;
        for (int i = 0; i < 3; i++)
            q[i] = L0[i] + t * Ld[i];
    }
    return sqrt(area_dot(q, q)) <= R;
}

/* The diffuse irradiance of the emitter over L_e: a sphere's exactly; a tube's as its cylinder,
 * a line of width 2R (Karis 2013's closed form of ∫ n·x/‖x‖³ along the segment), plus its two
 * hemispherical ends as one ball at its centre; π from inside (`inside`, inside_emitter: the
 * line's form diverges on the axis). */
static double diffuse_irradiance(const sc_light *light, const double pos[3], const double n[3],
                                 int inside)
{
    double c[3], R = light->area.radius;
    if (inside)
        return AREA_PI;
    area_centre(light, c);
    for (int i = 0; i < 3; i++)
        c[i] -= pos[i];
    double ball = ball_irradiance(c, R, n);
    if (light->kind != SC_LIGHT_TUBE)
        return ball;
    double L0[3], L1[3];
    for (int i = 0; i < 3; i++) {
        L0[i] = light->area.p0[i] - pos[i];
        L1[i] = light->area.p1[i] - pos[i];
    }
    double a = sqrt(area_dot(L0, L0)), b = sqrt(area_dot(L1, L1)), den = a * b + area_dot(L0, L1);
    double line = den > 0.0 ? (area_dot(n, L0) / a + area_dot(n, L1) / b) / den : 0.0;
    return ball + fmax(0.0, 2.0 * R * tube_length(light) * line);
}

/* The point of the tube's axis (or the sphere's centre) closest to the ray along r, relative
 * to pos. */
static void closest_centre(const sc_light *light, const double pos[3], const double r[3],
                           double L[3])
{
    area_centre(light, L);
    for (int i = 0; i < 3; i++)
        L[i] -= pos[i];
    if (light->kind != SC_LIGHT_TUBE)
        return;
    double L0[3], Ld[3];
    for (int i = 0; i < 3; i++) {
        L0[i] = light->area.p0[i] - pos[i];
        Ld[i] = light->area.p1[i] - light->area.p0[i];
    }
    double rd = area_dot(r, Ld), den = area_dot(Ld, Ld) - rd * rd;
    double t = den > 0.0 ? (area_dot(r, L0) * rd - area_dot(L0, Ld)) / den : 0.5;
    t = fmin(1.0, fmax(0.0, t));
    for (int i = 0; i < 3; i++)
        L[i] = L0[i] + t * Ld[i];
}

/* Karis's α' = saturate(α + w/(2d)) for GGX, per dimension of the emitter of half-width w
 * seen at distance d: the specular part is scaled by α/α' across (w = R) and along (a tube:
 * w = ℓ/2 + R) the emitter, (α/α')² for a sphere; 1 for the other BRDFs. Anisotropic α:
 * √(α_x α_y). */
static double energy_normalisation(const sc_brdf *b, double across, double along, double d)
{
    if (b->kind != SC_BRDF_COOK_TORRANCE || b->D != SC_D_GGX)
        return 1.0;
    double alpha = sqrt(fmax(b->ax, 1e-4) * fmax(b->ay, 1e-4));
    if (!(d > 0.0))
        return alpha * alpha;
    return alpha / fmin(1.0, alpha + across / (2.0 * d)) *
           (alpha / fmin(1.0, alpha + along / (2.0 * d)));
}

/* The direction of the diffuse term: to the centre; where that is below the horizon, its
 * tangential part raised by 10⁻³ (the irradiance carries the horizon; for Lambert any
 * direction above it gives the same f). */
static void diffuse_direction(const double c[3], const double n[3], double l[3])
{
    double len = area_unit(c, l), cos_c = len > 0.0 ? area_dot(n, l) : 0.0;
    if (len > 0.0 && cos_c > 0.0)
        return;
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = (len > 0.0 ? l[i] - cos_c * n[i] : 0.0) + 1e-3 * n[i];
    area_unit(t, l);
}

static void representative_method(const sc_light *light, area_integrand *g, const double pos[3],
                                  sc_area_result *out)
{
    const double *n = g->frame->n, *v = g->v;
    double R = light->area.radius, c[3], ld[3], r[3], L[3], C[3], P[3], ls[3];
    sc_brdf_terms td, ts;
    area_centre(light, c);
    for (int i = 0; i < 3; i++)
        c[i] -= pos[i];
    diffuse_direction(c, n, ld);
    sc_brdf_eval(SC_DOUBLE, g->b, g->frame, ld, v, &td);
    int inside = inside_emitter(light, pos);
    double E_diffuse = diffuse_irradiance(light, pos, n, inside);
    double nv = area_dot(n, v);
    for (int i = 0; i < 3; i++)
        r[i] = 2.0 * nv * n[i] - v[i];
    closest_centre(light, pos, r, L);
    double d = sqrt(area_dot(L, L)), Lr = area_dot(L, r);
    for (int i = 0; i < 3; i++)
        C[i] = Lr * r[i] - L[i];
    double cl = sqrt(area_dot(C, C)), toward = cl > 0.0 ? fmin(1.0, R / cl) : 0.0;
    for (int i = 0; i < 3; i++)
        P[i] = L[i] + C[i] * toward;
    if (inside || !(area_unit(P, ls) > 0.0)) /* inside: the whole sky is the light */
        memcpy(ls, r, sizeof ls);
    sc_brdf_eval(SC_DOUBLE, g->b, g->frame, ls, v, &ts);
    double cos_s = ts.cos_i > 0.0 ? ts.cos_i : 0.0;
    double along = R + (light->kind == SC_LIGHT_TUBE ? 0.5 * tube_length(light) : 0.0);
    /* the emitter's energy: its irradiance on a plane facing the representative point */
    double E_spec = diffuse_irradiance(light, pos, ls, inside);
    double spec = energy_normalisation(g->b, R, along, d) * E_spec * cos_s;
    for (int i = 0; i < 3; i++)
        out->L[i] = g->Le[i] * (td.diffuse[i] * E_diffuse + ts.specular[i] * spec);
    memcpy(out->l, ls, sizeof out->l);
    out->evaluations = 2;
}

int sc_area_eval(const sc_light *light, sc_area_method method, const sc_brdf *b,
                 const sc_frame *frame, const double pos[3], const double v[3], sc_area_result *out)
{
    char msg[160];
    memset(out, 0, sizeof *out);
    double c[3];
    area_centre(light, c);
    for (int i = 0; i < 3; i++)
        c[i] -= pos[i];
    out->r = area_unit(c, out->l);
    if (!(out->r > 0.0))
        memcpy(out->l, frame->n, sizeof out->l);
    out->converged = 1;
    if (!sc_light_is_area(light->kind) ||
        sc_area_method_applies(light->kind, method, b, msg, sizeof msg) < 0)
        return -1;
    area_integrand g = {.b = b, .frame = frame, .v = v};
    memcpy(g.Le, light->intensity, sizeof g.Le);
    switch (method) {
    case SC_AREA_REFERENCE: area_reference(light, &g, pos, out); break;
    case SC_AREA_REPRESENTATIVE: representative_method(light, &g, pos, out); break;
    case SC_AREA_LTC: area_ltc(light, &g, pos, out); break;
    default: point_method(light, &g, pos, out); break;
    }
    return 0;
}
