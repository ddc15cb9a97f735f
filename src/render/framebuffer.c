/* Framebuffers, shading mode names and the error of an image against a reference (render.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "image/adopt.h"
#include "shadecalc/render.h"
#include "util/bigalloc.h"

static const char *const shading_names[] = {"flat", "gouraud", "phong", "exact"};

int sc_shading_parse(const char *name, sc_shading *out)
{
    for (int i = 0; i < 4; i++)
        if (strcmp(name, shading_names[i]) == 0) {
            *out = (sc_shading)i;
            return 0;
        }
    return -1;
}

const char *sc_shading_name(sc_shading s) { return shading_names[s]; }

int sc_framebuffer_init_planes(sc_framebuffer *fb, int width, int height, int planes)
{
    memset(fb, 0, sizeof *fb);
    if (width < 1 || height < 1 || width > SC_RENDER_MAX_SIDE || height > SC_RENDER_MAX_SIDE ||
        (long)width * height > SC_RENDER_MAX_PIXELS || planes < 0 || planes > SC_FRAMEBUFFER_ALL)
        return -1;
    size_t n = (size_t)width * (size_t)height;
    int depth = planes & SC_FRAMEBUFFER_DEPTH, normal = planes & SC_FRAMEBUFFER_NORMAL;
    fb->width = width;
    fb->height = height;
    fb->rgba = sc_big_calloc(4 * n, sizeof *fb->rgba);
    fb->depth = depth ? sc_big_calloc(n, sizeof *fb->depth) : NULL;
    fb->normal = normal ? sc_big_calloc(3 * n, sizeof *fb->normal) : NULL;
    if (!fb->rgba || (depth && !fb->depth) || (normal && !fb->normal)) {
        sc_framebuffer_free(fb);
        return -1;
    }
    return 0;
}

int sc_framebuffer_init(sc_framebuffer *fb, int width, int height)
{
    return sc_framebuffer_init_planes(fb, width, height, SC_FRAMEBUFFER_ALL);
}

void sc_framebuffer_free(sc_framebuffer *fb)
{
    sc_big_free(fb->rgba);
    sc_big_free(fb->depth);
    sc_big_free(fb->normal);
    memset(fb, 0, sizeof *fb);
}

void sc_render_compare(const sc_framebuffer *img, const sc_framebuffer *ref, float *map,
                       sc_render_error *out)
{
    size_t n = (size_t)ref->width * (size_t)ref->height;
    double sum = 0.0, worst = 0.0;
    long pixels = 0;
    for (size_t i = 0; i < n; i++) {
        double largest = 0.0;
        if (ref->rgba[4 * i + 3] > 0.0f) {
            for (int c = 0; c < 3; c++) {
                double d = fabs((double)img->rgba[4 * i + c] - ref->rgba[4 * i + c]);
                sum += d * d;
                largest = fmax(largest, d);
            }
            pixels++;
        }
        worst = fmax(worst, largest);
        if (map)
            map[i] = (float)largest;
    }
    out->rmse = pixels ? sqrt(sum / (3.0 * (double)pixels)) : 0.0;
    out->max_error = worst;
    out->pixels = pixels;
}

/* An image of fb's size with the channels R, G, B, A, [Z], [N.X, N.Y, N.Z], its pixels a new
 * array, or `adopted` (image/adopt.h); 0, or -1. */
static int image_for(const sc_framebuffer *fb, int depth, int normals, float *adopted,
                     sc_image *out)
{
    const char *names[8] = {"R", "G", "B", "A"};
    int n = 4;
    if (depth)
        names[n++] = "Z";
    if (normals) {
        names[n++] = "N.X";
        names[n++] = "N.Y";
        names[n++] = "N.Z";
    }
    if (!fb->rgba || (depth && !fb->depth) || (normals && !fb->normal)) {
        memset(out, 0, sizeof *out);
        return -1;
    }
    return adopted ? image_adopt(out, fb->width, fb->height, n, names, adopted)
                   : sc_image_init(out, fb->width, fb->height, n, names);
}

int sc_render_image(const sc_framebuffer *fb, int depth, int normals, sc_image *out)
{
    if (image_for(fb, depth, normals, NULL, out) < 0)
        return -1;
    int n = out->n_channels;
    size_t pixels = (size_t)fb->width * (size_t)fb->height;
    for (size_t i = 0; i < pixels; i++) {
        float *px = out->data + i * (size_t)n;
        memcpy(px, fb->rgba + 4 * i, 4 * sizeof *px);
        if (depth)
            px[4] = fb->depth[i];
        if (normals)
            memcpy(px + n - 3, fb->normal + 3 * i, 3 * sizeof *px);
    }
    return 0;
}

/* fb's RGBA array comes from sc_big_calloc (util/bigalloc.h), as image/adopt.h asks. */
int sc_render_image_take(sc_framebuffer *fb, int depth, int normals, sc_image *out)
{
    if (depth || normals || !fb->rgba)
        return sc_render_image(fb, depth, normals, out);
    if (image_for(fb, 0, 0, fb->rgba, out) < 0)
        return -1;
    fb->rgba = NULL;
    return 0;
}
