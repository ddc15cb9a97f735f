/* make exhaustive: every binary32 input of each one-argument highp built-in and u1 batch kernel,
 * >= 10^9 biased pairs of pow and atan2, and every binary16 input of mediump and lowp, checked
 * against the correctly rounded result (checker.h); every binary32 printed as the shortest
 * decimal that reads back (group print, shortest_check.h). Each subject's misses go to
 * OUTDIR/<name>.txt, the summary to OUTDIR/summary.txt. --audit sends every input to MPFR too
 * (slow: for samples), which checks the stated bounds themselves.
 *
 * usage: exhaustive [--threads N] [--stride S] [--range LO HI] [--pairs N] [--audit]
 *                   [--only NAME,...] [--groups highp,batch,pairs,half,print] [--outdir DIR]
 * Exit status 0: every highp one-argument result correctly rounded, no result beyond its stated
 * bound, and the checker's premises held (cores, bounds); 1 otherwise; 2 on a usage error. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "shortest_check.h"
#include "subjects.h"

typedef struct {
    int threads, audit;
    uint64_t stride, first, count, pairs;
    const char *only, *groups, *outdir;
} options;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int listed(const char *list, const char *name)
{
    if (!list)
        return 1;
    size_t n = strlen(name);
    for (const char *p = list; *p;) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0)
            return 1;
        p += len + (end != NULL);
    }
    return 0;
}

static uint32_t bits_of(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static int parse_number(const char *s, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(s, &end);
    return errno || end == s || *end ? -1 : 0;
}

static int usage(const char *msg, const char *arg)
{
    fprintf(stderr,
            "exhaustive: %s%s%s\nusage: exhaustive [--threads N] [--stride S] "
            "[--range LO HI] [--pairs N] [--audit] [--only NAME,...] "
            "[--groups highp,batch,pairs,half,print] [--outdir DIR]\n",
            msg, arg ? ": " : "", arg ? arg : "");
    return 2;
}

static int parse_args(int argc, char **argv, options *o)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    *o = (options){cpus > 0 ? (int)cpus : 1,
                   0,
                   1,
                   0,
                   1ULL << 32,
                   1000000000ULL,
                   NULL,
                   "highp,batch,pairs,half,print",
                   "build/exhaustive"};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        double v, w;
        int more = i + 1 < argc;
        if (strcmp(a, "--threads") == 0 && more && parse_number(argv[++i], &v) == 0 && v >= 1 &&
            v <= 256)
            o->threads = (int)v;
        else if (strcmp(a, "--stride") == 0 && more && parse_number(argv[++i], &v) == 0 && v >= 1 &&
                 v < 0x1p32 && v == floor(v))
            o->stride = (uint64_t)v;
        else if (strcmp(a, "--pairs") == 0 && more && parse_number(argv[++i], &v) == 0 && v >= 0 &&
                 v < 0x1p50 && v == floor(v))
            o->pairs = (uint64_t)v;
        else if (strcmp(a, "--range") == 0 && i + 2 < argc && parse_number(argv[i + 1], &v) == 0 &&
                 parse_number(argv[i + 2], &w) == 0 && v >= 0 && w > v && w <= FLT_MAX) {
            /* positive binary32 inputs in [v, w): consecutive bit patterns */
            o->first = bits_of((float)v);
            o->count = bits_of((float)w) - o->first;
            i += 2;
        } else if (strcmp(a, "--audit") == 0) {
            o->audit = 1;
        } else if (strcmp(a, "--only") == 0 && more)
            o->only = argv[++i];
        else if (strcmp(a, "--groups") == 0 && more)
            o->groups = argv[++i];
        else if (strcmp(a, "--outdir") == 0 && more)
            o->outdir = argv[++i];
        else
            return usage("bad argument", a);
    }
    if (o->count == 0)
        return usage("empty --range", NULL);
    return 0;
}

/* The file name of a subject's misses: its name with spaces as dashes. */
static int miss_path(char *buf, size_t size, const options *o, const char *name)
{
    int n = snprintf(buf, size, "%s/%s.txt", o->outdir, name);
    for (char *p = buf + strlen(o->outdir); *p; p++)
        if (*p == ' ')
            *p = '-';
    return n > 0 && (size_t)n < size ? 0 : -1;
}

typedef struct {
    FILE *summary;
    int failed;
} report;

static void both(report *r, const char *line)
{
    fputs(line, stdout);
    fflush(stdout);
    if (fputs(line, r->summary) < 0)
        r->failed = 1;
}

/* Runs one subject, writes its misses, reports; stated_ulp: the bound beyond which it fails,
 * must_round: 1 if every result must be correctly rounded. */
static void run_subject(const exh_subject *s, const exh_run_spec *spec, const options *o,
                        double stated_ulp, int must_round, report *r)
{
    exh_stats st;
    double t0 = now();
    if (exh_run(s, spec, &st) != 0) {
        fprintf(stderr, "exhaustive: %s: out of memory\n", s->name);
        r->failed = 1;
        exh_stats_free(&st);
        return;
    }
    char line[512], path[4096];
    FILE *mem = fmemopen(line, sizeof line, "w");
    if (mem) {
        exh_print_summary(mem, s, &st, now() - t0);
        fclose(mem);
        both(r, line);
    }
    if (miss_path(path, sizeof path, o, s->name) != 0 || exh_write_misses(path, s, &st) != 0) {
        fprintf(stderr, "exhaustive: cannot write %s: %s\n", path, strerror(errno));
        r->failed = 1;
    }
    if (st.not_core || st.bound_broken || st.max_ulp > stated_ulp || (must_round && st.wrong))
        r->failed = 1;
    exh_stats_free(&st);
}

static void run_half(const exh_subject *s, report *r)
{
    exh_half_stats h;
    exh_half_check(s, &h);
    char line[256];
    snprintf(line, sizeof line,
             "%-22s half inputs %ld  highp not-cr %ld  mediump != round(highp) %ld  lowp != "
             "round(highp) %ld  double-rounded %ld\n",
             s->name, h.inputs, h.highp_wrong, h.mediump_mismatch, h.lowp_mismatch,
             h.double_rounded);
    both(r, line);
    if (h.highp_wrong || h.mediump_mismatch || h.lowp_mismatch)
        r->failed = 1;
}

static void run_highp(const options *o, const exh_run_spec *ones, report *r)
{
    exh_run_spec pairs = {0, o->pairs, 1, NULL, o->audit, o->threads};
    for (int i = 0; i < exh_highp_count; i++) {
        const exh_subject *s = &exh_highp[i];
        if (!listed(o->only, s->name))
            continue;
        if (s->arity == 1 && listed(o->groups, "highp"))
            run_subject(s, ones, o, 1.0, 1, r);
        if (s->arity == 2 && listed(o->groups, "pairs")) {
            pairs.gen = exh_pair_generator(s->name);
            run_subject(s, &pairs, o, 1.0, 0, r);
        }
        if (s->arity == 1 && listed(o->groups, "half"))
            run_half(s, r);
    }
}

static void run_batch(const options *o, const exh_run_spec *ones, report *r)
{
    exh_subject subjects[64];
    char names[64][EXH_NAME_MAX];
    int n = exh_batch_subjects(subjects, names, 64);
    for (int i = 0; i < n; i++)
        if (listed(o->only, subjects[i].name) || listed(o->only, subjects[i].entry->kernel))
            run_subject(&subjects[i], ones, o, subjects[i].entry->bound_ulp, 0, r);
}

/* sc_format_shortest over the binary32 inputs of the run (--range, --stride). */
static void run_print(const options *o, const exh_run_spec *ones, report *r)
{
    char why[256], line[640];
    double t0 = now();
    uint64_t failures = shortest_check_binary32(ones->first, ones->count, ones->stride, o->threads,
                                                why, sizeof why);
    snprintf(line, sizeof line,
             "%-22s binary32 inputs %llu  not the shortest decimal reading back %llu  %.0f s%s%s\n",
             "print highp", (unsigned long long)ones->count, (unsigned long long)failures,
             now() - t0, failures ? "  first: " : "", failures ? why : "");
    both(r, line);
    if (failures)
        r->failed = 1;
}

static void describe_run(report *r, int argc, char **argv, const options *o)
{
    char line[1024];
    struct utsname u;
    size_t n = (size_t)snprintf(line, sizeof line, "# command:");
    for (int i = 0; i < argc && n < sizeof line; i++)
        n += (size_t)snprintf(line + n, sizeof line - n, " %s", argv[i]);
    both(r, line);
    snprintf(line, sizeof line, "\n# machine: %s %s, %ld processors, %d threads\n",
             uname(&u) == 0 ? u.sysname : "?", uname(&u) == 0 ? u.machine : "?",
             sysconf(_SC_NPROCESSORS_ONLN), o->threads);
    both(r, line);
}

int main(int argc, char **argv)
{
    options o;
    int status = parse_args(argc, argv, &o);
    if (status)
        return status;
    char path[4096];
    if ((mkdir(o.outdir, 0777) != 0 && errno != EEXIST) ||
        snprintf(path, sizeof path, "%s/summary.txt", o.outdir) >= (int)sizeof path) {
        fprintf(stderr, "exhaustive: cannot create %s: %s\n", o.outdir, strerror(errno));
        return 1;
    }
    report r = {fopen(path, "w"), 0};
    if (!r.summary) {
        fprintf(stderr, "exhaustive: cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    describe_run(&r, argc, argv, &o);
    uint64_t count = (o.count + o.stride - 1) / o.stride;
    exh_run_spec ones = {o.first, count, o.stride, NULL, o.audit, o.threads};
    double t0 = now();
    run_highp(&o, &ones, &r);
    if (listed(o.groups, "batch"))
        run_batch(&o, &ones, &r);
    if (listed(o.groups, "print"))
        run_print(&o, &ones, &r);
    char line[128];
    snprintf(line, sizeof line, "# wall time %.0f s: %s\n", now() - t0,
             r.failed ? "FAILED" : "passed");
    both(&r, line);
    if (fclose(r.summary) != 0) {
        fprintf(stderr, "exhaustive: cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    return r.failed ? 1 : 0;
}
