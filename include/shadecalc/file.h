/*
 * shadecalc/file.h — writing a file atomically: the whole new file or nothing.
 *
 *   sc_atomic_file          an open atomic write (opaque)
 *   sc_atomic_open          open a temporary next to the target
 *   sc_atomic_stream        the FILE * to write to
 *   sc_atomic_temp_path     the temporary's path, for libraries that open files by name
 *   sc_atomic_commit        flush, fsync, close, rename over the target
 *   sc_atomic_abort         close and remove the temporary
 *   sc_atomic_allow_read_only   let sc_atomic_open replace read-only files (--force)
 *   sc_atomic_remove_on_signals remove the temporaries on SIGINT, SIGTERM, SIGHUP
 *
 * What the target is decides how it is written:
 *   - "-", or the file standard output is open on (/dev/stdout, /dev/fd/1): stdout itself; no
 *     temporary, commit only flushes.
 *   - a regular file, or no file yet: a temporary ".NAME.PID.N.tmp" in the target's directory
 *     (a rename never crosses file systems), created with O_EXCL and mode 0666 & ~umask, then
 *     renamed over the target at commit. A symbolic link is followed (however many) and the file
 *     it ends at is replaced in that file's own directory, so the link stays a link; a dangling
 *     link gets its target created. A replaced file keeps its permission bits, and its owner and
 *     group where the caller may give them (as root). A read-only file (one the caller may not
 *     write, or, for root, one without any write bit) is refused unless
 *     sc_atomic_allow_read_only(1) was called. A file with other hard links gets a new inode:
 *     the other names keep the old contents.
 *   - anything else (a character or block device, a FIFO, a terminal): opened and written
 *     straight into, not replaced: /dev/null stays the device, a FIFO's reader gets the data
 *     (opening a FIFO waits for its reader). Such a write is not atomic.
 * Until commit the target, if any, is untouched; a failed commit removes the temporary and
 * leaves the target as it was. Errors are written to err as "PATH: reason" (PATH the target,
 * as given).
 */
#ifndef SHADECALC_FILE_H
#define SHADECALC_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef struct sc_atomic_file sc_atomic_file;

/* Opens path for writing as above; NULL with err ("PATH: reason") on failure (missing
 * directory, no permission, path is a directory, a read-only file, out of memory). */
sc_atomic_file *sc_atomic_open(const char *path, char *err, size_t errsize);

/* The stream to write to (stdout for "-" and the file stdout is open on). Do not fclose it. */
FILE *sc_atomic_stream(sc_atomic_file *f);

/* The temporary's path (NULL when writing straight: stdout, a device, a FIFO). A library may
 * write to it by name before the commit. */
const char *sc_atomic_temp_path(const sc_atomic_file *f);

/* Flushes, fsyncs, closes, renames the temporary over the target (written straight: flushes
 * and closes, stdout only flushed). 0, or -1 with err (the temporary is removed, the target
 * untouched). Frees f. */
int sc_atomic_commit(sc_atomic_file *f, char *err, size_t errsize);

/* Closes and removes the temporary; the target is untouched (written straight: what was
 * written stays written). Frees f. NULL is a no-op. */
void sc_atomic_abort(sc_atomic_file *f);

/* Whether sc_atomic_open may replace a read-only regular file (process-wide; default 0: it
 * refuses with "PATH: read-only file, not replaced (--force replaces it)"). */
void sc_atomic_allow_read_only(int allow);

/* Installs a handler for SIGINT, SIGTERM and SIGHUP (except those ignored, as under nohup)
 * that removes every temporary not yet committed or aborted, then lets the signal kill the
 * process (exit status 128 + the signal's number in a shell); whichever thread receives it.
 * Also ignores SIGXFSZ, so that a write beyond `ulimit -f` fails with EFBIG and removes its
 * temporary. Call it once at program start; 0, or -1 with errno. */
int sc_atomic_remove_on_signals(void);

SC_END_DECLS

#endif
