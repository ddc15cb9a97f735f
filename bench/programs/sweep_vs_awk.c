/* The CSV curve against the one-liner (issue 13 §3): in one run, rounds of
 *     shadecalc sweep --threads 1 --var x=0:1:N 'pow(x, 32.0)'
 *     shadecalc sweep --threads 2 --var x=0:1:N 'pow(x, 32.0)'
 *     awk 'BEGIN{for(i=0;i<N;i++){x=i/(N-1); printf "%.9g,%.9g\n", x, x^32}}'
 * each writing to /dev/null, the three interleaved so that a change in the machine's load
 * falls on all of them. Prints the median wall and CPU (user + system) seconds of each and the
 * ratios: awk / one thread (at least 1: as fast as the one-liner) and one thread / two threads
 * (2 is perfect scaling). The wall ratio of threads means something only on an idle machine.
 * usage: sweep_vs_awk SHADECALC [ROWS [ROUNDS]]   (default 10^6 rows, 5 rounds) */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { COMMANDS = 3, ROUNDS_MAX = 101 };

typedef struct {
    double wall, cpu;
} timing;

static double seconds(struct timespec t) { return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec; }

/* CPU seconds (user + system) of the children waited for so far. */
static double children_cpu(void)
{
    struct rusage use;
    getrusage(RUSAGE_CHILDREN, &use);
    return (double)use.ru_utime.tv_sec + 1e-6 * (double)use.ru_utime.tv_usec +
           (double)use.ru_stime.tv_sec + 1e-6 * (double)use.ru_stime.tv_usec;
}

/* Runs argv with standard output on /dev/null; 0 and its timing, or -1 if it failed. */
static int run(char *const argv[], timing *t)
{
    struct timespec t0, t1;
    double cpu0 = children_cpu();
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null < 0 || dup2(null, STDOUT_FILENO) < 0)
            _exit(127);
        execvp(argv[0], argv);
        _exit(127);
    }
    int status;
    if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    t->wall = seconds(t1) - seconds(t0);
    t->cpu = children_cpu() - cpu0;
    return 0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int main(int argc, char **argv)
{
    long rows = argc > 2 ? atol(argv[2]) : 1000000;
    int rounds = argc > 3 ? atoi(argv[3]) : 5;
    if (argc < 2 || argc > 4 || rows < 2 || rounds < 1 || rounds > ROUNDS_MAX) {
        fprintf(stderr, "usage: sweep_vs_awk SHADECALC [ROWS [ROUNDS]]  (ROUNDS 1..%d)\n",
                ROUNDS_MAX);
        return 2;
    }
    char var[64], program[160];
    snprintf(var, sizeof var, "x=0:1:%ld", rows);
    snprintf(program, sizeof program,
             "BEGIN{for(i=0;i<%ld;i++){x=i/%ld; printf \"%%.9g,%%.9g\\n\", x, x^32}}", rows,
             rows - 1);
    char *const commands[COMMANDS][8] = {
        {argv[1], "sweep", "--threads", "1", "--var", var, "pow(x, 32.0)", NULL},
        {argv[1], "sweep", "--threads", "2", "--var", var, "pow(x, 32.0)", NULL},
        {"awk", program, NULL},
    };
    static const char *const names[COMMANDS] = {"sweep, 1 thread", "sweep, 2 threads",
                                                "awk one-liner"};
    double wall[COMMANDS][ROUNDS_MAX], cpu[COMMANDS][ROUNDS_MAX];
    for (int r = 0; r < rounds; r++)
        for (int c = 0; c < COMMANDS; c++) {
            timing t;
            if (run(commands[c], &t) != 0) {
                fprintf(stderr, "sweep_vs_awk: %s failed\n", names[c]);
                return 1;
            }
            wall[c][r] = t.wall;
            cpu[c][r] = t.cpu;
        }
    timing m[COMMANDS];
    printf("%ld rows, median of %d rounds\n| command | wall s | cpu s |\n|---|---|---|\n", rows,
           rounds);
    for (int c = 0; c < COMMANDS; c++) {
        m[c] = (timing){median(wall[c], rounds), median(cpu[c], rounds)};
        printf("| %s | %.3f | %.3f |\n", names[c], m[c].wall, m[c].cpu);
    }
    printf("awk / 1 thread: wall %.2f, cpu %.2f (>= 1: at least as fast as awk)\n",
           m[2].wall / m[0].wall, m[2].cpu / m[0].cpu);
    printf("1 thread / 2 threads: wall %.2f (2: perfect scaling; needs two idle cores), cpu "
           "%.2f\n",
           m[0].wall / m[1].wall, m[0].cpu / m[1].cpu);
    return 0;
}
