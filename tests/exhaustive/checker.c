/* The correct-rounding checker (checker.h): the sound fast decision, MPFR for the rest, the
 * threads over the inputs and the list of misses. */
#include "checker.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum { CHUNK = 4096 };

static uint32_t bits_of(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static float float_of(uint32_t u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

int exh_same(float a, float b) { return (isnan(a) && isnan(b)) || bits_of(a) == bits_of(b); }

/* The half-width of the interval the decision rounds: the bound and the two ends are computed
 * in binary64; 2^-20 of the bound covers the roundings inside the bound's formula,
 * |approx|·2^-52 those of approx ± slack. */
static double slack_of(double approx, double bound)
{
    return bound * (1.0 + 0x1p-20) + fabs(approx) * 0x1p-52;
}

int exh_rounds_to_one(double approx, double bound, float *out)
{
    if (isinf(approx) || approx == 0.0) {
        /* exact (a special value), or beyond binary64's range and so beyond binary32's */
        *out = (float)approx;
        return 1;
    }
    if (!isfinite(approx) || !(bound < INFINITY))
        return 0;
    double slack = slack_of(approx, bound);
    float lo = (float)(approx - slack), hi = (float)(approx + slack);
    if (bits_of(lo) != bits_of(hi))
        return 0;
    *out = lo;
    return 1;
}

float exh_mpfr_round(const exh_subject *s, float x, float y, mpfr_prec_t prec, mpfr_exp_t emin,
                     mpfr_exp_t emax)
{
    mpfr_exp_t old_min = mpfr_get_emin(), old_max = mpfr_get_emax();
    mpfr_t mx, my, r;
    mpfr_inits2(24, mx, my, (mpfr_ptr)0);
    mpfr_init2(r, prec);
    mpfr_set_flt(mx, x, MPFR_RNDN);
    mpfr_set_flt(my, y, MPFR_RNDN);
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
    int t = s->arity == 1 ? s->mpfr1(r, mx, MPFR_RNDN) : s->mpfr2(r, mx, my, MPFR_RNDN);
    t = mpfr_check_range(r, t, MPFR_RNDN);
    mpfr_subnormalize(r, t, MPFR_RNDN);
    float out = mpfr_get_flt(r, MPFR_RNDN);
    mpfr_set_emin(old_min);
    mpfr_set_emax(old_max);
    mpfr_clears(mx, my, r, (mpfr_ptr)0);
    return out;
}

float exh_mpfr_round32(const exh_subject *s, float x, float y, double *exact)
{
    mpfr_t mx, my, r;
    mpfr_inits2(24, mx, my, (mpfr_ptr)0);
    mpfr_init2(r, 128);
    mpfr_set_flt(mx, x, MPFR_RNDN);
    mpfr_set_flt(my, y, MPFR_RNDN);
    if (s->arity == 1)
        s->mpfr1(r, mx, MPFR_RNDN);
    else
        s->mpfr2(r, mx, my, MPFR_RNDN);
    *exact = mpfr_get_d(r, MPFR_RNDN);
    mpfr_clears(mx, my, r, (mpfr_ptr)0);
    /* binary32 in MPFR's terms (significands in [1/2, 1)): 2^-149 = 2^-148/2, FLT_MAX < 2^128 */
    return exh_mpfr_round(s, x, y, 24, -148, 128);
}

/* ULP of binary32 at v (finite): 2^(exponent of v − 23), at least 2^-149. */
static double ulp32(double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    uint64_t e = (u >> 52) & 0x7ff; /* biased exponent of v */
    if (e < 1023 - 126)
        e = 1023 - 126;
    u = (e - 23) << 52;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* |got − exact| in binary32 ULPs at exact; 0 for the same infinity, +Inf for other mismatches
 * of infinities, NaN. */
static double ulp_error(float got, double exact)
{
    if (isnan(got) || isnan(exact) || isinf(got) || isinf(exact) || fabs(exact) > FLT_MAX)
        return exh_same(got, (float)exact) ? 0.0 : INFINITY;
    return fabs((double)got - exact) / ulp32(exact);
}

void exh_stats_init(exh_stats *s) { memset(s, 0, sizeof *s); }

void exh_stats_free(exh_stats *s)
{
    free(s->misses);
    exh_stats_init(s);
}

static int add_miss(exh_stats *st, exh_miss m)
{
    if (st->n_misses == st->cap_misses) {
        size_t cap = st->cap_misses ? 2 * st->cap_misses : 64;
        exh_miss *p = realloc(st->misses, cap * sizeof *p);
        if (!p)
            return -1;
        st->misses = p;
        st->cap_misses = cap;
    }
    st->misses[st->n_misses++] = m;
    return 0;
}

static void note_error(exh_stats *st, float x, float y, double err)
{
    if (err > st->max_ulp) {
        st->max_ulp = err;
        st->worst_x = x;
        st->worst_y = y;
    }
}

/* The audit: the exact value (binary64 of MPFR's) lies in the interval the decision rounds,
 * or both it and the approximation lie beyond binary32's range on the same side (the clamps of
 * src/math/exp.c), or both are NaN. */
static int within_bound(double a, double b, double exact)
{
    if (isnan(a) || isnan(exact))
        return isnan(a) && isnan(exact);
    int same_side = signbit(a) == signbit(exact);
    if (same_side && fabs(a) >= 0x1p128 && fabs(exact) >= 0x1p128)
        return 1;
    if (same_side && fabs(a) < 0x1p-151 && fabs(exact) < 0x1p-151)
        return 1;
    return a == exact || fabs(a - exact) <= slack_of(a, b);
}

/* Checks one result; returns -1 only when out of memory. */
static int check_one(const exh_subject *s, int audit, float x, float y, float got, exh_stats *st)
{
    double a = s->arity == 1 ? s->approx1(x) : s->approx2(x, y);
    double b = s->bound(x, y, a);
    float want;
    double exact = a;
    int decided = isnan(a) ? (want = NAN, 1) : exh_rounds_to_one(a, b, &want);
    st->inputs++;
    if (s->approx_is_core && !exh_same(got, (float)a)) {
        st->not_core++;
        if (add_miss(st, (exh_miss){x, y, got, (float)a, 0.0, EXH_NOT_CORE}))
            return -1;
    }
    if (decided)
        st->decided++;
    if (!decided || audit) {
        float cr = exh_mpfr_round32(s, x, y, &exact);
        st->settled += !decided;
        if (!within_bound(a, b, exact) || (decided && !exh_same(cr, want))) {
            st->bound_broken++;
            if (add_miss(st, (exh_miss){x, y, got, cr, ulp_error(got, exact), EXH_BOUND_BROKEN}))
                return -1;
        }
        want = cr;
    }
    if (exh_same(got, want))
        return 0; /* correctly rounded: an error of at most 0.5 ULP */
    st->wrong++;
    if (decided && !audit) /* the exact value, for the size of the error */
        exh_mpfr_round32(s, x, y, &exact);
    double err = ulp_error(got, exact);
    if (err < INFINITY)
        note_error(st, x, y, err);
    return add_miss(st, (exh_miss){x, y, got, want, err, EXH_WRONG});
}

/* Evaluates the subject on n inputs. */
static void evaluate(const exh_subject *s, const float *x, const float *y, float *out, size_t n)
{
    if (s->entry) {
        sc_batch_args a = {{0}, {out}, n, s->entry->params};
        /* a subject's (x, y) are its first and second arguments: atan2's (y, x) */
        a.in[0] = x;
        a.in[1] = y;
        s->entry->fn(&a);
    } else if (s->arity == 1) {
        for (size_t i = 0; i < n; i++)
            out[i] = s->f1(x[i]);
    } else {
        for (size_t i = 0; i < n; i++)
            out[i] = s->f2(x[i], y[i]);
    }
}

typedef struct {
    const exh_subject *s;
    const exh_run_spec *spec;
    pthread_mutex_t lock;
    uint64_t next_chunk, n_chunks;
    exh_stats total;
    int failed;
} run_state;

/* splitmix64: the seed of chunk k's generator */
static uint64_t chunk_seed(uint64_t k)
{
    uint64_t z = (k + 1) * 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static size_t fill_chunk(const exh_run_spec *spec, uint64_t k, float *x, float *y)
{
    uint64_t start = k * CHUNK, n = spec->count - start < CHUNK ? spec->count - start : CHUNK;
    if (spec->gen) {
        uint64_t rng = chunk_seed(k);
        for (uint64_t i = 0; i < n; i++)
            spec->gen(&rng, &x[i], &y[i]);
    } else {
        for (uint64_t i = 0; i < n; i++) {
            x[i] = float_of((uint32_t)(spec->first + (start + i) * spec->stride));
            y[i] = 0.0f;
        }
    }
    return (size_t)n;
}

static int merge(exh_stats *into, const exh_stats *from)
{
    into->inputs += from->inputs;
    into->decided += from->decided;
    into->settled += from->settled;
    into->wrong += from->wrong;
    into->not_core += from->not_core;
    into->bound_broken += from->bound_broken;
    if (from->max_ulp > into->max_ulp) {
        into->max_ulp = from->max_ulp;
        into->worst_x = from->worst_x;
        into->worst_y = from->worst_y;
    }
    for (size_t i = 0; i < from->n_misses; i++)
        if (add_miss(into, from->misses[i]))
            return -1;
    return 0;
}

static void *worker(void *arg)
{
    run_state *rs = arg;
    exh_stats local;
    exh_stats_init(&local);
    float x[CHUNK], y[CHUNK], out[CHUNK];
    int failed = 0;
    for (;;) {
        pthread_mutex_lock(&rs->lock);
        uint64_t k = rs->next_chunk++;
        pthread_mutex_unlock(&rs->lock);
        if (k >= rs->n_chunks || failed)
            break;
        size_t n = fill_chunk(rs->spec, k, x, y);
        evaluate(rs->s, x, y, out, n);
        for (size_t i = 0; i < n && !failed; i++)
            failed = check_one(rs->s, rs->spec->audit, x[i], y[i], out[i], &local) != 0;
    }
    pthread_mutex_lock(&rs->lock);
    if (failed || merge(&rs->total, &local))
        rs->failed = 1;
    pthread_mutex_unlock(&rs->lock);
    exh_stats_free(&local);
    mpfr_free_cache();
    return NULL;
}

static int by_input(const void *pa, const void *pb)
{
    const exh_miss *a = pa, *b = pb;
    uint64_t ka = (uint64_t)bits_of(a->x) << 32 | bits_of(a->y);
    uint64_t kb = (uint64_t)bits_of(b->x) << 32 | bits_of(b->y);
    if (ka != kb)
        return ka < kb ? -1 : 1;
    return (int)a->kind - (int)b->kind;
}

int exh_run(const exh_subject *s, const exh_run_spec *spec, exh_stats *out)
{
    run_state rs = {.s = s, .spec = spec, .n_chunks = (spec->count + CHUNK - 1) / CHUNK};
    exh_stats_init(&rs.total);
    pthread_mutex_init(&rs.lock, NULL);
    int n = spec->threads > 0 ? spec->threads : 1;
    pthread_t *t = calloc((size_t)n, sizeof *t);
    int started = 0;
    if (!t)
        rs.failed = 1;
    for (; t && started < n; started++)
        if (pthread_create(&t[started], NULL, worker, &rs) != 0)
            break;
    if (started == 0 && t)
        worker(&rs);
    for (int i = 0; i < started; i++)
        pthread_join(t[i], NULL);
    free(t);
    pthread_mutex_destroy(&rs.lock);
    if (rs.total.n_misses)
        qsort(rs.total.misses, rs.total.n_misses, sizeof *rs.total.misses, by_input);
    *out = rs.total;
    return rs.failed ? -1 : 0;
}

static const char *const kind_names[] = {"wrong", "not-core", "bound-broken"};

static int write_miss(FILE *f, const exh_subject *s, const exh_miss *m)
{
    if (s->arity == 1)
        return fprintf(f, "0x%08x %.9g got %.9g want %.9g ulp %.6f %s\n", (unsigned)bits_of(m->x),
                       (double)m->x, (double)m->got, (double)m->want, m->ulp, kind_names[m->kind]);
    return fprintf(f, "0x%08x 0x%08x %.9g %.9g got %.9g want %.9g ulp %.6f %s\n",
                   (unsigned)bits_of(m->x), (unsigned)bits_of(m->y), (double)m->x, (double)m->y,
                   (double)m->got, (double)m->want, m->ulp, kind_names[m->kind]);
}

int exh_write_misses(const char *path, const exh_subject *s, const exh_stats *st)
{
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp", path) >= (int)sizeof tmp) {
        errno = ENAMETOOLONG;
        return -1;
    }
    FILE *f = fopen(tmp, "w");
    if (!f)
        return -1;
    int bad = fprintf(f,
                      "# %s: %llu inputs, %llu not correctly rounded (input, result, correct "
                      "result, error in ULPs)\n",
                      s->name, (unsigned long long)st->inputs, (unsigned long long)st->wrong) < 0;
    for (size_t i = 0; i < st->n_misses && !bad; i++)
        bad = write_miss(f, s, &st->misses[i]) < 0;
    int saved = errno;
    if (fclose(f) != 0 || bad) {
        saved = bad ? saved : errno;
        remove(tmp);
        errno = saved;
        return -1;
    }
    return rename(tmp, path);
}

void exh_print_summary(FILE *f, const exh_subject *s, const exh_stats *st, double seconds)
{
    fprintf(f, "%-22s inputs %11llu  mpfr %8llu  not-cr %7llu", s->name,
            (unsigned long long)st->inputs, (unsigned long long)st->settled,
            (unsigned long long)st->wrong);
    if (!st->wrong)
        fprintf(f, "  max <= 0.5 ULP");
    else if (s->arity == 1)
        fprintf(f, "  max %.6f ULP at %a", st->max_ulp, (double)st->worst_x);
    else
        fprintf(f, "  max %.6f ULP at (%a, %a)", st->max_ulp, (double)st->worst_x,
                (double)st->worst_y);
    if (st->not_core || st->bound_broken)
        fprintf(f, "  NOT-CORE %llu  BOUND-BROKEN %llu", (unsigned long long)st->not_core,
                (unsigned long long)st->bound_broken);
    fprintf(f, "  %.1f s\n", seconds);
}
