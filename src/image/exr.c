/* OpenEXR files through OpenEXR's Core C API (OpenEXR 3.1, openexr.h): the writer encodes a
 * scanline file (none, RLE, ZIPS, ZIP, PIZ or PXR24 compression) into memory, its chunks
 * compressed on several threads, and hands the bytes to an atomic file (shadecalc/file.h); the
 * reader decodes a file held in memory, chunk by chunk, into the float image.
 *
 * Pipeline (OpenEXR "Reading and Writing Image Files", Core API): a context with custom
 * read/write callbacks; per chunk, exr_{read,write}_*_chunk_info, then an encode or decode
 * pipeline whose channel pointers address planar staging buffers, run with the library's default
 * (un)pack routines (which convert half and uint to float when reading). Half values have the
 * bits of sc_half_from_double (image/half.h), so a file holds exactly the mediump values the
 * rest of shadecalc computes. Two defects of OpenEXR 3.1 are worked around below (planar
 * buffers, tie-sized ZIP chunks), and its lock over a whole encoding run (one context per
 * worker). */
#include "shadecalc/image.h"

#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <OpenEXR/openexr.h>

#include "image/half.h"
#include "shadecalc/file.h"

/* The image's own channel order (EXR sorts channels by name), as a string vector. */
static const char channel_order_attr[] = "shadecalc:channel_order";
enum { EXR_SHORT_NAME_MAX = 31 }; /* longer names need the file's long-name flag */

/* ---- a byte stream in memory, and the first error OpenEXR reported on it ------------------- */

typedef struct {
    unsigned char *data; /* written bytes (grows), or the bytes being read */
    size_t size, capacity;
    char message[256];
} exr_stream;

static int fail(exr_stream *s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Records a reason (only the first one: later ones are consequences) and returns -1. */
static int fail(exr_stream *s, const char *fmt, ...)
{
    if (!s->message[0]) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(s->message, sizeof s->message, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* 0 for EXR_ERR_SUCCESS; otherwise records the library's generic message for the code. */
static int check(exr_stream *s, exr_result_t r)
{
    return r == EXR_ERR_SUCCESS ? 0 : fail(s, "%s", exr_get_default_error_message(r));
}

/* The stream of the operation running on this thread. OpenEXR calls the error handler with the
 * context locked, so the handler cannot ask the context for its user data (exr_get_user_data
 * takes the same lock). */
static _Thread_local exr_stream *reporting_to;

static void keep_first_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    if (reporting_to)
        fail(reporting_to, "%s", msg ? msg : exr_get_default_error_message(code));
}

/* pwrite() into the growing buffer. */
static int64_t stream_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t sz,
                            uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = user;
    if (offset > SIZE_MAX / 2 || sz > SIZE_MAX / 2 - offset)
        return error_cb(ctxt, EXR_ERR_WRITE_IO, "write beyond the address space"), -1;
    size_t end = (size_t)(offset + sz);
    if (end > s->capacity) {
        size_t capacity = end > 2 * s->capacity ? end : 2 * s->capacity;
        unsigned char *grown = realloc(s->data, capacity);
        if (!grown)
            return error_cb(ctxt, EXR_ERR_OUT_OF_MEMORY, "out of memory"), -1;
        s->data = grown;
        s->capacity = capacity;
    }
    if (offset > s->size) /* a gap the library will fill later: keep it defined */
        memset(s->data + s->size, 0, (size_t)offset - s->size);
    memcpy(s->data + offset, buffer, (size_t)sz);
    if (end > s->size)
        s->size = end;
    return (int64_t)sz;
}

/* pread() from the buffer: short at the end, 0 past it. */
static int64_t stream_read(exr_const_context_t ctxt, void *user, void *buffer, uint64_t sz,
                           uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    (void)ctxt;
    (void)error_cb;
    const exr_stream *s = user;
    if (offset >= s->size)
        return 0;
    size_t n = sz < s->size - offset ? (size_t)sz : s->size - (size_t)offset;
    memcpy(buffer, s->data + offset, n);
    return (int64_t)n;
}

static int64_t stream_size(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return (int64_t)((const exr_stream *)user)->size;
}

static exr_context_initializer_t stream_initializer(exr_stream *s)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = s;
    init.error_handler_fn = keep_first_error;
    init.read_fn = stream_read;
    init.size_fn = stream_size;
    init.write_fn = stream_write;
    return init;
}

static void report(char *err, size_t errsize, const char *path, const char *reason)
{
    if (err && errsize)
        snprintf(err, errsize, "%s: %s", path, reason[0] ? reason : "unknown OpenEXR error");
}

/* ---- writing ------------------------------------------------------------------------------ */

static int check_image(exr_stream *s, const sc_image *img)
{
    if (!img || !img->data || img->width < 1 || img->height < 1 || img->n_channels < 1 ||
        img->n_channels > SC_IMAGE_MAX_CHANNELS)
        return fail(s, "not a valid image");
    if ((size_t)img->width * (size_t)img->n_channels > INT32_MAX / sizeof(float))
        return fail(s, "image too wide (%d pixels of %d channels)", img->width, img->n_channels);
    return 0;
}

static int check_attrs(exr_stream *s, const sc_image_attr *attrs, int n_attrs)
{
    if (n_attrs < 0 || (n_attrs > 0 && !attrs))
        return fail(s, "invalid attribute list");
    for (int i = 0; i < n_attrs; i++) {
        const char *name = attrs[i].name;
        if (!name || !name[0] || !attrs[i].value)
            return fail(s, "attribute %d has no name or no value", i + 1);
        if (strcmp(name, channel_order_attr) == 0)
            return fail(s, "attribute name '%s' is reserved", name);
        for (int j = 0; j < i; j++)
            if (strcmp(name, attrs[j].name) == 0)
                return fail(s, "attribute '%s' given twice", name);
    }
    return 0;
}

static int needs_long_names(const sc_image *img, const sc_image_attr *attrs, int n_attrs)
{
    for (int c = 0; c < img->n_channels; c++)
        if (strlen(img->channel[c]) > EXR_SHORT_NAME_MAX)
            return 1;
    for (int i = 0; i < n_attrs; i++)
        if (strlen(attrs[i].name) > EXR_SHORT_NAME_MAX)
            return 1;
    return 0;
}

/* ---- compression names ---------------------------------------------------------------------- */

/* What sc_exr_compression means to OpenEXR. */
static const struct {
    const char *name;
    exr_compression_t exr;
} compressions[SC_EXR_COMPRESSION_COUNT] = {
    {"none", EXR_COMPRESSION_NONE}, {"rle", EXR_COMPRESSION_RLE}, {"zips", EXR_COMPRESSION_ZIPS},
    {"zip", EXR_COMPRESSION_ZIP},   {"piz", EXR_COMPRESSION_PIZ}, {"pxr24", EXR_COMPRESSION_PXR24},
};

const char *sc_exr_compression_name(sc_exr_compression c)
{
    return (unsigned)c < SC_EXR_COMPRESSION_COUNT ? compressions[c].name : NULL;
}

int sc_exr_compression_parse(const char *name, sc_exr_compression *out)
{
    for (int i = 0; i < SC_EXR_COMPRESSION_COUNT; i++)
        if (strcmp(name, compressions[i].name) == 0) {
            *out = (sc_exr_compression)i;
            return 0;
        }
    return -1;
}

/* One scanline part: required attributes, the compression, the channels, the channel order,
 * the caller's string attributes; then the header is written. */
static exr_result_t define_header(exr_context_t ctx, const sc_image *img, const sc_exr_options *opt,
                                  const sc_image_attr *attrs, int n_attrs)
{
    int part = 0;
    exr_pixel_type_t type = opt->type == SC_PIXEL_HALF ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT;
    exr_result_t r = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (!r)
        r = exr_initialize_required_attr_simple(ctx, part, img->width, img->height,
                                                compressions[opt->compression].exr);
    if (!r && needs_long_names(img, attrs, n_attrs))
        r = exr_set_longname_support(ctx, 1);
    for (int c = 0; !r && c < img->n_channels; c++)
        r = exr_add_channel(ctx, part, img->channel[c], type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (!r)
        r = exr_attr_set_string_vector(ctx, part, channel_order_attr, img->n_channels,
                                       (const char **)img->channel);
    for (int i = 0; !r && i < n_attrs; i++)
        r = exr_attr_set_string(ctx, part, attrs[i].name, attrs[i].value);
    return r ? r : exr_write_header(ctx);
}

/* Chunks travel through planar buffers, one plane of width × rows values per channel: OpenEXR
 * 3.1's fast paths for interleaved pixels assume the channel pointers in the file's (sorted)
 * order and swap channels otherwise (RGBA half came back ABGR), and planes take no fast path. */
typedef struct {
    unsigned char *bytes;
    size_t size;
} plane_buffer;

/* Room for n_channels planes of `values` values of elem_size bytes each; 0 or -1. */
static int reserve_planes(plane_buffer *b, size_t values, int n_channels, int elem_size)
{
    size_t need = values * (size_t)n_channels * (size_t)elem_size;
    if (need <= b->size)
        return 0;
    unsigned char *grown = realloc(b->bytes, need);
    if (!grown)
        return -1;
    b->bytes = grown;
    b->size = need;
    return 0;
}

/* Points every coding channel at the plane of the image channel of the same name. */
static void point_at_planes(exr_coding_channel_info_t *channels, int count, const sc_image *img,
                            unsigned char *planes, int width, int rows, int elem_size)
{
    size_t plane_bytes = (size_t)width * (size_t)rows * (size_t)elem_size;
    for (int i = 0; i < count; i++) {
        exr_coding_channel_info_t *ch = &channels[i];
        int c = sc_image_channel_index(img, ch->channel_name);
        ch->user_bytes_per_element = (int16_t)elem_size;
        ch->user_line_stride = elem_size * width;
        ch->user_pixel_stride = elem_size;
        ch->decode_to_ptr = planes + (size_t)c * plane_bytes; /* also encode_from_ptr */
    }
}

/* Rows [y, y + rows) of img into planes, as binary16 (image/half.h: sc_half_from_double's bits)
 * or binary32; row: scratch for one row of one channel. */
static void fill_planes(const sc_image *img, int y, int rows, sc_pixel_type type,
                        unsigned char *planes, float *row)
{
    size_t width = (size_t)img->width, n_channels = (size_t)img->n_channels;
    size_t plane_values = width * (size_t)rows;
    for (size_t c = 0; c < n_channels; c++)
        for (int r = 0; r < rows; r++) {
            const float *pixels = sc_image_pixel(img, 0, y + r);
            size_t at = c * plane_values + (size_t)r * width;
            float *dest = type == SC_PIXEL_HALF ? row : (float *)planes + at;
            for (size_t x = 0; x < width; x++)
                dest[x] = pixels[x * n_channels + c];
            if (type == SC_PIXEL_HALF)
                image_halves_from_floats(row, (uint16_t *)planes + at, width, 0);
        }
}

/* ---- writing: chunks compressed on several threads, written in order ----------------------- *
 * OpenEXR 3.1 holds a context's lock for the whole of exr_encoding_run, so chunks encoded on one
 * context never overlap. Each worker therefore opens its own context with the same header
 * (writing nowhere), compresses the chunks it takes into memory, and the file's context writes
 * the compressed chunks in order (exr_write_scanline_chunk): the bytes of a chunk depend only
 * on the header and the pixels, so the file is the same for any number of threads. */

typedef struct {
    unsigned char *bytes;
    size_t size;
} chunk_bytes;

typedef struct {
    const char *name;
    const sc_image *img;
    const sc_exr_options *opt;
    const sc_image_attr *attrs;
    int n_attrs, lines, n_chunks;
    chunk_bytes *chunks;
    atomic_int next_chunk, failed;
} chunk_job;

typedef struct {
    chunk_job *job;
    exr_stream stream; /* discards the bytes; keeps the worker's first error */
    exr_context_t ctx;
    exr_encode_pipeline_t enc;
    int started;
    plane_buffer planes;
    float *row;
    exr_result_t (*library_compress)(exr_encode_pipeline_t *enc);
    chunk_bytes *target; /* where the chunk being encoded goes */
} chunk_worker;

/* A worker's context writes only its header, to nowhere. */
static int64_t discard_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t sz,
                             uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    (void)ctxt;
    (void)user;
    (void)buffer;
    (void)offset;
    (void)error_cb;
    return (int64_t)sz;
}

/* The file format stores a chunk raw when compressing does not make it smaller, and readers
 * take a chunk as raw when its size is the raw size. OpenEXR's Core writer before the fix of
 * issue #2306 (PR #2307) keeps zlib output of exactly the raw size, which every reader then
 * misreads (seen here: the last 16-byte chunk of a 2 × 49 RGBA half image). The library's
 * compressor is wrapped to store such a chunk raw. */
static exr_result_t compress_or_store_raw(exr_encode_pipeline_t *enc)
{
    const chunk_worker *w = enc->encoding_user_data;
    exr_result_t r = w->library_compress(enc);
    if (r == EXR_ERR_SUCCESS && enc->compressed_bytes >= enc->packed_bytes &&
        enc->compressed_buffer != enc->packed_buffer) {
        memcpy(enc->compressed_buffer, enc->packed_buffer, enc->packed_bytes);
        enc->compressed_bytes = enc->packed_bytes;
    }
    return r;
}

/* Instead of writing the chunk: a copy of its bytes for the file's context. */
static exr_result_t keep_chunk(exr_encode_pipeline_t *enc)
{
    chunk_worker *w = enc->encoding_user_data;
    const void *bytes = enc->compress_fn ? enc->compressed_buffer : enc->packed_buffer;
    size_t size = enc->compress_fn ? enc->compressed_bytes : enc->packed_bytes;
    w->target->bytes = malloc(size ? size : 1);
    if (!w->target->bytes)
        return EXR_ERR_OUT_OF_MEMORY;
    memcpy(w->target->bytes, bytes, size);
    w->target->size = size;
    return EXR_ERR_SUCCESS;
}

static exr_result_t encode_chunk(chunk_worker *w, int index)
{
    const chunk_job *job = w->job;
    const sc_image *img = job->img;
    sc_pixel_type type = job->opt->type;
    int elem_size = type == SC_PIXEL_HALF ? (int)sizeof(uint16_t) : (int)sizeof(float);
    exr_chunk_info_t chunk;
    exr_result_t r = exr_write_scanline_chunk_info(w->ctx, 0, index * job->lines, &chunk);
    if (!r)
        r = w->started ? exr_encoding_update(w->ctx, 0, &chunk, &w->enc)
                       : exr_encoding_initialize(w->ctx, 0, &chunk, &w->enc);
    if (r)
        return r;
    w->started = 1;
    if (reserve_planes(&w->planes, (size_t)img->width * (size_t)chunk.height, img->n_channels,
                       elem_size) != 0)
        return EXR_ERR_OUT_OF_MEMORY;
    fill_planes(img, chunk.start_y, chunk.height, type, w->planes.bytes, w->row);
    point_at_planes(w->enc.channels, w->enc.channel_count, img, w->planes.bytes, img->width,
                    chunk.height, elem_size);
    for (int i = 0; i < w->enc.channel_count; i++)
        w->enc.channels[i].user_data_type = w->enc.channels[i].data_type;
    r = exr_encoding_choose_default_routines(w->ctx, 0, &w->enc);
    if (r)
        return r;
    if (w->enc.compress_fn) {
        w->library_compress = w->enc.compress_fn;
        w->enc.compress_fn = compress_or_store_raw;
    }
    w->enc.encoding_user_data = w;
    w->enc.yield_until_ready_fn = NULL; /* chunks finish out of order; the file orders them */
    w->enc.write_fn = keep_chunk;
    w->target = &job->chunks[index];
    return exr_encoding_run(w->ctx, 0, &w->enc);
}

/* The worker's context, with the file's header. */
static int open_worker(chunk_worker *w)
{
    const chunk_job *job = w->job;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &w->stream;
    init.error_handler_fn = keep_first_error;
    init.write_fn = discard_write;
    w->enc = (exr_encode_pipeline_t)EXR_ENCODE_PIPELINE_INITIALIZER;
    w->row = malloc((size_t)job->img->width * sizeof *w->row);
    if (!w->row)
        return fail(&w->stream, "out of memory");
    if (check(&w->stream, exr_start_write(&w->ctx, job->name, EXR_WRITE_FILE_DIRECTLY, &init)))
        return -1;
    return check(&w->stream, define_header(w->ctx, job->img, job->opt, job->attrs, job->n_attrs));
}

/* Takes chunks until none is left or a worker failed. */
static void *run_worker(void *arg)
{
    chunk_worker *w = arg;
    chunk_job *job = w->job;
    exr_stream *outer = reporting_to;
    reporting_to = &w->stream;
    int rc = open_worker(w);
    for (int i; rc == 0 && !atomic_load(&job->failed) &&
                (i = atomic_fetch_add(&job->next_chunk, 1)) < job->n_chunks;)
        rc = check(&w->stream, encode_chunk(w, i));
    if (rc != 0)
        atomic_store(&job->failed, 1);
    if (w->started)
        exr_encoding_destroy(w->ctx, &w->enc);
    if (w->ctx)
        exr_finish(&w->ctx); /* an unfinished file to nowhere: its verdict does not matter */
    free(w->planes.bytes);
    free(w->row);
    reporting_to = outer;
    return NULL;
}

enum { MAX_EXR_THREADS = 64 };

static int worker_count(const sc_exr_options *opt, int n_chunks)
{
    long n = opt->threads > 0 ? opt->threads : sysconf(_SC_NPROCESSORS_ONLN);
    n = n < 1 ? 1 : n > MAX_EXR_THREADS ? MAX_EXR_THREADS : n;
    return (int)(n < n_chunks ? n : n_chunks);
}

/* Runs the workers (the calling thread is one of them); the first failure's reason into s. */
static int compress_chunks(chunk_job *job, exr_stream *s)
{
    chunk_worker workers[MAX_EXR_THREADS];
    pthread_t threads[MAX_EXR_THREADS];
    int n = worker_count(job->opt, job->n_chunks), started = 1;
    for (int i = 0; i < n; i++)
        workers[i] = (chunk_worker){.job = job};
    while (started < n &&
           pthread_create(&threads[started], NULL, run_worker, &workers[started]) == 0)
        started++;
    run_worker(&workers[0]);
    for (int i = 1; i < started; i++)
        pthread_join(threads[i], NULL);
    for (int i = 0; i < started; i++)
        if (workers[i].stream.message[0])
            fail(s, "%s", workers[i].stream.message);
    return atomic_load(&job->failed) ? fail(s, "encoding a chunk failed") : 0;
}

static int write_chunks(exr_context_t ctx, exr_stream *s, chunk_job *job)
{
    if (check(s, exr_get_scanlines_per_chunk(ctx, 0, &job->lines)) != 0)
        return -1;
    job->n_chunks = (job->img->height + job->lines - 1) / job->lines;
    job->chunks = calloc((size_t)job->n_chunks, sizeof *job->chunks);
    if (!job->chunks)
        return fail(s, "out of memory");
    int rc = compress_chunks(job, s);
    for (int i = 0; rc == 0 && i < job->n_chunks; i++)
        rc = check(s, exr_write_scanline_chunk(ctx, 0, i * job->lines, job->chunks[i].bytes,
                                               job->chunks[i].size));
    for (int i = 0; i < job->n_chunks; i++)
        free(job->chunks[i].bytes);
    free(job->chunks);
    return rc;
}

static int encode_exr(const char *name, const sc_image *img, const sc_exr_options *opt,
                      const sc_image_attr *attrs, int n_attrs, exr_stream *s)
{
    exr_context_initializer_t init = stream_initializer(s);
    exr_context_t ctx = NULL;
    chunk_job job = {.name = name, .img = img, .opt = opt, .attrs = attrs, .n_attrs = n_attrs};
    atomic_init(&job.next_chunk, 0);
    atomic_init(&job.failed, 0);
    reporting_to = s;
    int rc = check(s, exr_start_write(&ctx, name, EXR_WRITE_FILE_DIRECTLY, &init));
    if (rc == 0)
        rc = check(s, define_header(ctx, img, opt, attrs, n_attrs));
    if (rc == 0)
        rc = write_chunks(ctx, s, &job);
    if (ctx) {
        exr_result_t finished = exr_finish(&ctx); /* writes the chunk offset table */
        if (rc == 0)
            rc = check(s, finished);
    }
    reporting_to = NULL;
    return rc;
}

static int write_bytes_atomically(const char *path, const exr_stream *s, char *err, size_t errsize)
{
    sc_atomic_file *f = sc_atomic_open(path, err, errsize);
    if (!f)
        return -1;
    if (fwrite(s->data, 1, s->size, sc_atomic_stream(f)) != s->size) {
        int errnum = errno ? errno : EIO;
        sc_atomic_abort(f);
        report(err, errsize, path, strerror(errnum));
        return -1;
    }
    return sc_atomic_commit(f, err, errsize);
}

static int check_options(exr_stream *s, const sc_exr_options *opt)
{
    if (!opt || (opt->type != SC_PIXEL_HALF && opt->type != SC_PIXEL_FLOAT) ||
        (unsigned)opt->compression >= SC_EXR_COMPRESSION_COUNT || opt->threads < 0)
        return fail(s, "invalid write options");
    return 0;
}

int sc_exr_write_with(const char *path, const sc_image *img, const sc_exr_options *opt,
                      const sc_image_attr *attrs, int n_attrs, char *err, size_t errsize)
{
    exr_stream s = {.data = NULL};
    int rc = check_options(&s, opt);
    if (rc == 0)
        rc = check_image(&s, img);
    if (rc == 0)
        rc = check_attrs(&s, attrs, n_attrs);
    if (rc == 0)
        rc = encode_exr(path, img, opt, attrs, n_attrs, &s);
    if (rc == 0)
        rc = write_bytes_atomically(path, &s, err, errsize);
    else
        report(err, errsize, path, s.message);
    free(s.data);
    return rc;
}

int sc_exr_write(const char *path, const sc_image *img, sc_pixel_type type,
                 const sc_image_attr *attrs, int n_attrs, char *err, size_t errsize)
{
    sc_exr_options opt = {type, SC_EXR_ZIP, 0};
    return sc_exr_write_with(path, img, &opt, attrs, n_attrs, err, errsize);
}

/* ---- reading ------------------------------------------------------------------------------ */

static const exr_attribute_t *find_attribute(exr_const_context_t ctx, const char *name)
{
    int32_t count = 0;
    const exr_attribute_t *a = NULL;
    if (exr_get_attribute_count(ctx, 0, &count) != EXR_ERR_SUCCESS)
        return NULL;
    for (int32_t i = 0; i < count; i++)
        if (exr_get_attribute_by_index(ctx, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a) ==
                EXR_ERR_SUCCESS &&
            strcmp(a->name, name) == 0)
            return a;
    return NULL;
}

/* The channel entry named exactly s (length-counted), or -1. */
static int entry_named(const exr_attr_chlist_t *chl, const exr_attr_string_t *s)
{
    for (int i = 0; i < chl->num_channels; i++)
        if (chl->entries[i].name.length == s->length &&
            memcmp(chl->entries[i].name.str, s->str, (size_t)s->length) == 0)
            return i;
    return -1;
}

/* The names in the image's own order when "shadecalc:channel_order" lists each of the file's
 * channels exactly once, otherwise in the file's (sorted) order. */
static void channel_order(exr_const_context_t ctx, const exr_attr_chlist_t *chl, const char **names)
{
    for (int i = 0; i < chl->num_channels; i++)
        names[i] = chl->entries[i].name.str;
    const exr_attribute_t *a = find_attribute(ctx, channel_order_attr);
    if (!a || a->type != EXR_ATTR_STRING_VECTOR || a->stringvector->n_strings != chl->num_channels)
        return;
    const char *ordered[SC_IMAGE_MAX_CHANNELS];
    int used[SC_IMAGE_MAX_CHANNELS] = {0};
    for (int i = 0; i < chl->num_channels; i++) {
        int e = entry_named(chl, &a->stringvector->strings[i]);
        if (e < 0 || used[e]++)
            return;
        ordered[i] = chl->entries[e].name.str;
    }
    memcpy(names, ordered, (size_t)chl->num_channels * sizeof *names);
}

static int check_channels(exr_stream *s, const exr_attr_chlist_t *chl)
{
    if (chl->num_channels < 1 || chl->num_channels > SC_IMAGE_MAX_CHANNELS)
        return fail(s, "%d channels (1 to %d are supported)", chl->num_channels,
                    SC_IMAGE_MAX_CHANNELS);
    for (int i = 0; i < chl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &chl->entries[i];
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return fail(s, "channel '%s' is subsampled (not supported)", e->name.str);
        if (e->name.length < 1 || (i > 0 && strcmp(e->name.str, chl->entries[i - 1].name.str) == 0))
            return fail(s, "invalid channel list");
    }
    return 0;
}

/* Storage, size and channels that this reader supports; then the zeroed image. */
static int prepare_image(exr_const_context_t ctx, exr_stream *s, sc_image *out,
                         exr_attr_box2i_t *window)
{
    exr_storage_t storage;
    const exr_attr_chlist_t *chl = NULL;
    int32_t chunks = 0;
    if (check(s, exr_get_storage(ctx, 0, &storage)) ||
        check(s, exr_get_data_window(ctx, 0, window)) || check(s, exr_get_channels(ctx, 0, &chl)) ||
        check(s, exr_get_chunk_count(ctx, 0, &chunks)))
        return -1;
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return fail(s, "deep data is not supported");
    if (check_channels(s, chl) != 0)
        return -1;
    if (chunks < 1 || (uint64_t)chunks * sizeof(uint64_t) > s->size)
        return fail(s, "file too short for its %ld chunks", (long)chunks);
    int64_t width = (int64_t)window->max.x - window->min.x + 1;
    int64_t height = (int64_t)window->max.y - window->min.y + 1;
    if (width < 1 || height < 1 ||
        (uint64_t)width * (uint64_t)height * (uint64_t)chl->num_channels > SC_EXR_MAX_VALUES)
        return fail(s, "image of %lld x %lld pixels x %d channels is too large", (long long)width,
                    (long long)height, chl->num_channels);
    const char *names[SC_IMAGE_MAX_CHANNELS];
    channel_order(ctx, chl, names);
    if (sc_image_init(out, (int)width, (int)height, chl->num_channels, names) != 0)
        return fail(s, "out of memory");
    return 0;
}

typedef struct {
    exr_const_context_t ctx;
    exr_decode_pipeline_t pipeline;
    int started;
    plane_buffer planes;
    sc_image *out;
} chunk_decoder;

/* Copies the decoded planes of a width × rows chunk to pixel (x, y) of out onwards. */
static void scatter_planes(sc_image *out, const float *planes, int x, int y, int width, int rows)
{
    size_t plane_values = (size_t)width * (size_t)rows;
    for (int c = 0; c < out->n_channels; c++)
        for (int r = 0; r < rows; r++)
            for (int i = 0; i < width; i++)
                sc_image_pixel(out, x + i, y + r)[c] =
                    planes[(size_t)c * plane_values + (size_t)r * (size_t)width + (size_t)i];
}

/* Decodes one chunk, converted to float, whose top-left pixel lands at (x, y) of the image. */
static exr_result_t decode_chunk(chunk_decoder *d, const exr_chunk_info_t *chunk, int x, int y)
{
    sc_image *out = d->out;
    if (x < 0 || y < 0 || chunk->width < 0 || chunk->height < 0 || chunk->width > out->width - x ||
        chunk->height > out->height - y)
        return EXR_ERR_CORRUPT_CHUNK;
    exr_result_t r = d->started ? exr_decoding_update(d->ctx, 0, chunk, &d->pipeline)
                                : exr_decoding_initialize(d->ctx, 0, chunk, &d->pipeline);
    if (r)
        return r;
    d->started = 1;
    if (reserve_planes(&d->planes, (size_t)chunk->width * (size_t)chunk->height, out->n_channels,
                       (int)sizeof(float)) != 0)
        return EXR_ERR_OUT_OF_MEMORY;
    point_at_planes(d->pipeline.channels, d->pipeline.channel_count, out, d->planes.bytes,
                    chunk->width, chunk->height, (int)sizeof(float));
    for (int i = 0; i < d->pipeline.channel_count; i++)
        d->pipeline.channels[i].user_data_type = EXR_PIXEL_FLOAT;
    r = exr_decoding_choose_default_routines(d->ctx, 0, &d->pipeline);
    if (!r)
        r = exr_decoding_run(d->ctx, 0, &d->pipeline);
    if (!r)
        scatter_planes(out, (const float *)d->planes.bytes, x, y, chunk->width, chunk->height);
    return r;
}

static exr_result_t read_scanlines(chunk_decoder *d, const exr_attr_box2i_t *window)
{
    int32_t lines = 0;
    exr_result_t r = exr_get_scanlines_per_chunk(d->ctx, 0, &lines);
    for (int64_t y = window->min.y; !r && y <= window->max.y; y += lines) {
        exr_chunk_info_t chunk;
        r = exr_read_scanline_chunk_info(d->ctx, 0, (int)y, &chunk);
        if (!r)
            r = decode_chunk(d, &chunk, 0, (int)((int64_t)chunk.start_y - window->min.y));
    }
    return r;
}

static exr_result_t read_tiles(chunk_decoder *d)
{
    int32_t tile_w = 0, tile_h = 0;
    exr_result_t r = exr_get_tile_sizes(d->ctx, 0, 0, 0, &tile_w, &tile_h);
    if (!r && (tile_w < 1 || tile_h < 1))
        r = EXR_ERR_INVALID_ATTR;
    int tiles_x = r ? 0 : (d->out->width - 1) / tile_w + 1;
    int tiles_y = r ? 0 : (d->out->height - 1) / tile_h + 1;
    for (int ty = 0; !r && ty < tiles_y; ty++)
        for (int tx = 0; !r && tx < tiles_x; tx++) {
            exr_chunk_info_t chunk;
            r = exr_read_tile_chunk_info(d->ctx, 0, tx, ty, 0, 0, &chunk);
            if (!r)
                r = decode_chunk(d, &chunk, tx * tile_w, ty * tile_h);
        }
    return r;
}

static int decode_pixels(exr_const_context_t ctx, exr_stream *s, sc_image *out,
                         const exr_attr_box2i_t *window)
{
    chunk_decoder d = {.ctx = ctx, .pipeline = EXR_DECODE_PIPELINE_INITIALIZER, .out = out};
    exr_storage_t storage = EXR_STORAGE_SCANLINE;
    exr_result_t r = exr_get_storage(ctx, 0, &storage);
    if (!r)
        r = storage == EXR_STORAGE_TILED ? read_tiles(&d) : read_scanlines(&d, window);
    if (d.started)
        exr_decoding_destroy(ctx, &d.pipeline);
    free(d.planes.bytes);
    return check(s, r);
}

static char *copy_bytes(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (c) {
        memcpy(c, s, n);
        c[n] = '\0';
    }
    return c;
}

/* The part's string attributes, in file order, without "type" (the part's storage kind, which
 * the file's structure states and the library writes itself). */
static int collect_attrs(exr_const_context_t ctx, exr_stream *s, sc_image_attr **attrs,
                         int *n_attrs)
{
    int32_t count = 0;
    if (check(s, exr_get_attribute_count(ctx, 0, &count)) != 0)
        return -1;
    sc_image_attr *list = calloc(count > 0 ? (size_t)count : 1, sizeof *list);
    if (!list)
        return fail(s, "out of memory");
    int n = 0;
    for (int32_t i = 0; i < count; i++) {
        const exr_attribute_t *a = NULL;
        if (exr_get_attribute_by_index(ctx, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a) !=
                EXR_ERR_SUCCESS ||
            a->type != EXR_ATTR_STRING || strcmp(a->name, "type") == 0)
            continue;
        list[n].name = copy_bytes(a->name, strlen(a->name));
        list[n].value = copy_bytes(a->string->str,
                                   a->string->length > 0 ? (size_t)a->string->length : 0);
        if (!list[n++].value || !list[n - 1].name) {
            sc_image_attrs_free(list, n);
            return fail(s, "out of memory");
        }
    }
    *attrs = list;
    *n_attrs = n;
    return 0;
}

static void clear_outputs(sc_image *out, sc_image_attr **attrs, int *n_attrs)
{
    memset(out, 0, sizeof *out);
    if (attrs)
        *attrs = NULL;
    if (n_attrs)
        *n_attrs = 0;
}

int sc_exr_read_memory(const void *bytes, size_t size, const char *name, sc_image *out,
                       sc_image_attr **attrs, int *n_attrs, char *err, size_t errsize)
{
    clear_outputs(out, attrs, n_attrs);
    exr_stream s = {.data = (unsigned char *)bytes, .size = size};
    exr_context_initializer_t init = stream_initializer(&s);
    exr_context_t ctx = NULL;
    exr_attr_box2i_t window;
    reporting_to = &s;
    int rc = check(&s, exr_start_read(&ctx, name, &init));
    if (rc == 0)
        rc = prepare_image(ctx, &s, out, &window);
    if (rc == 0)
        rc = decode_pixels(ctx, &s, out, &window);
    if (rc == 0 && attrs && n_attrs)
        rc = collect_attrs(ctx, &s, attrs, n_attrs);
    if (ctx)
        exr_finish(&ctx);
    reporting_to = NULL;
    if (rc != 0) {
        sc_image_free(out);
        report(err, errsize, name, s.message);
    }
    return rc;
}

/* The whole file in memory (OpenEXR reads a file out of order: header, offsets, chunks). */
static int read_whole_file(const char *path, unsigned char **bytes, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    size_t capacity = 1 << 16, n = 0;
    unsigned char *data = malloc(capacity);
    while (data) {
        n += fread(data + n, 1, capacity - n, f);
        if (n < capacity || capacity > SIZE_MAX / 2)
            break;
        unsigned char *grown = realloc(data, capacity *= 2);
        if (!grown)
            free(data);
        data = grown;
    }
    int failed = !data || ferror(f);
    int errnum = data ? errno : ENOMEM;
    fclose(f);
    if (failed) {
        free(data);
        errno = errnum ? errnum : EIO;
        return -1;
    }
    *bytes = data;
    *size = n;
    return 0;
}

int sc_exr_read(const char *path, sc_image *out, sc_image_attr **attrs, int *n_attrs, char *err,
                size_t errsize)
{
    unsigned char *bytes = NULL;
    size_t size = 0;
    if (read_whole_file(path, &bytes, &size) != 0) {
        clear_outputs(out, attrs, n_attrs);
        report(err, errsize, path, strerror(errno));
        return -1;
    }
    int rc = sc_exr_read_memory(bytes, size, path, out, attrs, n_attrs, err, errsize);
    free(bytes);
    return rc;
}
