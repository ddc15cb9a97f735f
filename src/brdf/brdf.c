/* BRDF dispatch, frames, defaults, names and validation (shadecalc/brdf.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brdf/brdf_internal.h"
#include "shadecalc/brdf_file.h"
#include "shadecalc/light.h"

static const char *const kind_names[] = {"lambert",    "phong",         "blinn-phong", "ward",
                                         "oren-nayar", "cook-torrance", "file"};
static const char *const form_names[][4] = {
    {"default", NULL},
    {"original", "modified", "normalized", NULL},
    {"normalized", "plain", NULL},
    {"1992", "duer", "gmd", NULL},
    {"qualitative", "full", NULL},
    {"walter", "1982", NULL},
    {"default", NULL},
};

const char *sc_brdf_kind_name(sc_brdf_kind kind) { return kind_names[kind]; }

const char *sc_brdf_form_name(sc_brdf_kind kind, int form)
{
    for (int i = 0; i <= form; i++)
        if (!form_names[kind][i])
            return NULL;
    return form_names[kind][form];
}

void sc_brdf_init(sc_brdf *b, sc_brdf_kind kind)
{
    *b = (sc_brdf){.kind = kind, .m = 32.0, .ax = 0.3, .ay = 0.3, .ior = 1.5};
    b->D = SC_D_GGX;
    b->G = SC_G_SMITH_CORRELATED;
    b->F = SC_F_SCHLICK;
    if (kind == SC_BRDF_PHONG)
        b->form = SC_PHONG_NORMALIZED;
    /* cook-torrance takes its specular colour from F (F0): c_spec is a plain multiplier */
    double spec = kind == SC_BRDF_COOK_TORRANCE                           ? 1.0
                  : kind == SC_BRDF_LAMBERT || kind == SC_BRDF_OREN_NAYAR ? 0.0
                                                                          : 0.2;
    for (int c = 0; c < 3; c++) {
        b->diff[c] = 0.8;
        b->spec[c] = spec;
        b->f0[c] = 0.04;
    }
}

double sc_lobe_pow(sc_prec p, double x, double y)
{
    if (y == 0.0)
        return 1.0;
    return x <= 0.0 ? 0.0 : sc_p_pow(p, x, y);
}

void sc_scale3(sc_prec p, const double colour[3], double scale, double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = sc_mul_reach(p, Q(colour[c]), scale);
}

double sc_alpha_floor(sc_prec p, double alpha)
{
    double a = Q(alpha > SC_ALPHA_FLOOR ? alpha : SC_ALPHA_FLOOR);
    return a > 0.0 ? a : sc_prec_ulp(p, 0.0); /* lowp: 1e-4 rounds to 0, its step is 2^-8 */
}

double sc_cos_floor(const brdf_geometry *g, double x)
{
    return x > g->cos_floor ? x : g->cos_floor;
}

/* ---- frames ---- */

static int normalize3(const double in[3], double out[3])
{
    double len = sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2]);
    if (!(len > 0.0) || !isfinite(len))
        return -1;
    for (int c = 0; c < 3; c++)
        out[c] = in[c] / len;
    return 0;
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Gram–Schmidt: t' = t − (t·n)n, normalized. Without a hint, e_x, or e_y where n_x is at least
 * twice each other component in magnitude (|n_x| >= 0.81 |n| there, so either axis keeps
 * |t'|² >= 0.2): decided on n as given by comparisons alone, which no rounding or scaling
 * changes, so that the float kernels choose the same axis for the same input (batch.h). */
int sc_frame_make(const double n[3], const double *tangent, sc_frame *out)
{
    if (normalize3(n, out->n) < 0)
        return -1;
    double hint[3] = {0, 0, 0};
    if (tangent)
        memcpy(hint, tangent, sizeof hint);
    else
        hint[fabs(n[0]) >= 2.0 * fmax(fabs(n[1]), fabs(n[2])) ? 1 : 0] = 1.0;
    double tn = hint[0] * out->n[0] + hint[1] * out->n[1] + hint[2] * out->n[2];
    double t[3];
    for (int c = 0; c < 3; c++)
        t[c] = hint[c] - tn * out->n[c];
    if (normalize3(t, out->t) < 0 || sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]) < 1e-9)
        return -1;
    cross3(out->n, out->t, out->b);
    return 0;
}

/* ---- evaluation ---- */

/* h = (l + v)/‖l + v‖, or n when l = −v (docs/formulas.md §1). */
static void half_vector(sc_prec p, const brdf_geometry *g, double h[3])
{
    double sum[3];
    for (int c = 0; c < 3; c++)
        sum[c] = sc_p_add(p, g->l[c], g->v[c]);
    if (sc_p_dot(p, sum, sum, 3) > 0.0)
        sc_p_normalize(p, sum, 3, h);
    else
        memcpy(h, g->frame->n, 3 * sizeof *h);
}

static void lambert(sc_prec p, const sc_brdf *b, const brdf_geometry *g, sc_brdf_terms *out)
{
    (void)g;
    sc_scale3(p, b->diff, Q(1.0 / SC_PI), out->diffuse);
}

/* The cosines of out and g (out cleared); whether l and v are above the horizon (else f = 0). */
static int geometry(sc_prec p, const sc_frame *frame, const double l[3], const double v[3],
                    brdf_geometry *g, sc_brdf_terms *out)
{
    memset(out, 0, sizeof *out);
    *g = (brdf_geometry){.frame = frame, .l = l, .v = v};
    g->cos_i = sc_p_dot(p, frame->n, l, 3);
    g->cos_o = sc_p_dot(p, frame->n, v, 3);
    half_vector(p, g, g->h);
    g->cos_h = sc_p_dot(p, frame->n, g->h, 3);
    out->cos_i = g->cos_i;
    out->cos_o = g->cos_o;
    out->cos_h = g->cos_h;
    return g->cos_i > 0.0 && g->cos_o > 0.0;
}

/* sc_brdf_eval with the divisions by cos θ_i, cos θ_o taking at least cos_floor. */
static void evaluate(sc_prec p, const sc_brdf *b, const sc_frame *frame, const double l[3],
                     const double v[3], double cos_floor, sc_brdf_terms *out)
{
    brdf_geometry g;
    if (!geometry(p, frame, l, v, &g, out))
        return; /* below the horizon: f = 0 */
    g.cos_floor = cos_floor;
    if (b->kind == SC_BRDF_FILE) {
        sc_brdf_file_eval(p, b, frame, l, v, out->f);
        return;
    }
    static void (*const models[])(sc_prec, const sc_brdf *, const brdf_geometry *,
                                  sc_brdf_terms *) = {
        lambert,      sc_brdf_phong,      sc_brdf_blinn_phong,
        sc_brdf_ward, sc_brdf_oren_nayar, sc_brdf_cook_torrance};
    models[b->kind](p, b, &g, out);
    for (int c = 0; c < 3; c++)
        out->f[c] = sc_p_add(p, out->diffuse[c], out->specular[c]);
}

void sc_brdf_eval(sc_prec p, const sc_brdf *b, const sc_frame *frame, const double l[3],
                  const double v[3], sc_brdf_terms *out)
{
    evaluate(p, b, frame, l, v, SC_COS_FLOOR, out);
}

/* Whether b is a BRDF file whose shader has failed. */
static int file_failed(const sc_brdf *b)
{
    return b->kind == SC_BRDF_FILE && sc_brdf_file_error(b->file) != NULL;
}

/* sc_brdf_eval_many one point at a time, the divisions by cos θ taking at least cos_floor. */
static int eval_each(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts, double cos_floor,
                     sc_brdf_terms *out)
{
    int done = n;
    for (int i = 0; i < n; i++) {
        evaluate(p, b, pts[i].frame, pts[i].l, pts[i].v, cos_floor, &out[i]);
        if (done == n && file_failed(b))
            done = i;
    }
    return done;
}

/* sc_brdf_eval_many of a BRDF file: the geometry of each point, then the shader over the points
 * above the horizon (gathered into `above`). */
static int eval_file_many(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                          sc_brdf_terms *out, sc_brdf_point *above, int *index, double (*f)[3])
{
    int m = 0, failed_before = file_failed(b);
    for (int i = 0; i < n; i++) {
        brdf_geometry g;
        if (geometry(p, pts[i].frame, pts[i].l, pts[i].v, &g, &out[i])) {
            above[m] = pts[i];
            index[m++] = i;
        }
    }
    int ran = sc_brdf_file_eval_many(p, b, m, above, f);
    for (int j = 0; j < m; j++)
        memcpy(out[index[j]].f, f[j], sizeof f[j]);
    return failed_before ? 0 : ran < m ? index[ran] : n;
}

int sc_brdf_eval_many(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                      sc_brdf_terms *out)
{
    if (b->kind != SC_BRDF_FILE || n <= 0)
        return eval_each(p, b, n, pts, SC_COS_FLOOR, out);
    sc_brdf_point *above = malloc((size_t)n * sizeof *above);
    int *index = malloc((size_t)n * sizeof *index);
    double(*f)[3] = malloc((size_t)n * sizeof *f);
    int done = above && index && f ? eval_file_many(p, b, n, pts, out, above, index, f)
                                   : eval_each(p, b, n, pts, SC_COS_FLOOR, out); /* out of memory */
    free(above);
    free(index);
    free(f);
    return done;
}

int sc_brdf_eval_many_unguarded(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                                sc_brdf_terms *out)
{
    return b->kind == SC_BRDF_FILE ? sc_brdf_eval_many(p, b, n, pts, out)
                                   : eval_each(p, b, n, pts, 0.0, out);
}

/* ---- validation ---- */

static int out_of_range(char *msg, size_t size, const char *key, double value, const char *range)
{
    snprintf(msg, size, "%s=%g: must be %s", key, value, range);
    return -1;
}

static int validate_colour(const char *key, const double c[3], char *msg, size_t size)
{
    for (int i = 0; i < 3; i++)
        if (!(c[i] >= 0.0) || !isfinite(c[i]))
            return out_of_range(msg, size, key, c[i], ">= 0 and finite");
    return 0;
}

int sc_brdf_check_range(sc_prec p, const sc_brdf *b, char *msg, size_t size)
{
    double sigma_deg = b->sigma * 180.0 / SC_PI;
    const sc_param params[] = {{"diff", b->diff, 3},     {"spec", b->spec, 3}, {"amb", b->amb, 3},
                               {"m", &b->m, 1},          {"alpha", &b->ax, 1}, {"ay", &b->ay, 1},
                               {"sigma", &sigma_deg, 1}, {"f0", b->f0, 3},     {"ior", &b->ior, 1}};
    return sc_params_in_range(p, params, (int)(sizeof params / sizeof params[0]), msg, size);
}

int sc_brdf_validate(const sc_brdf *b, char *msg, size_t size)
{
    if (validate_colour("diff", b->diff, msg, size) < 0 ||
        validate_colour("spec", b->spec, msg, size) < 0 ||
        validate_colour("amb", b->amb, msg, size) < 0 ||
        validate_colour("f0", b->f0, msg, size) < 0)
        return -1;
    if (!(b->m >= 0.0))
        return out_of_range(msg, size, "m", b->m, ">= 0");
    if (!(b->ax >= 0.0) || !isfinite(b->ax))
        return out_of_range(msg, size, "alpha", b->ax, ">= 0 and finite");
    if (!(b->ay >= 0.0) || !isfinite(b->ay))
        return out_of_range(msg, size, "ay", b->ay, ">= 0 and finite");
    if (!(b->sigma >= 0.0) || !isfinite(b->sigma))
        return out_of_range(msg, size, "sigma", b->sigma * 180.0 / SC_PI, ">= 0 degrees");
    if (!(b->ior > 0.0) || !isfinite(b->ior))
        return out_of_range(msg, size, "ior", b->ior, "> 0 and finite");
    return 0;
}
