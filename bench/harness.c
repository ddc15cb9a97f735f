/* `shadecalc bench`: every selected kernel × instruction set × tier (× scene for shade) × size
 * on the same inputs — time (median of K repeats after a warm-up, min, max), accuracy against
 * the double reference, speedups against the scalar accurate kernel and the libm loop, the
 * roofline bound. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "bench/timer.h"
#include "shadecalc/accuracy.h"
#include "batch/reference.h"
#include "cli/progress.h"
#include "simd/uniforms.h"

enum { ACCURACY_SAMPLE = 1 << 16, MIN_SAMPLE_NS = 200000, MAX_ROWS = 4096 };

/* The scenes shade is measured with: what a scene names is what it pays for. */
typedef struct {
    const char *name;
    sc_brdf_kind brdf;
    int n_dir, n_point, n_spot;
} bench_scene;
static const bench_scene scenes[] = {
    {"lambert 1d", SC_BRDF_LAMBERT, 1, 0, 0},
    {"blinn-phong 1d", SC_BRDF_BLINN_PHONG, 1, 0, 0},
    {"ggx 1d", SC_BRDF_COOK_TORRANCE, 1, 0, 0},
    {"blinn-phong 1p", SC_BRDF_BLINN_PHONG, 0, 1, 0},
    {"blinn-phong 1s", SC_BRDF_BLINN_PHONG, 0, 0, 1},
    {"blinn-phong 4d", SC_BRDF_BLINN_PHONG, 4, 0, 0},
    {"ggx 4d", SC_BRDF_COOK_TORRANCE, 4, 0, 0},
    {"blinn-phong 1d+3p", SC_BRDF_BLINN_PHONG, 1, 3, 0},
};
enum { N_SCENES = (int)(sizeof scenes / sizeof scenes[0]) };

/* Arithmetic operations per element of shade, counted from its code (src/simd/scene_impl.h,
 * shade_impl.h, spot_impl.h) for the tier measured: every vector instruction of the arithmetic
 * counts one — an FMA, a compare, a select, a min or max, a division, a square root, an
 * estimate — loads, stores, broadcasts of uniforms and the tests of rare lanes' branches not.
 * Recount when the kernels change. The primitives as a tier computes them: */
typedef struct {
    double rsqrt_n; /* 1/√x of the normalizations: accurate √ and ÷ (2); bits12 an estimate
                     * and a Newton step: est, 2 mul, fma, mul (5) */
    double unit; /* a/|a| from a·a: max, then accurate √ and 3 ÷ (5), bits12 rsqrt_n + 3 mul */
    double rcp;  /* 1/x: accurate ÷; bits12 est, mul, sub, mul (4) */
} tier_costs;

static tier_costs shade_tier_costs(const char *tier)
{
    if (strcmp(tier, "accurate") == 0)
        return (tier_costs){2, 5, 1};
    return (tier_costs){5, 9, 4}; /* bits12 */
}

/* Multiplies of x^m by binary powering (pow_int): ⌊log2 m⌋ squarings, popcount(m) − 1
 * products. The bench's lobes have integer m (32: 5). */
static double pow_int_muls(double m)
{
    unsigned u = (unsigned)m, muls = 0;
    for (unsigned b = u; b > 1; b >>= 1)
        muls += 1 + (b & 1u);
    return muls;
}

static double shade_ops(const sc_scene *s, const sc_batch_plan *plan, const char *tier)
{
    tier_costs t = shade_tier_costs(tier);
    const sc_brdf *b = &s->model.brdf;
    /* n, v: two dots (6), the overflow test (max, compare: 2), two units; n·v (3; the fast
     * tiers' of the loaded vectors times both inverse lengths: 5) */
    int fast = strcmp(tier, "accurate") != 0;
    double ops = 11 + 2 * t.unit + (fast ? 2 : 0);
    /* a light's direction and factor, by kind (light_dir): directional none; point p − pos (3),
     * r² (3), 1/r² (accurate max, min and rcp; fast tiers the square of l's 1/|d| and a min:
     * 2), l (overflow compare + unit), the r = 0 lanes (a compare; their selects in a branch
     * taken by rare vectors), w = n·l falloff (1); a spot (the bench's: OpenGL, exponent 2)
     * also −l·axis (4), the cone test (1), the max of lobe_pow, its integer power (accurate in
     * double: 2 halves converted and back, extract, insert, a product each: 8; fast in float: 1
     * product), the cone's select and the product with the falloff (2) */
    double point = 11 + t.unit + (fast ? 0 : t.rcp), spot = point + 8 + (fast ? 1 : 8);
    /* the lobe (own_specular; lobe factor and colours folded into the uniforms): h = l + v (3),
     * h·h (3), max (1); then Blinn-Phong n·h = (n·l + n·v) rsqrt (add, mul, max: 3 + rsqrt_n),
     * in the accurate tier the cutoff (compare, select; the fast tiers' is the max), and the
     * squarings of pow_int, or in the fast tiers for an even integer m (the plan's lobe_m)
     * (n·h)² = (n·l + n·v)²/h·h (add, mul, division, max: 4) and the squarings of pow_int
     * to m/2; GGX without the max: d |h|² (add, mul, fma), g_v and g_l (each mul, fma, √, mul),
     * |h|⁴/((d |h|²)² (g_v + g_l)) (mul, mul, add, mul, division), (v·h)²:
     * accurate from v·l (3: fma, max), then b = 1 − √(v·h)² (√, sub); fast b = 1 − √(|h|²)/2
     * (√, fma), b⁵ and F (mul, mul, mul, fma), D V F (mul); then the lit select of f_s and,
     * Blinn-Phong, f = f_s E ⊙ c_spec + E ⊙ c_diff/π (3 FMA: 4), GGX, w f_s and acc += w f_s E ⊙
     * c_spec (product, 3 FMA: 5) */
    double lobe = 0;
    unsigned lobe_m = sc_batch_plan_uniforms(plan)->lobe_m;
    if (b->kind == SC_BRDF_BLINN_PHONG && fast && lobe_m % 2 == 0 && lobe_m)
        lobe = 7 + 4 + pow_int_muls(lobe_m / 2) + 4;
    else if (b->kind == SC_BRDF_BLINN_PHONG)
        lobe = 7 + 3 + t.rsqrt_n + (fast ? 0 : 2) + pow_int_muls(b->m) + 4;
    else if (b->kind == SC_BRDF_COOK_TORRANCE)
        lobe = 6 + 3 + 2 * 4 + 5 + (fast ? 0 : 3 + 2) + 2 + 4 + 1 + 5;
    /* each light: n·l (3), the lit mask (min, compare), the weight select (1), acc += w E
     * c_diff/π (Blinn-Phong: w f; 3 FMA), its colours made once per call (shade_vecs_make), in
     * the generic loop too; a directional light in the fast tiers takes n·l of the loaded
     * vectors, times the inverse length (1 mul) */
    for (int k = 0; k < s->n_lights; k++) {
        sc_light_kind kind = s->lights[k].kind;
        ops += 9 + lobe;
        if (fast && kind == SC_LIGHT_DIRECTIONAL)
            ops += 1;
        ops += kind == SC_LIGHT_POINT ? point : kind == SC_LIGHT_SPOT ? spot : 0;
    }
    return ops;
}

/* Input arrays a kernel reads for a scene: shade reads p only for point lights. */
static int inputs_read(const sc_batch_entry *e, const sc_scene *s)
{
    if (!s)
        return e->n_in;
    for (int k = 0; k < s->n_lights; k++)
        if (s->lights[k].kind != SC_LIGHT_DIRECTIONAL)
            return 9;
    return 6;
}

/* ---- data of one kernel × scene × size: inputs, reference, output buffers ---- */

typedef struct {
    float *in[9], *out[3];
    size_t n;
} bench_arrays;

/* Times are taken on `timed`: inputs uniform in value over the domain, the ordinary inputs of
 * a user (the test distribution's log-uniform magnitudes would time microcode assists on
 * subnormal intermediates in every row). Accuracy is measured on `checked`: the test
 * distribution (sc_batch_sample), ACCURACY_SAMPLE elements at most. */
typedef struct {
    bench_arrays timed, checked;
    double *ref; /* (n_out + 1) per element of `checked` */
    size_t n;
    sc_light lights[SC_BATCH_MAX_LIGHTS];
    sc_scene scene;
    sc_batch_plan *plan; /* shade: the scene's plan (the shade rows' params) */
    const void *params;  /* the kernel's parameters: its batch table's, or the plan */
} bench_data;

static void arrays_free(bench_arrays *b)
{
    for (int j = 0; j < 9; j++)
        free(b->in[j]);
    for (int j = 0; j < 3; j++)
        free(b->out[j]);
}

static void data_free(bench_data *d)
{
    arrays_free(&d->timed);
    arrays_free(&d->checked);
    free(d->ref);
    sc_batch_plan_free(d->plan);
}

static sc_batch_args arrays_args(const bench_data *d, const bench_arrays *b)
{
    sc_batch_args a = {{0}, {0}, b->n, d->params};
    for (int j = 0; j < 9; j++)
        a.in[j] = b->in[j];
    for (int j = 0; j < 3; j++)
        a.out[j] = b->out[j];
    return a;
}

static sc_batch_args data_args(bench_data *d) { return arrays_args(d, &d->timed); }

/* A value uniform in [lo, hi] */
static float uniform_in(uint64_t *rng, double lo, double hi)
{
    double u = (double)(sc_accuracy_random(rng) >> 11) * 0x1p-53;
    return (float)fmin(lo + (hi - lo) * u, hi);
}

/* n elements of e's inputs: the test distribution, or (uniform) uniform in value over e's
 * range where e has no generator of its own */
static int arrays_make(bench_arrays *b, const sc_batch_entry *e, size_t n, int uniform)
{
    b->n = n;
    for (int j = 0; j < e->n_in; j++)
        if (!(b->in[j] = malloc(n * sizeof(float))))
            return -1;
    for (int j = 0; j < e->n_out; j++)
        if (!(b->out[j] = calloc(n, sizeof(float))))
            return -1;
    uint64_t rng = 0x9E3779B97F4A7C15ULL;
    for (size_t i = 0; i < n; i++) {
        float v[9];
        if (uniform && !e->gen)
            for (int j = 0; j < e->n_in; j++)
                v[j] = uniform_in(&rng, e->lo[j], e->hi[j]);
        else
            sc_batch_sample(e, &rng, v);
        for (int j = 0; j < e->n_in; j++)
            b->in[j][i] = v[j];
    }
    return 0;
}

/* Inputs from the domain of `domain_of` (the kernel's narrowest tier: valid for all tiers). */
static int data_make(bench_data *d, const sc_batch_entry *domain_of, size_t n,
                     const bench_scene *bs)
{
    memset(d, 0, sizeof *d);
    d->n = n;
    d->params = domain_of->params;
    if (bs) {
        char why[256];
        sc_batch_example_scene(bs->brdf, bs->n_dir, bs->n_point, bs->n_spot, d->lights, &d->scene);
        if (!(d->plan = sc_batch_plan_compile(&d->scene, domain_of->tier, SC_ISA_SCALAR, why,
                                              sizeof why)))
            return -1;
        d->params = d->plan;
    }
    size_t checked = n < ACCURACY_SAMPLE ? n : ACCURACY_SAMPLE;
    if (arrays_make(&d->timed, domain_of, n, 1) != 0 ||
        arrays_make(&d->checked, domain_of, checked, 0) != 0 ||
        !(d->ref = malloc(checked * 4 * sizeof(double))))
        return -1;
    sc_batch_args a = arrays_args(d, &d->checked);
    for (size_t i = 0; i < checked; i++)
        domain_of->ref(&a, i, d->ref + 4 * i);
    return 0;
}

/* ---- timing ---- */

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of the sorted v[0..n) */
static double median_sorted(const double *v, int n)
{
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Median, min, max, MAD and robust CV of n samples (sorted in place). */
static void dispersion(double *samples, int n, bench_row *r)
{
    double dev[64];
    qsort(samples, (size_t)n, sizeof samples[0], compare_doubles);
    r->ns_per_elem = median_sorted(samples, n);
    r->ns_min = samples[0];
    r->ns_max = samples[n - 1];
    for (int k = 0; k < n; k++)
        dev[k] = fabs(samples[k] - r->ns_per_elem);
    qsort(dev, (size_t)n, sizeof dev[0], compare_doubles);
    r->ns_mad = median_sorted(dev, n);
    r->cv = r->ns_per_elem > 0 ? 1.4826 * r->ns_mad / r->ns_per_elem : 0.0;
    r->noisy = r->cv > BENCH_NOISY_CV || r->ns_max > 2.0 * r->ns_per_elem;
}

/* ns per element of `repeat` samples, each of enough calls to last 0.2 ms, after `warmup`
 * untimed calls (the last of which calibrates the calls per sample) */
static void time_fn(sc_batch_fn fn, const sc_batch_args *a, const bench_options *o, bench_row *r)
{
    double once = 0;
    for (int w = 0; w < (o->warmup > 1 ? o->warmup : 1); w++) {
        double t0 = bench_now_ns();
        fn(a);
        once = bench_now_ns() - t0;
    }
    int calls = once > 0 && once < MIN_SAMPLE_NS ? (int)(MIN_SAMPLE_NS / once) + 1 : 1;
    double samples[64];
    int repeat = o->repeat > 64 ? 64 : o->repeat;
    for (int k = 0; k < repeat; k++) {
        double t0 = bench_now_ns();
        for (int c = 0; c < calls; c++)
            fn(a);
        samples[k] = (bench_now_ns() - t0) / ((double)calls * (double)a->n);
    }
    dispersion(samples, repeat, r);
}

/* Whether got is the reference rounded to float; only normal results count (NaN for NaN). */
static int rounded_ok(float got, double ref)
{
    float want = (float)ref;
    if (isnan(ref) || !(fabsf(want) >= FLT_MIN))
        return 1;
    return got == want;
}

/* The accuracy of fn (a row of kernel e, or a peer of it) on the checked inputs */
static void accuracy(sc_batch_fn fn, const sc_batch_entry *e, bench_data *d, bench_row *r)
{
    sc_batch_args a = arrays_args(d, &d->checked);
    fn(&a);
    sc_batch_error_init(&r->err);
    r->not_rounded = 0;
    for (size_t i = 0; i < a.n; i++) {
        const double *ref = d->ref + 4 * i;
        sc_batch_error_against(e, &a, i, ref, &r->err);
        for (int j = 0; j < e->n_out; j++)
            r->not_rounded += !rounded_ok(a.out[j][i], ref[j]);
    }
}

/* ---- selection ---- */

static int contains(const char *name, const char *const *list, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(list[i], name) == 0)
            return 1;
    return 0;
}

/* An empty selection selects everything. */
int bench_selected(const char *name, const char *const *list, int n)
{
    return n == 0 || contains(name, list, n);
}

static int entry_selected(const bench_options *o, const sc_batch_entry *e)
{
    return sc_isa_supported(e->isa) && (o->isa_mask == 0 || (o->isa_mask >> e->isa & 1)) &&
           bench_selected(e->tier, o->tiers, o->n_tiers);
}

/* The kernel's last table entry for the scalar ISA: its narrowest domain; and its first: the
 * accurate tier, the baseline of the speedups. */
static const sc_batch_entry *kernel_entry(const char *kernel, int last)
{
    const sc_batch_entry *found = NULL;
    for (int i = 0; i < sc_batch_count; i++)
        if (sc_batch_table[i].isa == SC_ISA_SCALAR &&
            strcmp(sc_batch_table[i].kernel, kernel) == 0) {
            found = &sc_batch_table[i];
            if (!last)
                break;
        }
    return found;
}

/* Whether entry e is measured among the rows of `kernel`: the kernel's accurate scalar entry
 * always (the baseline of the speedups), the others if the options select them. */
static int measured(const bench_options *o, const sc_batch_entry *e, const char *kernel)
{
    return strcmp(e->kernel, kernel) == 0 && (e == kernel_entry(kernel, 0) || entry_selected(o, e));
}

/* SLEEF's loops for a kernel when the binary has them (the count; *loops the first). */
static int sleef_loops_for(const char *kernel, const bench_sleef **loops)
{
    return bench_sleef_available() ? bench_sleef_loops(kernel, loops) : 0;
}

/* ---- one kernel × scene × size ---- */

/* The arrays of the stream loop (bench_stream_pass_avx2): `count` of them, as many as the
 * rows have needed so far, n floats each. */
enum { PROBE_ARRAYS = 12 }; /* shade and brdf: 9 inputs, 3 outputs */
typedef struct {
    float *arrays[PROBE_ARRAYS];
    int count;
    size_t n;
} stream_probe;

typedef struct {
    const bench_options *o;
    const bench_machine *m;
    bench_row *rows;
    int n_rows, done, total;
    sc_progress bar;
    stream_probe probe; /* allocated when a streaming row first needs it */
} bench_state;

static void progress(bench_state *st, const char *what)
{
    st->done++;
    sc_progress_update(&st->bar, st->total ? (double)st->done / st->total : 1.0, what);
}

static bench_row *add_row(bench_state *st, const char *kernel, const char *isa, const char *tier,
                          const char *scene, size_t n)
{
    if (st->n_rows >= MAX_ROWS)
        return NULL;
    bench_row *r = &st->rows[st->n_rows++];
    memset(r, 0, sizeof *r);
    r->kernel = kernel;
    r->isa = isa;
    r->tier = tier;
    r->scene = scene;
    r->n = n;
    return r;
}

static void probe_release(stream_probe *p)
{
    for (int j = 0; j < PROBE_ARRAYS; j++)
        free(p->arrays[j]);
    memset(p, 0, sizeof *p);
}

/* At least `count` arrays of n elements in the probe (whole vectors of 8, aligned_alloc's size
 * a multiple of its alignment), each written once so that the passes take no page faults: 0,
 * or -1 without the memory. */
static int probe_arrays(stream_probe *p, int count, size_t n)
{
    n -= n % 8;
    if (p->n != n)
        probe_release(p);
    p->n = n;
    for (; p->count < count; p->count++) {
        if (!(p->arrays[p->count] = aligned_alloc(32, n * sizeof(float)))) {
            probe_release(p);
            return -1;
        }
        for (size_t i = 0; i < n; i++)
            p->arrays[p->count][i] = 1.0f;
    }
    return 0;
}

/* The bandwidth a kernel reading k arrays and writing m can reach at n elements, in bytes per
 * ns: a stream loop over as many arrays of that size, best of 3 passes, taken after the row's
 * timing, as the machine's memory is shared (on this project's VM the same loop read 39 GB/s
 * and 27 a few minutes apart). With more arrays the loop moves fewer bytes per ns (one Zen 5
 * core: 48 GB/s over one input and one output, 39 over six and three, 33 over nine and
 * three), so the two-array figure of the machine is no bound a kernel of nine arrays can
 * reach; it stands in where there is no AVX2 or no memory for the arrays. */
static double row_bandwidth(bench_state *st, int k, int m, size_t n)
{
    double best = 0.0;
    if (bench_stream_avx2_supported() && n >= 8 && k + m <= PROBE_ARRAYS &&
        probe_arrays(&st->probe, k + m, n) == 0)
        for (int r = 0; r < 3; r++) {
            double t = bench_stream_pass_avx2(st->probe.arrays, k, m, st->probe.n);
            double bandwidth = t > 0 ? (double)(k + m) * st->probe.n * sizeof(float) / t : 0.0;
            best = bandwidth > best ? bandwidth : best;
        }
    return best > 0 ? best : st->m->bandwidth;
}

static void roofline(bench_state *st, const sc_batch_entry *e, const bench_data *d, int width,
                     bench_row *r)
{
    const sc_scene *s = d->plan ? &d->scene : NULL;
    double ops = s ? shade_ops(s, d->plan, e->tier) : e->ops;
    double compute = ops / (st->m->lane_ops_ns * width / 8.0);
    int k = inputs_read(e, s);
    double bytes = 4.0 * (k + e->n_out);
    int streaming = bytes * (double)d->n > 8.0 * (1 << 20);
    double bandwidth = streaming ? row_bandwidth(st, k, e->n_out, d->n) : 0.0;
    double memory = bandwidth > 0 ? bytes / bandwidth : 0.0;
    r->roofline_ns = memory > compute ? memory : compute;
    r->roofline_fraction = r->roofline_ns / r->ns_per_elem;
}

static void measure_entry(bench_state *st, const sc_batch_entry *e, bench_data *d,
                          const char *scene_name)
{
    bench_row *r = add_row(st, e->kernel, sc_isa_name(e->isa), e->tier, scene_name, d->n);
    if (!r)
        return;
    sc_batch_args a = data_args(d);
    time_fn(e->fn, &a, st->o, r);
    accuracy(e->fn, e, d, r);
    r->entry = e;
    roofline(st, e, d, bench_isa_width(e->isa), r);
    char what[96];
    snprintf(what, sizeof what, "%s %s %s %s", e->kernel, sc_isa_name(e->isa), e->tier, scene_name);
    progress(st, what);
}

/* A plain loop a user would write instead (isa "libm", "gcc-fast", "clang-fast"; tier "loop"),
 * built for instruction set `built` */
static void measure_loop(bench_state *st, const sc_batch_entry *accurate, bench_data *d,
                         const char *scene_name, const char *isa, sc_isa built, sc_batch_fn loop)
{
    bench_row *r = loop && sc_isa_supported(built)
                       ? add_row(st, accurate->kernel, isa, "loop", scene_name, d->n)
                       : NULL;
    if (!r)
        return;
    r->peer_isa = built;
    sc_batch_args a = data_args(d);
    time_fn(loop, &a, st->o, r);
    accuracy(loop, accurate, d, r);
    r->roofline_ns = r->roofline_fraction = NAN; /* its operation count is the compiler's */
    progress(st, isa);
}

/* The plain loops of a kernel: -O2 (the libm baseline), then -O3 -ffast-math by gcc and by clang
 * when the build had them, with -march=native (the best instruction set of this CPU: NATIVE)
 * and with -mavx2 -mfma. */
enum { NATIVE = -1 };
static const struct {
    const char *isa;
    int built; /* sc_isa, or NATIVE */
    sc_batch_fn (*lookup)(const char *kernel);
} plain_loops[] = {{"libm", SC_ISA_SCALAR, bench_libm_loop},
                   {"gcc-fast", NATIVE, bench_fast_gcc_loop},
                   {"clang-fast", NATIVE, bench_fast_clang_loop},
                   {"gcc-fast-avx2", SC_ISA_AVX2, bench_fast_gcc_avx2_loop},
                   {"clang-fast-avx2", SC_ISA_AVX2, bench_fast_clang_avx2_loop}};
enum { N_PLAIN = (int)(sizeof plain_loops / sizeof plain_loops[0]) };

/* The best instruction set of this CPU: what -march=native builds for */
static sc_isa best_isa(void)
{
    int i = SC_ISA_COUNT - 1;
    while (i > 0 && !sc_isa_supported((sc_isa)i))
        i--;
    return (sc_isa)i;
}

static int plain_loop_count(const char *kernel)
{
    int n = 0;
    for (int i = 0; i < N_PLAIN; i++)
        n += plain_loops[i].lookup(kernel) != NULL &&
             (plain_loops[i].built == NATIVE || sc_isa_supported((sc_isa)plain_loops[i].built));
    return n;
}

/* SLEEF's AVX2 functions for the kernel, when the binary has them: comparison rows. */
static void measure_sleef(bench_state *st, const sc_batch_entry *accurate, bench_data *d)
{
    const bench_sleef *loops;
    int n = sleef_loops_for(accurate->kernel, &loops);
    for (int i = 0; i < n; i++) {
        bench_row *r = add_row(st, accurate->kernel, "sleef-avx2", loops[i].tier, "", d->n);
        if (!r)
            return;
        r->peer_isa = SC_ISA_AVX2;
        sc_batch_args a = data_args(d);
        time_fn(loops[i].fn, &a, st->o, r);
        accuracy(loops[i].fn, accurate, d, r);
        r->roofline_ns = r->roofline_fraction = NAN; /* its operation count is SLEEF's */
        progress(st, "sleef");
    }
}

/* Speedups of the rows [first, end) against their scalar accurate and libm rows. */
static void speedups(bench_row *rows, int first, int end, const char *accurate_tier)
{
    double scalar = 0, libm = 0;
    for (int i = first; i < end; i++) {
        if (strcmp(rows[i].isa, "scalar") == 0 && strcmp(rows[i].tier, accurate_tier) == 0)
            scalar = rows[i].ns_per_elem;
        if (strcmp(rows[i].isa, "libm") == 0)
            libm = rows[i].ns_per_elem;
    }
    for (int i = first; i < end; i++) {
        rows[i].speedup_vs_scalar = scalar > 0 ? scalar / rows[i].ns_per_elem : 0;
        rows[i].speedup_vs_libm = libm > 0 ? libm / rows[i].ns_per_elem : 0;
    }
}

/* a's median is below b's by more than 3 × their combined MAD (the test of --compare) */
static int significantly_faster(const bench_row *a, const bench_row *b)
{
    double spread = sqrt(a->ns_mad * a->ns_mad + b->ns_mad * b->ns_mad);
    return a->ns_per_elem < b->ns_per_elem - 3.0 * spread;
}

/* a dominates b (Pareto): no less accurate (max ULP) and not slower — not significantly, and
 * its fastest repeat no slower than b's median — and better in one of the two: more accurate,
 * or significantly faster. Two rows that compute the same to the same error in times within
 * their noise (a memory-bound loop and its plain C twin) dominate neither way, where comparing
 * bare medians flagged one or the other by chance; and a noisy row does not dominate by its
 * noise alone (a libm loop at 4.5 ns with a MAD of 1.0 was "not significantly slower" than a
 * 1.6 ns tier). */
static int dominates(const bench_row *a, const bench_row *b)
{
    if (!(a->err.max_ulp <= b->err.max_ulp) || significantly_faster(b, a) ||
        a->ns_min > b->ns_per_elem)
        return 0;
    return a->err.max_ulp < b->err.max_ulp || significantly_faster(a, b);
}

/* Pareto set of rows [first, end), peers included: the rows no other row dominates; and for
 * each tier, the first peer row that dominates it among those built for the tier's instruction
 * set or an older one: a loop built with AVX-512 beats an AVX2 tier only on the CPUs where the
 * AVX-512 tier runs instead. */
static void pareto(bench_row *rows, int first, int end)
{
    for (int i = first; i < end; i++) {
        bench_row *b = &rows[i];
        b->pareto = 1;
        b->dominated_by = NULL;
        for (int j = first; j < end; j++) {
            const bench_row *a = &rows[j];
            if (j == i || !dominates(a, b))
                continue;
            b->pareto = 0;
            if (b->entry && !a->entry && a->peer_isa <= b->entry->isa && !b->dominated_by)
                b->dominated_by = a;
        }
    }
}

static int measure_group(bench_state *st, const char *kernel, const bench_scene *bs, size_t n)
{
    const sc_batch_entry *narrow = kernel_entry(kernel, 1), *accurate = kernel_entry(kernel, 0);
    bench_data d;
    if (data_make(&d, narrow, n, bs) != 0) {
        data_free(&d);
        return -1;
    }
    const char *scene_name = bs ? bs->name : "";
    int first = st->n_rows;
    for (int i = 0; i < sc_batch_count; i++)
        if (measured(st->o, &sc_batch_table[i], kernel))
            measure_entry(st, &sc_batch_table[i], &d, scene_name);
    for (int i = 0; i < N_PLAIN; i++)
        measure_loop(st, accurate, &d, scene_name, plain_loops[i].isa,
                     plain_loops[i].built == NATIVE ? best_isa() : (sc_isa)plain_loops[i].built,
                     plain_loops[i].lookup(accurate->kernel));
    measure_sleef(st, accurate, &d);
    speedups(st->rows, first, st->n_rows, accurate->tier);
    pareto(st->rows, first, st->n_rows);
    data_free(&d);
    return 0;
}

/* ---- the whole run ---- */

/* Kernels in table order, each once, filtered by the options. */
static int kernel_list(const bench_options *o, const char **out)
{
    int n = 0;
    for (int i = 0; i < sc_batch_count; i++) {
        const char *k = sc_batch_table[i].kernel;
        if (sc_batch_table[i].isa == SC_ISA_SCALAR && bench_selected(k, o->kernels, o->n_kernels) &&
            !contains(k, out, n))
            out[n++] = k;
    }
    return n;
}

static int count_rows(const bench_options *o, const char *const *kernels, int n_kernels)
{
    int total = 0;
    for (int k = 0; k < n_kernels; k++) {
        const bench_sleef *sleef;
        int per = plain_loop_count(kernels[k]) + sleef_loops_for(kernels[k], &sleef);
        for (int i = 0; i < sc_batch_count; i++)
            per += measured(o, &sc_batch_table[i], kernels[k]);
        total += per * (strcmp(kernels[k], "shade") == 0 ? N_SCENES : 1);
    }
    return total * o->n_sizes;
}

int bench_run(const bench_options *o, const bench_machine *m, bench_row **rows, int *n_rows)
{
    const char *kernels[64];
    int n_kernels = kernel_list(o, kernels);
    bench_state st = {.o = o, .m = m, .rows = calloc(MAX_ROWS, sizeof(bench_row))};
    if (!st.rows)
        return -1;
    sc_progress_start(&st.bar, "bench", 0.0);
    st.total = count_rows(o, kernels, n_kernels);
    for (int s = 0; s < o->n_sizes; s++)
        for (int k = 0; k < n_kernels; k++) {
            int shade = strcmp(kernels[k], "shade") == 0;
            for (int c = 0; c < (shade ? N_SCENES : 1); c++)
                if (measure_group(&st, kernels[k], shade ? &scenes[c] : NULL, o->sizes[s]) != 0) {
                    sc_progress_clear(&st.bar);
                    probe_release(&st.probe);
                    free(st.rows);
                    return -1;
                }
        }
    sc_progress_clear(&st.bar);
    probe_release(&st.probe);
    *rows = st.rows;
    *n_rows = st.n_rows;
    return 0;
}
