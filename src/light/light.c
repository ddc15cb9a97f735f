/* Light sources, distance attenuation and spotlight functions (shadecalc/light.h;
 * docs/formulas.md §2–§4). Intermediates are rounded to the precision with Q(). */
#include "shadecalc/light.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "shadecalc/area.h"
#include "shadecalc/pmath.h"

#define Q(x) sc_round(p, (x))

static const double pi = 3.14159265358979323846;
static const double denom_floor = 1e-4; /* Filament's ε² for 1/r² at r -> 0 */

/* cos of an angle in degrees, as a uniform the host computes in double. */
static double cos_deg(sc_prec p, double deg) { return Q(cos(deg * (pi / 180.0))); }

/* x^y with pow(0, 0) = 1 and a non-positive base giving 0 for y > 0 (the cosine lobes). */
static double lobe_pow(sc_prec p, double x, double y)
{
    if (y == 0.0)
        return 1.0;
    return x <= 0.0 ? 0.0 : sc_p_pow(p, x, y);
}

/* ---- distance attenuation (docs/formulas.md §3) ---- */

/* 1/r²; where r² overflows the precision but 1/r² may not (highp r = 1e20: 1e-40, a
 * subnormal, not 0), r² is formed in double (r is at most the precision's largest value, so
 * r² <= 1.2e77) and only 1/r² rounded. */
static double inverse_square(sc_prec p, double r)
{
    double r2 = Q(r * r);
    if (isinf(r2) && isfinite(r))
        return Q(1.0 / (r * r));
    return Q(1.0 / fmax(r2, denom_floor));
}

/* 1/(s_c + s_l r + s_q r²); where the sum overflows the precision, formed in double. */
static double clq(sc_prec p, const sc_atten *a, double r)
{
    double d = Q(Q(a->sc + Q(a->sl * r)) + Q(a->sq * Q(r * r)));
    if (isinf(d) && isfinite(r))
        return Q(1.0 / (a->sc + a->sl * r + a->sq * r * r));
    return Q(1.0 / fmax(d, denom_floor));
}

static double window(sc_prec p, const sc_atten *a, double r)
{
    if (r <= a->r_start)
        return 1.0;
    if (r >= a->r_end)
        return 0.0; /* r_start = r_end never reaches the ramp: a step */
    return Q(Q(a->r_end - r) / Q(a->r_end - a->r_start));
}

/* Barzel 1997 (RTR3 §7.4.1): f_max·exp(k0·(r/r_c)^(−k1)) inside r_c, f_c·(r_c/r)^s_e outside.
 * f_c = f_max gives k0 = 0 and k1 = ±inf: the limit, the constant f_max, is returned. */
static double pixar(sc_prec p, const sc_atten *a, double r)
{
    if (r > a->r_c)
        return Q(a->f_c * sc_p_pow(p, Q(a->r_c / r), a->s_e));
    if (a->f_c == a->f_max)
        return a->f_max;
    double k0 = sc_p_log(p, Q(a->f_c / a->f_max));
    double k1 = Q(a->s_e / k0);
    double t = lobe_pow(p, Q(r / a->r_c), -k1); /* -k1 > 0: t -> 0 as r -> 0 */
    return Q(a->f_max * sc_p_exp(p, Q(k0 * t)));
}

/* Karis 2013 / Filament: (saturate(1 − (r/r_max)^4))² / max(r², 1e-4). */
static double windowed(sc_prec p, const sc_atten *a, double r)
{
    double x = Q(r / a->r_max);
    double x2 = Q(x * x);
    double w = fmin(fmax(Q(1.0 - Q(x2 * x2)), 0.0), 1.0);
    return Q(Q(w * w) * inverse_square(p, r));
}

double sc_atten_eval(sc_prec p, const sc_atten *a, double r)
{
    switch (a->kind) {
    case SC_ATTEN_INVERSE_SQUARE: return inverse_square(p, r);
    case SC_ATTEN_CLQ: return clq(p, a, r);
    case SC_ATTEN_WINDOW: return window(p, a, r);
    case SC_ATTEN_PIXAR: return pixar(p, a, r);
    case SC_ATTEN_WINDOWED: return windowed(p, a, r);
    default: return 1.0;
    }
}

/* ---- spotlight functions (docs/formulas.md §4) ---- */

static double spot_opengl(sc_prec p, const sc_spot *s, double cos_s)
{
    if (s->cutoff == 180.0)
        return 1.0;
    return cos_s >= cos_deg(p, s->cutoff) ? lobe_pow(p, cos_s, s->exponent) : 0.0;
}

/* 1 inside the inner cone (cos θ_s >= cos θ_p), 0 outside the outer one (cos θ_s <= cos θ_u),
 * else -1 with the ramp (cos θ_s − cos θ_u)/(cos θ_p − cos θ_u) in *ramp (docs/formulas.md §4). */
static double penumbra(sc_prec p, const sc_spot *s, double cos_s, double *ramp)
{
    double cp = cos_deg(p, s->inner), cu = cos_deg(p, s->outer);
    if (cos_s >= cp)
        return 1.0;
    if (cos_s <= cu)
        return 0.0; /* inner = outer: one of the two tests always holds, a hard edge */
    *ramp = Q(Q(cos_s - cu) / Q(cp - cu));
    return -1.0;
}

static double spot_directx(sc_prec p, const sc_spot *s, double cos_s)
{
    double t, edge = penumbra(p, s, cos_s, &t);
    return edge >= 0.0 ? edge : lobe_pow(p, t, s->exponent);
}

/* pbrt-v4 SpotLight::I: smoothstep of the same ramp, t²(3 − 2t). */
static double spot_smoothstep(sc_prec p, const sc_spot *s, double cos_s)
{
    double t, edge = penumbra(p, s, cos_s, &t);
    return edge >= 0.0 ? edge : Q(Q(t * t) * Q(3.0 - Q(2.0 * t)));
}

double sc_spot_eval(sc_prec p, const sc_spot *s, double cos_s)
{
    switch (s->kind) {
    case SC_SPOT_DIRECTX: return spot_directx(p, s, cos_s);
    case SC_SPOT_SMOOTHSTEP: return spot_smoothstep(p, s, cos_s);
    default: return spot_opengl(p, s, cos_s);
    }
}

/* ---- lights (docs/formulas.md §2) ---- */

int sc_light_is_area(sc_light_kind kind)
{
    return kind >= SC_LIGHT_SPHERE && kind <= SC_LIGHT_RECT;
}

void sc_light_init(sc_light *light, sc_light_kind kind)
{
    *light = (sc_light){.kind = kind};
    light->dir[2] = 1.0;
    light->area.normal[2] = -1.0;
    light->area.tol = 1e-9;
    if (kind == SC_LIGHT_SPOT)
        light->dir[2] = -1.0;
    for (int c = 0; c < 3; c++)
        light->intensity[c] = light->diffuse[c] = light->specular[c] = 1.0;
    light->atten.kind = kind == SC_LIGHT_DIRECTIONAL ? SC_ATTEN_NONE : SC_ATTEN_INVERSE_SQUARE;
    light->atten.sc = 1.0;
    light->spot.kind = SC_SPOT_OPENGL;
    light->spot.cutoff = 180.0;
    light->spot.outer = 180.0;
    light->range = HUGE_VAL;
}

static int is_zero3(const double v[3]) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

static void rounded3(sc_prec p, const double in[3], double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = Q(in[c]);
}

double sc_mul_reach(sc_prec p, double a, double b)
{
    return a == 0.0 || b == 0.0 ? 0.0 : sc_p_mul(p, a, b);
}

/* Whether ‖d‖² of a rounded vector d is safe in p: no overflow, and not below the smallest
 * normal number, where the square root of an underflowed sum loses digits or becomes 0. lowp
 * saturates instead and is left as it is. */
static int square_is_safe(sc_prec p, const double d[3])
{
    static const double smallest_normal[] = {0x1p-1022, 0x1p-126, 0x1p-14, 0.0};
    double big = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    if (p == SC_LOWP || big == 0.0 || !isfinite(big))
        return 1;
    double dot = sc_p_dot(p, d, d, 3);
    return isfinite(dot) && dot >= smallest_normal[p];
}

/* ‖d‖ and d/‖d‖ in precision p for a rounded d, hypot-style: where ‖d‖² would overflow or
 * underflow, d is first scaled by the power of two 2^-k that brings its largest component into
 * [1, 2) (exact), and ‖d‖ is the scaled length times 2^k (inf only if ‖d‖ itself is beyond the
 * precision's range). */
static double length_unit(sc_prec p, const double d[3], double unit[3])
{
    if (square_is_safe(p, d)) {
        double len = sc_p_length(p, d, 3);
        if (len > 0.0)
            sc_p_normalize(p, d, 3, unit);
        return len;
    }
    int k = ilogb(fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2]))));
    double scaled[3];
    for (int c = 0; c < 3; c++)
        scaled[c] = Q(ldexp(d[c], -k));
    sc_p_normalize(p, scaled, 3, unit);
    return Q(ldexp(sc_p_length(p, scaled, 3), k));
}

/* The unit vector of a light's direction (a uniform the host prepares): where its rounded
 * components vanish in p or their squared length would over/underflow, the direction is first
 * scaled by a power of two in double (dir=1e-30,0,1e-30 in mediump: (0.707, 0, 0.707)). */
static void unit_direction(sc_prec p, const double dir[3], double out[3])
{
    double d[3];
    rounded3(p, dir, d);
    if (is_zero3(d) || !square_is_safe(p, d)) {
        int k = ilogb(fmax(fabs(dir[0]), fmax(fabs(dir[1]), fabs(dir[2]))));
        for (int c = 0; c < 3; c++)
            d[c] = Q(ldexp(dir[c], -k));
    }
    length_unit(p, d, out);
}

/* p_L − p_S in precision p, halved (and *twice = 1) where a difference overflows: the
 * direction survives and the distance is twice the halved length. */
static void light_offset(sc_prec p, const double pos_l[3], const double pos_s[3], double d[3],
                         int *twice)
{
    *twice = 0;
    for (int c = 0; c < 3; c++) {
        d[c] = sc_p_sub(p, Q(pos_l[c]), Q(pos_s[c]));
        *twice |= isinf(d[c]) && isfinite(Q(pos_l[c])) && isfinite(Q(pos_s[c]));
    }
    for (int c = 0; *twice && c < 3; c++)
        d[c] = sc_p_sub(p, Q(0.5 * Q(pos_l[c])), Q(0.5 * Q(pos_s[c])));
}

void sc_light_eval(sc_prec p, const sc_light *light, const double pos[3], const double n[3],
                   sc_light_sample *out)
{
    sc_light stand_in;
    if (sc_light_is_area(light->kind)) {
        sc_area_stand_in(light, &stand_in);
        light = &stand_in;
    }
    *out = (sc_light_sample){.f_d = 1.0, .spot = 1.0};
    double d[3];
    if (light->kind == SC_LIGHT_DIRECTIONAL) {
        unit_direction(p, light->dir, out->l);
    } else {
        int twice;
        light_offset(p, light->pos, pos, d, &twice);
        out->r = length_unit(p, d, out->l);
        if (twice)
            out->r = Q(2.0 * out->r);
        if (!(out->r > 0.0))
            rounded3(p, n, out->l); /* on the light: l = n (docs/formulas.md §2, r = 0) */
        out->f_d = sc_atten_eval(p, &light->atten, out->r);
    }
    if (light->kind == SC_LIGHT_SPOT) {
        double s[3], minus_l[3] = {-out->l[0], -out->l[1], -out->l[2]};
        unit_direction(p, light->dir, s);
        out->cos_s = sc_p_dot(p, s, minus_l, 3);
        out->spot = sc_spot_eval(p, &light->spot, out->cos_s);
    }
    double scale = sc_mul_reach(p, out->f_d, out->spot);
    for (int c = 0; c < 3; c++)
        out->E[c] = sc_mul_reach(p, Q(light->intensity[c]), scale);
}

/* ---- validation ---- */

static int invalid(char *msg, size_t size, const char *text)
{
    snprintf(msg, size, "%s", text);
    return -1;
}

static int validate_atten(const sc_atten *a, char *msg, size_t size)
{
    switch (a->kind) {
    case SC_ATTEN_CLQ:
        if (!(a->sc >= 0 && a->sl >= 0 && a->sq >= 0) || a->sc + a->sl + a->sq == 0) {
            snprintf(msg, size, "sc=%g sl=%g sq=%g: clq needs each >= 0, not all 0", a->sc, a->sl,
                     a->sq);
            return -1;
        }
        return 0;
    case SC_ATTEN_WINDOW:
        if (!(a->r_start >= 0 && a->r_start <= a->r_end)) {
            snprintf(msg, size, "rstart=%g rend=%g: window needs 0 <= rstart <= rend", a->r_start,
                     a->r_end);
            return -1;
        }
        return 0;
    case SC_ATTEN_PIXAR:
        if (!(a->f_c > 0 && a->f_c <= a->f_max)) {
            snprintf(msg, size, "fc=%g fmax=%g: pixar needs 0 < fc <= fmax", a->f_c, a->f_max);
            return -1;
        }
        if (!(a->r_c > 0 && a->s_e > 0)) {
            snprintf(msg, size, "rc=%g se=%g: pixar needs rc > 0 and se > 0", a->r_c, a->s_e);
            return -1;
        }
        return 0;
    case SC_ATTEN_WINDOWED:
        if (!(a->r_max > 0)) {
            snprintf(msg, size, "rmax=%g: must be > 0", a->r_max);
            return -1;
        }
        return 0;
    default: return 0;
    }
}

static int validate_spot(const sc_spot *s, char *msg, size_t size)
{
    if (s->exponent < 0)
        return invalid(msg, size, "exp must be >= 0");
    if (s->kind == SC_SPOT_OPENGL) {
        if (!((s->cutoff >= 0 && s->cutoff <= 90) || s->cutoff == 180)) {
            snprintf(msg, size, "cutoff=%g: spot=opengl takes 0..90 or 180", s->cutoff);
            return -1;
        }
        return 0;
    }
    if (!(s->inner >= 0 && s->outer <= 180)) {
        snprintf(msg, size, "inner=%g outer=%g: half-angles must be in 0..180", s->inner, s->outer);
        return -1;
    }
    if (s->inner > s->outer) {
        snprintf(msg, size, "inner=%g > outer=%g: the inner cone must not exceed the outer",
                 s->inner, s->outer);
        return -1;
    }
    return 0;
}

int sc_params_in_range(sc_prec p, const sc_param *params, int count, char *msg, size_t size)
{
    static const double largest[] = {DBL_MAX, FLT_MAX, 65504.0, SC_LOWP_MAX};
    for (int i = 0; i < count; i++)
        for (int k = 0; k < params[i].n; k++)
            if (isinf(sc_round(p, params[i].v[k]))) {
                snprintf(msg, size, "%s=%g: beyond the %s range (|x| <= %.8g)", params[i].key,
                         params[i].v[k], sc_prec_name(p), largest[p]);
                return -1;
            }
    return 0;
}

int sc_light_check_range(sc_prec p, const sc_light *l, char *msg, size_t size)
{
    const sc_param params[] = {{"I", l->intensity, 3},
                               {"amb", l->ambient, 3},
                               {"diff", l->diffuse, 3},
                               {"spec", l->specular, 3},
                               {"dir", l->dir, 3},
                               {"pos", l->pos, 3},
                               {"sc", &l->atten.sc, 1},
                               {"sl", &l->atten.sl, 1},
                               {"sq", &l->atten.sq, 1},
                               {"rstart", &l->atten.r_start, 1},
                               {"rend", &l->atten.r_end, 1},
                               {"fmax", &l->atten.f_max, 1},
                               {"fc", &l->atten.f_c, 1},
                               {"rc", &l->atten.r_c, 1},
                               {"se", &l->atten.s_e, 1},
                               {"rmax", &l->atten.r_max, 1},
                               {"exp", &l->spot.exponent, 1},
                               {"radius", &l->area.radius, 1},
                               {"p0", l->area.p0, 3},
                               {"p1", l->area.p1, 3},
                               {"normal", l->area.normal, 3},
                               {"edge1", l->area.edge1, 3},
                               {"edge2", l->area.edge2, 3}};
    return sc_params_in_range(p, params, (int)(sizeof params / sizeof params[0]), msg, size);
}

/* The emitter's size and orientation, and whether its method applies to its kind. */
static int validate_area(const sc_light *light, char *msg, size_t size)
{
    const sc_area *a = &light->area;
    if (!(a->radius >= 0.0)) {
        snprintf(msg, size, "radius=%g: must be >= 0", a->radius);
        return -1;
    }
    if (light->kind == SC_LIGHT_DISK && is_zero3(a->normal))
        return invalid(msg, size, "normal must not be the zero vector");
    double e[3] = {a->edge1[1] * a->edge2[2] - a->edge1[2] * a->edge2[1],
                   a->edge1[2] * a->edge2[0] - a->edge1[0] * a->edge2[2],
                   a->edge1[0] * a->edge2[1] - a->edge1[1] * a->edge2[0]};
    if (light->kind == SC_LIGHT_RECT && (is_zero3(e) || !isfinite(e[0] + e[1] + e[2])))
        return invalid(msg, size, "edge1, edge2: a degenerate rectangle (zero or parallel edges)");
    if (a->samples != 0 && (a->samples < 2 || a->samples > 512)) {
        snprintf(msg, size, "samples=%d: must be 2..512 (or 0: until tol)", a->samples);
        return -1;
    }
    if (!(a->tol > 0.0 && a->tol < 1.0)) {
        snprintf(msg, size, "tol=%g: must be in (0, 1)", a->tol);
        return -1;
    }
    return sc_area_method_applies(light->kind, a->method, NULL, msg, size);
}

int sc_light_validate(const sc_light *light, char *msg, size_t size)
{
    if (sc_light_is_area(light->kind))
        return validate_area(light, msg, size);
    if (light->kind != SC_LIGHT_POINT && is_zero3(light->dir))
        return invalid(msg, size, "dir must not be the zero vector");
    if (validate_atten(&light->atten, msg, size) < 0)
        return -1;
    return light->kind == SC_LIGHT_SPOT ? validate_spot(&light->spot, msg, size) : 0;
}
