/* shadecalc normal — surface normals (exact, by automatic differentiation for user surfaces),
 * triangle normals and the normal matrix (docs/formulas.md §7). */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "shadecalc/mesh.h"
#include "shadecalc/precision.h"
#include "shadecalc/surface.h"
#include "shadecalc/transform.h"
#include "shadecalc/vec.h"

enum { MAX_POINTS = 64 };
enum { FMT_TEXT, FMT_CSV };

typedef struct {
    const char *surface_spec, *matrix_spec;
    sc_surface *surface;
    double uv[MAX_POINTS][2];
    int n_uv;
    int has_triangle;
    double triangle[3][3];
    sc_dmat4 matrix;
    int explain, format;
} normal_options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc normal --surface SPEC --uv U,V [--uv U,V...] [OPTIONS]\n"
            "       shadecalc normal --triangle X,Y,Z X,Y,Z X,Y,Z [OPTIONS]\n"
            "       shadecalc normal --matrix M [OPTIONS]\n"
            "\n"
            "The point and unit normal n = dS/du x dS/dv / |...| of a parametric surface at\n"
            "(u,v) in [0,1]^2, derivatives exact (closed forms; automatic differentiation for\n"
            "user surfaces); the normal (P2-P1) x (P3-P1) of a triangle; or the normal matrix\n"
            "(M3^-1)^T of a transform's upper-left 3x3.\n"
            "\n"
            "  -s, --surface SPEC  sphere [r=1] | torus [R=1] [r=0.3] | plane [size=2] |\n"
            "                      cylinder [r=1] [h=2] | user x=EXPR y=EXPR z=EXPR (in u, v)\n"
            "  -u, --uv U,V        surface parameters in [0,1] (repeatable)\n"
            "  -t, --triangle P1 P2 P3   three points X,Y,Z (three arguments)\n"
            "  -m, --matrix M      16 numbers, column-major, or a chain such as\n"
            "                      scale(1,2,3)*rotate(30,0,1,0)*translate(1,2,3)\n"
            "  -e, --explain       show the derivatives, cross product and method\n"
            "  -f, --format F      text|csv (default text)\n"
            "  -h, --help          this help\n");
}

/* ---- printing (+ 0.0 turns −0 into 0) ---- */

static void print_vec(const char *label, const double *v)
{
    printf("  %-14s (%.10g, %.10g, %.10g)\n", label, v[0] + 0.0, v[1] + 0.0, v[2] + 0.0);
}

/* csv: the shortest decimal that reads back to the same double. */
static void csv_value(double x, const char *end)
{
    char buf[64];
    sc_format_shortest(buf, sizeof buf, x + 0.0, SC_DOUBLE);
    printf("%s%s", buf, end);
}

static void csv_values(const double *v, int n, const char *end)
{
    for (int k = 0; k < n; k++)
        csv_value(v[k], k + 1 < n ? "," : end);
}

static sc_dvec3 dvec3(const double *a) { return sc_dvec3_make(a[0], a[1], a[2]); }

/* Prints a × b and its length; returns the length. */
static double explain_cross(const double *a, const double *b, const char *label, int print)
{
    sc_dvec3 c = sc_dvec3_cross(dvec3(a), dvec3(b));
    double length = sc_dvec3_length(c);
    if (print) {
        print_vec(label, (const double[3]){c.x, c.y, c.z});
        printf("  %-14s %.10g\n", "length", length);
    }
    return length;
}

static void print_point_text(const normal_options *o, double u, double v, const sc_surface_point *q)
{
    printf("%s at u=%g v=%g\n", o->surface_spec, u, v);
    print_vec("p", q->p);
    if (o->explain) {
        print_vec("dS/du", q->dpdu);
        print_vec("dS/dv", q->dpdv);
        explain_cross(q->dpdu, q->dpdv, "dS/du x dS/dv", 1);
        printf(q->degenerate ? "  the cross product vanishes (a pole or other degenerate point):\n"
                               "  n is its limit from inside, the normal a step 2^-30 toward "
                               "(0.5, 0.5)\n"
                             : "  n = dS/du x dS/dv / length\n");
    }
    print_vec("n", q->n);
}

static void print_point_csv(const normal_options *o, const sc_surface_point *q)
{
    csv_values(q->p, 3, ",");
    csv_values(q->n, 3, o->explain ? "," : "\n");
    if (o->explain) {
        csv_values(q->dpdu, 3, ",");
        csv_values(q->dpdv, 3, ",");
        printf("%d\n", q->degenerate);
    }
}

static int run_surface(const normal_options *o)
{
    if (o->format == FMT_CSV)
        printf("x,y,z,nx,ny,nz%s\n",
               o->explain ? ",dpdu_x,dpdu_y,dpdu_z,dpdv_x,dpdv_y,dpdv_z,degenerate" : "");
    for (int i = 0; i < o->n_uv; i++) {
        sc_surface_point q;
        sc_surface_eval(o->surface, o->uv[i][0], o->uv[i][1], &q);
        if (o->format == FMT_CSV)
            print_point_csv(o, &q);
        else
            print_point_text(o, o->uv[i][0], o->uv[i][1], &q);
    }
    return SC_EXIT_OK;
}

static int run_triangle(const normal_options *o)
{
    const double *a = o->triangle[0], *b = o->triangle[1], *c = o->triangle[2];
    double n[3], e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
    }
    sc_triangle_normal(a, b, c, n);
    if (o->format == FMT_TEXT)
        printf("triangle (%g, %g, %g) (%g, %g, %g) (%g, %g, %g)\n", a[0], a[1], a[2], b[0], b[1],
               b[2], c[0], c[1], c[2]);
    if (o->explain && o->format == FMT_TEXT) {
        print_vec("P2 - P1", e1);
        print_vec("P3 - P1", e2);
    }
    int degenerate = n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
    double area = 0.5 * explain_cross(e1, e2, "cross", o->explain && o->format == FMT_TEXT);
    if (o->format == FMT_CSV) {
        printf("nx,ny,nz,area,degenerate\n");
        csv_values(n, 3, ",");
        csv_value(degenerate ? 0.0 : area, ",");
        printf("%d\n", degenerate);
        return SC_EXIT_OK;
    }
    printf("  %-14s %.10g\n", "area", degenerate ? 0.0 : area);
    if (degenerate)
        printf("  degenerate triangle (collinear points): no normal\n");
    else
        print_vec("n", n);
    return SC_EXIT_OK;
}

static void print_rows(const double *m, int n, int rows)
{
    for (int r = 0; r < rows; r++) {
        printf("  [");
        for (int c = 0; c < n; c++)
            printf(" %14.10g", m[c * n + r] + 0.0);
        printf(" ]\n");
    }
}

static int run_matrix(const normal_options *o)
{
    sc_dmat3 nm;
    int rigid;
    if (sc_normal_matrix(&o->matrix, &nm, &rigid) < 0) {
        sc_error("normal: --matrix %s: the upper-left 3x3 is singular: it has no normal matrix",
                 o->matrix_spec);
        return SC_EXIT_USAGE;
    }
    if (o->format == FMT_CSV) {
        printf("c0r0,c0r1,c0r2,c1r0,c1r1,c1r2,c2r0,c2r1,c2r2\n");
        csv_values(nm.m, 9, "\n");
        return SC_EXIT_OK;
    }
    if (o->explain) {
        printf("M =\n");
        print_rows(o->matrix.m, 4, 4);
        printf(rigid ? "the upper-left 3x3 M3 is orthogonal (a rigid transform): R = M3\n"
                     : "R = transpose(inverse(M3)), M3 the upper-left 3x3 of M\n");
    }
    printf("normal matrix R =\n");
    print_rows(nm.m, 3, 3);
    return SC_EXIT_OK;
}

/* ---- options ---- */

static int parse_uv(const char *arg, normal_options *o)
{
    double *uv = o->uv[o->n_uv];
    if (o->n_uv == MAX_POINTS) {
        sc_error("normal: too many --uv (at most %d)", MAX_POINTS);
        return SC_EXIT_USAGE;
    }
    if (sc_parse_doubles(arg, uv, 2) < 0 || !(uv[0] >= 0.0 && uv[0] <= 1.0) ||
        !(uv[1] >= 0.0 && uv[1] <= 1.0)) {
        sc_error("normal: --uv %s: expected U,V with both in [0,1]", arg);
        return SC_EXIT_USAGE;
    }
    o->n_uv++;
    return SC_EXIT_OK;
}

static int parse_point(const char *arg, double *p)
{
    if (arg == NULL || sc_parse_doubles(arg, p, 3) < 0 || !isfinite(p[0]) || !isfinite(p[1]) ||
        !isfinite(p[2])) {
        sc_error("normal: --triangle: '%s': expected three points X,Y,Z X,Y,Z X,Y,Z",
                 arg ? arg : "(missing)");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

/* --triangle takes its first point as the option's value, the other two from the operands. */
static int parse_triangle(const char *arg, normal_options *o)
{
    o->has_triangle = 1;
    return parse_point(arg, o->triangle[0]);
}

/* The second and third points of --triangle: the first two operands. */
static int parse_triangle_rest(int argc, char **argv, normal_options *o)
{
    int status = SC_EXIT_OK;
    for (int k = 1; k < 3 && status == SC_EXIT_OK; k++)
        status = parse_point(optind < argc ? argv[optind++] : NULL, o->triangle[k]);
    return status;
}

static int parse_surface(const char *arg, normal_options *o)
{
    char err[256];
    sc_surface_free(o->surface);
    o->surface_spec = arg;
    o->surface = sc_surface_parse(arg, err, sizeof err);
    if (o->surface == NULL) {
        sc_error("normal: --surface: %s", err);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int parse_matrix(const char *arg, normal_options *o)
{
    char err[256];
    o->matrix_spec = arg;
    if (sc_transform_parse(arg, &o->matrix, err, sizeof err) < 0) {
        sc_error("normal: --matrix: %s", err);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int parse_format(const char *arg, normal_options *o)
{
    if (strcmp(arg, "text") && strcmp(arg, "csv")) {
        sc_error("normal: unknown format '%s' (text, csv)", arg);
        return SC_EXIT_USAGE;
    }
    o->format = strcmp(arg, "csv") == 0 ? FMT_CSV : FMT_TEXT;
    return SC_EXIT_OK;
}

/* Exactly one of --surface (with --uv), --triangle, --matrix. */
static int check_mode(const normal_options *o)
{
    int modes = (o->surface != NULL) + o->has_triangle + (o->matrix_spec != NULL);
    if (modes != 1) {
        sc_error("normal: give exactly one of --surface, --triangle, --matrix (see 'shadecalc "
                 "normal --help')");
        return SC_EXIT_USAGE;
    }
    if ((o->surface != NULL) != (o->n_uv > 0)) {
        sc_error(o->surface ? "normal: --surface needs --uv U,V"
                            : "normal: --uv needs --surface SPEC");
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int parse_options(int argc, char **argv, normal_options *o)
{
    static const struct option longs[] = {
        {"surface", required_argument, NULL, 's'},  {"uv", required_argument, NULL, 'u'},
        {"triangle", required_argument, NULL, 't'}, {"matrix", required_argument, NULL, 'm'},
        {"explain", no_argument, NULL, 'e'},        {"format", required_argument, NULL, 'f'},
        {"help", no_argument, NULL, 'h'},           {NULL, 0, NULL, 0}};
    int c, status = SC_EXIT_OK;
    sc_getopt_reset();
    while (status == SC_EXIT_OK && (c = sc_getopt(argc, argv, "s:u:t:m:ef:h", longs)) != -1) {
        switch (c) {
        case 's': status = parse_surface(optarg, o); break;
        case 'u': status = parse_uv(optarg, o); break;
        case 't': status = parse_triangle(optarg, o); break;
        case 'm': status = parse_matrix(optarg, o); break;
        case 'e': o->explain = 1; break;
        case 'f': status = parse_format(optarg, o); break;
        case 'h': usage(stdout); return -1;
        default: return sc_usage_error("normal", argv, optopt);
        }
    }
    if (status == SC_EXIT_OK && o->has_triangle)
        status = parse_triangle_rest(argc, argv, o);
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("normal: unexpected argument '%s'", argv[optind]);
        status = SC_EXIT_USAGE;
    }
    return status == SC_EXIT_OK ? check_mode(o) : status;
}

static int run(int argc, char **argv)
{
    normal_options o = {0};
    int status = parse_options(argc, argv, &o);
    if (status == SC_EXIT_OK)
        status = o.surface ? run_surface(&o) : o.has_triangle ? run_triangle(&o) : run_matrix(&o);
    sc_surface_free(o.surface);
    return status < 0 ? SC_EXIT_OK : status;
}

const sc_command sc_cmd_normal = {
    "normal", "surface, triangle and transformed normals (exact derivatives)", run};
