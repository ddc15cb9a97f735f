/* The ordered multi-threaded sweep runner (shadecalc/sweep.h).
 *
 * Rows are cut into blocks. Workers take blocks in order and fill one of a ring of
 * 2 × threads slots (values, results and the formatted text); the calling thread takes the
 * slots back in block order, writes and consumes them, and frees the slot for the block one ring
 * further on. Memory is the ring, whatever the number of rows; the output is the same for any
 * number of threads because every row is formatted on its own and written in order.
 */
#include "shadecalc/sweep.h"

#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum { BLOCK_MAX = 1024, ERR_MAX = 256 };

typedef enum { SLOT_FREE, SLOT_BUSY, SLOT_READY } slot_state;

typedef struct {
    slot_state state;
    uint64_t block; /* FREE: the block it may take next; else the block it holds */
    int rows;       /* rows evaluated; fewer than the block's when eval failed */
    int failed;     /* 0, or the status of the failed row (SC_SWEEP_FAILED, SC_SWEEP_INVALID) */
    char err[ERR_MAX];
    double *vars, *results;
    char *text;
    size_t text_len;
} slot;

typedef struct {
    const sc_sweep_job *job;
    uint64_t rows, blocks;
    int block_rows, n_slots, n_vars;
    size_t row_max;
    slot *slots;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    uint64_t next_block; /* the next block a worker takes */
    int stop;
    int write_errno; /* errno of a failed write */
} runner;

typedef struct {
    runner *r;
    int worker;
} worker_arg;

static int block_row_count(const runner *r, uint64_t block)
{
    uint64_t first = block * (uint64_t)r->block_rows;
    uint64_t left = r->rows - first;
    return left < (uint64_t)r->block_rows ? (int)left : r->block_rows;
}

/* The status of a row for which eval or consume returned `code` < 0. */
static sc_sweep_status row_failure(int code)
{
    return code == SC_SWEEP_ROW_INVALID ? SC_SWEEP_INVALID : SC_SWEEP_FAILED;
}

/* Evaluates rows first.. of the block one at a time: the number evaluated before one failed
 * (its status in s->failed). */
static int eval_rows(const runner *r, int worker, uint64_t first, int count, slot *s, char *msg,
                     size_t size)
{
    const sc_sweep_job *job = r->job;
    for (int i = 0; i < count; i++) {
        double *vars = s->vars + (size_t)i * (size_t)r->n_vars;
        sc_sweep_grid_point(job->grid, first + (uint64_t)i, vars);
        int code = job->eval(job->user, worker, vars,
                             s->results + (size_t)i * (size_t)job->n_results, msg, size);
        if (code < 0) {
            s->failed = row_failure(code);
            return i;
        }
    }
    return count;
}

/* The same through eval_block, every row at once. */
static int eval_rows_at_once(const runner *r, int worker, uint64_t first, int count, slot *s,
                             char *msg, size_t size)
{
    const sc_sweep_job *job = r->job;
    for (int i = 0; i < count; i++)
        sc_sweep_grid_point(job->grid, first + (uint64_t)i,
                            s->vars + (size_t)i * (size_t)r->n_vars);
    int failure = SC_SWEEP_FAILED;
    int done = job->eval_block(job->user, worker, count, s->vars, s->results, &failure, msg, size);
    s->failed = row_failure(failure);
    return done;
}

/* Evaluates and formats one block into s (no lock held). */
static void fill_block(const runner *r, int worker, uint64_t block, slot *s)
{
    const sc_sweep_job *job = r->job;
    int count = block_row_count(r, block);
    uint64_t first = block * (uint64_t)r->block_rows;
    char msg[ERR_MAX - 32] = "";
    s->rows = job->eval_block ? eval_rows_at_once(r, worker, first, count, s, msg, sizeof msg)
                              : eval_rows(r, worker, first, count, s, msg, sizeof msg);
    s->text_len = 0;
    for (int i = 0; job->table && i < s->rows; i++) {
        int len = sc_sweep_format_row(s->text + s->text_len, r->row_max, job->table,
                                      s->vars + (size_t)i * (size_t)r->n_vars,
                                      s->results + (size_t)i * (size_t)job->n_results);
        s->text_len += len > 0 ? (size_t)len : 0;
    }
    if (s->rows == count)
        s->failed = 0;
    else
        snprintf(s->err, sizeof s->err, "row %llu: %s",
                 (unsigned long long)(first + (uint64_t)s->rows + 1), msg);
}

static void *worker_main(void *p)
{
    worker_arg *a = p;
    runner *r = a->r;
    pthread_mutex_lock(&r->lock);
    while (!r->stop && r->next_block < r->blocks) {
        uint64_t block = r->next_block++;
        slot *s = &r->slots[block % (uint64_t)r->n_slots];
        while (!r->stop && !(s->state == SLOT_FREE && s->block == block))
            pthread_cond_wait(&r->changed, &r->lock);
        if (r->stop)
            break;
        s->state = SLOT_BUSY;
        pthread_mutex_unlock(&r->lock);
        fill_block(r, a->worker, block, s);
        pthread_mutex_lock(&r->lock);
        s->state = SLOT_READY;
        pthread_cond_broadcast(&r->changed);
    }
    pthread_mutex_unlock(&r->lock);
    return NULL;
}

/* Writes and consumes a ready slot in the calling thread. */
static sc_sweep_status drain_block(runner *r, uint64_t block, slot *s, char *err, size_t errsize)
{
    const sc_sweep_job *job = r->job;
    if (job->table && s->text_len && fwrite(s->text, 1, s->text_len, job->out) != s->text_len) {
        r->write_errno = errno;
        return SC_SWEEP_WRITE_ERROR;
    }
    uint64_t first = block * (uint64_t)r->block_rows;
    for (int i = 0; job->consume && i < s->rows; i++) {
        char msg[ERR_MAX - 32];
        int code = job->consume(job->user, first + (uint64_t)i,
                                s->vars + (size_t)i * (size_t)r->n_vars,
                                s->results + (size_t)i * (size_t)job->n_results, msg, sizeof msg);
        if (code < 0) {
            snprintf(err, errsize, "row %llu: %s", (unsigned long long)(first + (uint64_t)i + 1),
                     msg);
            return row_failure(code);
        }
    }
    if (s->failed) {
        snprintf(err, errsize, "%s", s->err);
        return (sc_sweep_status)s->failed;
    }
    if (job->progress)
        job->progress(job->user, first + (uint64_t)s->rows, r->rows);
    return SC_SWEEP_OK;
}

/* The calling thread's loop with worker threads running. */
static sc_sweep_status drain_all(runner *r, char *err, size_t errsize)
{
    sc_sweep_status status = SC_SWEEP_OK;
    for (uint64_t block = 0; block < r->blocks && status == SC_SWEEP_OK; block++) {
        slot *s = &r->slots[block % (uint64_t)r->n_slots];
        pthread_mutex_lock(&r->lock);
        while (!(s->state == SLOT_READY && s->block == block))
            pthread_cond_wait(&r->changed, &r->lock);
        pthread_mutex_unlock(&r->lock);
        status = drain_block(r, block, s, err, errsize);
        pthread_mutex_lock(&r->lock);
        s->state = SLOT_FREE;
        s->block = block + (uint64_t)r->n_slots;
        r->stop |= status != SC_SWEEP_OK;
        pthread_cond_broadcast(&r->changed);
        pthread_mutex_unlock(&r->lock);
    }
    return status;
}

/* One thread: the same blocks, filled and drained in turn. */
static sc_sweep_status run_inline(runner *r, char *err, size_t errsize)
{
    sc_sweep_status status = SC_SWEEP_OK;
    for (uint64_t block = 0; block < r->blocks && status == SC_SWEEP_OK; block++) {
        fill_block(r, 0, block, &r->slots[0]);
        status = drain_block(r, block, &r->slots[0], err, errsize);
    }
    return status;
}

static sc_sweep_status run_threads(runner *r, int threads, char *err, size_t errsize)
{
    pthread_t *ids = calloc((size_t)threads, sizeof *ids);
    worker_arg *args = calloc((size_t)threads, sizeof *args);
    int started = 0;
    sc_sweep_status status = ids && args ? SC_SWEEP_OK : SC_SWEEP_NO_MEMORY;
    pthread_mutex_init(&r->lock, NULL);
    pthread_cond_init(&r->changed, NULL);
    for (; status == SC_SWEEP_OK && started < threads; started++) {
        args[started] = (worker_arg){r, started};
        if (pthread_create(&ids[started], NULL, worker_main, &args[started]) != 0)
            break;
    }
    if (status == SC_SWEEP_OK) /* no thread could start: do the work here */
        status = started ? drain_all(r, err, errsize) : run_inline(r, err, errsize);
    for (int i = 0; i < started; i++)
        pthread_join(ids[i], NULL);
    pthread_cond_destroy(&r->changed);
    pthread_mutex_destroy(&r->lock);
    free(ids);
    free(args);
    return status;
}

static int alloc_slots(runner *r)
{
    const sc_sweep_job *job = r->job;
    r->slots = calloc((size_t)r->n_slots, sizeof *r->slots);
    if (!r->slots)
        return -1;
    size_t n = (size_t)r->block_rows;
    for (int i = 0; i < r->n_slots; i++) {
        slot *s = &r->slots[i];
        s->block = (uint64_t)i;
        s->vars = malloc(n * (size_t)(r->n_vars > 0 ? r->n_vars : 1) * sizeof *s->vars);
        s->results = malloc(n * (size_t)job->n_results * sizeof *s->results);
        s->text = job->table ? malloc(n * r->row_max) : NULL;
        if (!s->vars || !s->results || (job->table && !s->text))
            return -1;
    }
    return 0;
}

static void free_slots(runner *r)
{
    for (int i = 0; r->slots && i < r->n_slots; i++) {
        free(r->slots[i].vars);
        free(r->slots[i].results);
        free(r->slots[i].text);
    }
    free(r->slots);
}

sc_sweep_status sc_sweep_run(const sc_sweep_job *job, char *err, size_t errsize)
{
    runner r = {.job = job, .n_vars = job->grid->n, .rows = sc_sweep_grid_rows(job->grid)};
    int threads = job->threads > 1 ? job->threads : 1;
    /* enough blocks to share out (four per thread), small enough to start writing soon */
    uint64_t per = r.rows / (uint64_t)(4 * threads);
    r.block_rows = per < 1 ? 1 : per > BLOCK_MAX ? BLOCK_MAX : (int)per;
    r.blocks = (r.rows + (uint64_t)r.block_rows - 1) / (uint64_t)r.block_rows;
    if ((uint64_t)threads > r.blocks)
        threads = r.blocks ? (int)r.blocks : 1;
    r.n_slots = threads > 1 ? 2 * threads : 1;
    r.row_max = job->table ? sc_sweep_row_max(job->table) : 0;
    sc_sweep_status status = SC_SWEEP_NO_MEMORY;
    if (alloc_slots(&r) == 0)
        status = threads > 1 ? run_threads(&r, threads, err, errsize)
                             : run_inline(&r, err, errsize);
    free_slots(&r);
    if (status == SC_SWEEP_NO_MEMORY)
        snprintf(err, errsize, "out of memory");
    if (status == SC_SWEEP_OK && job->table && fflush(job->out) == EOF) {
        r.write_errno = errno;
        status = SC_SWEEP_WRITE_ERROR;
    }
    errno = r.write_errno;
    return status;
}
