/* The cost of one evaluation of the Disney principled BRDF (Burley 2012) written in GLSL
 * (bench/programs/disney.glsl) and run by the language's block execution
 * (sc_program_run_block), against the same code translated by hand to C (below, binary32 as
 * GLSL's float, compiled with the project's flags: -O2), against one element at a time
 * (sc_program_run), and against the closest built-in model, cook-torrance with GGX, Smith and
 * Schlick (sc_brdf_eval). One thread; CPU time of this process (the machine may be shared), and
 * wall time beside it. Directions are random in the upper hemisphere (no early return), then,
 * for the block path, with V over the whole sphere (half the elements return early: divergence).
 *
 * usage: brdf_disney [GLSL_FILE [ELEMENTS]]   (default bench/programs/disney.glsl, 65536) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "shadecalc/brdf.h"
#include "shadecalc/lang.h"

/* ---- the GLSL of disney.glsl in C (same operations, same order, binary32) ---- */

typedef struct {
    float x, y, z;
} v3;

static v3 v3_make(float x, float y, float z) { return (v3){x, y, z}; }
static v3 add(v3 a, v3 b) { return v3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 scale(v3 a, float s) { return v3_make(a.x * s, a.y * s, a.z * s); }
static float dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 divide(v3 a, float s) { return v3_make(a.x / s, a.y / s, a.z / s); }
static v3 normalize(v3 a) { return divide(a, sqrtf(dot(a, a))); }
static float mixf(float x, float y, float a) { return x * (1.0f - a) + y * a; }
static v3 mix3(v3 x, v3 y, float a)
{
    return v3_make(mixf(x.x, y.x, a), mixf(x.y, y.y, a), mixf(x.z, y.z, a));
}
static float clampf(float x, float lo, float hi) { return fminf(fmaxf(x, lo), hi); }

static const v3 base_color = {0.82f, 0.67f, 0.16f};
static const float metallic = 0.2f, subsurface = 0.3f, specular = 0.5f, roughness = 0.5f,
                   specular_tint = 0.1f, anisotropic = 0.4f, sheen = 0.5f, sheen_tint = 0.5f,
                   clearcoat = 0.6f, clearcoat_gloss = 0.8f;
#define PI_F 3.14159265358979323846f

static float sqr(float x) { return x * x; }

static float schlick_fresnel(float u)
{
    float m = clampf(1.0f - u, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

static float gtr1(float n_h, float a)
{
    if (a >= 1.0f)
        return 1.0f / PI_F;
    float a2 = a * a;
    float t = 1.0f + (a2 - 1.0f) * n_h * n_h;
    return (a2 - 1.0f) / (PI_F * logf(a2) * t);
}

static float gtr2_aniso(float n_h, float h_x, float h_y, float ax, float ay)
{
    return 1.0f / (PI_F * ax * ay * sqr(sqr(h_x / ax) + sqr(h_y / ay) + n_h * n_h));
}

static float smith_g_ggx(float n_v, float alpha_g)
{
    float a = alpha_g * alpha_g;
    float b = n_v * n_v;
    return 1.0f / (n_v + sqrtf(a + b - a * b));
}

static v3 mon2lin(v3 x) { return v3_make(powf(x.x, 2.2f), powf(x.y, 2.2f), powf(x.z, 2.2f)); }

static v3 disney_c(v3 L, v3 V, v3 N, v3 X, v3 Y)
{
    float n_l = dot(N, L), n_v = dot(N, V);
    if (n_l < 0.0f || n_v < 0.0f)
        return v3_make(0, 0, 0);
    v3 H = normalize(add(L, V));
    float n_h = dot(N, H), l_h = dot(L, H);
    v3 cdlin = mon2lin(base_color);
    float cdlum = 0.3f * cdlin.x + 0.6f * cdlin.y + 0.1f * cdlin.z;
    v3 one = v3_make(1, 1, 1);
    v3 ctint = cdlum > 0.0f ? divide(cdlin, cdlum) : one;
    v3 cspec0 = mix3(scale(mix3(one, ctint, specular_tint), specular * 0.08f), cdlin, metallic);
    v3 csheen = mix3(one, ctint, sheen_tint);
    float fl = schlick_fresnel(n_l), fv = schlick_fresnel(n_v);
    float fd90 = 0.5f + 2.0f * l_h * l_h * roughness;
    float fd = mixf(1.0f, fd90, fl) * mixf(1.0f, fd90, fv);
    float fss90 = l_h * l_h * roughness;
    float fss = mixf(1.0f, fss90, fl) * mixf(1.0f, fss90, fv);
    float ss = 1.25f * (fss * (1.0f / (n_l + n_v) - 0.5f) + 0.5f);
    float aspect = sqrtf(1.0f - anisotropic * 0.9f);
    float ax = fmaxf(0.001f, sqr(roughness) / aspect), ay = fmaxf(0.001f, sqr(roughness) * aspect);
    float ds = gtr2_aniso(n_h, dot(H, X), dot(H, Y), ax, ay);
    float fh = schlick_fresnel(l_h);
    v3 fs = mix3(cspec0, one, fh);
    float roughg = sqr(roughness * 0.5f + 0.5f);
    float gs = smith_g_ggx(n_l, roughg) * smith_g_ggx(n_v, roughg);
    v3 fsheen = scale(csheen, fh * sheen);
    float dr = gtr1(n_h, mixf(0.1f, 0.001f, clearcoat_gloss));
    float fr = mixf(0.04f, 1.0f, fh);
    float gr = smith_g_ggx(n_l, 0.25f) * smith_g_ggx(n_v, 0.25f);
    v3 diffuse = add(scale(cdlin, (1.0f / PI_F) * mixf(fd, ss, subsurface)), fsheen);
    return add(add(scale(diffuse, 1.0f - metallic), scale(scale(fs, gs), ds)),
               scale(one, 0.25f * clearcoat * gr * fr * dr));
}

/* ---- inputs ---- */

enum { COLUMNS = 15 }; /* L, V, N, X, Y: three components each */

static double unit_random(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* A random unit vector, in the upper hemisphere (z >= 0) unless `sphere`. */
static void direction(unsigned long long *s, int sphere, double *d)
{
    double z = sphere ? 2.0 * unit_random(s) - 1.0 : unit_random(s),
           phi = 6.283185307 * unit_random(s);
    double r = sqrt(1.0 - z * z);
    d[0] = r * cos(phi), d[1] = r * sin(phi), d[2] = z;
}

static void make_inputs(double **cols, long n, int sphere)
{
    unsigned long long s = 12345;
    static const double frame[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0}; /* N, X, Y */
    for (long e = 0; e < n; e++) {
        double l[3], v[3];
        direction(&s, 0, l);
        direction(&s, sphere, v);
        for (int k = 0; k < 3; k++) {
            cols[k][e] = l[k];
            cols[3 + k][e] = v[k];
        }
        for (int k = 0; k < 9; k++)
            cols[6 + k][e] = frame[k];
    }
}

/* ---- timing ---- */

typedef struct {
    double cpu, wall;
} stamp;

static stamp now(void)
{
    struct timespec c, w;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
    clock_gettime(CLOCK_MONOTONIC, &w);
    return (stamp){(double)c.tv_sec + 1e-9 * (double)c.tv_nsec,
                   (double)w.tv_sec + 1e-9 * (double)w.tv_nsec};
}

typedef struct {
    const char *name;
    double cpu_ns, wall_ns; /* per evaluation */
} result;

typedef void (*pass_fn)(void *ctx, long n);

/* Repeats pass(ctx, n) for at least 0.5 s of CPU time: the cost of one evaluation. */
static result measure(const char *name, pass_fn pass, void *ctx, long n)
{
    long evaluations = 0;
    stamp t0 = now(), t1;
    do {
        pass(ctx, n);
        evaluations += n;
        t1 = now();
    } while (t1.cpu - t0.cpu < 0.5);
    return (result){name, 1e9 * (t1.cpu - t0.cpu) / (double)evaluations,
                    1e9 * (t1.wall - t0.wall) / (double)evaluations};
}

/* ---- the passes ---- */

typedef struct {
    double **in, **out;
    const sc_program *prog;
    sc_prec prec;
} context;

static void pass_c(void *p, long n)
{
    context *c = p;
    double **in = c->in;
    for (long e = 0; e < n; e++) {
        v3 L = v3_make((float)in[0][e], (float)in[1][e], (float)in[2][e]);
        v3 V = v3_make((float)in[3][e], (float)in[4][e], (float)in[5][e]);
        v3 N = v3_make((float)in[6][e], (float)in[7][e], (float)in[8][e]);
        v3 X = v3_make((float)in[9][e], (float)in[10][e], (float)in[11][e]);
        v3 Y = v3_make((float)in[12][e], (float)in[13][e], (float)in[14][e]);
        v3 f = disney_c(L, V, N, X, Y);
        c->out[0][e] = f.x, c->out[1][e] = f.y, c->out[2][e] = f.z;
    }
}

static void pass_block(void *p, long n)
{
    context *c = p;
    sc_lang_block job = {
        c->prec, n,   (const double *const *)c->in, sc_program_values(c->prog) - 1, c->out,
        NULL,    NULL};
    sc_lang_error err;
    if (sc_program_run_block(c->prog, &job, &err) != n) {
        fprintf(stderr, "brdf_disney: %d:%d: %s\n", err.line, err.column, err.message);
        exit(1);
    }
}

typedef struct {
    double *out[3];
    long element;
} one_element;

static int keep(void *user, const char *text, int len, int line, const sc_lvalue *v)
{
    one_element *o = user;
    (void)text, (void)len, (void)line;
    for (int k = 0; k < 3; k++)
        o->out[k][o->element] = v->v[k];
    return 0;
}

static void pass_elements(void *p, long n)
{
    context *c = p;
    one_element o = {{c->out[0], c->out[1], c->out[2]}, 0};
    for (; o.element < n; o.element++) {
        sc_lvalue in[5];
        for (int i = 0; i < 5; i++) {
            in[i].type = (sc_ltype){SC_KIND_FLOAT, 1, 3};
            for (int k = 0; k < 3; k++)
                in[i].v[k] = c->in[3 * i + k][o.element];
        }
        sc_lang_error err;
        sc_program_run(c->prog, c->prec, in, keep, NULL, &o, &err);
    }
}

static void pass_builtin(void *p, long n)
{
    context *c = p;
    sc_brdf b;
    sc_brdf_init(&b, SC_BRDF_COOK_TORRANCE);
    sc_frame frame;
    static const double normal[3] = {0, 0, 1}, tangent[3] = {1, 0, 0};
    sc_frame_make(normal, tangent, &frame);
    for (long e = 0; e < n; e++) {
        double l[3] = {c->in[0][e], c->in[1][e], c->in[2][e]};
        double v[3] = {c->in[3][e], c->in[4][e], c->in[5][e]};
        sc_brdf_terms t;
        sc_brdf_eval(c->prec, &b, &frame, l, v, &t);
        c->out[0][e] = t.f[0], c->out[1][e] = t.f[1], c->out[2][e] = t.f[2];
    }
}

/* ---- main ---- */

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "r");
    char *buf = malloc(1 << 20);
    size_t len = f && buf ? fread(buf, 1, (1 << 20) - 64, f) : 0;
    if (f)
        fclose(f);
    if (!len) {
        free(buf);
        return NULL;
    }
    strcpy(buf + len, "\nBRDF(L, V, N, X, Y)\n");
    return buf;
}

/* The largest |a - b| / max(|b|, 1e-3) over the elements: how far the VM is from the C code. */
static double max_relative(double **a, double **b, long n)
{
    double worst = 0.0;
    for (int k = 0; k < 3; k++)
        for (long e = 0; e < n; e++) {
            double d = fabs(a[k][e] - b[k][e]) / fmax(fabs(b[k][e]), 1e-3);
            worst = d > worst ? d : worst;
        }
    return worst;
}

static void print_row(const result *r, double c_ns)
{
    printf("| %-44s | %8.1f | %8.1f | %6.2f |\n", r->name, r->cpu_ns, r->wall_ns, r->cpu_ns / c_ns);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "bench/programs/disney.glsl";
    long n = argc > 2 ? atol(argv[2]) : 65536;
    char *src = read_text(path);
    if (!src || n < 1) {
        fprintf(stderr, "usage: brdf_disney [GLSL_FILE [ELEMENTS]] (cannot read '%s')\n", path);
        return 2;
    }
    sc_lang_input decl[5];
    static const char *const names[5] = {"L", "V", "N", "X", "Y"};
    for (int i = 0; i < 5; i++)
        decl[i] = (sc_lang_input){names[i], {SC_KIND_FLOAT, 1, 3}};
    sc_lang_error err;
    sc_program *prog = sc_program_compile(src, decl, 5, NULL, &err);
    if (!prog) {
        fprintf(stderr, "brdf_disney: %s:%d:%d: %s\n", path, err.line, err.column, err.message);
        return 1;
    }
    double *in[COLUMNS], *out[3], *ref[3];
    for (int k = 0; k < COLUMNS; k++)
        in[k] = malloc((size_t)n * sizeof(double));
    for (int k = 0; k < 3; k++) {
        out[k] = malloc((size_t)n * sizeof(double));
        ref[k] = malloc((size_t)n * sizeof(double));
    }
    make_inputs(in, n, 0);
    context c = {in, ref, prog, SC_HIGHP};
    result r[7];
    r[0] = measure("C, binary32, -O2", pass_c, &c, n);
    c.out = out;
    r[1] = measure("GLSL, block execution, highp", pass_block, &c, n);
    double differs = max_relative(out, ref, n);
    c.prec = SC_DOUBLE;
    r[2] = measure("GLSL, block execution, double", pass_block, &c, n);
    c.prec = SC_HIGHP;
    r[3] = measure("GLSL, one element at a time, highp", pass_elements, &c, n / 16);
    r[4] = measure("built-in cook-torrance GGX (sc_brdf_eval), highp", pass_builtin, &c, n);
    make_inputs(in, n, 1);
    c.out = ref;
    r[5] = measure("C, V over the sphere (half return early)", pass_c, &c, n);
    c.out = out;
    r[6] = measure("GLSL, block, highp, V over the sphere", pass_block, &c, n);
    printf("Disney BRDF (%s), %ld elements, ns per evaluation on one thread\n\n", path, n);
    printf("| %-44s | %8s | %8s | %6s |\n|%s|%s|%s|%s|\n", "", "CPU ns", "wall ns", "x C",
           "----------------------------------------------", "----------", "----------",
           "--------");
    for (int i = 0; i < 5; i++)
        print_row(&r[i], r[0].cpu_ns);
    for (int i = 5; i < 7; i++)
        print_row(&r[i], r[5].cpu_ns);
    printf("\nlargest relative difference, block highp vs C: %.2g (libm's powf, logf against "
           "shadecalc's correctly rounded ones)\n",
           differs);
    sc_program_free(prog);
    free(src);
    for (int k = 0; k < COLUMNS; k++)
        free(in[k]);
    for (int k = 0; k < 3; k++) {
        free(out[k]);
        free(ref[k]);
    }
    return 0;
}
