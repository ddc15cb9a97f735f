/* Axis ticks (shadecalc/plot.h). */
#include "shadecalc/plot.h"

#include <math.h>

/* Heckbert's nice number: 1, 2, 5 or 10 × 10^k near x, rounded or at least x. */
static double nice_number(double x, int round_it)
{
    double e = floor(log10(x)), f = x / pow(10.0, e), nice;
    if (round_it)
        nice = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
    else
        nice = f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0;
    return nice * pow(10.0, e);
}

int sc_plot_ticks(double lo, double hi, int target, double *ticks, int max, double *step)
{
    double range = nice_number(hi - lo, 0);
    *step = nice_number(range / (target > 1 ? target : 1), 1);
    double first = floor(lo / *step), last = ceil(hi / *step);
    first -= first * *step > lo; /* k·step rounded past the end */
    last += last * *step < hi;
    int n = 0;
    for (double k = first; k <= last && n < max; k++) {
        double t = k * *step;
        ticks[n++] = t == 0.0 ? 0.0 : t; /* no -0 labels */
    }
    return n;
}

int sc_plot_log_ticks(double lo, double hi, double *ticks, int max)
{
    double first = floor(log10(lo)), last = ceil(log10(hi));
    if (last == first)
        last++;
    double every = ceil((last - first) / 10.0); /* at most about ten labelled decades */
    last = first + ceil((last - first) / every) * every;
    int fine = last - first < 3.0, n = 0;
    static const double within[] = {1.0, 2.0, 5.0};
    for (double e = first; e <= last && n < max; e += every)
        for (int m = 0; m < (fine && e < last ? 3 : 1) && n < max; m++)
            ticks[n++] = within[m] * pow(10.0, e);
    return n;
}
