/* Matrix built-ins in a chosen precision (shadecalc/pmath.h): column-major n×n, every
 * operation rounded, sums left to right. */
#include "shadecalc/pmath.h"

/* Row r of the column-major n×n matrix m. */
static void row_of(const double *m, int n, int r, double *row)
{
    for (int k = 0; k < n; k++)
        row[k] = m[k * n + r];
}

void sc_p_mat_vec(sc_prec p, const double *m, const double *v, int n, double *out)
{
    double res[4], row[4];
    for (int r = 0; r < n; r++) {
        row_of(m, n, r, row);
        res[r] = sc_p_dot(p, row, v, n);
    }
    for (int r = 0; r < n; r++)
        out[r] = res[r];
}

/* v·m = transpose(m)·v: component c is dot(v, column c). */
void sc_p_vec_mat(sc_prec p, const double *v, const double *m, int n, double *out)
{
    double res[4];
    for (int c = 0; c < n; c++)
        res[c] = sc_p_dot(p, v, m + c * n, n);
    for (int c = 0; c < n; c++)
        out[c] = res[c];
}

void sc_p_matmul(sc_prec p, const double *a, const double *b, int n, double *out)
{
    double res[16];
    for (int c = 0; c < n; c++)
        sc_p_mat_vec(p, a, b + c * n, n, res + c * n);
    for (int k = 0; k < n * n; k++)
        out[k] = res[k];
}

void sc_p_transpose(const double *m, int n, double *out)
{
    double res[16];
    for (int c = 0; c < n; c++)
        row_of(m, n, c, res + c * n);
    for (int k = 0; k < n * n; k++)
        out[k] = res[k];
}

void sc_p_comp_mult(sc_prec p, const double *a, const double *b, int n, double *out)
{
    for (int k = 0; k < n * n; k++)
        out[k] = sc_p_mul(p, a[k], b[k]);
}

void sc_p_outer(sc_prec p, const double *c, const double *r, int n, double *out)
{
    double res[16];
    for (int col = 0; col < n; col++)
        for (int row = 0; row < n; row++)
            res[col * n + row] = sc_p_mul(p, c[row], r[col]);
    for (int k = 0; k < n * n; k++)
        out[k] = res[k];
}

/* The (n-1)×(n-1) matrix left when row `skip_r` and column `skip_c` are removed. */
static void minor_of(const double *m, int n, int skip_r, int skip_c, double *out)
{
    int k = 0;
    for (int c = 0; c < n; c++)
        for (int r = 0; r < n; r++)
            if (r != skip_r && c != skip_c)
                out[k++] = m[c * n + r];
}

/* Laplace expansion along the first column: det = Σ_r (-1)^r · m[r][0] · det(minor(r, 0)). */
double sc_p_determinant(sc_prec p, const double *m, int n)
{
    if (n == 1)
        return m[0];
    double sum = 0.0, minor[9];
    for (int r = 0; r < n; r++) {
        minor_of(m, n, r, 0, minor);
        double term = sc_p_mul(p, m[r], sc_p_determinant(p, minor, n - 1));
        sum = r == 0 ? term : (r % 2 ? sc_p_sub(p, sum, term) : sc_p_add(p, sum, term));
    }
    return sum;
}

/* inverse = adjugate / det, adjugate(r, c) = (-1)^(r+c) · det(minor(c, r)). */
double sc_p_inverse(sc_prec p, const double *m, int n, double *out)
{
    double det = sc_p_determinant(p, m, n), res[16], minor[9];
    for (int c = 0; c < n; c++)
        for (int r = 0; r < n; r++) {
            minor_of(m, n, c, r, minor);
            double cof = sc_p_determinant(p, minor, n - 1);
            if ((r + c) % 2)
                cof = sc_p_neg(p, cof);
            res[c * n + r] = sc_p_div(p, cof, det);
        }
    for (int k = 0; k < n * n; k++)
        out[k] = res[k];
    return det;
}
