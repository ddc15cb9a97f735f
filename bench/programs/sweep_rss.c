/* Peak memory of a sweep against its number of rows (issue 5: "10^8 rows must work", streamed
 * in constant memory). Each size runs in a child process that sweeps x over N rows through
 * `pow(x, 32.0) * 0.5 + x` in highp, formats every row as CSV and writes it to /dev/null, then
 * prints its own time and peak resident set (getrusage ru_maxrss: a fresh process per size).
 * usage: sweep_rss [THREADS [ROWS...]]   (default: 2 threads, 10^5 10^6 10^7 rows) */
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "shadecalc/expr.h"
#include "shadecalc/sweep.h"

static int eval_row(void *user, int worker, const double *vars, double *results, char *err,
                    size_t errsize)
{
    (void)worker;
    (void)err;
    (void)errsize;
    const sc_value in[1] = {{SC_FLOAT, {vars[0]}}};
    results[0] = sc_expr_eval(user, SC_HIGHP, in, NULL, NULL).v[0];
    return 0;
}

/* The child: one sweep of `rows` rows to /dev/null, then its line of the table. */
static int sweep_rows(long rows, int threads)
{
    char arg[64], err[256];
    snprintf(arg, sizeof arg, "x=0:1:%ld", rows);
    sc_sweep_grid g = {.n = 0};
    sc_sweep_var v;
    const sc_expr_input inputs[1] = {{"x", SC_FLOAT}};
    sc_expr_error e;
    sc_expr *expr = sc_expr_compile("pow(x, 32.0) * 0.5 + x", inputs, 1, &e);
    FILE *out = fopen("/dev/null", "w");
    if (!expr || !out || sc_sweep_var_parse(arg, &v, err, sizeof err) < 0 ||
        sc_sweep_grid_add(&g, &v, err, sizeof err) < 0)
        return 1;
    static const char *const names[] = {"x", "value"};
    sc_sweep_table table = {SC_SWEEP_CSV, SC_HIGHP, names, 1, 1};
    sc_sweep_job job = {&g, 1, eval_row, expr, NULL, &table, out, NULL, threads, NULL};
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int status = sc_sweep_run(&job, err, sizeof err) == SC_SWEEP_OK ? 0 : 1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    struct rusage use;
    getrusage(RUSAGE_SELF, &use);
    double s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("| %ld | %d | %.2f | %.0f | %ld |\n", rows, threads, s, 1e9 * s / (double)rows,
           use.ru_maxrss);
    fclose(out);
    sc_expr_free(expr);
    sc_sweep_grid_free(&g);
    return status;
}

int main(int argc, char **argv)
{
    int threads = argc > 1 ? atoi(argv[1]) : 2;
    static const long defaults[] = {100000, 1000000, 10000000};
    int n = argc > 2 ? argc - 2 : 3;
    if (threads < 1) {
        fprintf(stderr, "usage: sweep_rss [THREADS [ROWS...]]\n");
        return 2;
    }
    printf("| rows | threads | seconds | ns per row | peak RSS (kB) |\n|---|---|---|---|---|\n");
    for (int i = 0; i < n; i++) {
        long rows = argc > 2 ? atol(argv[2 + i]) : defaults[i];
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0)
            _exit(sweep_rows(rows, threads) == 0 && fflush(stdout) == 0 ? 0 : 1);
        int status;
        if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) ||
            WEXITSTATUS(status) != 0) {
            fprintf(stderr, "sweep_rss: the sweep of %ld rows failed\n", rows);
            return 1;
        }
    }
    return 0;
}
