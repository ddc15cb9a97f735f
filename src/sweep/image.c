/* Images of two-variable sweeps, written as EXR (shadecalc/sweep.h, shadecalc/image.h). */
#include "shadecalc/sweep.h"

#include <string.h>

enum { LIST_SHOWN = 200 };

void sc_sweep_describe_var(const sc_sweep_var *v, char *buf, size_t size)
{
    char a[32], b[32];
    sc_format_shortest(a, sizeof a, v->start, SC_DOUBLE);
    sc_format_shortest(b, sizeof b, v->stop, SC_DOUBLE);
    if (v->spacing != SC_SPACING_LIST) {
        snprintf(buf, size, "%s=%s:%s:%ld%s", v->name, a, b, v->count,
                 v->spacing == SC_SPACING_LOG ? " log" : "");
        return;
    }
    size_t n = (size_t)snprintf(buf, size, "%s=", v->name);
    for (long i = 0; i < v->count && n + 40 < size; i++) {
        sc_format_shortest(a, sizeof a, v->list[i], SC_DOUBLE);
        n += (size_t)snprintf(buf + n, size - n, "%s%s", i ? "," : "", a);
        if (n > LIST_SHOWN && i + 1 < v->count) {
            snprintf(buf + n, size - n, ",...");
            return;
        }
    }
}

int sc_sweep_image_init(sc_image *img, const sc_sweep_grid *g, int n_results, char *err,
                        size_t errsize)
{
    static const char *const y[] = {"Y"}, *const rgba[] = {"R", "G", "B", "A"};
    memset(img, 0, sizeof *img);
    if (g->n != 2 || n_results < 1 || n_results > 4) {
        snprintf(err, errsize,
                 "an image needs exactly two variables (width, height) and 1 to 4 "
                 "result columns, not %d and %d",
                 g->n, n_results);
        return -1;
    }
    double values = (double)g->var[0].count * (double)g->var[1].count * n_results;
    if (values > (double)SC_EXR_MAX_VALUES || g->var[0].count > 1 << 24 ||
        g->var[1].count > 1 << 24) {
        snprintf(err, errsize, "an image of %ld x %ld pixels is too large", g->var[0].count,
                 g->var[1].count);
        return -1;
    }
    if (sc_image_init(img, (int)g->var[0].count, (int)g->var[1].count, n_results,
                      n_results == 1 ? y : rgba) < 0) { /* the arguments are valid: no memory */
        snprintf(err, errsize, "out of memory for an image of %ld x %ld pixels", g->var[0].count,
                 g->var[1].count);
        return -2;
    }
    return 0;
}

void sc_sweep_image_store(sc_image *img, uint64_t row, const double *results)
{
    uint64_t w = (uint64_t)img->width;
    int j = (int)(row / w); /* the second variable's first value on the bottom row */
    float *px = sc_image_pixel(img, (int)(row % w), img->height - 1 - j);
    for (int c = 0; c < img->n_channels; c++)
        px[c] = (float)results[c];
}

int sc_sweep_image_write(const char *path, const sc_image *img, sc_pixel_type type,
                         const sc_sweep_grid *g, const char *command, char *err, size_t errsize)
{
    char x_range[LIST_SHOWN + 64], y_range[LIST_SHOWN + 64], cmd[4096];
    sc_sweep_describe_var(&g->var[0], x_range, sizeof x_range);
    sc_sweep_describe_var(&g->var[1], y_range, sizeof y_range);
    snprintf(cmd, sizeof cmd, "%s", command);
    const sc_image_attr attrs[] = {
        {"shadecalc:command", cmd}, {"shadecalc:x_range", x_range}, {"shadecalc:y_range", y_range}};
    return sc_exr_write(path, img, type, attrs, 3, err, errsize);
}
