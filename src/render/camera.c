/* The perspective camera: validation, framing a mesh, the view transform (render.h, view.h). */
#include <math.h>
#include <stdio.h>

#include "render/view.h"

static const double pi = 3.14159265358979323846;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    double r[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    out[0] = r[0], out[1] = r[1], out[2] = r[2];
}

static double normalize3(double v[3])
{
    double len = sqrt(dot3(v, v));
    if (len > 0.0)
        for (int c = 0; c < 3; c++)
            v[c] /= len;
    return len;
}

static int finite3(const double v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

int sc_camera_validate(const sc_camera *c, char *err, size_t errsize)
{
    double f[3] = {c->at[0] - c->eye[0], c->at[1] - c->eye[1], c->at[2] - c->eye[2]}, side[3];
    if (!finite3(c->eye) || !finite3(c->at) || !finite3(c->up)) {
        snprintf(err, errsize, "camera: --eye, --at and --up must be finite");
        return -1;
    }
    if (!(normalize3(f) > 0.0) || !isfinite(f[0] + f[1] + f[2])) {
        snprintf(err, errsize, "camera: --eye %g,%g,%g equals --at", c->eye[0], c->eye[1],
                 c->eye[2]);
        return -1;
    }
    double up[3] = {c->up[0], c->up[1], c->up[2]};
    cross3(f, up, side);
    if (!(normalize3(up) > 0.0) || !(sqrt(dot3(side, side)) > 1e-9 * sqrt(dot3(c->up, c->up)))) {
        snprintf(err, errsize, "camera: --up %g,%g,%g is zero or along the view direction",
                 c->up[0], c->up[1], c->up[2]);
        return -1;
    }
    if (!(c->fov > 0.0 && c->fov < 180.0)) {
        snprintf(err, errsize, "camera: --fov %g: must be between 0 and 180 degrees", c->fov);
        return -1;
    }
    return 0;
}

void render_view_make(const sc_camera *c, int width, int height, render_view *out)
{
    double f[3] = {c->at[0] - c->eye[0], c->at[1] - c->eye[1], c->at[2] - c->eye[2]};
    double distance = normalize3(f);
    for (int k = 0; k < 3; k++) {
        out->eye[k] = c->eye[k];
        out->forward[k] = f[k];
    }
    cross3(f, c->up, out->right);
    normalize3(out->right);
    cross3(out->right, f, out->up);
    out->scale_y = 1.0 / tan(c->fov * pi / 360.0);
    out->scale_x = out->scale_y * height / width;
    out->near = distance / 1000.0;
}

void render_view_project(const render_view *v, const double p[3], raster_vertex *out)
{
    double d[3] = {p[0] - v->eye[0], p[1] - v->eye[1], p[2] - v->eye[2]};
    out->x = dot3(d, v->right) * v->scale_x;
    out->y = dot3(d, v->up) * v->scale_y;
    out->w = dot3(d, v->forward);
}

/* Centre and radius of a sphere around every vertex (centre: the bounding box's). */
static double bounding_sphere(const sc_mesh *m, double centre[3])
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double r2 = 0.0;
    for (int i = 0; i < m->n_vertices; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->pos[3 * i + k]);
            hi[k] = fmax(hi[k], m->pos[3 * i + k]);
        }
    for (int k = 0; k < 3; k++)
        centre[k] = m->n_vertices > 0 ? 0.5 * (lo[k] + hi[k]) : 0.0;
    for (int i = 0; i < m->n_vertices; i++) {
        double d[3] = {m->pos[3 * i] - centre[0], m->pos[3 * i + 1] - centre[1],
                       m->pos[3 * i + 2] - centre[2]};
        r2 = fmax(r2, dot3(d, d));
    }
    return r2 > 0.0 ? sqrt(r2) : 1.0;
}

void sc_camera_fit(sc_camera *c, const sc_mesh *m, const double direction[3], int width, int height)
{
    double centre[3], dir[3] = {direction[0], direction[1], direction[2]};
    double radius = bounding_sphere(m, centre);
    if (!(normalize3(dir) > 0.0))
        dir[2] = 1.0;
    double half_v = c->fov * pi / 360.0;
    double half_h = atan(tan(half_v) * width / height);
    double distance = 1.05 * radius / sin(fmin(half_v, half_h));
    for (int k = 0; k < 3; k++) {
        c->at[k] = centre[k];
        c->eye[k] = centre[k] + distance * dir[k];
    }
}
