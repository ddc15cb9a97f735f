/* Atomic file writing (shadecalc/file.h): a temporary in the target's directory, renamed over
 * the target once everything is written and synced. rename(2) replaces the target in one step,
 * so a reader sees the old file or the whole new one, never a part. */
#include "shadecalc/file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

struct sc_atomic_file {
    FILE *stream;
    char *path; /* the target */
    char *temp; /* NULL when writing to stdout ("-") */
};

static atomic_uint temp_counter;

static void report(char *err, size_t errsize, const char *path, int errnum)
{
    if (err && errsize)
        snprintf(err, errsize, "%s: %s", path, strerror(errnum ? errnum : EIO));
}

static char *copy_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *c = malloc(n);
    return c ? memcpy(c, s, n) : NULL;
}

/* "DIR/.BASE.PID.N.tmp" for path "DIR/BASE"; N counts temporaries made by this process. */
static char *temp_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    int dir_len = slash ? (int)(slash - path + 1) : 0;
    size_t size = strlen(path) + 48;
    char *temp = malloc(size);
    if (temp)
        snprintf(temp, size, "%.*s.%s.%ld.%u.tmp", dir_len, path, path + dir_len, (long)getpid(),
                 atomic_fetch_add(&temp_counter, 1u));
    return temp;
}

/* Creates a fresh temporary (O_EXCL: never an existing file), with the mode of the file it will
 * replace if there is one. Returns the descriptor and sets *temp_out, or -1 with errno. */
static int create_temp(const char *path, char **temp_out)
{
    struct stat target;
    int have_target = stat(path, &target) == 0;
    if (have_target && S_ISDIR(target.st_mode)) {
        errno = EISDIR;
        return -1;
    }
    for (int attempt = 0; attempt < 100; attempt++) {
        char *temp = temp_name(path);
        if (!temp) {
            errno = ENOMEM;
            return -1;
        }
        int fd = open(temp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            if (have_target && S_ISREG(target.st_mode))
                (void)fchmod(fd, target.st_mode & 07777); /* best effort, like cp */
            *temp_out = temp;
            return fd;
        }
        int saved = errno;
        free(temp);
        if (saved != EEXIST) {
            errno = saved;
            return -1;
        }
    }
    errno = EEXIST;
    return -1;
}

static sc_atomic_file *new_atomic_file(const char *path)
{
    sc_atomic_file *f = calloc(1, sizeof *f);
    if (f && !(f->path = copy_string(path))) {
        free(f);
        f = NULL;
    }
    return f;
}

static void free_atomic_file(sc_atomic_file *f)
{
    free(f->temp);
    free(f->path);
    free(f);
}

sc_atomic_file *sc_atomic_open(const char *path, char *err, size_t errsize)
{
    sc_atomic_file *f = new_atomic_file(path);
    if (!f) {
        report(err, errsize, path, ENOMEM);
        return NULL;
    }
    if (strcmp(path, "-") == 0) {
        f->stream = stdout;
        return f;
    }
    int fd = create_temp(path, &f->temp);
    if (fd >= 0 && !(f->stream = fdopen(fd, "wb"))) {
        int saved = errno;
        close(fd);
        unlink(f->temp);
        errno = saved;
    }
    if (!f->stream) {
        report(err, errsize, path, errno);
        free_atomic_file(f);
        return NULL;
    }
    return f;
}

FILE *sc_atomic_stream(sc_atomic_file *f)
{
    return f->stream;
}

const char *sc_atomic_temp_path(const sc_atomic_file *f)
{
    return f->temp;
}

/* Flushes and syncs the stream; 0, or the errno of the first failure. */
static int flush_and_sync(FILE *stream, int sync)
{
    errno = 0;
    if (fflush(stream) != 0 || ferror(stream))
        return errno ? errno : EIO;
    if (sync && fsync(fileno(stream)) != 0)
        return errno;
    return 0;
}

int sc_atomic_commit(sc_atomic_file *f, char *err, size_t errsize)
{
    if (!f->temp) { /* stdout: nothing to rename */
        int failure = flush_and_sync(f->stream, 0);
        if (failure)
            report(err, errsize, f->path, failure);
        free_atomic_file(f);
        return failure ? -1 : 0;
    }
    int failure = flush_and_sync(f->stream, 1);
    errno = 0;
    if (fclose(f->stream) != 0 && !failure)
        failure = errno ? errno : EIO;
    if (!failure && rename(f->temp, f->path) != 0)
        failure = errno;
    if (failure) {
        unlink(f->temp);
        report(err, errsize, f->path, failure);
    }
    free_atomic_file(f);
    return failure ? -1 : 0;
}

void sc_atomic_abort(sc_atomic_file *f)
{
    if (!f)
        return;
    if (f->temp) {
        fclose(f->stream);
        unlink(f->temp);
    }
    free_atomic_file(f);
}
