/* Wavefront OBJ meshes: positions, normals and faces (shadecalc/mesh.h). */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/file.h"
#include "shadecalc/mesh.h"
#include "util/text.h"

enum { MAX_ELEMENTS = INT_MAX / 8 };

/* A growable array of `size`-byte elements. */
typedef struct {
    void *data;
    int n, cap;
} array;

static void *array_push(array *a, size_t size)
{
    if (a->n == a->cap) {
        int cap = a->cap ? 2 * a->cap : 64;
        void *data = a->n < MAX_ELEMENTS ? realloc(a->data, (size_t)cap * size) : NULL;
        if (data == NULL)
            return NULL;
        a->data = data;
        a->cap = cap;
    }
    return (char *)a->data + (size_t)a->n++ * size;
}

/* A mesh vertex: an OBJ position with one OBJ normal (or -1). Vertices sharing a position are
 * chained from first[position] through next. */
typedef struct {
    int position, normal, next;
} corner_vertex;

typedef struct {
    const char *path;
    int line;
    array v, vn; /* float[3] each */
    array first; /* int per position: its first vertex, or -1 */
    array verts; /* corner_vertex */
    array tri;   /* int[3] */
    int with_normal, without_normal;
    int not_content; /* the failure is no fault of the file's content (memory, reading) */
    char *err;
    size_t errsize;
} obj_reader;

static int fail(obj_reader *r, const char *what, const char *token, int len)
{
    char shown[96];
    snprintf(r->err, r->errsize, "%s:%d: %s '%s'", r->path, r->line, what,
             sc_escape_n(token, (size_t)len, shown, sizeof shown));
    return -1;
}

static int out_of_memory(obj_reader *r)
{
    snprintf(r->err, r->errsize, "%s:%d: out of memory or too many elements", r->path, r->line);
    r->not_content = 1;
    return -1;
}

/* The next whitespace-separated token at *p (its length in *len), or NULL at the end. */
static const char *next_token(const char **p, int *len)
{
    const char *s = *p;
    while (isspace((unsigned char)*s))
        s++;
    const char *e = s;
    while (*e && !isspace((unsigned char)*e))
        e++;
    *p = e;
    *len = (int)(e - s);
    return *len ? s : NULL;
}

/* `v x y z [w]` or `vn x y z`: three finite numbers (w ignored). */
static int read_vector(obj_reader *r, const char *p, array *into)
{
    float *out = array_push(into, 3 * sizeof(float));
    if (out == NULL)
        return out_of_memory(r);
    for (int k = 0; k < 4; k++) {
        int len;
        const char *t = next_token(&p, &len);
        char *end;
        if (t == NULL && k == 3)
            return 0;
        if (t == NULL) {
            snprintf(r->err, r->errsize, "%s:%d: expected 3 coordinates, got %d", r->path, r->line,
                     k);
            return -1;
        }
        double x = strtod(t, &end);
        if (end != t + len || !isfinite(x) || fabs(x) > 3.4e38)
            return fail(r, "not a finite float:", t, len);
        if (k < 3)
            out[k] = (float)x;
    }
    return 0;
}

/* A 1-based (or negative: relative to the end) index among `count` elements, into *out. */
static int parse_index(const char *s, const char *end, int count, int *out)
{
    char *stop;
    long i = strtol(s, &stop, 10);
    if (stop != end || s == end)
        return -1;
    if (i < 0)
        i += count + 1;
    if (i < 1 || i > count)
        return -1;
    *out = (int)(i - 1);
    return 0;
}

/* The mesh vertex of (position, normal), made on first use. */
static int vertex_of(obj_reader *r, int position, int normal)
{
    int *first = (int *)r->first.data, k;
    corner_vertex *cv = (corner_vertex *)r->verts.data;
    for (k = first[position]; k >= 0; k = cv[k].next)
        if (cv[k].normal == normal)
            return k;
    corner_vertex *add = array_push(&r->verts, sizeof *add);
    if (add == NULL)
        return -1;
    *add = (corner_vertex){position, normal, first[position]};
    first[position] = r->verts.n - 1;
    return r->verts.n - 1;
}

/* One face corner "i", "i/t", "i//n" or "i/t/n" -> a mesh vertex. */
static int read_corner(obj_reader *r, const char *t, int len, int *vertex)
{
    const char *end = t + len, *slash = memchr(t, '/', (size_t)len);
    const char *slash2 = slash ? memchr(slash + 1, '/', (size_t)(end - slash - 1)) : NULL;
    int position, normal = -1;
    if (parse_index(t, slash ? slash : end, r->v.n, &position) < 0)
        return fail(r, "bad vertex index in", t, len);
    if (slash2 && parse_index(slash2 + 1, end, r->vn.n, &normal) < 0)
        return fail(r, "bad normal index in", t, len);
    if (normal >= 0)
        r->with_normal++;
    else
        r->without_normal++;
    *vertex = vertex_of(r, position, normal);
    return *vertex < 0 ? out_of_memory(r) : 0;
}

/* `f c1 c2 c3 ...`: a polygon of at least 3 corners, split into a fan of triangles. */
static int read_face(obj_reader *r, const char *p)
{
    int corners = 0, first = 0, previous = 0, len;
    for (const char *t; (t = next_token(&p, &len)) != NULL; corners++) {
        int vertex;
        if (read_corner(r, t, len, &vertex) < 0)
            return -1;
        if (corners >= 2) {
            int *tri = array_push(&r->tri, 3 * sizeof(int));
            if (tri == NULL)
                return out_of_memory(r);
            tri[0] = first;
            tri[1] = previous;
            tri[2] = vertex;
        }
        if (corners == 0)
            first = vertex;
        previous = vertex;
    }
    if (corners >= 3)
        return 0;
    snprintf(r->err, r->errsize, "%s:%d: a face needs at least 3 corners, got %d", r->path, r->line,
             corners);
    return -1;
}

static int read_position(obj_reader *r, const char *p)
{
    int *first = array_push(&r->first, sizeof(int));
    if (first == NULL)
        return out_of_memory(r);
    *first = -1;
    return read_vector(r, p, &r->v);
}

static int read_line(obj_reader *r, const char *line)
{
    static const char *const ignored[] = {"vt", "vp", "o", "g", "s", "usemtl", "mtllib", "l", "p"};
    const char *p = line;
    int len;
    const char *key = next_token(&p, &len);
    if (key == NULL || key[0] == '#')
        return 0;
    if (len == 1 && key[0] == 'v')
        return read_position(r, p);
    if (len == 2 && strncmp(key, "vn", 2) == 0)
        return read_vector(r, p, &r->vn);
    if (len == 1 && key[0] == 'f')
        return read_face(r, p);
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; i++)
        if (strlen(ignored[i]) == (size_t)len && strncmp(key, ignored[i], (size_t)len) == 0)
            return 0;
    return fail(r, "unknown statement", key, len);
}

/* The reader's vertices and triangles as a mesh (normals only if every corner had one). */
static int build_mesh(obj_reader *r, sc_mesh *out)
{
    const corner_vertex *cv = (const corner_vertex *)r->verts.data;
    const float *v = (const float *)r->v.data, *vn = (const float *)r->vn.data;
    int n = r->verts.n, normals = r->with_normal > 0 && r->without_normal == 0;
    memset(out, 0, sizeof *out);
    out->pos = malloc(sizeof(float) * 3 * (size_t)n);
    out->normal = normals ? malloc(sizeof(float) * 3 * (size_t)n) : NULL;
    if (out->pos == NULL || (normals && out->normal == NULL)) {
        sc_mesh_free(out);
        return out_of_memory(r);
    }
    for (int k = 0; k < n; k++) {
        memcpy(&out->pos[3 * k], &v[3 * cv[k].position], 3 * sizeof(float));
        if (normals)
            memcpy(&out->normal[3 * k], &vn[3 * cv[k].normal], 3 * sizeof(float));
    }
    out->n_vertices = n;
    out->n_triangles = r->tri.n;
    out->tri = r->tri.data;
    r->tri.data = NULL;
    return 0;
}

static int read_stream(obj_reader *r, FILE *f, sc_mesh *out)
{
    char *line = NULL;
    size_t cap = 0;
    int status = 0;
    ssize_t len;
    while (status == 0 && (len = getline(&line, &cap, f)) >= 0) {
        r->line++;
        status = memchr(line, '\0', (size_t)len) ? fail(r, "a NUL byte in", line, (int)strlen(line))
                                                 : read_line(r, line);
    }
    free(line);
    if (status == 0 && ferror(f)) {
        snprintf(r->err, r->errsize, "%s: %s", r->path, strerror(errno));
        r->not_content = 1;
        status = -1;
    }
    if (status == 0 && r->tri.n == 0) {
        snprintf(r->err, r->errsize, "%s: no faces", r->path);
        status = -1;
    }
    return status == 0 ? build_mesh(r, out) : -1;
}

int sc_obj_read(const char *path, sc_mesh *out, char *err, size_t errsize)
{
    int from_stdin = strcmp(path, "-") == 0;
    obj_reader r = {.path = from_stdin ? "standard input" : path, .err = err, .errsize = errsize};
    FILE *f = from_stdin ? stdin : fopen(path, "r");
    if (f == NULL) {
        snprintf(err, errsize, "%s: cannot open: %s", path, strerror(errno));
        return -2;
    }
    int status = read_stream(&r, f, out);
    if (!from_stdin)
        fclose(f);
    free(r.v.data);
    free(r.vn.data);
    free(r.first.data);
    free(r.verts.data);
    free(r.tri.data);
    return status < 0 && r.not_content ? -2 : status;
}

/* ---- writing ---- */

static void write_floats(FILE *f, const char *key, const float *x, int n)
{
    fputs(key, f);
    for (int k = 0; k < n; k++)
        fprintf(f, " %.9g", (double)x[k]);
    fputc('\n', f);
}

/* One corner "i", "i/i", "i//i" or "i/i/i" (1-based; vt and vn share the vertex's index). */
static void write_corner(FILE *f, const sc_mesh *m, int k)
{
    fprintf(f, " %d", k + 1);
    if (m->uv)
        fprintf(f, "/%d", k + 1);
    if (m->normal)
        fprintf(f, m->uv ? "/%d" : "//%d", k + 1);
}

static void write_mesh(FILE *f, const sc_mesh *m)
{
    fprintf(f, "# shadecalc mesh: %d vertices, %d triangles\n", m->n_vertices, m->n_triangles);
    for (int k = 0; k < m->n_vertices; k++)
        write_floats(f, "v", &m->pos[3 * k], 3);
    for (int k = 0; m->normal && k < m->n_vertices; k++)
        write_floats(f, "vn", &m->normal[3 * k], 3);
    for (int k = 0; m->uv && k < m->n_vertices; k++)
        write_floats(f, "vt", &m->uv[2 * k], 2);
    for (int t = 0; t < m->n_triangles; t++) {
        fputc('f', f);
        for (int c = 0; c < 3; c++)
            write_corner(f, m, m->tri[3 * t + c]);
        fputc('\n', f);
    }
}

int sc_obj_write(const char *path, const sc_mesh *m, char *err, size_t errsize)
{
    sc_atomic_file *f = sc_atomic_open(path, err, errsize);
    if (f == NULL)
        return -1;
    write_mesh(sc_atomic_stream(f), m);
    if (ferror(sc_atomic_stream(f))) {
        snprintf(err, errsize, "%s: write error", path);
        sc_atomic_abort(f);
        return -1;
    }
    return sc_atomic_commit(f, err, errsize);
}
