/* The progress bar of long commands (cli/progress.h). */
#include "cli/progress.h"

#include <stdio.h>
#include <unistd.h>

enum { BAR = 30, LINE = 110 };
static const double redraw_interval = 0.1; /* seconds: at most ten redraws a second */

void sc_progress_start(sc_progress *p, const char *label, double delay)
{
    p->label = label;
    p->delay = delay;
    p->tty = isatty(STDERR_FILENO);
    p->shown = 0;
    p->drawn = 0.0;
    clock_gettime(CLOCK_MONOTONIC, &p->start);
}

double sc_progress_seconds(const sc_progress *p)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - p->start.tv_sec) + 1e-9 * (double)(t.tv_nsec - p->start.tv_nsec);
}

/* The time left at this rate, "12s", "3m05s" or "2h10m"; "" before any progress. */
static const char *eta(double elapsed, double fraction, char *buf, size_t size)
{
    if (!(fraction > 0.0 && fraction < 1.0))
        return "";
    double left = elapsed * (1.0 - fraction) / fraction;
    long s = left > 359999.0 ? 359999L : (long)(left + 0.5);
    if (s < 60)
        snprintf(buf, size, "ETA %lds", s);
    else if (s < 3600)
        snprintf(buf, size, "ETA %ldm%02lds", s / 60, s % 60);
    else
        snprintf(buf, size, "ETA %ldh%02ldm", s / 3600, s / 60 % 60);
    return buf;
}

void sc_progress_update(sc_progress *p, double fraction, const char *detail)
{
    if (!p->tty)
        return;
    double now = sc_progress_seconds(p);
    if ((!p->shown && now < p->delay) || (p->shown && now - p->drawn < redraw_interval))
        return;
    fraction = fraction < 0.0 ? 0.0 : fraction > 1.0 ? 1.0 : fraction;
    int filled = (int)(BAR * fraction);
    char left[32];
    fprintf(stderr, "\r%s [%.*s%*s] %3d%% %-12s %-40.40s", p->label, filled,
            "##############################", BAR - filled, "", (int)(100.0 * fraction),
            eta(now, fraction, left, sizeof left), detail ? detail : "");
    fflush(stderr);
    p->shown = 1;
    p->drawn = now;
}

void sc_progress_clear(sc_progress *p)
{
    if (p->shown)
        fprintf(stderr, "\r%*s\r", LINE, "");
    p->shown = 0;
}
