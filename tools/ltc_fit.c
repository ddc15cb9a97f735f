/* ltc_fit — fits the table of linearly transformed cosines (src/light/ltc_table.c) to the GGX
 * specular lobe of the library (Cook–Torrance, Smith height-correlated G, evaluated by
 * sc_brdf_eval), and measures how well the compiled table does. docs/ltc.md describes the fit.
 *
 *   ltc_fit table FILE.c   fit every (α, cos θ_v) of the grid, write the table to FILE.c
 *   ltc_fit error          the compiled table against brute-force integration (a summary)
 *
 * `make ltc-table` runs both. Everything is deterministic: stratified samples, no random numbers.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "light/ltc.h"
#include "shadecalc/brdf.h"

static const double pi = 3.14159265358979323846;

/* Samples per cell: a KxK stratified grid for the moments (A, B, the mean direction) and for
 * the reference integrals of `error`, SxS per strategy for the fit's error. */
enum { MOMENT_K = 256, FIT_S = 32, FIT_ITERATIONS = 400 };

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double normalize3(double a[3])
{
    double len = sqrt(dot3(a, a));
    for (int c = 0; c < 3; c++)
        a[c] /= len;
    return len;
}

/* A 3x3 matrix in a struct: passed by const pointer without C11's qualifier rules on arrays. */
typedef struct {
    double m[3][3];
} mat3;

static void mat_vec(const mat3 *a, const double x[3], double out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = a->m[r][0] * x[0] + a->m[r][1] * x[1] + a->m[r][2] * x[2];
}

static double det3(const mat3 *a)
{
    const double(*m)[3] = a->m;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/* The inverse by cofactors (the transposed cofactor matrix over the determinant). */
static mat3 inverse3(const mat3 *a)
{
    double d = det3(a);
    mat3 out;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            out.m[r][c] = (a->m[r1][c1] * a->m[r2][c2] - a->m[r1][c2] * a->m[r2][c1]) / d;
        }
    return out;
}

/* ---- the lobe: f cos θ_i of the library's GGX, F = 1, in the view frame ---- */

typedef struct {
    double alpha, cos_v, v[3];
    sc_brdf brdf;
    sc_frame frame;
} lobe;

static lobe lobe_make(double alpha, double cos_v)
{
    lobe b = {.alpha = alpha, .cos_v = cos_v};
    b.v[0] = sqrt(1.0 - cos_v * cos_v);
    b.v[2] = cos_v;
    sc_ltc_brdf(alpha, NULL, &b.brdf);
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
    sc_frame_make(n, t, &b.frame);
    return b;
}

static double lobe_value(const lobe *b, const double l[3])
{
    if (l[2] <= 0.0)
        return 0.0;
    sc_brdf_terms terms;
    sc_brdf_eval(SC_DOUBLE, &b->brdf, &b->frame, l, b->v, &terms);
    return terms.specular[0] * l[2];
}

/* GGX D(h) = 1/(π α² (s + h_z²)²), s = (h_x² + h_y²)/α². */
static double ggx_d(double alpha, const double h[3])
{
    double s = (h[0] * h[0] + h[1] * h[1]) / (alpha * alpha) + h[2] * h[2];
    return 1.0 / (pi * alpha * alpha * s * s);
}

/* The density of l when h is drawn from D(h) cos θ_h and l is v reflected about h. */
static double ndf_pdf(const lobe *b, const double l[3])
{
    double h[3] = {l[0] + b->v[0], l[1] + b->v[1], l[2] + b->v[2]};
    if (normalize3(h) == 0.0)
        return 0.0;
    if (h[2] < 0.0)
        for (int c = 0; c < 3; c++)
            h[c] = -h[c];
    double vh = fabs(dot3(b->v, h));
    return vh > 0.0 ? ggx_d(b->alpha, h) * h[2] / (4.0 * vh) : 0.0;
}

/* Stratum (i, j) of a KxK grid: h from D cos θ_h (tan²θ_h = α² u/(1 − u)), l = reflect(v). */
static void ndf_sample(const lobe *b, int i, int j, int k, double l[3])
{
    double u1 = (i + 0.5) / k, u2 = (j + 0.5) / k;
    double t2 = b->alpha * b->alpha * u1 / (1.0 - u1), ct = 1.0 / sqrt(1.0 + t2);
    double st = sqrt(t2) * ct, phi = 2.0 * pi * u2;
    double h[3] = {st * cos(phi), st * sin(phi), ct}, vh = dot3(b->v, h);
    for (int c = 0; c < 3; c++)
        l[c] = 2.0 * vh * h[c] - b->v[c];
}

/* Schlick's (1 − v·h)⁵ at l, h the half vector of l and v. */
static double schlick_tail(const lobe *b, const double l[3])
{
    double h[3] = {l[0] + b->v[0], l[1] + b->v[1], l[2] + b->v[2]};
    normalize3(h);
    double x = 1.0 - fmin(fmax(dot3(b->v, h), 0.0), 1.0);
    return x * x * x * x * x;
}

typedef struct {
    double a, b;   /* ∫ f cos dω, ∫ f (1 − v·h)⁵ cos dω */
    double dir[3]; /* the lobe's mean direction, normalised */
} moments;

/* Calls visit(ctx, b, l, w) for each of the KxK stratified GGX samples where the lobe is not
 * 0, w = f cos θ_i / (pdf K²): Σ w g(l) estimates ∫ f cos θ_i g dω. */
typedef void lobe_visitor(void *ctx, const lobe *b, const double l[3], double w);

static void for_each_sample(const lobe *b, lobe_visitor *visit, void *ctx)
{
    double n = (double)MOMENT_K * MOMENT_K;
    for (int i = 0; i < MOMENT_K; i++)
        for (int j = 0; j < MOMENT_K; j++) {
            double l[3];
            ndf_sample(b, i, j, MOMENT_K, l);
            double value = lobe_value(b, l), pdf = ndf_pdf(b, l);
            if (value != 0.0 && pdf != 0.0)
                visit(ctx, b, l, value / pdf / n);
        }
}

static void add_moments(void *ctx, const lobe *b, const double l[3], double w)
{
    moments *m = ctx;
    m->a += w;
    m->b += w * schlick_tail(b, l);
    for (int c = 0; c < 3; c++)
        m->dir[c] += w * l[c];
}

static moments lobe_moments(const lobe *b)
{
    moments m = {0};
    for_each_sample(b, add_moments, &m);
    m.dir[1] = 0.0; /* the lobe is symmetric about the plane of n and v */
    normalize3(m.dir);
    return m;
}

/* ---- the linearly transformed cosine ---- */

typedef struct {
    mat3 m, minv;
    double det_inv, mass; /* mass: its share above the horizon */
} ltc;

/* M = [X Y Z] [[a, 0, skew], [0, b, 0], [0, 0, 1]], Z the lobe's mean direction. */
static ltc ltc_make(const double dir[3], const double p[3])
{
    double a = exp(p[0]), b = exp(p[1]), skew = p[2];
    double x[3] = {dir[2], 0.0, -dir[0]};
    double s[3][3] = {{a, 0, skew}, {0, b, 0}, {0, 0, 1}}, frame[3][3];
    for (int r = 0; r < 3; r++) {
        frame[r][0] = x[r];
        frame[r][1] = r == 1;
        frame[r][2] = dir[r];
    }
    ltc t;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            t.m.m[r][c] = frame[r][0] * s[0][c] + frame[r][1] * s[1][c] + frame[r][2] * s[2][c];
    t.minv = inverse3(&t.m);
    t.det_inv = fabs(det3(&t.minv));
    double row = sqrt(dot3(t.m.m[2], t.m.m[2]));
    t.mass = 0.5 * (1.0 + t.m.m[2][2] / row); /* the lune, as in ltc.c: mass_above_horizon */
    return t;
}

/* D(w) = D_o(M⁻¹w/|M⁻¹w|) |det M⁻¹| / |M⁻¹w|³ with D_o = max(z, 0)/π, w a unit vector. */
static double ltc_density(const ltc *t, const double w[3])
{
    double o[3];
    mat_vec(&t->minv, w, o);
    double len = sqrt(dot3(o, o));
    return o[2] <= 0.0 ? 0.0 : o[2] / (pi * len) * t->det_inv / (len * len * len);
}

/* ---- the fit ---- */

typedef struct {
    double l[3], value, pdf; /* a direction, the normalised lobe there, the NDF sampling density */
} sample;

typedef struct {
    const lobe *lobe;
    moments mom;
    sample brdf_samples[FIT_S * FIT_S];
    double cos_samples[FIT_S * FIT_S][3];
} fit_problem;

static void fit_prepare(fit_problem *fp, const lobe *b)
{
    fp->lobe = b;
    fp->mom = lobe_moments(b);
    for (int i = 0; i < FIT_S; i++)
        for (int j = 0; j < FIT_S; j++) {
            sample *s = &fp->brdf_samples[i * FIT_S + j];
            ndf_sample(b, i, j, FIT_S, s->l);
            s->value = lobe_value(b, s->l) / fp->mom.a;
            s->pdf = ndf_pdf(b, s->l);
            double u1 = (i + 0.5) / FIT_S, phi = 2.0 * pi * (j + 0.5) / FIT_S, r = sqrt(u1);
            double *w = fp->cos_samples[i * FIT_S + j]; /* cosine-distributed (Malley) */
            w[0] = r * cos(phi);
            w[1] = r * sin(phi);
            w[2] = sqrt(1.0 - u1);
        }
}

/* |lobe − LTC|³ at l, over the density of drawing l from either strategy (balance heuristic).
 * The LTC is compared as evaluated: cut at the horizon and renormalised. */
static double cubed_difference(const ltc *t, const double l[3], double lobe_value, double pdf)
{
    double d = ltc_density(t, l), shown = l[2] > 0.0 ? d / t->mass : 0.0;
    double diff = fabs(lobe_value - shown), mix = pdf + d;
    return mix > 0.0 ? diff * diff * diff / mix : 0.0;
}

/* The L3 distance between the normalised lobe and the LTC with parameters p (Heitz et al.
 * 2016: importance-sampled from both distributions). */
static double fit_error(const double p[3], const fit_problem *fp)
{
    ltc t = ltc_make(fp->mom.dir, p);
    if (!(t.mass > 1e-3))
        return HUGE_VAL;
    double err = 0.0;
    for (int k = 0; k < FIT_S * FIT_S; k++) {
        const sample *s = &fp->brdf_samples[k];
        err += cubed_difference(&t, s->l, s->value, s->pdf);
        double l[3];
        mat_vec(&t.m, fp->cos_samples[k], l);
        normalize3(l);
        err += cubed_difference(&t, l, lobe_value(fp->lobe, l) / fp->mom.a, ndf_pdf(fp->lobe, l));
    }
    return err / (FIT_S * FIT_S);
}

/* Nelder–Mead (1965) over the three parameters, from x with initial steps `step`. */
static double nelder_mead(const fit_problem *fp, double x[3], double step)
{
    double simplex[4][3], f[4];
    for (int v = 0; v < 4; v++) {
        memcpy(simplex[v], x, sizeof simplex[v]);
        if (v > 0)
            simplex[v][v - 1] += step;
        f[v] = fit_error(simplex[v], fp);
    }
    for (int it = 0; it < FIT_ITERATIONS; it++) {
        int best = 0, worst = 0, second = 0;
        for (int v = 1; v < 4; v++) {
            best = f[v] < f[best] ? v : best;
            worst = f[v] > f[worst] ? v : worst;
        }
        second = best;
        for (int v = 0; v < 4; v++)
            if (v != worst && f[v] > f[second])
                second = v;
        if (f[worst] - f[best] <= 1e-9 * fabs(f[best]))
            break;
        double centre[3] = {0, 0, 0}, trial[3], trial2[3];
        for (int v = 0; v < 4; v++)
            for (int c = 0; c < 3 && v != worst; c++)
                centre[c] += simplex[v][c] / 3.0;
        for (int c = 0; c < 3; c++)
            trial[c] = centre[c] + (centre[c] - simplex[worst][c]);
        double ft = fit_error(trial, fp);
        if (ft < f[best]) { /* expand */
            for (int c = 0; c < 3; c++)
                trial2[c] = centre[c] + 2.0 * (centre[c] - simplex[worst][c]);
            double fe = fit_error(trial2, fp);
            if (fe < ft) {
                memcpy(trial, trial2, sizeof trial);
                ft = fe;
            }
        } else if (ft >= f[second]) { /* contract toward the better of worst and reflected */
            const double *from = ft < f[worst] ? trial : simplex[worst];
            for (int c = 0; c < 3; c++)
                trial2[c] = centre[c] + 0.5 * (from[c] - centre[c]);
            double fc = fit_error(trial2, fp);
            if (fc < fmin(ft, f[worst])) {
                memcpy(trial, trial2, sizeof trial);
                ft = fc;
            } else { /* shrink toward the best */
                for (int v = 0; v < 4; v++) {
                    if (v == best)
                        continue;
                    for (int c = 0; c < 3; c++)
                        simplex[v][c] = simplex[best][c] + 0.5 * (simplex[v][c] - simplex[best][c]);
                    f[v] = fit_error(simplex[v], fp);
                }
                continue;
            }
        }
        memcpy(simplex[worst], trial, sizeof trial);
        f[worst] = ft;
    }
    int best = 0;
    for (int v = 1; v < 4; v++)
        best = f[v] < f[best] ? v : best;
    memcpy(x, simplex[best], sizeof simplex[best]);
    return f[best];
}

/* The grid of light/ltc.h. */
static double grid_alpha(double i)
{
    double r = i / (SC_LTC_SIZE - 1);
    return fmax(r * r, SC_LTC_ALPHA_MIN);
}

static double grid_cos(double j)
{
    double u = j / (SC_LTC_SIZE - 1);
    return fmax(1.0 - u * u, SC_LTC_COS_MIN);
}

typedef struct {
    double entry[SC_LTC_FIELDS];
    double params[3], error;
} fitted;

static fitted fit_cell(int i, int j, const double start[3], fit_problem *fp)
{
    lobe b = lobe_make(grid_alpha(i), grid_cos(j));
    fit_prepare(fp, &b);
    fitted out;
    memcpy(out.params, start, sizeof out.params);
    out.error = nelder_mead(fp, out.params, 0.1);
    out.error = nelder_mead(fp, out.params, 0.02); /* a restart, against a collapsed simplex */
    ltc t = ltc_make(fp->mom.dir, out.params);
    double k = t.minv.m[2][2]; /* M⁻¹ up to a factor: the carried polygon is normalised */
    out.entry[SC_LTC_M00] = t.minv.m[0][0] / k;
    out.entry[SC_LTC_M02] = t.minv.m[0][2] / k;
    out.entry[SC_LTC_M11] = t.minv.m[1][1] / k;
    out.entry[SC_LTC_M20] = t.minv.m[2][0] / k;
    out.entry[SC_LTC_A] = fp->mom.a;
    out.entry[SC_LTC_B] = fp->mom.b;
    return out;
}

static int write_table(const char *path, fitted (*cells)[SC_LTC_SIZE], double seconds)
{
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp", path) >= (int)sizeof tmp) {
        fprintf(stderr, "ltc_fit: %s: path too long\n", path);
        return -1;
    }
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "ltc_fit: %s: %s\n", tmp, strerror(errno));
        return -1;
    }
    fprintf(
        f,
        "/* Generated by tools/ltc_fit.c (`make ltc-table`, %.0f s on one core): do not edit.\n"
        " * The LTC fit of the library's GGX lobe (Smith height-correlated G, F = 1), per\n"
        " * (cos θ_v, α) of the grid of light/ltc.h: M⁻¹ (m00, m02, m11, m20; m22 = 1), the\n"
        " * magnitude A and the Fresnel part B. Each cell minimises the L3 distance between the\n"
        " * normalised lobe and the LTC by Nelder–Mead (%dx%d samples per strategy); A and B\n"
        " * from %dx%d stratified GGX samples. docs/ltc.md: the method and the fit's error. */\n"
        "/* clang-format off */\n#include \"light/ltc.h\"\n\n"
        "const double sc_ltc_table[SC_LTC_SIZE][SC_LTC_SIZE][SC_LTC_FIELDS] = {\n",
        seconds, FIT_S, FIT_S, MOMENT_K, MOMENT_K);
    for (int j = 0; j < SC_LTC_SIZE; j++) {
        fprintf(f, "  { /* cos θ_v = %.6f */\n", grid_cos(j));
        for (int i = 0; i < SC_LTC_SIZE; i++) {
            const double *e = cells[j][i].entry;
            fprintf(f, "    {%.9e, %.9e, %.9e, %.9e, %.9e, %.9e},\n", e[0], e[1], e[2], e[3], e[4],
                    e[5]);
        }
        fprintf(f, "  },\n");
    }
    fprintf(f, "};\n");
    if (ferror(f) | fclose(f) || rename(tmp, path) != 0) {
        fprintf(stderr, "ltc_fit: writing %s: %s\n", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

/* Rows of cos θ_v from the normal outward, each from α = 1 down: every cell starts from its
 * neighbour's fit (Heitz et al. 2016 fit from smooth to sharp lobes the same way). */
static int fit_table(const char *path)
{
    static fitted cells[SC_LTC_SIZE][SC_LTC_SIZE];
    static fit_problem fp;
    clock_t start = clock();
    for (int j = 0; j < SC_LTC_SIZE; j++) {
        for (int i = SC_LTC_SIZE - 1; i >= 0; i--) {
            double first[3] = {0, 0, 0};
            const double *from = i < SC_LTC_SIZE - 1 ? cells[j][i + 1].params
                                 : j > 0             ? cells[j - 1][i].params
                                                     : first;
            cells[j][i] = fit_cell(i, j, from, &fp);
        }
        fprintf(
            stderr, "ltc_fit: row %d/%d (cos θ_v %.4f), L3 error at α = 1: %.3g, at α_min: %.3g\n",
            j + 1, SC_LTC_SIZE, grid_cos(j), cells[j][SC_LTC_SIZE - 1].error, cells[j][0].error);
    }
    double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    fprintf(stderr, "ltc_fit: fit in %.0f s\n", seconds);
    return write_table(path, cells, seconds);
}

/* ---- the error of the compiled table ---- */

/* A square (half-size `size`) or a disk (radius `size`) around `centre`, in the plane spanned by
 * e1, e2 (orthonormal), emitting toward the shading point at the origin (two-sided). */
typedef struct {
    int disk;
    double centre[3], e1[3], e2[3], normal[3], size;
} emitter;

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Centred at `centre`, its plane at angle `tilt` (radians, about e2) from facing the origin. */
static emitter emitter_make(int disk, const double centre[3], double size, double tilt)
{
    emitter e = {.disk = disk, .size = size};
    memcpy(e.centre, centre, sizeof e.centre);
    double facing[3] = {-centre[0], -centre[1], -centre[2]}, up[3] = {0, 1, 0}, x[3];
    normalize3(facing);
    if (fabs(facing[1]) > 0.9)
        up[1] = 0, up[0] = 1;
    cross3(up, facing, x);
    normalize3(x);
    cross3(facing, x, e.e2);
    for (int c = 0; c < 3; c++) {
        e.normal[c] = cos(tilt) * facing[c] + sin(tilt) * x[c];
        e.e1[c] = cos(tilt) * x[c] - sin(tilt) * facing[c];
    }
    return e;
}

static int emitter_hit(const emitter *e, const double l[3])
{
    double along = dot3(l, e->normal);
    if (along == 0.0)
        return 0;
    double t = dot3(e->centre, e->normal) / along, q[3];
    if (t <= 0.0)
        return 0;
    for (int c = 0; c < 3; c++)
        q[c] = t * l[c] - e->centre[c];
    double u = dot3(q, e->e1), v = dot3(q, e->e2);
    return e->disk ? u * u + v * v <= e->size * e->size : fabs(u) <= e->size && fabs(v) <= e->size;
}

/* Each measurement with F = 1 (the fit alone) and with Schlick's F0 = 0.04 (a dielectric: the
 * Fresnel split spreads F over the lobe as the LTC's shape, most wrong where F varies most). */
enum { FRESNELS = 2 };
static const double fresnel_f0[FRESNELS] = {1.0, 0.04};

/* The emitter by LTC, spec[k] with F0 fresnel_f0[k]; a disk as a polygon of `sides` sides
 * (0: sc_ltc_disk). */
static sc_ltc_result emitter_ltc(const emitter *e, const lobe *b, int sides)
{
    const double f0[3] = {fresnel_f0[0], fresnel_f0[1], 0.0};
    sc_ltc_result r;
    if (e->disk && sides == 0) {
        sc_ltc_disk(&b->frame, b->v, b->alpha, f0, e->centre, e->normal, e->size, 1, &r);
        return r;
    }
    static double verts[SC_LTC_MAX_VERTS][3];
    int n = e->disk ? sides : 4;
    /* a disk's polygon has its area: n sin(2π/n) R'²/2 = π R² */
    double step = 2.0 * pi / n,
           radius = e->disk ? e->size * sqrt(2.0 * pi / (n * sin(step))) : e->size * sqrt(2.0);
    for (int k = 0; k < n; k++) {
        double phi = k * step + (e->disk ? 0.0 : pi / 4);
        for (int c = 0; c < 3; c++)
            verts[k][c] = e->centre[c] + radius * (cos(phi) * e->e1[c] + sin(phi) * e->e2[c]);
    }
    sc_ltc_polygon(&b->frame, b->v, b->alpha, f0, (const double(*)[3])verts, n, 1, &r);
    return r;
}

typedef struct {
    const emitter *e;
    int count;
    double (*out)[FRESNELS], *whole;
} reference_sums;

static void add_reference(void *ctx, const lobe *b, const double l[3], double w)
{
    reference_sums *r = ctx;
    double tail = schlick_tail(b, l);
    for (int f = 0; f < FRESNELS; f++) {
        double wf = w * (fresnel_f0[f] + (1.0 - fresnel_f0[f]) * tail);
        r->whole[f] += wf;
        for (int k = 0; k < r->count; k++)
            r->out[k][f] += emitter_hit(&r->e[k], l) ? wf : 0.0;
    }
}

/* ∫ f F cos dω over each emitter (out[k][f]) and over the hemisphere (whole[f]), F with F0
 * fresnel_f0[f], from stratified GGX samples. */
static void reference(const lobe *b, const emitter *e, int count, double (*out)[FRESNELS],
                      double whole[FRESNELS])
{
    memset(out, 0, count * sizeof *out);
    memset(whole, 0, FRESNELS * sizeof *whole);
    reference_sums sums = {e, count, out, whole};
    for_each_sample(b, add_reference, &sums);
}

typedef struct {
    double max, sum, max_alpha, max_cos; /* relative error where the emitter holds >= 1% */
    double max_of_lobe;                  /* max |got − want| / (the whole lobe) everywhere */
    int count, skipped;
} error_stats;

/* Adds |got − want| against want (unless the emitter holds under 1% of `whole`, the integral
 * over the hemisphere) and against `whole`. */
static void add_error(error_stats *s, double got, double want, double whole, const lobe *b)
{
    double diff = fabs(got - want);
    if (!(whole > 0.0) && diff == 0.0) { /* nothing of the emitter above the horizon */
        s->skipped++;
        return;
    }
    s->max_of_lobe = fmax(s->max_of_lobe, diff / whole);
    if (!(want >= 1e-2 * whole)) {
        s->skipped++;
        return;
    }
    double rel = diff / want;
    s->sum += rel;
    s->count++;
    if (rel > s->max) {
        s->max = rel;
        s->max_alpha = b->alpha;
        s->max_cos = b->cos_v;
    }
}

/* One row of a Markdown table: what, relative max (where), mean, count, max of the lobe. */
static void print_stats(const char *what, const error_stats *s)
{
    printf("| %s | %.3g (α %.3g, cos θ_v %.3g) | %.3g | %d (%d) | %.3g |\n", what, s->max,
           s->max_alpha, s->max_cos, s->count ? s->sum / s->count : 0.0, s->count, s->skipped,
           s->max_of_lobe);
}

static void print_header(void)
{
    printf("| emitter, views, F0, where | max relative error | mean | points (< 1%% of the lobe, "
           "left out) | max error / whole lobe |\n|---|---|---|---|---|\n");
}

/* Views up to 80° from the normal, and the grazing ones beyond (LTC's worst). */
enum { VIEW_CLASSES = 2 };
static const char *view_class_name[VIEW_CLASSES] = {"θ_v ≤ 80°", "θ_v > 80°"};
static int view_class(double cos_v) { return cos_v < cos(80.0 * pi / 180.0); }

enum { SQUARES = 3 };
static const char *square_name[SQUARES] = {"square ½-size 0.2 on the mirror direction",
                                           "square ½-size 1 on the mirror direction",
                                           "square ½-size 0.5 toward (0, 1, 1)"};

typedef error_stats square_stats[VIEW_CLASSES][FRESNELS][SQUARES];

/* One point of the table: three squares at distance 1, by LTC and by GGX sampling. */
static void measure_point(double alpha, double cos_v, square_stats stats)
{
    lobe b = lobe_make(alpha, cos_v);
    double st = sqrt(1.0 - cos_v * cos_v);
    const double mirror[3] = {-st, 0.0, cos_v}, side[3] = {0.0, sqrt(0.5), sqrt(0.5)};
    emitter sq[SQUARES] = {emitter_make(0, mirror, 0.2, 0.0), emitter_make(0, mirror, 1.0, 0.0),
                           emitter_make(0, side, 0.5, 0.0)};
    double ref[SQUARES][FRESNELS], whole[FRESNELS];
    reference(&b, sq, SQUARES, ref, whole);
    for (int k = 0; k < SQUARES; k++) {
        sc_ltc_result r = emitter_ltc(&sq[k], &b, 0);
        for (int f = 0; f < FRESNELS; f++)
            add_error(&stats[view_class(cos_v)][f][k], r.spec[f], ref[k][f], whole[f], &b);
    }
}

/* The squares at the nodes, where the table is what the fit gave, and at the cells' centres,
 * where it is interpolated. */
static void measure_squares(void)
{
    static square_stats nodes, centres;
    for (int j = 0; j < SC_LTC_SIZE; j++)
        for (int i = 0; i < SC_LTC_SIZE; i++) {
            measure_point(grid_alpha(i), grid_cos(j), nodes);
            if (i + 1 < SC_LTC_SIZE && j + 1 < SC_LTC_SIZE)
                measure_point(grid_alpha(i + 0.5), grid_cos(j + 0.5), centres);
        }
    print_header();
    char what[160];
    for (int k = 0; k < SQUARES; k++)
        for (int g = 0; g < VIEW_CLASSES; g++)
            for (int f = 0; f < FRESNELS; f++) {
                snprintf(what, sizeof what, "%s, %s, F0 %g, nodes", square_name[k],
                         view_class_name[g], fresnel_f0[f]);
                print_stats(what, &nodes[g][f][k]);
                snprintf(what, sizeof what, "%s, %s, F0 %g, centres", square_name[k],
                         view_class_name[g], fresnel_f0[f]);
                print_stats(what, &centres[g][f][k]);
            }
}

enum { DISKS = 4 };

/* Disks: Lambert on the axis against π R²/(R² + h²); the 64-sided stand-in against one of
 * SC_LTC_MAX_VERTS sides (the disk's own error, LTC or not); GGX against sampling. */
static void measure_disks(void)
{
    error_stats axis = {0}, cosine = {0}, spec = {0}, ggx[VIEW_CLASSES][FRESNELS] = {{{0}}};
    lobe b = lobe_make(0.5, 1.0);
    for (double r = 0.05; r < 20.0; r *= 1.5) { /* R/h, h = 1 */
        const double centre[3] = {0, 0, 1};
        emitter e = emitter_make(1, centre, r, 0.0);
        double want = pi * r * r / (1.0 + r * r);
        add_error(&axis, emitter_ltc(&e, &b, 0).cosine, want, want, &b);
    }
    const double centres[DISKS][3] = {
        {0, 0, 1}, {-0.8, 0.2, 0.6}, {0.5, -0.7, 0.3}, {1, 0.5, -0.1}};
    const double radii[DISKS] = {0.3, 0.6, 0.5, 0.8}, tilts[DISKS] = {0.0, 0.4, -0.9, 1.2};
    emitter disks[DISKS];
    for (int k = 0; k < DISKS; k++)
        disks[k] = emitter_make(1, centres[k], radii[k], tilts[k]);
    for (int j = 0; j < SC_LTC_SIZE; j += 3)
        for (int i = 0; i < SC_LTC_SIZE; i += 3) {
            b = lobe_make(grid_alpha(i + 0.5), grid_cos(j + 0.5));
            double ref[DISKS][FRESNELS], whole[FRESNELS];
            reference(&b, disks, DISKS, ref, whole);
            for (int k = 0; k < DISKS; k++) {
                sc_ltc_result d = emitter_ltc(&disks[k], &b, 0);
                sc_ltc_result fine = emitter_ltc(&disks[k], &b, SC_LTC_MAX_VERTS);
                add_error(&cosine, d.cosine, fine.cosine, fine.cosine, &b);
                add_error(&spec, d.spec[0], fine.spec[0], whole[0], &b);
                for (int f = 0; f < FRESNELS; f++)
                    add_error(&ggx[view_class(b.cos_v)][f], d.spec[f], ref[k][f], whole[f], &b);
            }
        }
    print_header();
    print_stats("disk, Lambert on the axis, against π R²/(R² + h²)", &axis);
    print_stats("disk, Lambert, against 256 sides", &cosine);
    print_stats("disk, GGX by LTC, F0 1, against 256 sides", &spec);
    char what[160];
    for (int g = 0; g < VIEW_CLASSES; g++)
        for (int f = 0; f < FRESNELS; f++) {
            snprintf(what, sizeof what, "disk, GGX by LTC, %s, F0 %g, against sampling",
                     view_class_name[g], fresnel_f0[f]);
            print_stats(what, &ggx[g][f]);
        }
}

static int measure_table(void)
{
    clock_t start = clock();
    measure_squares();
    printf("\n");
    measure_disks();
    printf("\nmeasured in %.0f s of CPU (%dx%d stratified GGX samples per reference)\n",
           (double)(clock() - start) / CLOCKS_PER_SEC, MOMENT_K, MOMENT_K);
    return ferror(stdout) ? -1 : 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "table") == 0)
        return fit_table(argv[2]) == 0 ? 0 : 1;
    if (argc == 2 && strcmp(argv[1], "error") == 0)
        return measure_table() == 0 ? 0 : 1;
    fprintf(stderr, "usage: ltc_fit table FILE.c | ltc_fit error\n");
    return 2;
}
