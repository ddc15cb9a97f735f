/* Meshes (shadecalc/mesh.h): tessellation against the surface it samples (exact vertex normals,
 * outward winding, seams and poles welded, the lecture's grid sizes), vertex normals on small
 * hand-made meshes with answers worked out by hand, degenerate triangles counted, OBJ round trip
 * and malformed files rejected with their line. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "shadecalc/mesh.h"

#define FLOAT_EPS 0x1p-24
#define PI 3.14159265358979323846

static sc_mesh tessellate(const char *spec, int triangles)
{
    char err[256];
    sc_mesh m;
    sc_surface *s = sc_surface_parse(spec, err, sizeof err);
    if (!s)
        fail_msg("'%s': %s", spec, err);
    if (sc_surface_tessellate(s, triangles, &m, err, sizeof err) < 0)
        fail_msg("tessellate '%s' %d: %s", spec, triangles, err);
    sc_surface_free(s);
    return m;
}

static const float *vertex(const sc_mesh *m, int k) { return &m->pos[3 * k]; }

static void triangle_cross(const sc_mesh *m, int t, double *c)
{
    const float *a = vertex(m, m->tri[3 * t]), *b = vertex(m, m->tri[3 * t + 1]),
                *d = vertex(m, m->tri[3 * t + 2]);
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* The lecture's sphere: 6320 = 2·79·40 triangles on a 79 × 40 grid; the two pole rows lose the
 * triangles of zero area (79 each). Vertices: 80 × 41. */
static void sphere_grid_has_the_lecture_proportions(void **state)
{
    (void)state;
    sc_mesh m = tessellate("sphere", 6320);
    assert_int_equal(m.n_vertices, 80 * 41);
    assert_int_equal(m.n_triangles, 2 * 79 * 40 - 2 * 79);
    sc_mesh_free(&m);
    m = tessellate("sphere", 1024); /* 32 × 16 */
    assert_int_equal(m.n_vertices, 33 * 17);
    sc_mesh_free(&m);
}

/* On a unit sphere the exact normal is the point itself: every vertex normal within the float
 * rounding of the two (a few float ε), and every triangle wound outward: its normal points
 * away from the centre. */
static void sphere_vertices_carry_exact_normals_and_triangles_face_out(void **state)
{
    (void)state;
    sc_mesh m = tessellate("sphere", 2000);
    for (int k = 0; k < m.n_vertices; k++) {
        const float *p = vertex(&m, k), *n = &m.normal[3 * k];
        for (int c = 0; c < 3; c++)
            assert_true(fabs((double)p[c] - n[c]) <= 4 * FLOAT_EPS);
        double u = m.uv[2 * k], v = m.uv[2 * k + 1];
        assert_true(u >= 0 && u <= 1 && v >= 0 && v <= 1);
    }
    for (int t = 0; t < m.n_triangles; t++) {
        double c[3];
        triangle_cross(&m, t, c);
        const float *a = vertex(&m, m.tri[3 * t]);
        assert_true(c[0] * a[0] + c[1] * a[1] + c[2] * a[2] > 0);
    }
    sc_mesh_free(&m);
}

/* The total area converges to 4π from below (inscribed triangles). */
static void sphere_area_approaches_four_pi(void **state)
{
    (void)state;
    double previous = 0;
    const int counts[] = {200, 1024, 6320, 40000};
    for (int i = 0; i < 4; i++) {
        sc_mesh m = tessellate("sphere", counts[i]);
        double area = 0;
        for (int t = 0; t < m.n_triangles; t++) {
            double c[3];
            triangle_cross(&m, t, c);
            area += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        }
        assert_true(area < 4 * PI && area > previous);
        previous = area;
        sc_mesh_free(&m);
    }
    assert_true(4 * PI - previous < 1e-3 * 4 * PI);
}

/* Seams: the last column (u = 1) repeats the first's position bitwise; (u,v) differ. Poles:
 * one position for the whole row. */
static void seams_and_poles_are_welded_bitwise(void **state)
{
    (void)state;
    sc_mesh m = tessellate("torus", 400);
    int row = 0;
    while (m.uv[2 * (row + 1)] > m.uv[2 * row]) /* vertices (0..nu, 0): u increasing */
        row++;
    int nu = row, nv = m.n_vertices / (nu + 1) - 1;
    for (int j = 0; j <= nv; j++)
        assert_memory_equal(vertex(&m, j * (nu + 1) + nu), vertex(&m, j * (nu + 1)),
                            3 * sizeof(float));
    for (int i = 0; i <= nu; i++)
        assert_memory_equal(vertex(&m, nv * (nu + 1) + i), vertex(&m, i), 3 * sizeof(float));
    assert_true(m.uv[2 * nu] == 1.0f && m.uv[0] == 0.0f);
    sc_mesh_free(&m);
    m = tessellate("sphere", 400);
    for (int k = 1; m.uv[2 * k + 1] == 0.0f; k++)
        assert_memory_equal(vertex(&m, k), vertex(&m, 0), 3 * sizeof(float));
    sc_mesh_free(&m);
}

static void triangle_count_is_about_the_request(void **state)
{
    (void)state;
    const int counts[] = {100, 1000, 6320, 40000};
    for (int i = 0; i < 4; i++) {
        sc_mesh m = tessellate("torus R=1 r=0.3", counts[i]);
        assert_true(abs(m.n_triangles - counts[i]) <= counts[i] / 10);
        sc_mesh_free(&m);
        m = tessellate("plane", counts[i]);
        assert_true(abs(m.n_triangles - counts[i]) <= counts[i] / 10);
        sc_mesh_free(&m);
    }
}

static void bad_counts_and_infinite_surfaces_are_errors(void **state)
{
    (void)state;
    char err[256];
    sc_mesh m;
    sc_surface *s = sc_surface_parse("sphere", err, sizeof err);
    assert_int_equal(sc_surface_tessellate(s, 1, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "1 triangles"));
    assert_int_equal(sc_surface_tessellate(s, (1 << 26) + 1, &m, err, sizeof err), -1);
    sc_surface_free(s);
    s = sc_surface_parse("user x=u y=v z=1./(u-0.5)", err, sizeof err);
    assert_int_equal(sc_surface_tessellate(s, 8, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "not finite at u=0.5"));
    sc_surface_free(s);
}

/* ---- vertex normals by hand ---- */

/* Three faces around the origin (vertex 0), worked out by hand:
 *   T_z = 0, (2,0,0), (2,2,0): cross (0,0,4), area 2, angle at 0 45°
 *   T_x = 0, (0,1,0), (0,0,1): cross (1,0,0), area ½, angle 90°
 *   T_y = 0, (0,0,3), (3,0,0): cross (0,9,0), area 9/2, angle 90°
 * plain (1,1,1)/√3; area (1,9,4)/√98; angle (π/2, π/2, π/4)/‖…‖ = (2,2,1)/3.
 * Plus two degenerate triangles (collinear; repeated vertex) and an unused vertex. */
static sc_mesh corner_mesh(void)
{
    static const float pos[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 1, 0, 0, 0, 1,
                                0, 0, 3, 3, 0, 0, 1, 1, 1, 2, 2, 2, 5, 5, 5};
    static const int tri[] = {0, 1, 2, 0, 3, 4, 0, 5, 6, 0, 7, 8, 7, 7, 1};
    sc_mesh m = {10, 5, malloc(sizeof pos), NULL, NULL, malloc(sizeof tri)};
    memcpy(m.pos, pos, sizeof pos);
    memcpy(m.tri, tri, sizeof tri);
    return m;
}

static void assert_normal(const sc_mesh *m, int k, double x, double y, double z)
{
    double want[3] = {x, y, z};
    for (int c = 0; c < 3; c++)
        if (!(fabs(m->normal[3 * k + c] - want[c]) <= 2 * FLOAT_EPS))
            fail_msg("normal %d[%d] = %.9g, want %.9g", k, c, m->normal[3 * k + c], want[c]);
}

static void plain_area_and_angle_weights_by_hand(void **state)
{
    (void)state;
    sc_mesh m = corner_mesh();
    assert_int_equal(sc_mesh_vertex_normals(&m, SC_NORMALS_PLAIN), 2);
    assert_normal(&m, 0, 1 / sqrt(3), 1 / sqrt(3), 1 / sqrt(3));
    assert_int_equal(sc_mesh_vertex_normals(&m, SC_NORMALS_AREA), 2);
    assert_normal(&m, 0, 1 / sqrt(98), 9 / sqrt(98), 4 / sqrt(98));
    assert_int_equal(sc_mesh_vertex_normals(&m, SC_NORMALS_ANGLE), 2);
    assert_normal(&m, 0, 2. / 3, 2. / 3, 1. / 3);
    assert_normal(&m, 1, 0, 0, 1); /* only T_z (the degenerate one adds nothing) */
    assert_normal(&m, 9, 0, 0, 1); /* unused: the documented (0, 0, 1) */
    sc_mesh_free(&m);
}

/* The lecture's vertex of four faces: a square pyramid's apex over (0,0,1); plain and angle
 * weights agree by symmetry: (0, 0, 1). */
static void pyramid_apex_points_up(void **state)
{
    (void)state;
    static const float pos[] = {0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0};
    static const int tri[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
    sc_mesh m = {5, 4, malloc(sizeof pos), NULL, NULL, malloc(sizeof tri)};
    memcpy(m.pos, pos, sizeof pos);
    memcpy(m.tri, tri, sizeof tri);
    for (int w = SC_NORMALS_PLAIN; w <= SC_NORMALS_ANGLE; w++) {
        assert_int_equal(sc_mesh_vertex_normals(&m, (sc_normal_weighting)w), 0);
        assert_normal(&m, 0, 0, 0, 1);
        /* vertex 1: faces 0 and 3, normals (1,1,1)/√3 and (1,−1,1)/√3: sum ∝ (1, 0, 1) */
        assert_normal(&m, 1, 1 / sqrt(2), 0, 1 / sqrt(2));
    }
    sc_mesh_free(&m);
}

static void triangle_normal_is_unit_or_zero(void **state)
{
    (void)state;
    double n[3];
    sc_triangle_normal((double[3]){1, 1, 1}, (double[3]){1, 4, 1}, (double[3]){1, 1, 5}, n);
    assert_true(n[0] == 1 && n[1] == 0 && n[2] == 0);
    sc_triangle_normal((double[3]){0, 0, 0}, (double[3]){1, 2, 3}, (double[3]){2, 4, 6}, n);
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == 0);
    sc_triangle_normal((double[3]){0, 0, 0}, (double[3]){NAN, 0, 0}, (double[3]){0, 1, 0}, n);
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == 0);
}

/* Scale does not make a triangle degenerate: corners 1e308 or 1e-200 apart (the cross product
 * of the edges would overflow or underflow), or tiny next to their distance from the origin. */
static void triangle_normal_at_extreme_scales(void **state)
{
    (void)state;
    static const double scales[] = {1e308, 1e-200, 4e-320, 1.0};
    double n[3];
    for (int i = 0; i < 4; i++) {
        double s = scales[i];
        sc_triangle_normal((double[3]){0, 0, 0}, (double[3]){s, 0, 0}, (double[3]){0, s, 0}, n);
        assert_true(n[0] == 0 && n[1] == 0 && n[2] == 1);
        sc_triangle_normal((double[3]){-s, -s, 0}, (double[3]){s, -s, 0}, (double[3]){0, s, s}, n);
        /* (2s, 0, 0) × (s, 2s, s) = (0, −2s², 4s²) */
        assert_true(fabs(n[0]) < 1e-15 && fabs(n[1] + 1.0 / sqrt(5.0)) < 1e-15 &&
                    fabs(n[2] - 2.0 / sqrt(5.0)) < 1e-15);
    }
    sc_triangle_normal((double[3]){1, 0, 0}, (double[3]){1, 1e-200, 0}, (double[3]){1, 0, 1e-200},
                       n);
    assert_true(n[0] == 1 && n[1] == 0 && n[2] == 0);
}

/* ---- OBJ ---- */

static char tmpdir[64];

static int make_tmpdir(void **state)
{
    (void)state;
    strcpy(tmpdir, "/tmp/test_mesh.XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int remove_tmpdir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *write_text(const char *name, const char *text)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return path;
}

/* Each triangle's corners, compared by value (the reader numbers vertices in order of use). */
static void obj_round_trip_keeps_every_triangle(void **state)
{
    (void)state;
    char path[128], err[256];
    sc_mesh m = tessellate("torus", 300), r;
    snprintf(path, sizeof path, "%s/torus.obj", tmpdir);
    assert_int_equal(sc_obj_write(path, &m, err, sizeof err), 0);
    assert_int_equal(sc_obj_read(path, &r, err, sizeof err), 0);
    assert_int_equal(r.n_triangles, m.n_triangles);
    assert_int_equal(r.n_vertices, m.n_vertices);
    assert_non_null(r.normal);
    assert_null(r.uv);
    for (int t = 0; t < m.n_triangles; t++)
        for (int c = 0; c < 3; c++) {
            int a = m.tri[3 * t + c], b = r.tri[3 * t + c];
            assert_memory_equal(&m.pos[3 * a], &r.pos[3 * b], 3 * sizeof(float));
            assert_memory_equal(&m.normal[3 * a], &r.normal[3 * b], 3 * sizeof(float));
        }
    sc_mesh_free(&m);
    sc_mesh_free(&r);
}

/* A quad becomes a fan; negative indices count back; a position used with two normals is two
 * vertices; comments, groups and texture coordinates are ignored. */
static void obj_fans_relative_indices_and_split_normals(void **state)
{
    (void)state;
    char err[256];
    sc_mesh r;
    const char *path = write_text("quad.obj", "# a quad\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                              "v 0 1 0 1\nvt 0 0\nvn 0 0 1\nvn 0 0 -1\ng a\n"
                                              "f -4//1 -3//1 -2//1 -1//1\nf 1//2 3//2 2//2\n");
    assert_int_equal(sc_obj_read(path, &r, err, sizeof err), 0);
    assert_int_equal(r.n_triangles, 3);
    assert_int_equal(r.n_vertices, 7); /* 4 with +z, 3 with −z */
    assert_true(r.tri[0] == 0 && r.tri[1] == 1 && r.tri[2] == 2);
    assert_true(r.tri[3] == 0 && r.tri[4] == 2 && r.tri[5] == 3);
    assert_true(r.normal[3 * r.tri[6] + 2] == -1.0f && r.pos[3 * r.tri[7] + 1] == 1.0f);
    sc_mesh_free(&r);
    path = write_text("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"
                                   "f 1 3 2\n");
    assert_int_equal(sc_obj_read(path, &r, err, sizeof err), 0);
    assert_null(r.normal); /* only some corners had normals */
    sc_mesh_free(&r);
}

static void malformed_obj_is_rejected_with_its_line(void **state)
{
    (void)state;
    static const char *const bad[][2] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", ":4: bad vertex index in '4'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", ":4: bad vertex index in '0'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", ":4: bad vertex index in '-4'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//2 2 3\n", ":4: bad normal index in '1//2'"},
        {"v 0 0 0\nv 1 0 0\n\nf 1 2\n", ":4: a face needs at least 3 corners, got 2"},
        {"# c\nv 0 0\n", ":2: expected 3 coordinates, got 2"},
        {"v 0 0 nan\n", ":1: not a finite float: 'nan'"},
        {"v 0 0 1e39\n", ":1: not a finite float: '1e39'"},
        {"v 0 0 1x\n", ":1: not a finite float: '1x'"},
        {"v 0 0 0\nbogus 1\n", ":2: unknown statement 'bogus'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", ":4: bad vertex index in '3x'"},
        {"v 0 0 0\n", ": no faces"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char err[256] = "";
        sc_mesh r;
        const char *path = write_text("bad.obj", bad[i][0]);
        if (sc_obj_read(path, &r, err, sizeof err) == 0 || !strstr(err, bad[i][1]) ||
            strncmp(err, path, strlen(path)) != 0)
            fail_msg("case %zu: message '%s', want '%s%s'", i, err, path, bad[i][1]);
    }
}

static void obj_write_to_a_missing_directory_fails_cleanly(void **state)
{
    (void)state;
    char path[128], err[256] = "";
    sc_mesh m = tessellate("plane", 2);
    snprintf(path, sizeof path, "%s/missing/plane.obj", tmpdir);
    assert_int_equal(sc_obj_write(path, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    assert_int_equal(access(path, F_OK), -1);
    sc_mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_grid_has_the_lecture_proportions),
        cmocka_unit_test(triangle_normal_at_extreme_scales),
        cmocka_unit_test(sphere_vertices_carry_exact_normals_and_triangles_face_out),
        cmocka_unit_test(sphere_area_approaches_four_pi),
        cmocka_unit_test(seams_and_poles_are_welded_bitwise),
        cmocka_unit_test(triangle_count_is_about_the_request),
        cmocka_unit_test(bad_counts_and_infinite_surfaces_are_errors),
        cmocka_unit_test(plain_area_and_angle_weights_by_hand),
        cmocka_unit_test(pyramid_apex_points_up),
        cmocka_unit_test(triangle_normal_is_unit_or_zero),
        cmocka_unit_test(obj_round_trip_keeps_every_triangle),
        cmocka_unit_test(obj_fans_relative_indices_and_split_normals),
        cmocka_unit_test(malformed_obj_is_rejected_with_its_line),
        cmocka_unit_test(obj_write_to_a_missing_directory_fails_cleanly),
    };
    return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
