/* The reference of an area light (shadecalc/area.h, docs/formulas.md §5.2): the integral of
 * f(l, v) L_e cos̄θ_i over the directions that see the emitter, by Gauss–Legendre panels in
 * solid-angle coordinates, with the horizon (n·l = 0) and the emitter's outline found exactly
 * per ring of directions, so that the integrand of each 1-D rule is smooth:
 *
 *   sphere  cone about the centre direction w: l = cos θ w + sin θ (cos φ e1 + sin φ e2),
 *           dω = sin θ dθ dφ, θ in [0, σ], sin σ = R/d; per ring, φ in [−φ_m, φ_m] above the
 *           horizon; θ panels split where a ring first touches the horizon
 *   disk,   polar about the foot F of the point on the emitter's plane, at height h:
 *   rect    l = −cos τ n_L + sin τ (cos ψ t1 + sin ψ t2), dω = sin τ dτ dψ; per ψ, the ray from F
 *           meets the emitter clipped to the horizon (a half-plane) in [ρ0, ρ1] and
 *           τ = atan(ρ/h); ψ panels split at the directions of the outline's corners and
 *           tangent points
 *   tube    a fan of planes through the point, parallel to the axis a: l = cos η d(ζ) + sin η a,
 *           d(ζ) = cos ζ d0 + sin ζ d1, dω = |cos η| dη dζ; each plane cuts the capsule in a
 *           stadium whose angular extent from the point is exact (the two end discs' tangents),
 *           intersected with the horizon's half-circle
 *
 * Outer panels use the substitution x = a + (b − a)(1 − cos πs)/2, which absorbs the
 * square-root behaviour at a panel end where a ring becomes tangent. The rule with N nodes per
 * panel and dimension gives Q(N); the error estimate is |Q(N) − Q(N/2)|. */
#include <math.h>
#include <string.h>

#include "light/area_internal.h"
#include "util/quadrature.h"

enum { MIN_NODES = 8, MAX_NODES = 512, MAX_BREAKS = 16, MAX_PLANES = 5 };

typedef struct {
    int n;
    double x[MAX_NODES], w[MAX_NODES]; /* Gauss–Legendre on [−1, 1] */
} gl_rule;

/* Node i of the rule on [a, b] (plain), and its weight. */
static double plain_node(const gl_rule *r, int i, double a, double b, double *weight)
{
    *weight = 0.5 * (b - a) * r->w[i];
    return 0.5 * (a + b) + 0.5 * (b - a) * r->x[i];
}

/* Node i of the rule on [a, b] graded toward both ends, x = a + (b − a)(1 − cos πs)/2. */
static double graded_node(const gl_rule *r, int i, double a, double b, double *weight)
{
    double s = 0.5 * (r->x[i] + 1.0);
    *weight = 0.5 * r->w[i] * (b - a) * 0.5 * AREA_PI * sin(AREA_PI * s);
    return a + (b - a) * 0.5 * (1.0 - cos(AREA_PI * s));
}

static double clamp1(double x) { return x < -1.0 ? -1.0 : x > 1.0 ? 1.0 : x; }

/* ---- sphere (and the inside of a sphere or tube: the hemisphere about n) ---- */

typedef struct {
    double w[3], e1[3], e2[3];
    double sigma; /* cone half-angle */
    double a, b;  /* n·l = a cos θ + b sin θ cos φ */
} cone;

/* The cone of directions toward a ball (centre c, radius R) from p; the hemisphere about n
 * when p is inside or on it, or `inside` (a tube's capsule). */
static void cone_setup(const double c[3], double R, const double p[3], int inside,
                       const sc_frame *frame, cone *k)
{
    double d3[3] = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
    double d = area_unit(d3, k->w);
    if (d <= R || inside) {
        memcpy(k->w, frame->n, sizeof k->w);
        k->sigma = AREA_PI / 2;
    } else {
        k->sigma = asin(R / d);
    }
    k->a = area_dot(frame->n, k->w);
    double m[3];
    for (int i = 0; i < 3; i++)
        m[i] = frame->n[i] - k->a * k->w[i];
    k->b = area_unit(m, k->e1);
    if (!(k->b > 1e-300))
        area_perpendicular(k->w, k->e1);
    area_cross(k->w, k->e1, k->e2);
}

/* Half-width φ_m of the arc of the ring at θ above the horizon (0: none, π: all). */
static double ring_arc(const cone *k, double theta)
{
    double above = k->a * cos(theta), spread = k->b * sin(theta);
    if (spread <= 0.0)
        return above > 0.0 ? AREA_PI : 0.0;
    return acos(clamp1(-above / spread));
}

static void cone_rule(const cone *k, const gl_rule *r, area_integrand *g, double acc[3])
{
    /* rings with θ below θ* = |π/2 − θ_w| are wholly above or wholly below the horizon */
    double star = fabs(AREA_PI / 2 - acos(clamp1(k->a)));
    double ends[3] = {0.0, k->sigma, k->sigma};
    int panels = 1;
    if (star > 0.0 && star < k->sigma) {
        ends[1] = star;
        panels = 2;
    }
    for (int pnl = 0; pnl < panels; pnl++)
        for (int i = 0; i < r->n; i++) {
            double wt, theta = graded_node(r, i, ends[pnl], ends[pnl + 1], &wt);
            double half = ring_arc(k, theta), st = sin(theta), ct = cos(theta);
            for (int j = 0; half > 0.0 && j < r->n; j++) {
                double wp, phi = plain_node(r, j, -half, half, &wp), l[3];
                for (int c = 0; c < 3; c++)
                    l[c] = ct * k->w[c] + st * (cos(phi) * k->e1[c] + sin(phi) * k->e2[c]);
                area_add(g, l, wt * wp * st, acc);
            }
        }
}

/* ---- disk and rect ---- */

typedef struct {
    double nl[3], t1[3], t2[3]; /* the emitter's frame, nl toward the point */
    double h;                   /* height of the point above the plane (> 0) */
    int n_planes;               /* the region: y·m >= k for each plane (2-D, about F) ... */
    double m[MAX_PLANES][2], k[MAX_PLANES];
    int circle; /* ... and inside the circle (disk) */
    double cc[2], radius;
    int n_breaks; /* ψ of the outline's corners and tangent points, sorted */
    double breaks[MAX_BREAKS];
} planar;

static void add_break(planar *s, double y0, double y1)
{
    if (s->n_breaks < MAX_BREAKS && (y0 != 0.0 || y1 != 0.0))
        s->breaks[s->n_breaks++] = atan2(y1, y0);
}

static void add_plane(planar *s, double m0, double m1, double k)
{
    s->m[s->n_planes][0] = m0;
    s->m[s->n_planes][1] = m1;
    s->k[s->n_planes++] = k;
}

/* Where the line y·m = k crosses the segment a–b: a breakpoint. */
static void line_segment_break(planar *s, const double m[2], double k, const double a[2],
                               const double b[2])
{
    double fa = m[0] * a[0] + m[1] * a[1] - k, fb = m[0] * b[0] + m[1] * b[1] - k;
    if ((fa < 0.0) == (fb < 0.0) || fa == fb)
        return;
    double t = fa / (fa - fb);
    add_break(s, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
}

/* A rect's corners (2-D, counter-clockwise) as four planes, with the corners and the horizon
 * line's crossings of its edges as breakpoints. */
static void rect_region(const sc_light *light, const double F[3], planar *s)
{
    const double *e1 = light->area.edge1, *e2 = light->area.edge2;
    static const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    double y[4][2];
    for (int i = 0; i < 4; i++) {
        double x[3];
        for (int c = 0; c < 3; c++)
            x[c] = light->pos[c] + 0.5 * (signs[i][0] * e1[c] + signs[i][1] * e2[c]) - F[c];
        y[i][0] = area_dot(x, s->t1);
        y[i][1] = area_dot(x, s->t2);
    }
    double area2 = 0.0;
    for (int i = 0; i < 4; i++)
        area2 += y[i][0] * y[(i + 1) % 4][1] - y[(i + 1) % 4][0] * y[i][1];
    double orient = area2 > 0.0 ? 1.0 : -1.0;
    const double *hm = s->m[0];
    for (int i = 0; i < 4; i++) {
        const double *a = y[i], *b = y[(i + 1) % 4];
        double m0 = -(b[1] - a[1]) * orient, m1 = (b[0] - a[0]) * orient;
        add_plane(s, m0, m1, m0 * a[0] + m1 * a[1]);
        add_break(s, a[0], a[1]);
        line_segment_break(s, hm, s->k[0], a, b);
    }
}

/* A disk's circle, with its tangent points from F and the horizon chord's ends as breakpoints. */
static void disk_region(const sc_light *light, const double F[3], planar *s)
{
    double x[3] = {light->pos[0] - F[0], light->pos[1] - F[1], light->pos[2] - F[2]};
    s->circle = 1;
    s->radius = light->area.radius;
    s->cc[0] = area_dot(x, s->t1);
    s->cc[1] = area_dot(x, s->t2);
    double D = hypot(s->cc[0], s->cc[1]), R = s->radius;
    if (D > R) {
        double psi = atan2(s->cc[1], s->cc[0]), spread = asin(R / D);
        add_break(s, cos(psi - spread), sin(psi - spread));
        add_break(s, cos(psi + spread), sin(psi + spread));
    }
    const double *m = s->m[0];
    double mm = hypot(m[0], m[1]);
    if (mm == 0.0)
        return;
    /* the horizon line y·m = k at distance q from the centre along m/|m| */
    double q = (s->k[0] - (m[0] * s->cc[0] + m[1] * s->cc[1])) / mm;
    if (fabs(q) >= R)
        return;
    double half = sqrt(R * R - q * q), u[2] = {m[0] / mm, m[1] / mm};
    for (int sgn = -1; sgn <= 1; sgn += 2)
        add_break(s, s->cc[0] + q * u[0] - sgn * half * u[1],
                  s->cc[1] + q * u[1] + sgn * half * u[0]);
}

static void sort_breaks(planar *s)
{
    for (int i = 1; i < s->n_breaks; i++)
        for (int j = i; j > 0 && s->breaks[j - 1] > s->breaks[j]; j--) {
            double t = s->breaks[j];
            s->breaks[j] = s->breaks[j - 1];
            s->breaks[j - 1] = t;
        }
}

/* 1 and the region of a disk or rect seen from p, or 0 when it sends nothing to p: behind a
 * one-sided emitter, or p in its plane. */
static int planar_setup(const sc_light *light, const double p[3], const sc_frame *frame, planar *s)
{
    memset(s, 0, sizeof *s);
    if (light->kind == SC_LIGHT_RECT)
        area_cross(light->area.edge1, light->area.edge2, s->nl);
    else
        memcpy(s->nl, light->area.normal, sizeof s->nl);
    area_unit(s->nl, s->nl);
    double x[3] = {p[0] - light->pos[0], p[1] - light->pos[1], p[2] - light->pos[2]};
    s->h = area_dot(x, s->nl);
    if (s->h < 0.0 && light->area.two_sided) {
        for (int c = 0; c < 3; c++)
            s->nl[c] = -s->nl[c];
        s->h = -s->h;
    }
    if (!(s->h > 0.0))
        return 0;
    area_perpendicular(s->nl, s->t1);
    area_cross(s->nl, s->t1, s->t2);
    double F[3];
    for (int c = 0; c < 3; c++)
        F[c] = p[c] - s->h * s->nl[c];
    /* the horizon n·(x − p) >= 0 in the plane: y·(n·t1, n·t2) >= h (n·n_L) */
    add_plane(s, area_dot(frame->n, s->t1), area_dot(frame->n, s->t2),
              s->h * area_dot(frame->n, s->nl));
    if (light->kind == SC_LIGHT_RECT)
        rect_region(light, F, s);
    else
        disk_region(light, F, s);
    sort_breaks(s);
    return 1;
}

/* [ρ0, ρ1] of the ray ρ·u from F inside the region; 0 if empty. */
static int ray_span(const planar *s, const double u[2], double *r0, double *r1)
{
    double lo = 0.0, hi = HUGE_VAL;
    for (int i = 0; i < s->n_planes; i++) {
        double mu = s->m[i][0] * u[0] + s->m[i][1] * u[1];
        if (mu > 0.0)
            lo = fmax(lo, s->k[i] / mu);
        else if (mu < 0.0)
            hi = fmin(hi, s->k[i] / mu);
        else if (s->k[i] > 0.0)
            return 0;
    }
    if (s->circle) {
        double b = u[0] * s->cc[0] + u[1] * s->cc[1];
        double disc = b * b - (s->cc[0] * s->cc[0] + s->cc[1] * s->cc[1]) + s->radius * s->radius;
        if (disc <= 0.0)
            return 0;
        lo = fmax(lo, b - sqrt(disc));
        hi = fmin(hi, b + sqrt(disc));
    }
    *r0 = lo;
    *r1 = hi;
    return hi > lo && isfinite(hi);
}

static void planar_panel(const planar *s, const gl_rule *r, double a, double b, area_integrand *g,
                         double acc[3])
{
    for (int i = 0; i < r->n; i++) {
        double wpsi, psi = graded_node(r, i, a, b, &wpsi), u[2] = {cos(psi), sin(psi)}, r0, r1;
        if (!ray_span(s, u, &r0, &r1))
            continue;
        double tau0 = atan2(r0, s->h), tau1 = atan2(r1, s->h), dir[3];
        for (int c = 0; c < 3; c++)
            dir[c] = u[0] * s->t1[c] + u[1] * s->t2[c];
        for (int j = 0; j < r->n; j++) {
            double wt, tau = plain_node(r, j, tau0, tau1, &wt), l[3];
            for (int c = 0; c < 3; c++)
                l[c] = -cos(tau) * s->nl[c] + sin(tau) * dir[c];
            area_add(g, l, wpsi * wt * sin(tau), acc);
        }
    }
}

static void planar_rule(const planar *s, const gl_rule *r, area_integrand *g, double acc[3])
{
    if (s->n_breaks == 0) {
        planar_panel(s, r, -AREA_PI, AREA_PI, g, acc);
        return;
    }
    for (int i = 0; i < s->n_breaks; i++) {
        double a = s->breaks[i];
        double b = i + 1 < s->n_breaks ? s->breaks[i + 1] : s->breaks[0] + 2 * AREA_PI;
        if (b > a)
            planar_panel(s, r, a, b, g, acc);
    }
}

/* ---- tube ---- */

typedef struct {
    double a[3], d0[3], d1[3]; /* axis; from the point toward the axis; a × d0 */
    double len, R, up, rho;    /* length, radius, the point's axial coordinate and distance */
    double zeta;               /* the fan spans ζ in [−zeta, zeta] */
} fan;

static void fan_setup(const sc_light *light, const double p[3], fan *f)
{
    const double *p0 = light->area.p0, *p1 = light->area.p1;
    double ax[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    double q[3] = {p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]}, perp[3];
    f->len = area_unit(ax, f->a);
    f->R = light->area.radius;
    f->up = area_dot(q, f->a);
    for (int c = 0; c < 3; c++)
        perp[c] = f->up * f->a[c] - q[c];
    f->rho = area_unit(perp, f->d0);
    if (!(f->rho > 0.0))
        area_perpendicular(f->a, f->d0);
    area_cross(f->a, f->d0, f->d1);
    f->zeta = f->rho > f->R ? asin(f->R / f->rho) : AREA_PI / 2;
}

/* The angular extent [lo, hi] from the origin of the disc of radius w about (t, s). */
static void disc_extent(double t, double s, double w, double *lo, double *hi)
{
    double centre = atan2(s, t), spread = asin(fmin(1.0, w / hypot(t, s)));
    *lo = fmin(*lo, centre - spread);
    *hi = fmax(*hi, centre + spread);
}

/* The inner integral over η in [lo, hi] with weight |cos η| (split where cos η changes sign). */
static void fan_line(const fan *f, const double d[3], const gl_rule *r, double lo, double hi,
                     double weight, area_integrand *g, double acc[3])
{
    double cuts[4] = {lo, hi, hi, hi};
    int n = 1;
    for (int s = -1; s <= 1; s += 2)
        if (s * AREA_PI / 2 > lo && s * AREA_PI / 2 < hi)
            cuts[n++] = s * AREA_PI / 2;
    cuts[n] = hi;
    for (int k = 0; k < n; k++)
        for (int j = 0; j < r->n; j++) {
            double we, eta = plain_node(r, j, cuts[k], cuts[k + 1], &we), l[3];
            for (int c = 0; c < 3; c++)
                l[c] = cos(eta) * d[c] + sin(eta) * f->a[c];
            area_add(g, l, weight * we * fabs(cos(eta)), acc);
        }
}

static void fan_plane(const fan *f, const sc_frame *frame, const gl_rule *r, double zeta,
                      double weight, area_integrand *g, double acc[3])
{
    double sz = f->rho * sin(zeta), w2 = f->R * f->R - sz * sz;
    if (!(w2 > 0.0))
        return;
    double w = sqrt(w2), t = f->rho * cos(zeta), lo = HUGE_VAL, hi = -HUGE_VAL, d[3];
    disc_extent(t, -f->up, w, &lo, &hi);
    disc_extent(t, f->len - f->up, w, &lo, &hi);
    for (int c = 0; c < 3; c++)
        d[c] = cos(zeta) * f->d0[c] + sin(zeta) * f->d1[c];
    /* the horizon: n·l = P cos η + Q sin η > 0 on the half-circle about η0 */
    double P = area_dot(frame->n, d), Q = area_dot(frame->n, f->a);
    if (P == 0.0 && Q == 0.0)
        return;
    double eta0 = atan2(Q, P), mid = 0.5 * (lo + hi);
    eta0 += 2 * AREA_PI * round((mid - eta0) / (2 * AREA_PI));
    lo = fmax(lo, eta0 - AREA_PI / 2);
    hi = fmin(hi, eta0 + AREA_PI / 2);
    if (hi > lo)
        fan_line(f, d, r, lo, hi, weight, g, acc);
}

static void fan_rule(const fan *f, const sc_frame *frame, const gl_rule *r, area_integrand *g,
                     double acc[3])
{
    for (int side = -1; side <= 1; side += 2)
        for (int i = 0; i < r->n; i++) {
            double wz, zeta = graded_node(r, i, 0.0, side * f->zeta, &wz);
            fan_plane(f, frame, r, zeta, fabs(wz), g, acc);
        }
}

/* ---- the driver ---- */

typedef struct {
    int kind; /* 0 cone, 1 planar, 2 fan, -1 nothing */
    cone k;
    planar s;
    fan f;
} geometry;

/* Whether p is inside or on the tube's capsule. */
static int inside_tube(const fan *f)
{
    double beyond = f->up < 0.0 ? -f->up : f->up > f->len ? f->up - f->len : 0.0;
    return hypot(beyond, f->rho) <= f->R;
}

static void geometry_setup(const sc_light *light, const double p[3], const sc_frame *frame,
                           geometry *geo)
{
    geo->kind = -1;
    if (light->kind != SC_LIGHT_RECT && !(light->area.radius > 0.0))
        return; /* a zero-size emitter */
    if (light->kind == SC_LIGHT_DISK || light->kind == SC_LIGHT_RECT) {
        geo->kind = planar_setup(light, p, frame, &geo->s) ? 1 : -1;
        return;
    }
    int inside = 0;
    if (light->kind == SC_LIGHT_TUBE) {
        fan_setup(light, p, &geo->f);
        inside = inside_tube(&geo->f);
        if (geo->f.len > 0.0 && !inside) {
            geo->kind = 2;
            return;
        }
    }
    double c[3];
    area_centre(light, c);
    cone_setup(c, light->area.radius, p, inside, frame, &geo->k);
    geo->kind = 0;
}

static void rule(const geometry *geo, const sc_frame *frame, int n, area_integrand *g,
                 double acc[3])
{
    gl_rule r;
    r.n = n;
    sc_gauss_legendre(n, r.x, r.w);
    acc[0] = acc[1] = acc[2] = 0.0;
    if (geo->kind == 0)
        cone_rule(&geo->k, &r, g, acc);
    else if (geo->kind == 1)
        planar_rule(&geo->s, &r, g, acc);
    else if (geo->kind == 2)
        fan_rule(&geo->f, frame, &r, g, acc);
}

static double max_abs3(const double v[3]) { return fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2]))); }

void area_reference(const sc_light *light, area_integrand *g, const double pos[3],
                    sc_area_result *out)
{
    geometry geo;
    geometry_setup(light, pos, g->frame, &geo);
    int fixed = light->area.samples, n = fixed ? fixed : MIN_NODES;
    double coarse[3], fine[3];
    rule(&geo, g->frame, (n + 1) / 2, g, coarse);
    for (;;) {
        rule(&geo, g->frame, n, g, fine);
        for (int c = 0; c < 3; c++)
            out->error[c] = fabs(fine[c] - coarse[c]);
        out->converged = fixed || max_abs3(out->error) <= light->area.tol * max_abs3(fine);
        if (out->converged || 2 * n > MAX_NODES)
            break;
        memcpy(coarse, fine, sizeof coarse);
        n *= 2;
    }
    memcpy(out->L, fine, sizeof out->L);
    out->nodes = n;
    out->evaluations = g->evaluations;
}
