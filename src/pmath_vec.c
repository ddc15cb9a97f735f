/* Geometric built-ins in a chosen precision: the GLSL ES §8.5 defining formulas, every
 * operation rounded (shadecalc/pmath.h). */
#include "shadecalc/pmath.h"

/* The double reference's dot product (what sc_p_mul and sc_p_add give for SC_DOUBLE), without
 * their two calls per term: the area and shading references of the batch tests take ~10^9. */
static double dot_in_double(const double *a, const double *b, int n)
{
    double sum = a[0] * b[0];
    for (int k = 1; k < n; k++)
        sum += a[k] * b[k];
    return sum;
}

double sc_p_dot(sc_prec p, const double *a, const double *b, int n)
{
    if (p == SC_DOUBLE)
        return dot_in_double(a, b, n);
    double sum = sc_p_mul(p, a[0], b[0]);
    for (int k = 1; k < n; k++)
        sum = sc_p_add(p, sum, sc_p_mul(p, a[k], b[k]));
    return sum;
}

double sc_p_length(sc_prec p, const double *a, int n) { return sc_p_sqrt(p, sc_p_dot(p, a, a, n)); }

double sc_p_distance(sc_prec p, const double *a, const double *b, int n)
{
    double d[4];
    for (int k = 0; k < n; k++)
        d[k] = sc_p_sub(p, a[k], b[k]);
    return sc_p_length(p, d, n);
}

void sc_p_normalize(sc_prec p, const double *a, int n, double *out)
{
    double len = sc_p_length(p, a, n);
    for (int k = 0; k < n; k++)
        out[k] = sc_p_div(p, a[k], len);
}

void sc_p_cross(sc_prec p, const double *a, const double *b, double *out)
{
    double c[3];
    c[0] = sc_p_sub(p, sc_p_mul(p, a[1], b[2]), sc_p_mul(p, b[1], a[2]));
    c[1] = sc_p_sub(p, sc_p_mul(p, a[2], b[0]), sc_p_mul(p, b[2], a[0]));
    c[2] = sc_p_sub(p, sc_p_mul(p, a[0], b[1]), sc_p_mul(p, b[0], a[1]));
    for (int k = 0; k < 3; k++)
        out[k] = c[k];
}

/* out = a - s·b, component by component. */
static void sub_scaled(sc_prec p, const double *a, double s, const double *b, int n, double *out)
{
    for (int k = 0; k < n; k++)
        out[k] = sc_p_sub(p, a[k], sc_p_mul(p, s, b[k]));
}

void sc_p_reflect(sc_prec p, const double *i, const double *nrm, int n, double *out)
{
    double two_d = sc_p_mul(p, 2.0, sc_p_dot(p, nrm, i, n));
    sub_scaled(p, i, two_d, nrm, n, out);
}

void sc_p_refract(sc_prec p, const double *i, const double *nrm, double eta, int n, double *out)
{
    double d = sc_p_dot(p, nrm, i, n);
    double k = sc_p_sub(p, 1.0,
                        sc_p_mul(p, sc_p_mul(p, eta, eta), sc_p_sub(p, 1.0, sc_p_mul(p, d, d))));
    if (k < 0.0) {
        for (int c = 0; c < n; c++)
            out[c] = 0.0;
        return;
    }
    double s = sc_p_add(p, sc_p_mul(p, eta, d), sc_p_sqrt(p, k));
    double ei[4];
    for (int c = 0; c < n; c++)
        ei[c] = sc_p_mul(p, eta, i[c]);
    sub_scaled(p, ei, s, nrm, n, out);
}

void sc_p_faceforward(sc_prec p, const double *nrm, const double *i, const double *nref, int n,
                      double *out)
{
    int keep = sc_p_dot(p, nref, i, n) < 0.0;
    for (int k = 0; k < n; k++)
        out[k] = keep ? nrm[k] : sc_p_neg(p, nrm[k]);
}
