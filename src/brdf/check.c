/* Directional albedo by quadrature about the mirror direction, and reciprocity
 * (shadecalc/check.h). */
#include "shadecalc/check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "brdf/brdf_internal.h"
#include "util/quadrature.h"

static const double pi = 3.14159265358979323846;
/* Panels shrink geometrically toward the lobe: π·2^-k for k = 1..K, K at least MIN_PANEL_EXP
 * and enough for the narrowest panel to be an eighth of the lobe's width. A lobe narrower than
 * MIN_LOBE_WIDTH is not resolved: cos θ near 1 is known to 2^-53, so cos^m θ with
 * m·2^-53 > 10^-3 (Blinn-Phong m > 8·10^12, width 2√(2/m) < 10^-6) is, as evaluated in double,
 * a staircase with steps above 0.1 %; K would exceed MAX_PANEL_EXP. */
#define MIN_LOBE_WIDTH 1e-6
enum { MAX_ORDER = 32, MIN_PANEL_EXP = 12, MAX_PANEL_EXP = 25 };

/* Sorted, de-duplicated breakpoints in [lo, hi]: the ends, each `centre ± π·2^-k` for
 * k = 1..panel_exp (panels shrinking geometrically toward the lobe), and `extra`. */
static int breakpoints(double lo, double hi, double centre, const double *extra, int n_extra,
                       int panel_exp, double *out)
{
    int n = 0;
    out[n++] = lo;
    out[n++] = hi;
    for (int i = 0; i < n_extra; i++)
        out[n++] = extra[i];
    for (int k = 1; k <= panel_exp; k++) {
        out[n++] = centre - pi * ldexp(1.0, -k);
        out[n++] = centre + pi * ldexp(1.0, -k);
    }
    out[n++] = centre;
    int m = 0;
    for (int i = 0; i < n; i++) { /* insertion sort of the points inside [lo, hi] */
        double x = out[i];
        if (x < lo || x > hi)
            continue;
        int j = m++;
        while (j > 0 && out[j - 1] > x) {
            out[j] = out[j - 1];
            j--;
        }
        out[j] = x;
    }
    int u = 0;
    for (int i = 0; i < m; i++)
        if (u == 0 || out[i] - out[u - 1] > 1e-15)
            out[u++] = out[i];
    return u;
}

/* Composite Gauss–Legendre nodes and weights over the panels between breakpoints. */
static int composite_nodes(const double *bp, int n_bp, int order, double *node, double *weight)
{
    double x[MAX_ORDER], w[MAX_ORDER];
    sc_gauss_legendre(order, x, w);
    int n = 0;
    for (int p = 0; p + 1 < n_bp; p++)
        for (int k = 0; k < order; k++) {
            double half = 0.5 * (bp[p + 1] - bp[p]);
            node[n] = bp[p] + half * (1.0 + x[k]);
            weight[n++] = half * w[k];
        }
    return n;
}

enum { MAX_BREAKS = 2 * MAX_PANEL_EXP + 8, MAX_NODES = MAX_BREAKS * MAX_ORDER };

/* The angular width of the specular lobe about the mirror direction (1/e of its peak):
 * √(2/m) for Phong's cos^m α_r, 2√(2/m) for Blinn-Phong's cos^m θ_h (θ_h is half the angle to
 * the mirror direction), 2α for Ward and the microfacet models (α floored as they floor it);
 * π for the models without a lobe. */
static double lobe_width(const sc_brdf *b)
{
    double alpha = fmax(fmin(b->ax, b->ay), 1e-4); /* SC_ALPHA_FLOOR */
    switch (b->kind) {
    case SC_BRDF_PHONG: return b->m > 2.0 ? sqrt(2.0 / b->m) : pi;
    case SC_BRDF_BLINN_PHONG: return b->m > 8.0 ? 2.0 * sqrt(2.0 / b->m) : pi;
    case SC_BRDF_WARD:
    case SC_BRDF_COOK_TORRANCE: return fmin(2.0 * alpha, pi);
    default: return pi;
    }
}

/* The K of the panels π·2^-k that resolve a lobe of width w >= MIN_LOBE_WIDTH: π·2^-K <= w/8. */
static int panel_exponent(double w)
{
    int k = (int)ceil(log2(8.0 * pi / fmax(w, MIN_LOBE_WIDTH)));
    return k < MIN_PANEL_EXP ? MIN_PANEL_EXP : k > MAX_PANEL_EXP ? MAX_PANEL_EXP : k;
}

/* ∫ over the upper hemisphere of f(l, v) cos θ_o dω in (θ_o, φ_o), with panels refined
 * toward the mirror direction (θ_i, π) and breakpoints at θ_i and φ = π/2, 3π/2 (the kinks of
 * the Oren–Nayar max terms); the horizon θ_o = π/2 is an end, not a kink. f is the model as
 * written, without the floor of shade's divisions by cos θ_o (sc_brdf_eval_many_unguarded).
 * Each ring is summed on its own, then the rings: returns the number of terms the longest of
 * these sums adds (nodes in θ plus nodes in φ), which bounds their rounding. */
static int integrate(const sc_brdf *b, const sc_frame *f, const double l[3], double theta_i,
                     int order, int panel_exp, sc_brdf_point *ring, sc_brdf_terms *terms,
                     double out[3])
{
    double th[MAX_NODES], tw[MAX_NODES], ph[MAX_NODES], pw[MAX_NODES]; /* 99 KB: thread-safe */
    double bp[MAX_BREAKS];
    const double phi_kinks[2] = {pi / 2.0, 1.5 * pi};
    int nt = composite_nodes(bp, breakpoints(0.0, pi / 2.0, theta_i, NULL, 0, panel_exp, bp), order,
                             th, tw);
    int np = composite_nodes(bp, breakpoints(0.0, 2.0 * pi, pi, phi_kinks, 2, panel_exp, bp), order,
                             ph, pw);
    memset(out, 0, 3 * sizeof *out);
    for (int i = 0; i < nt; i++) { /* a ring of constant θ_o at a time */
        double st = sin(th[i]), ct = cos(th[i]), ring_sum[3] = {0, 0, 0};
        for (int j = 0; j < np; j++) {
            ring[j] = (sc_brdf_point){
                f, {l[0], l[1], l[2]}, {st * cos(ph[j]), st * sin(ph[j]), ct}};
        }
        sc_brdf_eval_many_unguarded(SC_DOUBLE, b, np, ring, terms);
        for (int j = 0; j < np; j++)
            for (int c = 0; c < 3; c++)
                ring_sum[c] += pw[j] * terms[j].f[c];
        for (int c = 0; c < 3; c++)
            out[c] += tw[i] * st * ct * ring_sum[c];
    }
    return nt + np;
}

int sc_albedo(const sc_brdf *b, double theta_i_deg, int order, sc_albedo_result *out)
{
    if (order < 2 || order > MAX_ORDER)
        order = 16;
    sc_frame f;
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
    sc_frame_make(n, t, &f);
    double th = theta_i_deg * pi / 180.0;
    double l[3] = {sin(th), 0.0, cos(th)}, coarse[3];
    double width = lobe_width(b);
    int resolved = width >= MIN_LOBE_WIDTH, panel_exp = panel_exponent(width);
    sc_brdf_point *ring = malloc(MAX_NODES * sizeof *ring);
    sc_brdf_terms *terms = malloc(MAX_NODES * sizeof *terms);
    if (!ring || !terms) { /* out of memory: no estimate */
        free(ring);
        free(terms);
        for (int c = 0; c < 3; c++)
            out->albedo[c] = NAN, out->error[c] = INFINITY;
        return -1;
    }
    int terms_summed = integrate(b, &f, l, th, order, panel_exp, ring, terms, out->albedo);
    integrate(b, &f, l, th, order / 2 > 1 ? order / 2 : 2, panel_exp, ring, terms, coarse);
    free(ring);
    free(terms);
    /* plus the staircase of the lobe as double evaluates it: cos^m θ with m ~ 8/width²
     * carries a relative rounding error up to m·2^-53 (see MIN_LOBE_WIDTH); plus the rounding
     * of the sums, at most 2^-53 relative per term added (f >= 0) */
    double relative = (8.0 / (width * width) + terms_summed) * 0x1p-53;
    for (int c = 0; c < 3; c++)
        out->error[c] = resolved ? fabs(out->albedo[c] - coarse[c]) + relative * out->albedo[c]
                                 : INFINITY;
    return resolved ? 0 : -1;
}

double sc_reciprocity_error(const sc_brdf *b, double worst_l[3], double worst_v[3])
{
    static const double thetas[] = {0, 10, 20, 30, 40, 50, 60, 70, 80, 89};
    sc_frame f;
    const double n[3] = {0, 0, 1}, t[3] = {1, 0, 0};
    sc_frame_make(n, t, &f);
    double worst = 0.0;
    double dirs[10 * 8][3];
    sc_brdf_point pts[2 * 10 * 8];
    sc_brdf_terms terms[2 * 10 * 8];
    int nd = 0;
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 8; j++) {
            double th = thetas[i] * pi / 180.0, ph = j * pi / 4.0;
            dirs[nd][0] = sin(th) * cos(ph);
            dirs[nd][1] = sin(th) * sin(ph);
            dirs[nd][2] = cos(th);
            nd++;
        }
    for (int a = 0; a < nd; a++) { /* f(l, v) and f(v, l) for every v after l: a batch */
        int pairs = 0;
        for (int c = a + 1; c < nd; c++, pairs += 2) {
            pts[pairs] = (sc_brdf_point){&f, {0}, {0}};
            memcpy(pts[pairs].l, dirs[a], sizeof dirs[a]);
            memcpy(pts[pairs].v, dirs[c], sizeof dirs[c]);
            pts[pairs + 1] = (sc_brdf_point){&f, {0}, {0}};
            memcpy(pts[pairs + 1].l, dirs[c], sizeof dirs[c]);
            memcpy(pts[pairs + 1].v, dirs[a], sizeof dirs[a]);
        }
        sc_brdf_eval_many(SC_DOUBLE, b, pairs, pts, terms);
        for (int c = a + 1; c < nd; c++) {
            const sc_brdf_terms lv = terms[2 * (c - a - 1)], vl = terms[2 * (c - a - 1) + 1];
            double big = fmax(fabs(lv.f[0]), fabs(vl.f[0]));
            double e = big > 0.0 ? fabs(lv.f[0] - vl.f[0]) / big : 0.0;
            if (e > worst) {
                worst = e;
                if (worst_l)
                    memcpy(worst_l, dirs[a], sizeof dirs[a]);
                if (worst_v)
                    memcpy(worst_v, dirs[c], sizeof dirs[c]);
            }
        }
    }
    return worst;
}
