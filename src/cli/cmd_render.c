/* shadecalc render — rasterize a tessellated surface or an OBJ mesh with flat, Gouraud, Phong or
 * exact shading into an EXR, or the lecture's Gouraud/Phong comparison with its errors
 * (docs/formulas.md §8). */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/brdf_file_cli.h"
#include "cli/cli.h"
#include "cli/progress.h"
#include "cli/setup.h"
#include "shadecalc/batch.h"
#include "shadecalc/file.h"
#include "shadecalc/render.h"

/* The default picture: a z-up world (the built-in surfaces' axes are z) seen from the front
 * right and above, lit from the viewer's upper left so that the highlight sits inside the
 * disc. */
static const double default_view[3] = {0.35, -1.0, 0.45};
static const char *const default_light = "directional dir=-0.4,-1,1.1 I=2";
static const char *const default_brdf = "blinn-phong diff=0.7,0.35,0.2 spec=0.3 m=60";
/* --compare: a sharper highlight, so that coarse Gouraud misses or smears it. */
static const char *const compare_brdf = "blinn-phong diff=0.5,0.25,0.15 spec=0.4 m=200";

enum { FMT_TABLE, FMT_CSV };

typedef struct {
    const char *surface, *mesh_path, *output, *output_dir;
    int triangles, width, height, threads, depth, normals, compare, format;
    sc_shading shading;
    sc_exr_options exr; /* type and compression; threads from --threads */
    sc_prec prec;
    const char *tier; /* the shading kernel's tier */
    int have_tier;
    double eye[3], at[3], up[3], fov;
    int have_eye, have_at;
    const char *plan_option; /* --shading or --triangles, which --compare's plan fixes */
    char *command;           /* the command line, for the EXR header */
} render_options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc render [OPTIONS] -o FILE.exr\n"
            "       shadecalc render --compare [--size WxH] [--output-dir DIR] [--format F]\n"
            "\n"
            "Rasterizes a tessellated surface (or an OBJ mesh) with flat, Gouraud, Phong or\n"
            "exact per-pixel shading into an OpenEXR image; --compare renders Gouraud at 1024,\n"
            "6320 and 40000 triangles and Phong at 6320 against the exact surface and prints\n"
            "mode,triangles,seconds,rmse,max_error.\n"
            "\n"
            "      --surface SPEC   sphere|torus|plane|cylinder|user ... (default sphere)\n"
            "      --mesh FILE      a Wavefront OBJ mesh instead of a surface\n"
            "  -n, --triangles N    about N triangles for the surface (default 6320)\n"
            "      --shading MODE   flat|gouraud|phong|exact (default phong)\n"
            "  -l, --light SPEC     a light (repeatable), as in 'shadecalc shade'\n"
            "  -b, --brdf SPEC      the model, as in 'shadecalc shade'\n"
            "  -a, --ambient C      global ambient radiance L_A\n"
            "  -s, --scene FILE     lights, model, ambient and eye from a scene file\n"
            "      --eye X,Y,Z      camera position (default: framing the mesh)\n"
            "      --at X,Y,Z       point looked at (default: the mesh's centre)\n"
            "      --up X,Y,Z       up direction (default 0,0,1)\n"
            "      --fov DEG        vertical field of view (default 40)\n"
            "      --size WxH       image size (default 512x512)\n"
            "  -o, --output FILE    the EXR to write (RGBA)\n"
            "      --exr-type T     half|float (default half)\n"
            "      --compression C  none|rle|zips|zip|piz|pxr24 (default zip)\n"
            "      --depth          add a Z channel (view depth)\n"
            "      --normals        add N.X N.Y N.Z (the shading normal)\n"
            "  -j, --threads N      threads (default: one per online core)\n"
            "  -p, --precision P    double|highp|mediump|lowp (default highp)\n"
            "      --isa I          scalar|sse4.1|avx2|avx512: the kernels' instruction set\n"
            "                       (default: SHADECALC_ISA, else the best this CPU has)\n"
            "      --tier T         accurate|bits12: the shading kernel's tier\n"
            "                       (default accurate)\n"
            "      --compare        the Gouraud/Phong comparison (writes into --output-dir)\n"
            "      --output-dir DIR where --compare writes its images (default .)\n"
            "  -f, --format F       table|csv for --compare (default table)\n"
            "      --force          replace read-only files among those written\n"
            "  -h, --help           this help\n"
            "\n"
            "example: shadecalc render --surface 'torus R=1 r=0.3' --shading phong -o torus.exr\n");
}

/* ---- option values ---- */

static int parse_size(const char *arg, render_options *o)
{
    char *end;
    long w = strtol(arg, &end, 10), h = 0;
    int ok = end != arg && (*end == 'x' || *end == 'X');
    if (ok) {
        const char *hs = end + 1;
        h = strtol(hs, &end, 10);
        ok = end != hs && *end == '\0';
    }
    if (!ok || w < 1 || h < 1 || w > SC_RENDER_MAX_SIDE || h > SC_RENDER_MAX_SIDE ||
        w * h > SC_RENDER_MAX_PIXELS) {
        sc_error("render: --size %s: expected WxH, each 1..%d, at most %ld pixels", arg,
                 SC_RENDER_MAX_SIDE, SC_RENDER_MAX_PIXELS);
        return SC_EXIT_USAGE;
    }
    o->width = (int)w;
    o->height = (int)h;
    return SC_EXIT_OK;
}

static int parse_count(const char *opt, const char *arg, long lo, long hi, int *out)
{
    long v;
    if (sc_parse_long(arg, &v) < 0 || v < lo || v > hi) {
        sc_error("render: %s %s: expected a whole number %ld..%ld", opt, arg, lo, hi);
        return SC_EXIT_USAGE;
    }
    *out = (int)v;
    return SC_EXIT_OK;
}

static int parse_vector(const char *opt, const char *arg, double out[3], int *flag)
{
    if (sc_parse_vector3(arg, out) < 0) {
        sc_error("render: %s %s: expected three numbers X,Y,Z", opt, arg);
        return SC_EXIT_USAGE;
    }
    if (flag)
        *flag = 1;
    return SC_EXIT_OK;
}

static int parse_choice(const char *opt, const char *arg, const char *const *names, int n, int *out)
{
    for (int i = 0; i < n; i++)
        if (strcmp(arg, names[i]) == 0) {
            *out = i;
            return SC_EXIT_OK;
        }
    sc_error("render: %s %s: expected %s", opt, arg,
             n == 2 && names[0][0] == 'h' ? "half|float" : "table|csv");
    return SC_EXIT_USAGE;
}

/* The command line as one shell-quoted string. */
static char *join_command(int argc, char **argv)
{
    size_t size = strlen("shadecalc") + 1;
    for (int i = 0; i < argc; i++)
        size += 4 * strlen(argv[i]) + 3;
    char *s = malloc(size), *p = s;
    if (!s)
        return NULL;
    p += sprintf(p, "shadecalc");
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int plain = *a && strspn(a, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                    "0123456789_./,=:+-@%") == strlen(a);
        *p++ = ' ';
        if (plain) {
            p += sprintf(p, "%s", a);
            continue;
        }
        *p++ = '\'';
        for (; *a; a++)
            p += *a == '\'' ? sprintf(p, "'\\''") : sprintf(p, "%c", *a);
        *p++ = '\'';
    }
    *p = '\0';
    return s;
}

/* ---- options ---- */

/* --isa: the instruction set of the batch shading kernel highp pixels go through */
static int parse_isa(const char *arg)
{
    sc_isa isa;
    if (sc_isa_parse(arg, &isa) != 0) {
        sc_error("render: --isa %s: expected scalar, sse4.1, avx2 or avx512", arg);
        return SC_EXIT_USAGE;
    }
    if (sc_isa_set(isa) != 0) {
        sc_error("render: --isa %s: not supported by this CPU or build", arg);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

/* --tier: a tier of the batch shading kernel */
static int parse_tier(const char *arg, const char **out)
{
    if (!sc_batch_find("shade", arg, SC_ISA_SCALAR)) {
        sc_error("render: --tier %s: expected accurate or bits12", arg);
        return SC_EXIT_USAGE;
    }
    *out = arg;
    return SC_EXIT_OK;
}

/* A --tier given must be one the batch kernel computes this scene with, in highp. */
static int check_tier(const render_options *o, const sc_scene *scene)
{
    char why[256];
    if (!o->have_tier)
        return SC_EXIT_OK;
    if (o->prec != SC_HIGHP) {
        sc_error("render: --tier %s: the shading kernel computes highp, not -p %s", o->tier,
                 sc_prec_name(o->prec));
        return SC_EXIT_USAGE;
    }
    sc_batch_plan *plan = sc_batch_plan_compile(scene, o->tier, sc_isa_active(), why, sizeof why);
    if (!plan) {
        sc_error("render: --tier %s: the shading kernel does not compute this scene: %s", o->tier,
                 why);
        return SC_EXIT_USAGE;
    }
    sc_batch_plan_free(plan);
    return SC_EXIT_OK;
}

static int parse_compression(const char *arg, sc_exr_compression *out)
{
    if (sc_exr_compression_parse(arg, out) != 0) {
        sc_error("render: --compression %s: expected none|rle|zips|zip|piz|pxr24", arg);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

enum {
    OPT_SURFACE = 256,
    OPT_MESH,
    OPT_SHADING,
    OPT_EYE,
    OPT_AT,
    OPT_UP,
    OPT_FOV,
    OPT_SIZE,
    OPT_EXR_TYPE,
    OPT_DEPTH,
    OPT_NORMALS,
    OPT_COMPARE,
    OPT_OUTPUT_DIR,
    OPT_ISA,
    OPT_TIER,
    OPT_COMPRESSION,
    OPT_FORCE
};

typedef struct {
    int opt;
    const char *arg;
} pending;

static int apply_value(render_options *o, int c, const char *arg)
{
    static const char *const types[] = {"half", "float"}, *const formats[] = {"table", "csv"};
    int choice, status = SC_EXIT_OK;
    switch (c) {
    case OPT_SURFACE: o->surface = arg; break;
    case OPT_MESH: o->mesh_path = arg; break;
    case 'n':
        o->plan_option = "--triangles";
        return parse_count("--triangles", arg, 2, 1L << 26, &o->triangles);
    case 'j': return parse_count("--threads", arg, 1, 1024, &o->threads);
    case OPT_ISA: return parse_isa(arg);
    case OPT_TIER: o->have_tier = 1; return parse_tier(arg, &o->tier);
    case OPT_COMPRESSION: return parse_compression(arg, &o->exr.compression);
    case OPT_SIZE: return parse_size(arg, o);
    case OPT_EYE: return parse_vector("--eye", arg, o->eye, &o->have_eye);
    case OPT_AT: return parse_vector("--at", arg, o->at, &o->have_at);
    case OPT_UP: return parse_vector("--up", arg, o->up, NULL);
    case 'o': o->output = arg; return sc_check_output_name("render", "-o", arg, "exr");
    case OPT_OUTPUT_DIR: o->output_dir = arg; break;
    case OPT_DEPTH: o->depth = 1; break;
    case OPT_NORMALS: o->normals = 1; break;
    case OPT_COMPARE: o->compare = 1; break;
    case OPT_FORCE: sc_atomic_allow_read_only(1); break;
    case OPT_FOV:
        if (sc_parse_double(arg, &o->fov) < 0 || !(o->fov > 0.0 && o->fov < 180.0)) {
            sc_error("render: --fov %s: expected degrees between 0 and 180", arg);
            return SC_EXIT_USAGE;
        }
        break;
    case OPT_SHADING:
        o->plan_option = "--shading";
        if (sc_shading_parse(arg, &o->shading) < 0) {
            sc_error("render: --shading %s: expected flat|gouraud|phong|exact", arg);
            return SC_EXIT_USAGE;
        }
        break;
    case OPT_EXR_TYPE:
        status = parse_choice("--exr-type", arg, types, 2, &choice);
        o->exr.type = choice ? SC_PIXEL_FLOAT : SC_PIXEL_HALF;
        break;
    case 'f': status = parse_choice("--format", arg, formats, 2, &o->format); break;
    case 'p':
        if (sc_prec_parse(arg, &o->prec) < 0) {
            sc_error("render: --precision %s: expected double|highp|mediump|lowp", arg);
            return SC_EXIT_USAGE;
        }
        break;
    }
    return status;
}

static int apply_setup(shade_setup *s, const pending *o)
{
    switch (o->opt) {
    case 'l': return setup_add_light(s, o->arg, "");
    case 'b': return setup_set_model(s, o->arg, "");
    default: return setup_set_value(s, "ambient", o->arg, "");
    }
}

static const struct option long_options[] = {
    {"surface", required_argument, NULL, OPT_SURFACE},
    {"mesh", required_argument, NULL, OPT_MESH},
    {"triangles", required_argument, NULL, 'n'},
    {"shading", required_argument, NULL, OPT_SHADING},
    {"light", required_argument, NULL, 'l'},
    {"brdf", required_argument, NULL, 'b'},
    {"ambient", required_argument, NULL, 'a'},
    {"scene", required_argument, NULL, 's'},
    {"eye", required_argument, NULL, OPT_EYE},
    {"at", required_argument, NULL, OPT_AT},
    {"up", required_argument, NULL, OPT_UP},
    {"fov", required_argument, NULL, OPT_FOV},
    {"size", required_argument, NULL, OPT_SIZE},
    {"output", required_argument, NULL, 'o'},
    {"exr-type", required_argument, NULL, OPT_EXR_TYPE},
    {"depth", no_argument, NULL, OPT_DEPTH},
    {"normals", no_argument, NULL, OPT_NORMALS},
    {"threads", required_argument, NULL, 'j'},
    {"isa", required_argument, NULL, OPT_ISA},
    {"tier", required_argument, NULL, OPT_TIER},
    {"compression", required_argument, NULL, OPT_COMPRESSION},
    {"precision", required_argument, NULL, 'p'},
    {"compare", no_argument, NULL, OPT_COMPARE},
    {"output-dir", required_argument, NULL, OPT_OUTPUT_DIR},
    {"format", required_argument, NULL, 'f'},
    {"force", no_argument, NULL, OPT_FORCE},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0}};

/* Lights, model and ambient: the scene file first, then the options in order. */
static int parse_options(int argc, char **argv, shade_setup *s, render_options *o)
{
    pending *todo = calloc((size_t)argc + 1, sizeof *todo);
    const char *scene = NULL;
    int n = 0, c, status = todo ? SC_EXIT_OK : SC_EXIT_RUNTIME;
    sc_getopt_reset();
    while (status == SC_EXIT_OK &&
           (c = sc_getopt(argc, argv, "n:l:b:a:s:o:j:p:f:h", long_options)) != -1) {
        switch (c) {
        case 's': scene = optarg; break;
        case 'l':
        case 'b':
        case 'a': todo[n++] = (pending){c, optarg}; break;
        case 'h':
            usage(stdout);
            status = -1;
            break;
        case '?': status = sc_usage_error("render", argv, optopt); break;
        default: status = apply_value(o, c, optarg); break;
        }
    }
    if (status == SC_EXIT_OK && optind < argc) {
        sc_error("render: unexpected argument '%s'", argv[optind]);
        status = SC_EXIT_USAGE;
    }
    if (status == SC_EXIT_OK && scene)
        status = setup_load_file(s, scene);
    for (int i = 0; status == SC_EXIT_OK && i < n; i++)
        status = apply_setup(s, &todo[i]);
    free(todo);
    return status;
}

static int check_options(const shade_setup *s, const render_options *o)
{
    const sc_brdf *b = &s->model.brdf;
    if (o->mesh_path && o->surface) {
        sc_error("render: give --surface or --mesh, not both");
        return SC_EXIT_USAGE;
    }
    if (o->mesh_path && (o->shading == SC_SHADING_EXACT || o->compare)) {
        sc_error("render: --mesh %s: exact shading and --compare need an analytic --surface",
                 o->mesh_path);
        return SC_EXIT_USAGE;
    }
    if (!o->compare && !o->output) {
        sc_error("render: no output: give -o FILE.exr (or --compare)");
        return SC_EXIT_USAGE;
    }
    if (o->compare && o->output) {
        sc_error("render: --compare writes into --output-dir, not -o %s", o->output);
        return SC_EXIT_USAGE;
    }
    if (o->compare && o->plan_option) {
        sc_error("render: --compare renders its own plan (Gouraud at 1024, 6320, 40000 "
                 "triangles, Phong at 6320, exact): %s does not apply",
                 o->plan_option);
        return SC_EXIT_USAGE;
    }
    if (s->model.kind == SC_MODEL_BRDF && b->ax != b->ay &&
        (b->kind == SC_BRDF_WARD || b->kind == SC_BRDF_COOK_TORRANCE)) {
        sc_error("render: brdf %s: anisotropic roughness (ax=%g ay=%g) needs a tangent field, "
                 "which render does not have",
                 sc_brdf_kind_name(b->kind), b->ax, b->ay);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

/* Default light and model where the options and scene gave none. */
static int complete_setup(shade_setup *s, const render_options *o)
{
    int status = SC_EXIT_OK;
    if (s->n_lights == 0)
        status = setup_add_light(s, default_light, "");
    if (status == SC_EXIT_OK && !s->have_model)
        status = setup_set_model(s, o->compare ? compare_brdf : default_brdf, "");
    return status == SC_EXIT_OK ? setup_check_range(s, o->prec) : status;
}

/* ---- meshes ---- */

static int load_surface(const render_options *o, sc_surface **out)
{
    char err[512];
    *out = sc_surface_parse(o->surface ? o->surface : "sphere", err, sizeof err);
    if (!*out) {
        sc_error("render: --surface: %s", err);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
}

static int tessellate(const sc_surface *surface, int triangles, sc_mesh *m)
{
    char err[512];
    if (sc_surface_tessellate(surface, triangles, m, err, sizeof err) < 0) {
        sc_error("render: %s", err);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

/* An OBJ without normals gets the lecture's per-vertex normals (plain average). */
static int load_obj(const char *path, sc_mesh *m)
{
    char err[512];
    int read = sc_obj_read(path, m, err, sizeof err);
    if (read < 0) {
        sc_error("%s", err);
        return read == -1 ? SC_EXIT_USAGE : SC_EXIT_RUNTIME; /* malformed content: 2 */
    }
    if (!m->normal && sc_mesh_vertex_normals(m, SC_NORMALS_PLAIN) < 0) {
        sc_error("render: out of memory");
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

/* ---- camera, progress, output ---- */

static void make_camera(const render_options *o, const shade_setup *s, const sc_mesh *m,
                        sc_camera *cam)
{
    memcpy(cam->up, o->up, sizeof cam->up);
    cam->fov = o->fov;
    sc_camera_fit(cam, m, default_view, o->width, o->height);
    if (o->have_at) {
        for (int k = 0; k < 3; k++) {
            cam->eye[k] += o->at[k] - cam->at[k];
            cam->at[k] = o->at[k];
        }
    }
    if (o->have_eye || s->have_eye)
        memcpy(cam->eye, o->have_eye ? o->eye : s->eye, sizeof cam->eye);
}

/* Drawn on a terminal once a render has taken half a second. */
static void progress_tick(void *ctx, int done, int total)
{
    sc_progress_update(ctx, (double)done / total, NULL);
}

/* Writes img with the command line and one more string attribute in the header. */
static int write_exr(const render_options *o, const sc_image *img, const char *path,
                     const char *key, const char *value)
{
    char err[1024];
    const sc_image_attr attrs[] = {{"shadecalc:command", o->command}, {(char *)key, (char *)value}};
    sc_exr_options exr = o->exr;
    exr.threads = o->threads;
    if (sc_exr_write_with(path, img, &exr, attrs, 2, err, sizeof err) < 0) {
        sc_error("%s", err);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

/* A framebuffer with the planes the image will have. */
static int init_framebuffer(const render_options *o, sc_framebuffer *fb)
{
    int planes = (o->depth ? SC_FRAMEBUFFER_DEPTH : 0) | (o->normals ? SC_FRAMEBUFFER_NORMAL : 0);
    return sc_framebuffer_init_planes(fb, o->width, o->height, planes);
}

/* Writes a framebuffer's image, made (sc_render_image or _take) with the status `made`, and
 * releases it. */
static int write_image(int made, sc_image *img, const render_options *o, const char *path,
                       const char *mode)
{
    if (made < 0) {
        sc_error("render: out of memory");
        return SC_EXIT_RUNTIME;
    }
    int status = write_exr(o, img, path, "shadecalc:shading", mode);
    sc_image_free(img);
    return status;
}

/* Renders and reports the seconds it took (the render only, not tessellation or output). */
static int draw(sc_render_params *rp, const char *label, sc_framebuffer *fb, double *seconds)
{
    char err[512];
    sc_progress bar;
    sc_progress_start(&bar, label, 0.5);
    rp->progress = progress_tick;
    rp->progress_ctx = &bar;
    int bad = sc_render(rp, fb, err, sizeof err);
    *seconds = sc_progress_seconds(&bar);
    sc_progress_clear(&bar);
    if (bad) {
        sc_error("%s", err);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

/* ---- one image ---- */

/* A warning if colours overflow: inf in the precision, or beyond half's 65504 in a half EXR. */
static void warn_overflow(const sc_framebuffer *fb, const render_options *o)
{
    double largest = o->exr.type == SC_PIXEL_HALF ? 65504.0 : HUGE_VAL;
    long count = 0;
    for (size_t i = 0; i < (size_t)fb->width * (size_t)fb->height; i++)
        for (int c = 0; c < 3; c++)
            if (fabs(fb->rgba[4 * i + c]) > largest || isinf(fb->rgba[4 * i + c])) {
                count++;
                break;
            }
    if (count)
        sc_warning("render: %ld pixels overflow to inf (beyond %s)", count,
                   o->exr.type == SC_PIXEL_HALF ? "half's 65504" : "the float range");
}

static int render_one(const render_options *o, const shade_setup *s, const sc_scene *scene)
{
    sc_surface *surface = NULL;
    sc_mesh mesh = {0};
    sc_framebuffer fb = {0};
    int status = o->mesh_path ? load_obj(o->mesh_path, &mesh) : load_surface(o, &surface);
    if (status == SC_EXIT_OK && surface)
        status = tessellate(surface, o->triangles, &mesh);
    if (status == SC_EXIT_OK && init_framebuffer(o, &fb) < 0) {
        sc_error("render: out of memory for a %dx%d image", o->width, o->height);
        status = SC_EXIT_RUNTIME;
    }
    double seconds;
    sc_render_params rp = {.mesh = &mesh,
                           .surface = surface,
                           .scene = scene,
                           .prec = o->prec,
                           .tier = o->tier,
                           .shading = o->shading,
                           .threads = o->threads};
    if (status == SC_EXIT_OK) {
        char err[512];
        make_camera(o, s, &mesh, &rp.camera);
        if (sc_camera_validate(&rp.camera, err, sizeof err) < 0) {
            sc_error("render: %s", err);
            status = SC_EXIT_USAGE;
        }
    }
    if (status == SC_EXIT_OK)
        status = draw(&rp, sc_shading_name(o->shading), &fb, &seconds);
    if (status == SC_EXIT_OK) /* a shader that failed gave NaN: no image */
        status = brdf_file_status(&scene->model, "render");
    if (status == SC_EXIT_OK) {
        warn_overflow(&fb, o);
        sc_image img; /* the colours move into it: no copy */
        status = write_image(sc_render_image_take(&fb, o->depth, o->normals, &img), &img, o,
                             o->output, sc_shading_name(o->shading));
    }
    sc_framebuffer_free(&fb);
    sc_mesh_free(&mesh);
    sc_surface_free(surface);
    return status;
}

/* ---- the comparison ---- */

typedef struct {
    sc_shading shading;
    int triangles;
} compare_step;

/* The lecture's comparison; the exact reference (last) is drawn on the finest mesh. */
static const compare_step plan[] = {{SC_SHADING_GOURAUD, 1024},
                                    {SC_SHADING_GOURAUD, 6320},
                                    {SC_SHADING_GOURAUD, 40000},
                                    {SC_SHADING_PHONG, 6320},
                                    {SC_SHADING_EXACT, 40000}};
enum { STEPS = sizeof plan / sizeof plan[0], REFERENCE = STEPS - 1, MESHES = 3 };
static const int mesh_sizes[MESHES] = {1024, 6320, 40000};

typedef struct {
    double seconds;
    int triangles;
    sc_render_error error;
} compare_row;

static int mesh_index(int triangles)
{
    int i = 0;
    while (mesh_sizes[i] != triangles)
        i++;
    return i;
}

static void step_name(int k, char *buf, size_t size)
{
    if (plan[k].shading == SC_SHADING_EXACT)
        snprintf(buf, size, "exact");
    else
        snprintf(buf, size, "%s-%d", sc_shading_name(plan[k].shading), plan[k].triangles);
}

static int write_error_map(const render_options *o, const sc_framebuffer *ref, const float *map,
                           const char *path)
{
    sc_image img;
    const char *names[] = {"Y"};
    if (sc_image_init(&img, ref->width, ref->height, 1, names) < 0) {
        sc_error("render: out of memory");
        return SC_EXIT_RUNTIME;
    }
    memcpy(img.data, map, (size_t)ref->width * (size_t)ref->height * sizeof *map);
    int status = write_exr(o, &img, path, "shadecalc:error", "max over R, G, B of |image - exact|");
    sc_image_free(&img);
    return status;
}

/* Writes step k's image (and its error map against ref unless it is the reference). */
static int write_step(const render_options *o, int k, const sc_framebuffer *fb,
                      const sc_framebuffer *ref, float *map, compare_row *row)
{
    char name[64], path[4096];
    step_name(k, name, sizeof name);
    snprintf(path, sizeof path, "%s/render-%s.exr", o->output_dir, name);
    sc_image img;
    int status = write_image(sc_render_image(fb, o->depth, o->normals, &img), &img, o, path,
                             sc_shading_name(plan[k].shading));
    sc_render_compare(fb, ref, map, &row->error);
    if (status == SC_EXIT_OK && k != REFERENCE) {
        snprintf(path, sizeof path, "%s/error-%s.exr", o->output_dir, name);
        status = write_error_map(o, ref, map, path);
    }
    return status;
}

static void print_rows(const render_options *o, const compare_row *rows)
{
    if (o->format == FMT_CSV)
        printf("mode,triangles,seconds,rmse,max_error\n");
    else
        printf("%-8s %9s %9s %12s %12s\n", "mode", "triangles", "seconds", "rmse", "max_error");
    for (int k = 0; k < STEPS; k++) {
        const compare_row *r = &rows[k];
        const char *mode = sc_shading_name(plan[k].shading);
        if (o->format == FMT_CSV)
            printf("%s,%d,%.6f,%.9g,%.9g\n", mode, r->triangles, r->seconds, r->error.rmse,
                   r->error.max_error);
        else
            printf("%-8s %9d %9.4f %12.6g %12.6g\n", mode, r->triangles, r->seconds, r->error.rmse,
                   r->error.max_error);
    }
}

typedef struct {
    sc_surface *surface;
    sc_mesh meshes[MESHES];
    sc_framebuffer images[STEPS];
    float *map;
} compare_state;

static void free_compare(compare_state *c)
{
    for (int i = 0; i < MESHES; i++)
        sc_mesh_free(&c->meshes[i]);
    for (int k = 0; k < STEPS; k++)
        sc_framebuffer_free(&c->images[k]);
    free(c->map);
    sc_surface_free(c->surface);
}

/* Creates directory `path` and its missing parents (mkdir -p); an exit status. */
static int make_directory(const char *path)
{
    char dir[4096];
    if (snprintf(dir, sizeof dir, "%s", path) >= (int)sizeof dir) {
        sc_error("render: --output-dir %.40s...: too long", path);
        return SC_EXIT_USAGE;
    }
    for (char *p = dir + 1;; p++) {
        if (*p != '/' && *p != '\0')
            continue;
        char end = *p;
        *p = '\0';
        struct stat st;
        if (mkdir(dir, 0777) < 0 &&
            (errno != EEXIST || stat(dir, &st) < 0 || !S_ISDIR(st.st_mode))) {
            sc_error("render: --output-dir %s: %s", dir,
                     errno == EEXIST ? "not a directory" : strerror(errno));
            return SC_EXIT_RUNTIME;
        }
        *p = end;
        if (end == '\0')
            return SC_EXIT_OK;
    }
}

static int prepare_compare(const render_options *o, compare_state *c)
{
    int status = make_directory(o->output_dir); /* before the work, not after it */
    if (status == SC_EXIT_OK)
        status = load_surface(o, &c->surface);
    for (int i = 0; status == SC_EXIT_OK && i < MESHES; i++)
        status = tessellate(c->surface, mesh_sizes[i], &c->meshes[i]);
    if (status != SC_EXIT_OK)
        return status;
    int ok = (c->map = malloc((size_t)o->width * (size_t)o->height * sizeof *c->map)) != NULL;
    for (int k = 0; ok && k < STEPS; k++)
        ok = init_framebuffer(o, &c->images[k]) == 0;
    if (!ok) {
        sc_error("render: out of memory for the comparison at %dx%d", o->width, o->height);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

static int render_compare(const render_options *o, const shade_setup *s, const sc_scene *scene)
{
    compare_state c = {0};
    compare_row rows[STEPS];
    int status = prepare_compare(o, &c);
    sc_render_params rp = {.surface = c.surface,
                           .scene = scene,
                           .prec = o->prec,
                           .tier = o->tier,
                           .threads = o->threads};
    if (status == SC_EXIT_OK) {
        char err[512];
        make_camera(o, s, &c.meshes[MESHES - 1], &rp.camera);
        if (sc_camera_validate(&rp.camera, err, sizeof err) < 0) {
            sc_error("render: %s", err);
            status = SC_EXIT_USAGE;
        }
    }
    for (int k = 0; status == SC_EXIT_OK && k < STEPS; k++) {
        char label[64];
        step_name(k, label, sizeof label);
        rp.mesh = &c.meshes[mesh_index(plan[k].triangles)];
        rp.shading = plan[k].shading;
        rows[k].triangles = rp.mesh->n_triangles;
        status = draw(&rp, label, &c.images[k], &rows[k].seconds);
    }
    for (int k = 0; status == SC_EXIT_OK && k < STEPS; k++)
        status = write_step(o, k, &c.images[k], &c.images[REFERENCE], c.map, &rows[k]);
    if (status == SC_EXIT_OK)
        print_rows(o, rows);
    free_compare(&c);
    return status;
}

/* ---- entry ---- */

static int run(int argc, char **argv)
{
    shade_setup *s = malloc(sizeof *s);
    render_options o = {.triangles = 6320,
                        .width = 512,
                        .height = 512,
                        .shading = SC_SHADING_PHONG,
                        .exr = {SC_PIXEL_HALF, SC_EXR_ZIP, 0},
                        .prec = SC_HIGHP,
                        .tier = "accurate",
                        .up = {0, 0, 1},
                        .fov = 40.0,
                        .output_dir = ".",
                        .command = join_command(argc, argv)};
    if (!s || !o.command) {
        free(s);
        free(o.command);
        sc_error("render: out of memory");
        return SC_EXIT_RUNTIME;
    }
    setup_init(s);
    int status = parse_options(argc, argv, s, &o);
    if (status == SC_EXIT_OK)
        status = check_options(s, &o);
    if (status == SC_EXIT_OK)
        status = complete_setup(s, &o);
    if (status == SC_EXIT_OK) {
        sc_scene scene = {
            s->lights, s->n_lights, s->model, {s->ambient[0], s->ambient[1], s->ambient[2]}};
        status = check_tier(&o, &scene);
        if (status == SC_EXIT_OK)
            status = o.compare ? render_compare(&o, s, &scene) : render_one(&o, s, &scene);
    }
    free(s);
    free(o.command);
    return status < 0 ? SC_EXIT_OK : status;
}

const sc_command sc_cmd_render = {"render",
                                  "rasterize a surface with flat/Gouraud/Phong/exact "
                                  "shading into an EXR; --compare",
                                  run};
