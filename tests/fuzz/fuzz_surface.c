/* libFuzzer harness: the surface spec, matrix chain and OBJ parsers (shadecalc/surface.h,
 * transform.h, mesh.h) accept or reject any input without crashing or hanging. Every input goes
 * to all three. Accepted surfaces are evaluated and tessellated and their normals are never NaN;
 * accepted matrices give a finite normal matrix or are singular; accepted OBJ files get vertex
 * normals, never NaN, by every weighting. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shadecalc/mesh.h"
#include "shadecalc/transform.h"
#include "tests/support/fuzz_text.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void require(int ok)
{
    if (!ok)
        abort();
}

static void require_unit(const double *n)
{
    require(fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) < 1e-9);
}

static void fuzz_surface(const char *spec)
{
    char err[256];
    sc_surface *s = sc_surface_parse(spec, err, sizeof err);
    if (s == NULL)
        return;
    static const double uv[][2] = {{0, 0}, {1, 1}, {0.5, 0.5}, {0.25, 0.75}, {1, 0}};
    for (size_t i = 0; i < sizeof uv / sizeof uv[0]; i++) {
        sc_surface_point q;
        sc_surface_eval(s, uv[i][0], uv[i][1], &q);
        require_unit(q.n); /* surface.h: the fallback too is a unit vector, never NaN */
    }
    sc_mesh m;
    if (sc_surface_tessellate(s, 24, &m, err, sizeof err) == 0) {
        for (int k = 0; k < 3 * m.n_vertices; k++)
            require(!isnan(m.normal[k]));
        sc_mesh_free(&m);
    }
    sc_surface_free(s);
}

static void fuzz_matrix(const char *spec)
{
    char err[256];
    sc_dmat4 m;
    sc_dmat3 r;
    int rigid;
    if (sc_transform_parse(spec, &m, err, sizeof err) < 0 || sc_normal_matrix(&m, &r, &rigid) < 0)
        return;
    for (int k = 0; k < 9; k++)
        require(!isnan(r.m[k]));
}

static void fuzz_obj(const uint8_t *data, size_t size)
{
    static char path[64];
    char err[256];
    if (path[0] == '\0') {
        strcpy(path, "/tmp/fuzz_surface.XXXXXX");
        int fd = mkstemp(path);
        require(fd >= 0);
        close(fd);
    }
    FILE *f = fopen(path, "wb");
    require(f != NULL);
    fwrite(data, 1, size, f);
    fclose(f);
    sc_mesh m;
    if (sc_obj_read(path, &m, err, sizeof err) < 0)
        return;
    for (int w = SC_NORMALS_PLAIN; w <= SC_NORMALS_ANGLE; w++) {
        require(sc_mesh_vertex_normals(&m, (sc_normal_weighting)w) >= 0);
        for (int k = 0; k < 3 * m.n_vertices; k++)
            require(!isnan(m.normal[k]));
    }
    sc_mesh_free(&m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size);
    if (text == NULL)
        return 0;
    fuzz_surface(text);
    fuzz_matrix(text);
    fuzz_obj(data, size);
    free(text);
    return 0;
}
