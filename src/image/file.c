/* Atomic file writing (shadecalc/file.h): a temporary in the target's directory, renamed over
 * the target once everything is written and synced. rename(2) replaces the target in one step,
 * so a reader sees the old file or the whole new one, never a part. What is not a regular file
 * (a device, a FIFO, a terminal, standard output) is written straight into instead: renaming
 * over it would replace the device node or the pipe, and its reader would get nothing. */
#include "shadecalc/file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { REGISTRY_SLOTS = 32, MAX_LINKS = 40 };

struct sc_atomic_file {
    FILE *stream;
    char *path;   /* the target as given, for messages */
    char *target; /* where the temporary is renamed: path with its symbolic links followed */
    int slot;     /* the temporary's registry slot, -1 when writing straight (no temporary) */
};

/* ---- the registry of temporaries, removed by the signal handler ---- */

/* The handler reads these: lock-free atomics and fixed buffers only (C11 7.14.1.1, and no free()
 * that the handler could race with). A slot is FREE, CLAIMED (its path being written) or LIVE. */
_Static_assert(ATOMIC_INT_LOCK_FREE == 2, "the signal handler needs lock-free atomic ints");
enum { SLOT_FREE, SLOT_CLAIMED, SLOT_LIVE };
static atomic_int slot_state[REGISTRY_SLOTS];
static char slot_path[REGISTRY_SLOTS][PATH_MAX];
static atomic_uint temp_counter;
static atomic_int read_only_allowed;

/* Claims a slot for temp and marks it live; the slot, or -1 with errno. */
static int register_temp(const char *temp)
{
    if (strlen(temp) >= PATH_MAX) {
        errno = ENAMETOOLONG;
        return -1;
    }
    for (int i = 0; i < REGISTRY_SLOTS; i++) {
        int expected = SLOT_FREE;
        if (atomic_compare_exchange_strong(&slot_state[i], &expected, SLOT_CLAIMED)) {
            strcpy(slot_path[i], temp);
            atomic_store(&slot_state[i], SLOT_LIVE);
            return i;
        }
    }
    errno = EMFILE; /* more than REGISTRY_SLOTS atomic files open at once */
    return -1;
}

static void unregister_temp(int slot) { atomic_store(&slot_state[slot], SLOT_FREE); }

/* SIGINT, SIGTERM, SIGHUP: remove every live temporary, then die of the signal (the handler is
 * installed with SA_RESETHAND, so raise() gets the default action). Whichever thread runs it, the
 * registry is the process's. */
static void remove_temporaries(int sig)
{
    int saved = errno;
    for (int i = 0; i < REGISTRY_SLOTS; i++)
        if (atomic_load(&slot_state[i]) == SLOT_LIVE)
            unlink(slot_path[i]);
    errno = saved;
    raise(sig);
}

int sc_atomic_remove_on_signals(void)
{
    static const int signals[] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction action = {.sa_handler = remove_temporaries, .sa_flags = SA_RESETHAND};
    sigemptyset(&action.sa_mask);
    for (size_t i = 0; i < sizeof signals / sizeof signals[0]; i++) {
        struct sigaction old;
        if (sigaction(signals[i], NULL, &old) != 0)
            return -1;
        if (old.sa_handler != SIG_IGN && sigaction(signals[i], &action, NULL) != 0)
            return -1; /* an ignored signal (nohup, a background job) stays ignored */
    }
    /* Past `ulimit -f` a write fails with EFBIG (and the temporary is removed) instead of the
     * process being killed by SIGXFSZ with the temporary left behind. */
    return signal(SIGXFSZ, SIG_IGN) == SIG_ERR ? -1 : 0;
}

void sc_atomic_allow_read_only(int allow) { atomic_store(&read_only_allowed, allow != 0); }

/* ---- paths ---- */

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

/* The length of "DIR/" in "DIR/BASE" (0 without a slash). */
static size_t dir_length(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? (size_t)(slash - path + 1) : 0;
}

/* What the symbolic link at link points to: its contents, relative to link's directory unless
 * absolute. NULL with errno. */
static char *link_target(const char *link)
{
    char contents[PATH_MAX];
    ssize_t n = readlink(link, contents, sizeof contents - 1);
    if (n < 0)
        return NULL;
    contents[n] = '\0';
    size_t dir_len = contents[0] == '/' ? 0 : dir_length(link);
    char *target = malloc(dir_len + (size_t)n + 1);
    if (!target) {
        errno = ENOMEM;
        return NULL;
    }
    memcpy(target, link, dir_len);
    memcpy(target + dir_len, contents, (size_t)n + 1);
    return target;
}

/* path with the symbolic links of its last component followed, however many (a dangling chain
 * ends at the name it points to). NULL with errno (ELOOP, ENOMEM). */
static char *follow_links(const char *path)
{
    char *current = copy_string(path);
    if (!current)
        errno = ENOMEM;
    for (int hops = 0; current && hops <= MAX_LINKS; hops++) {
        struct stat st;
        if (lstat(current, &st) != 0 || !S_ISLNK(st.st_mode))
            return current;
        char *next = link_target(current);
        free(current);
        current = next;
    }
    if (current)
        errno = ELOOP;
    free(current);
    return NULL;
}

/* "DIR/.BASE.PID.N.tmp" for path "DIR/BASE"; N counts temporaries made by this process. */
static char *temp_name(const char *path)
{
    size_t dir_len = dir_length(path);
    size_t size = strlen(path) + 48;
    char *temp = malloc(size);
    if (temp)
        snprintf(temp, size, "%.*s.%s.%ld.%u.tmp", (int)dir_len, path, path + dir_len,
                 (long)getpid(), atomic_fetch_add(&temp_counter, 1u));
    return temp;
}

/* ---- opening ---- */

/* The owner and permission bits of the file replaced, best effort (like cp -p): the owner only
 * as root, the group where the caller belongs to it. */
static void copy_owner_and_mode(int fd, const struct stat *target)
{
    if (fchown(fd, target->st_uid, target->st_gid) != 0 &&
        fchown(fd, (uid_t)-1, target->st_gid) != 0) {
        /* not the caller's to give away: the new file stays the caller's */
    }
    if (fchmod(fd, target->st_mode & 07777) != 0) {
        /* the temporary keeps 0666 & ~umask */
    }
}

/* Creates a fresh temporary next to target and registers it (the name holds our PID, so a file
 * already there is ours or a dead process's: the signal handler may remove it). The descriptor,
 * or -1 with errno. */
static int create_temp(sc_atomic_file *f, const struct stat *replaced)
{
    for (int attempt = 0; attempt < 100; attempt++) {
        char *temp = temp_name(f->target);
        if (!temp) {
            errno = ENOMEM;
            return -1;
        }
        f->slot = register_temp(temp);
        int fd = f->slot < 0 ? -1 : open(temp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        int saved = errno;
        free(temp);
        if (fd >= 0) {
            if (replaced)
                copy_owner_and_mode(fd, replaced);
            return fd;
        }
        if (f->slot >= 0)
            unregister_temp(f->slot);
        f->slot = -1;
        errno = saved;
        if (saved != EEXIST)
            return -1;
    }
    errno = EEXIST;
    return -1;
}

/* A regular file the caller may not write, or (for root, who may write anything) whose mode has
 * no write bit. */
static int is_read_only(const char *path, const struct stat *st)
{
    return access(path, W_OK) != 0 || (st->st_mode & 0222) == 0;
}

/* path names the file standard output is open on for writing (/dev/stdout, /dev/fd/1, or the
 * same file by another name). */
static int is_stdout(const struct stat *st)
{
    struct stat out;
    int flags = fcntl(STDOUT_FILENO, F_GETFL);
    return flags != -1 && (flags & O_ACCMODE) != O_RDONLY && fstat(STDOUT_FILENO, &out) == 0 &&
           out.st_dev == st->st_dev && out.st_ino == st->st_ino;
}

/* A temporary next to the regular file (or free name) at the end of path's links. 0, or -1
 * with err. */
static int open_replacement(sc_atomic_file *f, char *err, size_t errsize)
{
    if (!(f->target = follow_links(f->path))) {
        report(err, errsize, f->path, errno);
        return -1;
    }
    struct stat st;
    int exists = stat(f->target, &st) == 0;
    if (exists && is_read_only(f->target, &st) && !atomic_load(&read_only_allowed)) {
        if (err && errsize)
            snprintf(err, errsize, "%s: read-only file, not replaced (--force replaces it)",
                     f->path);
        return -1;
    }
    int fd = create_temp(f, exists ? &st : NULL);
    if (fd >= 0 && !(f->stream = fdopen(fd, "wb"))) {
        int saved = errno;
        close(fd);
        unlink(slot_path[f->slot]);
        unregister_temp(f->slot);
        f->slot = -1;
        errno = saved;
    }
    if (!f->stream) {
        report(err, errsize, f->path, errno);
        return -1;
    }
    return 0;
}

/* A device, FIFO or terminal: opened for writing as it is (a FIFO waits for its reader). */
static int open_straight(sc_atomic_file *f, char *err, size_t errsize)
{
    int fd = open(f->path, O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd >= 0 && !(f->stream = fdopen(fd, "wb")))
        close(fd);
    if (!f->stream)
        report(err, errsize, f->path, errno);
    return f->stream ? 0 : -1;
}

static void free_atomic_file(sc_atomic_file *f)
{
    free(f->target);
    free(f->path);
    free(f);
}

/* Opens the stream for f->path: stdout, straight into a non-regular file, or a temporary. */
static int open_target(sc_atomic_file *f, char *err, size_t errsize)
{
    struct stat st;
    if (strcmp(f->path, "-") == 0) {
        f->stream = stdout;
        return 0;
    }
    if (stat(f->path, &st) != 0) {
        if (errno == ENOENT) /* a new file, or the end of a dangling link */
            return open_replacement(f, err, errsize);
        report(err, errsize, f->path, errno);
        return -1;
    }
    if (is_stdout(&st)) {
        f->stream = stdout;
        return 0;
    }
    if (S_ISDIR(st.st_mode)) {
        report(err, errsize, f->path, EISDIR);
        return -1;
    }
    return S_ISREG(st.st_mode) ? open_replacement(f, err, errsize) : open_straight(f, err, errsize);
}

sc_atomic_file *sc_atomic_open(const char *path, char *err, size_t errsize)
{
    sc_atomic_file *f = calloc(1, sizeof *f);
    if (!f || !(f->path = copy_string(path))) {
        free(f);
        report(err, errsize, path, ENOMEM);
        return NULL;
    }
    f->slot = -1;
    if (open_target(f, err, errsize) != 0) {
        free_atomic_file(f);
        return NULL;
    }
    return f;
}

FILE *sc_atomic_stream(sc_atomic_file *f) { return f->stream; }

const char *sc_atomic_temp_path(const sc_atomic_file *f)
{
    return f->slot >= 0 ? slot_path[f->slot] : NULL;
}

/* ---- finishing ---- */

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

/* Flushes (and syncs a temporary), then closes the stream unless it is stdout; 0 or an errno. */
static int finish_stream(sc_atomic_file *f)
{
    int failure = flush_and_sync(f->stream, f->slot >= 0);
    if (f->stream == stdout)
        return failure;
    errno = 0;
    if (fclose(f->stream) != 0 && !failure)
        failure = errno ? errno : EIO;
    return failure;
}

int sc_atomic_commit(sc_atomic_file *f, char *err, size_t errsize)
{
    int failure = finish_stream(f);
    if (f->slot >= 0) {
        if (!failure && rename(slot_path[f->slot], f->target) != 0)
            failure = errno;
        if (failure)
            unlink(slot_path[f->slot]);
        unregister_temp(f->slot);
    }
    if (failure)
        report(err, errsize, f->path, failure);
    free_atomic_file(f);
    return failure ? -1 : 0;
}

void sc_atomic_abort(sc_atomic_file *f)
{
    if (!f)
        return;
    if (f->stream != stdout)
        fclose(f->stream);
    if (f->slot >= 0) {
        unlink(slot_path[f->slot]);
        unregister_temp(f->slot);
    }
    free_atomic_file(f);
}
