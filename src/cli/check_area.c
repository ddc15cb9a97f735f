/* shadecalc check --light: the error and cost of each area light method against the converged
 * reference over a standard set of configurations (docs/formulas.md §5.4).
 *
 * The light's shape (kind, size, L_e, sidedness) is kept; it is placed with its centre at
 * distance d = ratio · s from the point (s: the radius; a rect's half diagonal) at angle θ_l
 * from the normal n = +z in the x–z plane, a disk or rect facing the point, a tube across the
 * direction (along y); the viewer is at θ_v on the other side (φ = 180°), where the mirror
 * direction of θ_v = θ_l meets the light. Roughness α takes 0.1, 0.3, 0.6, 1 for cook-torrance
 * and ward, else the BRDF as given. */
#include "cli/check_area.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "shadecalc/area.h"

static const double radians = 0.017453292519943295;
static const double ratios[] = {1.5, 2, 4, 10};
static const double light_angles[] = {0, 30, 60, 85, 100};
static const double view_angles[] = {0, 30, 60, 80};
static const double alphas[] = {0.1, 0.3, 0.6, 1.0};
enum {
    N_RATIOS = sizeof ratios / sizeof ratios[0],
    N_LIGHT = sizeof light_angles / sizeof light_angles[0],
    N_VIEW = sizeof view_angles / sizeof view_angles[0],
    N_ALPHAS = sizeof alphas / sizeof alphas[0],
    MAX_CONFIGS = N_RATIOS * N_LIGHT * N_VIEW * N_ALPHAS,
    MAX_METHODS = 4,
    TIMING_ROUNDS = 3
};
/* The reference's relative error goal: far below the approximations' errors (>= 1e-4). */
static const double REFERENCE_TOL = 1e-8;

typedef struct {
    double ratio, theta_l, theta_v, alpha;
    sc_light light;
    sc_brdf brdf;
    double v[3];
    double reference[3], estimate[3]; /* its value and error estimate */
} config;

typedef struct {
    sc_area_method method;
    double max_error, mean_error, ns;
    const config *worst;
    int counted;
} method_row;

static double length3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* The light's size s: its radius, or a rect's half diagonal. */
static double light_size(const sc_light *l)
{
    if (l->kind != SC_LIGHT_RECT)
        return l->area.radius;
    double a = length3(l->area.edge1), b = length3(l->area.edge2);
    return 0.5 * sqrt(a * a + b * b);
}

/* `proto` moved to distance d at angle theta (degrees) from +z, facing the origin. */
static void place(const sc_light *proto, double d, double theta, sc_light *out)
{
    *out = *proto;
    double dir[3] = {sin(theta * radians), 0, cos(theta * radians)}, y[3] = {0, 1, 0};
    for (int c = 0; c < 3; c++)
        out->pos[c] = d * dir[c];
    double half = 0.5 * sqrt(pow(proto->area.p1[0] - proto->area.p0[0], 2) +
                             pow(proto->area.p1[1] - proto->area.p0[1], 2) +
                             pow(proto->area.p1[2] - proto->area.p0[2], 2));
    double e1 = length3(proto->area.edge1), e2 = length3(proto->area.edge2);
    /* toward the point: n_L = −dir; rect: edge1 along y, edge2 along n_L × y */
    double b[3] = {dir[2], 0, -dir[0]};
    for (int c = 0; c < 3; c++) {
        out->area.p0[c] = out->pos[c] - half * y[c];
        out->area.p1[c] = out->pos[c] + half * y[c];
        out->area.normal[c] = -dir[c];
        out->area.edge1[c] = e1 * y[c];
        out->area.edge2[c] = e2 * b[c];
    }
}

static int has_roughness(const sc_brdf *b)
{
    return b->kind == SC_BRDF_COOK_TORRANCE || b->kind == SC_BRDF_WARD;
}

static int make_configs(const sc_light *proto, const sc_brdf *brdf, config *out)
{
    int n = 0, n_alpha = has_roughness(brdf) ? N_ALPHAS : 1;
    for (int a = 0; a < n_alpha; a++)
        for (int r = 0; r < N_RATIOS; r++)
            for (int i = 0; i < N_LIGHT; i++)
                for (int j = 0; j < N_VIEW; j++) {
                    config *c = &out[n++];
                    c->ratio = ratios[r];
                    c->theta_l = light_angles[i];
                    c->theta_v = view_angles[j];
                    c->brdf = *brdf;
                    c->alpha = has_roughness(brdf) ? alphas[a] : NAN;
                    if (has_roughness(brdf))
                        c->brdf.ax = c->brdf.ay = alphas[a];
                    place(proto, ratios[r] * light_size(proto), light_angles[i], &c->light);
                    c->v[0] = -sin(view_angles[j] * radians);
                    c->v[1] = 0;
                    c->v[2] = cos(view_angles[j] * radians);
                }
    return n;
}

static const sc_frame up_frame = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
static const double origin[3] = {0, 0, 0};

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

/* The largest relative error over the channels whose reference is not 0 (-1 if none). */
static double relative_error(const double got[3], const double want[3])
{
    double worst = -1.0;
    for (int c = 0; c < 3; c++)
        if (want[c] != 0.0)
            worst = fmax(worst, fabs(got[c] - want[c]) / fabs(want[c]));
    return worst;
}

/* The mean time of an evaluation by an approximation (the best of a few rounds). */
static double time_method(sc_area_method method, const config *configs, int n)
{
    sc_area_result r;
    double best = HUGE_VAL;
    for (int round = 0; round < TIMING_ROUNDS; round++) {
        double t0 = now_ns();
        for (int i = 0; i < n; i++)
            sc_area_eval(&configs[i].light, method, &configs[i].brdf, &up_frame, origin,
                         configs[i].v, &r);
        best = fmin(best, (now_ns() - t0) / n);
    }
    return best;
}

/* One method over every configuration: its errors against the reference (the reference: its
 * own error estimate), and its time per evaluation. */
static void measure(method_row *row, const config *configs, int n, double reference_ns)
{
    sc_area_result r;
    double sum = 0.0;
    row->max_error = -1.0;
    row->counted = 0;
    row->ns = row->method == SC_AREA_REFERENCE ? reference_ns
                                               : time_method(row->method, configs, n);
    for (int i = 0; i < n; i++) {
        const config *c = &configs[i];
        double e;
        if (row->method == SC_AREA_REFERENCE) {
            double bound[3] = {c->reference[0] + c->estimate[0], c->reference[1] + c->estimate[1],
                               c->reference[2] + c->estimate[2]};
            e = relative_error(bound, c->reference);
        } else {
            sc_area_eval(&c->light, row->method, &c->brdf, &up_frame, origin, c->v, &r);
            e = relative_error(r.L, c->reference);
        }
        if (e < 0.0)
            continue;
        sum += e;
        row->counted++;
        if (e > row->max_error) {
            row->max_error = e;
            row->worst = &configs[i];
        }
    }
    row->mean_error = row->counted ? sum / row->counted : 0.0;
}

static void print_worst(const config *c)
{
    printf("d/s=%g theta_l=%g theta_v=%g", c->ratio, c->theta_l, c->theta_v);
    if (!isnan(c->alpha))
        printf(" alpha=%g", c->alpha);
}

/* s as a CSV field: quoted, inner quotes doubled. */
static void print_csv_string(const char *s)
{
    putchar('"');
    for (; *s; s++)
        fputs(*s == '"' ? "\"\"" : (char[2]){*s, 0}, stdout);
    putchar('"');
}

static void print_header(const char *light, const char *brdf, int n_configs, int alpha,
                         check_area_format format)
{
    if (format == CHECK_AREA_CSV) {
        printf("light,brdf,method,configs,max_rel_error,mean_rel_error,ns_per_eval,worst\n");
    } else if (format == CHECK_AREA_JSON) {
        printf("{\"light\": ");
        sc_print_json_string(stdout, light);
        printf(", \"brdf\": ");
        sc_print_json_string(stdout, brdf);
        printf(", \"configs\": %d, \"methods\": [", n_configs);
    } else {
        printf("light %s\nbrdf %s\n%d configurations (d/s, theta_l, theta_v%s)\n", light, brdf,
               n_configs, alpha ? ", alpha" : "");
        printf("%-22s %13s %14s %12s  %s\n", "method", "max_rel_error", "mean_rel_error",
               "ns_per_eval", "worst configuration");
    }
}

static void print_row(const char *light, const char *brdf, const method_row *r, int first,
                      check_area_format format)
{
    const char *name = sc_area_method_name(r->method);
    if (format == CHECK_AREA_TABLE) {
        printf("%-22s %13.3g %14.3g %12.0f  ", name, r->max_error, r->mean_error, r->ns);
    } else if (format == CHECK_AREA_CSV) {
        print_csv_string(light);
        putchar(',');
        print_csv_string(brdf);
        printf(",%s,%d,%.6g,%.6g,%.1f,\"", name, r->counted, r->max_error, r->mean_error, r->ns);
    } else {
        printf("%s{\"method\": \"%s\", \"configs\": %d, \"max_rel_error\": %.6g, "
               "\"mean_rel_error\": %.6g, \"ns_per_eval\": %.1f, \"worst\": \"",
               first ? "" : ", ", name, r->counted, r->max_error, r->mean_error, r->ns);
    }
    if (r->worst)
        print_worst(r->worst);
    fputs(format == CHECK_AREA_TABLE ? "\n" : format == CHECK_AREA_CSV ? "\"\n" : "\"}", stdout);
}

double check_area_error(const sc_light *proto, sc_area_method method, const sc_brdf *b,
                        double ratio, double theta_l, double theta_v)
{
    sc_light light;
    sc_area_result ref, r;
    place(proto, ratio * light_size(proto), theta_l, &light);
    light.area.samples = 0;
    light.area.tol = REFERENCE_TOL;
    double v[3] = {-sin(theta_v * radians), 0, cos(theta_v * radians)};
    sc_area_eval(&light, SC_AREA_REFERENCE, b, &up_frame, origin, v, &ref);
    if (sc_area_eval(&light, method, b, &up_frame, origin, v, &r) < 0)
        return NAN;
    return relative_error(r.L, ref.L);
}

int check_area_run(const char *light_spec, const sc_light *light, const char *brdf_spec,
                   const sc_brdf *brdf, check_area_format format)
{
    static config configs[MAX_CONFIGS];
    int n = make_configs(light, brdf, configs);
    double t0 = now_ns();
    for (int i = 0; i < n; i++) {
        sc_area_result r;
        configs[i].light.area.samples = 0;
        configs[i].light.area.tol = REFERENCE_TOL;
        sc_area_eval(&configs[i].light, SC_AREA_REFERENCE, &configs[i].brdf, &up_frame, origin,
                     configs[i].v, &r);
        memcpy(configs[i].reference, r.L, sizeof r.L);
        memcpy(configs[i].estimate, r.error, sizeof r.error);
    }
    double reference_ns = (now_ns() - t0) / n;
    method_row rows[MAX_METHODS];
    int n_rows = 0;
    char msg[160];
    for (int m = 0; sc_area_method_name((sc_area_method)m); m++)
        if (sc_area_method_applies(light->kind, (sc_area_method)m, brdf, msg, sizeof msg) == 0 &&
            n_rows < MAX_METHODS) {
            rows[n_rows] = (method_row){.method = (sc_area_method)m};
            measure(&rows[n_rows++], configs, n, reference_ns);
        }
    print_header(light_spec, brdf_spec, n, has_roughness(brdf), format);
    for (int i = 0; i < n_rows; i++)
        print_row(light_spec, brdf_spec, &rows[i], i == 0, format);
    if (format == CHECK_AREA_JSON)
        printf("]}\n");
    return SC_EXIT_OK;
}
