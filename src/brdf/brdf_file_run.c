/* .brdf files compiled once and evaluated (shadecalc/brdf_file.h): the program is the file's
 * GLSL followed by one line that calls BRDF with the point's directions, which are inputs
 * named __L __V __N __X __Y (GLSL reserves names with "__" for the implementation) beside the
 * parameters. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brdf/brdf_file_internal.h"
#include "shadecalc/scene.h"
#include "util/text.h"

enum { N_DIRECTIONS = 5, MAX_FILE_SIZE = 1 << 20 };

static const char *const direction_names[N_DIRECTIONS] = {"__L", "__V", "__N", "__X", "__Y"};
static const char call_line[] = "vec3 __f = BRDF(__L, __V, __N, __X, __Y); __f;\n";

static sc_ltype param_type(sc_brdf_param_type t)
{
    sc_ltype lt = {SC_KIND_FLOAT, 1, 1};
    if (t == SC_BRDF_PARAM_BOOL)
        lt.kind = SC_KIND_BOOL;
    if (t == SC_BRDF_PARAM_COLOR)
        lt.rows = 3;
    return lt;
}

/* The line of the parameter a compile error without a line names ('NAME' is reserved). */
static int parameter_line_of(const sc_brdf_file *f, const char *message)
{
    for (int i = 0; i < f->n_params; i++) {
        char quoted[72];
        snprintf(quoted, sizeof quoted, "'%s'", f->params[i].name);
        if (strstr(message, quoted))
            return f->params[i].line;
    }
    return 0;
}

static void compile_error(const sc_brdf_file *f, const sc_lang_error *e, int call_at,
                          int shader_line, char *err, size_t size)
{
    if (e->line == call_at) /* the call of BRDF the program ends with */
        snprintf(err, size,
                 "%s:%d: the shader must define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, "
                 "vec3 Y) (%s)",
                 f->name, shader_line,
                 strstr(e->message, "'__f'") ? "its BRDF returns another type" : e->message);
    else if (e->line > 0)
        snprintf(err, size, "%s:%d:%d: %s", f->name, e->line, e->column, e->message);
    else
        snprintf(err, size, "%s:%d: %s", f->name, parameter_line_of(f, e->message), e->message);
}

int sc_brdf_file_compile(sc_brdf_file *f, const char *glsl, int shader_line, char *err, size_t size)
{
    size_t len = strlen(glsl);
    char *src = malloc(len + sizeof call_line);
    if (!src) {
        snprintf(err, size, "%s: out of memory", f->name);
        return -1;
    }
    memcpy(src, glsl, len);
    memcpy(src + len, call_line, sizeof call_line);
    int call_at = 1;
    for (const char *p = glsl; (p = strchr(p, '\n')) != NULL; p++)
        call_at++;
    sc_lang_input inputs[SC_BRDF_FILE_MAX_PARAMS + N_DIRECTIONS];
    for (int i = 0; i < f->n_params; i++)
        inputs[i] = (sc_lang_input){f->params[i].name, param_type(f->params[i].type)};
    for (int i = 0; i < N_DIRECTIONS; i++)
        inputs[f->n_params + i] = (sc_lang_input){direction_names[i], {SC_KIND_FLOAT, 1, 3}};
    sc_lang_options options = {.max_iterations = SC_BRDF_FILE_MAX_ITERATIONS,
                               .implicit_int_to_float = 1,
                               .desktop_builtins = 1};
    sc_lang_error e;
    f->prog = sc_program_compile(src, inputs, f->n_params + N_DIRECTIONS, &options, &e);
    free(src);
    if (!f->prog)
        compile_error(f, &e, call_at, shader_line, err, size);
    return f->prog ? 0 : -1;
}

static sc_brdf_file *new_file(const char *name)
{
    sc_brdf_file *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->name = malloc(strlen(name) + 1);
    f->status = calloc(1, sizeof *f->status);
    if (!f->name || !f->status || pthread_mutex_init(&f->status->lock, NULL) != 0) {
        free(f->name);
        free(f->status);
        free(f);
        return NULL;
    }
    memcpy(f->name, name, strlen(name) + 1);
    return f;
}

sc_brdf_file *sc_brdf_file_parse(const char *text, const char *name, char *err, size_t size)
{
    sc_brdf_file *f = new_file(name);
    if (!f) {
        snprintf(err, size, "%s: out of memory", name);
        return NULL;
    }
    char *glsl = NULL;
    int shader_line = 0;
    int status = sc_brdf_file_split(text, f, &glsl, &shader_line, err, size);
    if (status == 0)
        status = sc_brdf_file_compile(f, glsl, shader_line, err, size);
    free(glsl);
    if (status < 0) {
        sc_brdf_file_free(f);
        return NULL;
    }
    return f;
}

void sc_brdf_file_free(sc_brdf_file *f)
{
    if (!f)
        return;
    sc_program_free(f->prog);
    pthread_mutex_destroy(&f->status->lock);
    free(f->status);
    free(f->name);
    free(f);
}

const char *sc_brdf_file_name(const sc_brdf_file *f) { return f->name; }

int sc_brdf_file_params(const sc_brdf_file *f, const sc_brdf_param **out)
{
    *out = f->params;
    return f->n_params;
}

/* ---- reading, once per path ---- */

/* Why the n bytes read from `in` are not a .brdf file's text (NULL if they are). */
static const char *unreadable(const char *text, size_t n, FILE *in)
{
    if (!text)
        return "out of memory";
    if (ferror(in))
        return strerror(errno ? errno : EIO);
    if (n > MAX_FILE_SIZE)
        return "over 1 MiB: not a .brdf file"; /* /dev/zero, an endless stream */
    return memchr(text, '\0', n) ? "a NUL byte: not a text file" : NULL;
}

/* The whole file as a string, or NULL with the error. */
static char *read_text(const char *path, char *err, size_t size)
{
    FILE *in = fopen(path, "rb");
    if (!in) {
        snprintf(err, size, "%s: %s", path, strerror(errno));
        return NULL;
    }
    char *text = malloc(MAX_FILE_SIZE + 1);
    size_t n = text ? fread(text, 1, MAX_FILE_SIZE + 1, in) : 0;
    const char *why = unreadable(text, n, in);
    fclose(in);
    if (why) {
        snprintf(err, size, "%s: %s", path, why);
        free(text);
        return NULL;
    }
    text[n] = '\0';
    return text;
}

typedef struct loaded {
    struct loaded *next;
    sc_brdf_file *file;
    char path[];
} loaded;

static pthread_mutex_t cache_lock = PTHREAD_MUTEX_INITIALIZER;
static loaded *cache;

static const sc_brdf_file *cached(const char *path)
{
    for (const loaded *c = cache; c; c = c->next)
        if (strcmp(c->path, path) == 0)
            return c->file;
    return NULL;
}

static const sc_brdf_file *load_new(const char *path, char *err, size_t size)
{
    char *text = read_text(path, err, size);
    sc_brdf_file *f = text ? sc_brdf_file_parse(text, path, err, size) : NULL;
    free(text);
    loaded *c = f ? malloc(sizeof *c + strlen(path) + 1) : NULL;
    if (f && !c) {
        sc_brdf_file_free(f);
        snprintf(err, size, "%s: out of memory", path);
        return NULL;
    }
    if (c) {
        c->file = f;
        memcpy(c->path, path, strlen(path) + 1);
        c->next = cache;
        cache = c;
    }
    return f;
}

const sc_brdf_file *sc_brdf_file_load(const char *path, char *err, size_t size)
{
    pthread_mutex_lock(&cache_lock);
    const sc_brdf_file *f = cached(path);
    if (!f)
        f = load_new(path, err, size);
    pthread_mutex_unlock(&cache_lock);
    return f;
}

/* ---- parameter values ---- */

void sc_brdf_file_defaults(const sc_brdf_file *f, sc_brdf *b)
{
    sc_brdf_init(b, SC_BRDF_FILE);
    b->file = f;
    for (int i = 0; i < f->n_params; i++) {
        const sc_brdf_param *prm = &f->params[i];
        int n = prm->type == SC_BRDF_PARAM_COLOR ? 3 : 1;
        memcpy(b->file_values + prm->offset, prm->def, (size_t)n * sizeof(double));
    }
}

static const sc_brdf_param *find_param(const sc_brdf_file *f, const char *name)
{
    for (int i = 0; i < f->n_params; i++)
        if (strcmp(f->params[i].name, name) == 0)
            return &f->params[i];
    return NULL;
}

static int unknown_param(const sc_brdf_file *f, const char *name, char *err, size_t size)
{
    sc_suggestion s;
    sc_suggest_init(&s, name);
    for (int i = 0; i < f->n_params; i++)
        sc_suggest_consider(&s, f->params[i].name);
    const char *best = sc_suggest_best(&s);
    char shown[80];
    snprintf(err, size, "%s: no parameter '%s'%s%s%s", f->name,
             sc_escape(name, shown, sizeof shown), best ? " (did you mean '" : "", best ? best : "",
             best ? "'?)" : "");
    return -1;
}

static int parse_value(const sc_brdf_param *prm, const char *value, double *out)
{
    char *end;
    switch (prm->type) {
    case SC_BRDF_PARAM_BOOL:
        if (strcmp(value, "1") != 0 && strcmp(value, "0") != 0 && strcmp(value, "true") != 0 &&
            strcmp(value, "false") != 0)
            return -1;
        out[0] = value[0] == '1' || value[0] == 't';
        return 0;
    case SC_BRDF_PARAM_COLOR: return sc_parse_colour(value, out);
    default:
        out[0] = strtod(value, &end);
        return end != value && *end == '\0' && isfinite(out[0]) ? 0 : -1;
    }
}

int sc_brdf_file_set(sc_brdf *b, const char *name, const char *value, char *err, size_t size)
{
    static const char *const expected[] = {"a finite number", "0, 1, true or false",
                                           "a colour (1 or 3 numbers)"};
    const sc_brdf_param *prm = find_param(b->file, name);
    if (!prm)
        return unknown_param(b->file, name, err, size);
    double x[3];
    char shown[80];
    if (parse_value(prm, value, x) < 0) {
        snprintf(err, size, "%s: %s=%s: expected %s", b->file->name, name,
                 sc_escape(value, shown, sizeof shown), expected[prm->type]);
        return -1;
    }
    if (prm->type == SC_BRDF_PARAM_FLOAT && !(x[0] >= prm->min && x[0] <= prm->max)) {
        snprintf(err, size, "%s: %s=%s: outside the file's range %.17g..%.17g (line %d)",
                 b->file->name, name, sc_escape(value, shown, sizeof shown), prm->min, prm->max,
                 prm->line);
        return -1;
    }
    memcpy(b->file_values + prm->offset, x,
           (prm->type == SC_BRDF_PARAM_COLOR ? 3 : 1) * sizeof(double));
    return 0;
}

/* ---- evaluation ---- */

static int take_result(void *user, const char *text, int len, int line, const sc_lvalue *value)
{
    (void)text, (void)len, (void)line;
    memcpy(user, value->v, 3 * sizeof(double));
    return 0;
}

static void record_error(const sc_brdf_file *f, const sc_lang_error *e)
{
    brdf_file_status *s = f->status;
    char message[sizeof e->message];
    memcpy(message, e->message, sizeof message);
    char *hint = strstr(message, " (the bound: --max-iterations)"); /* eval's option */
    if (hint)
        *hint = '\0';
    pthread_mutex_lock(&s->lock);
    if (!atomic_load(&s->failed)) {
        snprintf(s->message, sizeof s->message, "%s:%d:%d: %s%s", f->name, e->line, e->column,
                 message, hint ? " in one evaluation" : "");
        atomic_store(&s->failed, 1);
    }
    pthread_mutex_unlock(&s->lock);
}

/* The inputs of one point: the parameters, then L, V, N, X, Y. */
static void point_inputs(const sc_brdf *b, const sc_frame *frame, const double l[3],
                         const double v[3], sc_lvalue *in)
{
    const sc_brdf_file *f = b->file;
    for (int i = 0; i < f->n_params; i++) {
        in[i].type = param_type(f->params[i].type);
        memcpy(in[i].v, b->file_values + f->params[i].offset,
               (size_t)in[i].type.rows * sizeof(double));
    }
    const double *dirs[N_DIRECTIONS] = {l, v, frame->n, frame->t, frame->b};
    for (int k = 0; k < N_DIRECTIONS; k++) {
        in[f->n_params + k].type = (sc_ltype){SC_KIND_FLOAT, 1, 3};
        memcpy(in[f->n_params + k].v, dirs[k], 3 * sizeof(double));
    }
}

/* f at n points, one program run each: the one place that runs a file's program (a block
 * execution of the interpreter would take its place). */
static void eval_points(sc_prec p, const sc_brdf *b, int n, const sc_frame *frames,
                        const double (*l)[3], const double (*v)[3], double (*f)[3])
{
    const sc_brdf_file *file = b->file;
    sc_lvalue in[SC_BRDF_FILE_MAX_PARAMS + N_DIRECTIONS];
    for (int i = 0; i < n; i++) {
        f[i][0] = f[i][1] = f[i][2] = NAN;
        if (atomic_load(&file->status->failed))
            continue;
        point_inputs(b, &frames[i], l[i], v[i], in);
        sc_lang_error e;
        if (sc_program_run(file->prog, p, in, take_result, NULL, f[i], &e) < 0)
            record_error(file, &e);
    }
}

void sc_brdf_file_eval(sc_prec p, const sc_brdf *b, const sc_frame *frame, const double l[3],
                       const double v[3], double f[3])
{
    eval_points(p, b, 1, frame, (const double(*)[3])l, (const double(*)[3])v, (double(*)[3])f);
}

/* ---- many points: block execution ---- */

/* Points per block execution: the input columns of one (at most 111 of them) stay within a
 * megabyte. */
enum { MANY_CHUNK = 1024, MANY_COLUMNS = SC_BRDF_FILE_MAX_VALUES + 3 * N_DIRECTIONS + 3 };

/* The input columns of n points in buf (MANY_COLUMNS × n): every parameter's value repeated,
 * then L, V, N, X, Y; *out the three output columns after them. */
static void point_columns(const sc_brdf *b, int n, const sc_brdf_point *pts, double *buf,
                          const double **in, double **out)
{
    int c = 0;
    for (int k = 0; k < b->file->n_values; k++, c++) {
        in[c] = buf + (size_t)c * (size_t)n;
        for (int i = 0; i < n; i++)
            buf[(size_t)c * (size_t)n + (size_t)i] = b->file_values[k];
    }
    for (int d = 0; d < N_DIRECTIONS; d++)
        for (int k = 0; k < 3; k++, c++) {
            double *column = buf + (size_t)c * (size_t)n;
            in[c] = column;
            for (int i = 0; i < n; i++) {
                const sc_frame *fr = pts[i].frame;
                const double *dirs[N_DIRECTIONS] = {pts[i].l, pts[i].v, fr->n, fr->t, fr->b};
                column[i] = dirs[d][k];
            }
        }
    for (int k = 0; k < 3; k++)
        out[k] = buf + (size_t)(c + k) * (size_t)n;
}

/* Up to MANY_CHUNK points in one block execution; the points before the first that failed
 * (their f written; the caller has set every f to NaN). */
static int eval_chunk(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts, double (*f)[3],
                      double *buf)
{
    const sc_brdf_file *file = b->file;
    const double *in[MANY_COLUMNS];
    double *out[3];
    point_columns(b, n, pts, buf, in, out);
    sc_lang_block job = {p, n, in, sc_program_values(file->prog) - 1, out, NULL, NULL};
    sc_lang_error e;
    long ran = sc_program_run_block(file->prog, &job, &e);
    for (int i = 0; i < ran; i++)
        for (int k = 0; k < 3; k++)
            f[i][k] = out[k][i];
    if (ran < n)
        record_error(file, &e);
    return (int)ran;
}

int sc_brdf_file_eval_many(sc_prec p, const sc_brdf *b, int n, const sc_brdf_point *pts,
                           double (*f)[3])
{
    const sc_brdf_file *file = b->file;
    int chunk = n < MANY_CHUNK ? n : MANY_CHUNK, done = 0;
    double *buf = malloc((size_t)MANY_COLUMNS * (size_t)(chunk > 0 ? chunk : 1) * sizeof *buf);
    for (int i = 0; i < n; i++)
        f[i][0] = f[i][1] = f[i][2] = NAN;
    if (!buf) { /* out of memory: one point at a time */
        for (; done < n && !atomic_load(&file->status->failed); done++)
            eval_points(p, b, 1, pts[done].frame, &pts[done].l, &pts[done].v, &f[done]);
        return done;
    }
    while (done < n && !atomic_load(&file->status->failed)) {
        int count = n - done < chunk ? n - done : chunk;
        done += eval_chunk(p, b, count, pts + done, f + done, buf);
    }
    free(buf);
    return done;
}

const char *sc_brdf_file_error(const sc_brdf_file *f)
{
    return atomic_load(&f->status->failed) ? f->status->message : NULL;
}
