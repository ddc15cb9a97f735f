/* Gauss–Legendre rules (util/quadrature.h). */
#include "util/quadrature.h"

#include <math.h>

static const double pi = 3.14159265358979323846;

/* Gauss–Legendre nodes and weights on [−1, 1] by Newton's method on P_n (Numerical Recipes
 * gauleg). */
void sc_gauss_legendre(int n, double *x, double *w)
{
    for (int i = 0; i < (n + 1) / 2; i++) {
        double z = cos(pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int iter = 0; iter < 100; iter++) {
            double p0 = 1.0, p1 = 0.0;
            for (int j = 1; j <= n; j++) { /* P_j = ((2j−1) z P_{j−1} − (j−1) P_{j−2}) / j */
                double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            double dz = p0 / dp;
            z -= dz;
            if (fabs(dz) < 1e-16)
                break;
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = w[n - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}
