/* sc_render: triangle setup, per-face and per-vertex shading, tiles on threads (render.h). */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "render/shade_span.h"
#include "render/view.h"

enum { TILE = 64, MAX_THREADS = 256, FAN_MAX = RASTER_CLIP_MAX - 2 };

typedef struct {
    const sc_render_params *p;
    const sc_mesh *mesh;
    sc_framebuffer *fb;
    render_view view;
    render_shader shader; /* the scene, precision, and the batch kernel's plan if it fits */
    raster_tri *tris;     /* set-up screen triangles, in mesh order */
    int n_tris;
    unsigned char *front; /* per mesh triangle: 1 if its counter-clockwise side faces the eye */
    double *face_n;       /* per mesh triangle: unit geometric normal, counter-clockwise side */
    float *face_rgb;      /* flat: 3 per mesh triangle, the side that faces the eye */
    float *vertex_rgb;    /* gouraud: 6 per vertex, front side then back side */
    int tiles_x, tiles_y, next_tile, tiles_done;
    pthread_mutex_t lock;
} render_job;

/* What one tile keeps per pixel between rasterizing and shading. */
typedef struct {
    double inv_w[TILE * TILE]; /* 0: empty */
    int source[TILE * TILE];
    double b[TILE * TILE][3];
    int x0, y0;
    const raster_tri *current;
} tile_buffer;

/* ---- per-triangle setup ---- */

static void vertex_pos(const sc_mesh *m, int v, double p[3])
{
    for (int c = 0; c < 3; c++)
        p[c] = m->pos[3 * v + c];
}

static void corner_positions(const sc_mesh *m, int t, double p[3][3])
{
    for (int k = 0; k < 3; k++)
        vertex_pos(m, m->tri[3 * t + k], p[k]);
}

/* Facing and geometric normal of mesh triangle t. */
static void classify_face(render_job *job, int t)
{
    double p[3][3], *n = job->face_n + 3 * t, facing = 0.0;
    corner_positions(job->mesh, t, p);
    sc_triangle_normal(p[0], p[1], p[2], n);
    for (int c = 0; c < 3; c++)
        facing += n[c] * (job->view.eye[c] - p[0][c]);
    job->front[t] = facing >= 0.0;
}

static int push_tri(render_job *job, const raster_tri *t, int *cap)
{
    if (job->n_tris == *cap) {
        int grown = *cap ? 2 * *cap : 1024;
        raster_tri *more = realloc(job->tris, (size_t)grown * sizeof *more);
        if (!more)
            return -1;
        job->tris = more;
        *cap = grown;
    }
    job->tris[job->n_tris++] = *t;
    return 0;
}

/* Projects, clips and sets up mesh triangle t (a fan of up to FAN_MAX screen triangles). */
static int setup_triangle(render_job *job, int t, double guard, int *cap)
{
    raster_vertex corner[3], poly[RASTER_CLIP_MAX];
    double p[3][3];
    corner_positions(job->mesh, t, p);
    for (int k = 0; k < 3; k++) {
        render_view_project(&job->view, p[k], &corner[k]);
        for (int j = 0; j < 3; j++)
            corner[k].bc[j] = j == k;
    }
    int n = raster_clip(corner, job->view.near, guard, poly);
    for (int i = 1; i + 1 < n; i++) {
        raster_vertex fan[3] = {poly[0], poly[i], poly[i + 1]};
        raster_tri tri;
        if (raster_setup(fan, job->fb->width, job->fb->height, t, &tri) &&
            push_tri(job, &tri, cap) < 0)
            return -1;
    }
    return 0;
}

static int setup_triangles(render_job *job)
{
    double guard = raster_guard_band(job->fb->width, job->fb->height);
    int cap = 0;
    for (int t = 0; t < job->mesh->n_triangles; t++) {
        classify_face(job, t);
        if (setup_triangle(job, t, guard, &cap) < 0)
            return -1;
    }
    return 0;
}

/* ---- colours per face (flat) and per vertex (gouraud) ---- */

enum { SPAN = 256 };

static void face_input(const render_job *job, int t, render_shade_input *in)
{
    double p[3][3], sign = job->front[t] ? 1.0 : -1.0;
    corner_positions(job->mesh, t, p);
    for (int c = 0; c < 3; c++) {
        in->pos[c] = (p[0][c] + p[1][c] + p[2][c]) / 3.0;
        in->normal[c] = sign * job->face_n[3 * t + c];
    }
}

/* Shades `count` items in spans: fill(job, i, in) gives item i's shading input. */
static void shade_items(const render_job *job, int count, float *rgb,
                        void (*fill)(const render_job *, int, render_shade_input *))
{
    render_shade_input in[SPAN];
    for (int start = 0; start < count; start += SPAN) {
        int n = count - start < SPAN ? count - start : SPAN;
        for (int i = 0; i < n; i++)
            fill(job, start + i, &in[i]);
        render_shade_span(&job->shader, job->view.eye, n, in, rgb + 3 * start);
    }
}

/* Item 2v + side: vertex v, its normal reversed for side 1 (seen from behind). */
static void vertex_side_input(const render_job *job, int item, render_shade_input *in)
{
    int v = item / 2;
    double sign = item % 2 ? -1.0 : 1.0;
    vertex_pos(job->mesh, v, in->pos);
    for (int c = 0; c < 3; c++)
        in->normal[c] = sign * job->mesh->normal[3 * v + c];
}

/* Flat needs a colour per face; gouraud one per vertex and side (both, to keep it simple:
 * the cost is per vertex, not per pixel). */
static int shade_faces_or_vertices(render_job *job)
{
    const sc_mesh *m = job->mesh;
    if (job->p->shading == SC_SHADING_FLAT) {
        job->face_rgb = malloc((size_t)m->n_triangles * 3 * sizeof *job->face_rgb);
        if (!job->face_rgb)
            return -1;
        shade_items(job, m->n_triangles, job->face_rgb, face_input);
    } else if (job->p->shading == SC_SHADING_GOURAUD) {
        job->vertex_rgb = malloc((size_t)m->n_vertices * 6 * sizeof *job->vertex_rgb);
        if (!job->vertex_rgb)
            return -1;
        shade_items(job, 2 * m->n_vertices, job->vertex_rgb, vertex_side_input);
    }
    return 0;
}

/* ---- per pixel ---- */

/* The interpolated and renormalized vertex normal, on the side facing the eye; the face
 * normal where the vertex normals cancel. */
static void interpolated_normal(const render_job *job, int t, const double b[3], double n[3])
{
    const int *v = job->mesh->tri + 3 * t;
    double sign = job->front[t] ? 1.0 : -1.0, len2 = 0.0;
    for (int c = 0; c < 3; c++) {
        n[c] = 0.0;
        for (int k = 0; k < 3; k++)
            n[c] += b[k] * job->mesh->normal[3 * v[k] + c];
        len2 += n[c] * n[c];
    }
    double len = sqrt(len2);
    for (int c = 0; c < 3; c++)
        n[c] = len > 0.0 ? sign * n[c] / len : sign * job->face_n[3 * t + c];
}

static void interpolated_pos(const render_job *job, int t, const double b[3], double p[3])
{
    const int *v = job->mesh->tri + 3 * t;
    for (int c = 0; c < 3; c++)
        p[c] = b[0] * job->mesh->pos[3 * v[0] + c] + b[1] * job->mesh->pos[3 * v[1] + c] +
               b[2] * job->mesh->pos[3 * v[2] + c];
}

/* Exact: the surface's own point and normal at the interpolated (u, v). */
static void exact_input(const render_job *job, int t, const double b[3], render_shade_input *in)
{
    const int *v = job->mesh->tri + 3 * t;
    const float *uv = job->mesh->uv;
    double u = 0.0, w = 0.0, sign = job->front[t] ? 1.0 : -1.0;
    for (int k = 0; k < 3; k++) {
        u += b[k] * uv[2 * v[k]];
        w += b[k] * uv[2 * v[k] + 1];
    }
    sc_surface_point sp;
    sc_surface_eval(job->p->surface, u, w, &sp);
    for (int c = 0; c < 3; c++) {
        in->pos[c] = sp.p[c];
        in->normal[c] = sign * sp.n[c];
    }
}

static void gouraud_colour(const render_job *job, int t, const double b[3], float rgb[3])
{
    const int *v = job->mesh->tri + 3 * t;
    int side = job->front[t] ? 0 : 3;
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)(b[0] * job->vertex_rgb[6 * v[0] + side + c] +
                         b[1] * job->vertex_rgb[6 * v[1] + side + c] +
                         b[2] * job->vertex_rgb[6 * v[2] + side + c]);
}

/* Where and with which normal pixel barycentrics b of mesh triangle t are shaded. */
static void pixel_input(const render_job *job, int t, const double b[3], render_shade_input *in)
{
    sc_shading mode = job->p->shading;
    if (mode == SC_SHADING_EXACT) {
        exact_input(job, t, b, in);
        return;
    }
    interpolated_pos(job, t, b, in->pos);
    if (mode == SC_SHADING_FLAT)
        for (int c = 0; c < 3; c++)
            in->normal[c] = (job->front[t] ? 1.0 : -1.0) * job->face_n[3 * t + c];
    else
        interpolated_normal(job, t, b, in->normal);
}

/* Shades the covered pixels of one row of a tile and stores them in the framebuffer. */
static void shade_row(const render_job *job, const tile_buffer *buf, int row, int width)
{
    render_shade_input in[TILE];
    float rgb[3 * TILE];
    int x_of[TILE], n = 0;
    sc_shading mode = job->p->shading;
    for (int x = 0; x < width; x++) {
        int i = row * TILE + x, t = buf->source[i];
        if (buf->inv_w[i] == 0.0)
            continue;
        x_of[n] = x;
        pixel_input(job, t, buf->b[i], &in[n]);
        if (mode == SC_SHADING_FLAT)
            memcpy(rgb + 3 * n, job->face_rgb + 3 * t, 3 * sizeof *rgb);
        else if (mode == SC_SHADING_GOURAUD)
            gouraud_colour(job, t, buf->b[i], rgb + 3 * n);
        n++;
    }
    if (n > 0 && (mode == SC_SHADING_PHONG || mode == SC_SHADING_EXACT))
        render_shade_span(&job->shader, job->view.eye, n, in, rgb);
    sc_framebuffer *fb = job->fb;
    for (int k = 0; k < n; k++) {
        int i = row * TILE + x_of[k];
        size_t at = (size_t)(buf->y0 + row) * (size_t)fb->width + (size_t)(buf->x0 + x_of[k]);
        for (int c = 0; c < 3; c++)
            fb->rgba[4 * at + c] = rgb[3 * k + c];
        fb->rgba[4 * at + 3] = 1.0f;
        if (fb->normal)
            for (int c = 0; c < 3; c++)
                fb->normal[3 * at + c] = (float)in[k].normal[c];
        if (fb->depth)
            fb->depth[at] = (float)(1.0 / buf->inv_w[i]);
    }
}

/* ---- tiles ---- */

/* Depth test on 1/w: the nearer fragment wins, the earlier triangle on a tie. */
static void keep_nearest(void *ctx, int x, int y, const double lambda[3])
{
    tile_buffer *buf = ctx;
    double b[3];
    double inv_w = raster_barycentric(buf->current, lambda, b);
    int i = (y - buf->y0) * TILE + (x - buf->x0);
    if (inv_w > buf->inv_w[i]) {
        buf->inv_w[i] = inv_w;
        buf->source[i] = buf->current->source;
        memcpy(buf->b[i], b, sizeof b);
    }
}

/* Empties columns x0..x1 of rows y0..y1: each tile clears its own pixels, on its own thread
 * (clearing the whole framebuffer first was a serial pass over 32 bytes a pixel). */
static void clear_tile(sc_framebuffer *fb, int x0, int y0, int x1, int y1)
{
    size_t w = (size_t)(x1 - x0 + 1);
    for (int y = y0; y <= y1; y++) {
        size_t at = (size_t)y * (size_t)fb->width + (size_t)x0;
        memset(fb->rgba + 4 * at, 0, 4 * w * sizeof *fb->rgba);
        if (fb->normal)
            memset(fb->normal + 3 * at, 0, 3 * w * sizeof *fb->normal);
        for (size_t i = 0; fb->depth && i < w; i++)
            fb->depth[at + i] = INFINITY;
    }
}

static void render_tile(const render_job *job, int tile, tile_buffer *buf)
{
    buf->x0 = tile % job->tiles_x * TILE;
    buf->y0 = tile / job->tiles_x * TILE;
    int x1 = buf->x0 + TILE - 1, y1 = buf->y0 + TILE - 1;
    x1 = x1 < job->fb->width ? x1 : job->fb->width - 1;
    y1 = y1 < job->fb->height ? y1 : job->fb->height - 1;
    clear_tile(job->fb, buf->x0, buf->y0, x1, y1);
    memset(buf->inv_w, 0, sizeof buf->inv_w);
    for (int k = 0; k < job->n_tris; k++) {
        const raster_tri *t = &job->tris[k];
        if (t->x1 < buf->x0 || t->x0 > x1 || t->y1 < buf->y0 || t->y0 > y1)
            continue;
        buf->current = t;
        raster_cover(t, buf->x0, buf->y0, x1, y1, keep_nearest, buf);
    }
    for (int row = 0; row <= y1 - buf->y0; row++)
        shade_row(job, buf, row, x1 - buf->x0 + 1);
}

static int take_tile(render_job *job)
{
    pthread_mutex_lock(&job->lock);
    int t = job->next_tile < job->tiles_x * job->tiles_y ? job->next_tile++ : -1;
    pthread_mutex_unlock(&job->lock);
    return t;
}

static void finish_tile(render_job *job)
{
    pthread_mutex_lock(&job->lock);
    job->tiles_done++;
    if (job->p->progress)
        job->p->progress(job->p->progress_ctx, job->tiles_done, job->tiles_x * job->tiles_y);
    pthread_mutex_unlock(&job->lock);
}

typedef struct {
    render_job *job;
    tile_buffer *buf;
} worker_arg;

static void *worker(void *arg)
{
    worker_arg *w = arg;
    int t;
    while ((t = take_tile(w->job)) >= 0) {
        render_tile(w->job, t, w->buf);
        finish_tile(w->job);
    }
    return NULL;
}

static int thread_count(const sc_render_params *p, int tiles)
{
    long n = p->threads > 0 ? p->threads : sysconf(_SC_NPROCESSORS_ONLN);
    n = n < 1 ? 1 : n;
    n = n > MAX_THREADS ? MAX_THREADS : n;
    return (int)(n < tiles ? n : tiles);
}

/* Runs the tiles on the threads; the calling thread is one of them. */
static int run_tiles(render_job *job)
{
    int n = thread_count(job->p, job->tiles_x * job->tiles_y), started = 0;
    pthread_t threads[MAX_THREADS];
    worker_arg args[MAX_THREADS];
    tile_buffer *bufs = malloc((size_t)n * sizeof *bufs);
    if (!bufs)
        return -1;
    for (int i = 0; i < n; i++)
        args[i] = (worker_arg){job, &bufs[i]};
    while (started + 1 < n &&
           pthread_create(&threads[started], NULL, worker, &args[started + 1]) == 0)
        started++;
    worker(&args[0]);
    for (int i = 0; i < started; i++)
        pthread_join(threads[i], NULL);
    free(bufs);
    return 0;
}

/* ---- entry ---- */

static int check_inputs(const sc_render_params *p, const sc_framebuffer *fb, char *err,
                        size_t errsize)
{
    const sc_mesh *m = p->mesh;
    if (!fb->rgba) {
        snprintf(err, errsize, "render: the framebuffer has no colour array");
        return -1;
    }
    if (sc_camera_validate(&p->camera, err, errsize) < 0)
        return -1;
    for (long i = 0; i < 3L * m->n_triangles; i++)
        if (m->tri[i] < 0 || m->tri[i] >= m->n_vertices) {
            snprintf(err, errsize, "mesh: triangle %ld has vertex index %d, not in 0..%d", i / 3,
                     m->tri[i], m->n_vertices - 1);
            return -1;
        }
    int needs_normals = p->shading == SC_SHADING_GOURAUD || p->shading == SC_SHADING_PHONG;
    if (needs_normals && !m->normal) {
        snprintf(err, errsize, "render: %s shading needs vertex normals; the mesh has none",
                 sc_shading_name(p->shading));
        return -1;
    }
    if (p->shading == SC_SHADING_EXACT && (!p->surface || !m->uv)) {
        snprintf(err, errsize, "render: exact shading needs the surface and a mesh with (u,v)");
        return -1;
    }
    return 0;
}

static void free_job(render_job *job)
{
    render_shader_free(&job->shader);
    free(job->tris);
    free(job->front);
    free(job->face_n);
    free(job->face_rgb);
    free(job->vertex_rgb);
}

int sc_render(const sc_render_params *p, sc_framebuffer *fb, char *err, size_t errsize)
{
    if (check_inputs(p, fb, err, errsize) < 0)
        return -1;
    render_job job = {.p = p, .mesh = p->mesh, .fb = fb};
    render_view_make(&p->camera, fb->width, fb->height, &job.view);
    char why[256];
    render_shader_init(&job.shader, p->scene, p->prec, p->tier, why, sizeof why);
    job.tiles_x = (fb->width + TILE - 1) / TILE;
    job.tiles_y = (fb->height + TILE - 1) / TILE;
    size_t n_faces = (size_t)p->mesh->n_triangles;
    job.front = malloc(n_faces ? n_faces : 1);
    job.face_n = malloc((n_faces ? n_faces : 1) * 3 * sizeof *job.face_n);
    int status = job.front && job.face_n ? 0 : -1;
    if (status == 0)
        status = setup_triangles(&job);
    if (status == 0)
        status = shade_faces_or_vertices(&job);
    if (status == 0) {
        pthread_mutex_init(&job.lock, NULL);
        status = run_tiles(&job);
        pthread_mutex_destroy(&job.lock);
    }
    free_job(&job);
    if (status < 0)
        snprintf(err, errsize, "render: out of memory");
    return status;
}
