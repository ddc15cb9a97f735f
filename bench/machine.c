/* The machine's description and the two measured bounds of the roofline: memory bandwidth
 * (a stream loop over two arrays far larger than the last-level cache; each streaming row has
 * its own, over as many arrays as it moves: bench/harness.c) and floating-point throughput
 * (bench/peak_avx2.c; without AVX2, independent scalar chains). An instruction set
 * of width w gets w/8 of the 8-lane peak: vector instructions issue at the rate of scalar ones
 * on the x86 cores we target. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench/bench.h"
#include "bench/timer.h"

static void cpu_name(char *out, size_t size)
{
    snprintf(out, size, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[256];
    while (fgets(line, sizeof line, f))
        if (strncmp(line, "model name", 10) == 0) {
            const char *colon = strchr(line, ':');
            if (colon) {
                snprintf(out, size, "%s", colon + 2);
                out[strcspn(out, "\n")] = '\0';
            }
            break;
        }
    fclose(f);
}

/* A stream loop: the inversesqrt bits11 batch kernel (one rsqrt per vector: the sqrt
 * instruction would be the bottleneck) on the best instruction set over 2 × 64 MiB, twice the
 * last-level cache of the machines we target: bytes read plus written per ns, best of 3 — the
 * machine's figure in the report's header, and the memory side of the roofline where the
 * rows' own stream loop cannot run (no AVX2). */
static double stream_bandwidth(void)
{
    enum { N = 16 << 20 };
    float *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
    const sc_batch_entry *e = sc_batch_find("inversesqrt", "bits11", sc_isa_active());
    if (!x || !y || !e) {
        free(x);
        free(y);
        return 0.0;
    }
    for (size_t i = 0; i < N; i++)
        x[i] = y[i] = (float)i;
    sc_batch_args a = {{x}, {y}, N, NULL};
    double best = 0.0;
    for (int r = 0; r < 3; r++) {
        double t0 = bench_now_ns();
        e->fn(&a);
        double t = bench_now_ns() - t0;
        bench_keep(y[N / 2]);
        if (t > 0 && 2.0 * N * sizeof(float) / t > best)
            best = 2.0 * N * sizeof(float) / t;
    }
    free(x);
    free(y);
    return best;
}

/* 16 independent chains x = x·m + c (a multiply and an add each): ops per ns, best of 3. */
static double scalar_throughput(void)
{
    enum { ITER = 10000000, CHAINS = 16 };
    double best = 0.0;
    for (int r = 0; r < 3; r++) {
        volatile float seed = 1.0f;
        float x[CHAINS];
        for (int k = 0; k < CHAINS; k++)
            x[k] = seed + (float)k;
        double t0 = bench_now_ns();
        for (int i = 0; i < ITER; i++)
            for (int k = 0; k < CHAINS; k++)
                x[k] = x[k] * 0.999999f + 1e-7f;
        double t = bench_now_ns() - t0;
        for (int k = 0; k < CHAINS; k++)
            bench_keep(x[k]);
        if (t > 0 && 2.0 * ITER * CHAINS / t > best)
            best = 2.0 * ITER * CHAINS / t;
    }
    return best;
}

/* The load averages of /proc/loadavg; -1 where unknown */
static void load_average(double load[3])
{
    load[0] = load[1] = load[2] = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (!f)
        return;
    if (fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
        load[0] = load[1] = load[2] = -1.0;
    fclose(f);
}

void bench_machine_measure(bench_machine *m)
{
    time_t now = time(NULL);
    struct tm utc;
    if (now == (time_t)-1 || !gmtime_r(&now, &utc) ||
        strftime(m->date, sizeof m->date, "%Y-%m-%dT%H:%M:%SZ", &utc) == 0)
        snprintf(m->date, sizeof m->date, "unknown");
    load_average(m->load);
    cpu_name(m->cpu, sizeof m->cpu);
    m->bandwidth = stream_bandwidth();
    double avx2 = bench_peak_avx2();
    m->lane_ops_ns = avx2 > 0 ? avx2 : 8.0 * scalar_throughput();
}

/* Float lanes per vector: the compute bound scales the AVX2 peak by width / 8 (AVX-512: 16, its
 * operations taken at the AVX2 rate, as on cores with two 512-bit FMA ports; scalar: the four
 * lanes of src/simd/scalar/vec.h). */
int bench_isa_width(sc_isa isa)
{
    static const int width[SC_ISA_COUNT] = {4, 4, 8, 16};
    return width[isa];
}
