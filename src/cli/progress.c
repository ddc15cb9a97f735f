/* The progress bar of long commands (cli/progress.h). */
#include "cli/progress.h"

#include <stdio.h>
#include <unistd.h>

enum { BAR = 30, LINE = 100 };

void sc_progress_start(sc_progress *p, const char *label, double delay)
{
    p->label = label;
    p->delay = delay;
    p->tty = isatty(STDERR_FILENO);
    p->shown = 0;
    clock_gettime(CLOCK_MONOTONIC, &p->start);
}

double sc_progress_seconds(const sc_progress *p)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - p->start.tv_sec) + 1e-9 * (double)(t.tv_nsec - p->start.tv_nsec);
}

void sc_progress_update(sc_progress *p, double fraction, const char *detail)
{
    if (!p->tty || (!p->shown && sc_progress_seconds(p) < p->delay))
        return;
    fraction = fraction < 0.0 ? 0.0 : fraction > 1.0 ? 1.0 : fraction;
    int filled = (int)(BAR * fraction);
    fprintf(stderr, "\r%s [%.*s%*s] %3d%% %-40.40s", p->label, filled,
            "##############################", BAR - filled, "", (int)(100.0 * fraction),
            detail ? detail : "");
    fflush(stderr);
    p->shown = 1;
}

void sc_progress_clear(sc_progress *p)
{
    if (p->shown)
        fprintf(stderr, "\r%*s\r", LINE, "");
    p->shown = 0;
}
