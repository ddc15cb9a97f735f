/* A progress bar on standard error for long work: drawn only when standard error is a terminal
 * and only once the work has lasted `delay` seconds, so that short runs print nothing; redrawn
 * at most ten times a second, with the time left (ETA) at the rate so far. Used by sweep,
 * render and bench. */
#ifndef SHADECALC_CLI_PROGRESS_H
#define SHADECALC_CLI_PROGRESS_H

#include <time.h>

typedef struct {
    const char *label;
    struct timespec start;
    double delay;
    double drawn; /* seconds since start at the last redraw */
    int tty, shown;
} sc_progress;

void sc_progress_start(sc_progress *p, const char *label, double delay);
/* fraction in [0, 1]; detail (or NULL) is printed after the percentage. */
void sc_progress_update(sc_progress *p, double fraction, const char *detail);
/* Seconds since sc_progress_start. */
double sc_progress_seconds(const sc_progress *p);
/* Erases the bar if it was drawn. */
void sc_progress_clear(sc_progress *p);

#endif
