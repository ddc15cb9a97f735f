/*
 * shadecalc/file.h — writing a file atomically: the whole new file or nothing.
 *
 *   sc_atomic_file          an open atomic write (opaque)
 *   sc_atomic_open          open a temporary next to the target
 *   sc_atomic_stream        the FILE * to write to
 *   sc_atomic_temp_path     the temporary's path, for libraries that open files by name
 *   sc_atomic_commit        flush, fsync, close, rename over the target
 *   sc_atomic_abort         close and remove the temporary
 *
 * The temporary is ".NAME.PID.N.tmp" in the target's directory (a rename never crosses file
 * systems), created with O_EXCL and mode 0666 & ~umask, or the mode of the file it replaces.
 * Until commit the target, if any, is untouched; a failed commit removes the temporary and
 * leaves the target as it was. The path "-" means stdout: no temporary, commit only flushes.
 * Errors are written to err as "PATH: reason" (PATH the target, as given).
 */
#ifndef SHADECALC_FILE_H
#define SHADECALC_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef struct sc_atomic_file sc_atomic_file;

/* Opens a temporary next to path for writing; NULL with err ("PATH: reason") on failure
 * (missing directory, no permission, path is a directory, out of memory). */
sc_atomic_file *sc_atomic_open(const char *path, char *err, size_t errsize);

/* The stream to write to (stdout for "-"). Do not fclose it. */
FILE *sc_atomic_stream(sc_atomic_file *f);

/* The temporary's path (NULL for "-"). A library may write to it by name before the commit. */
const char *sc_atomic_temp_path(const sc_atomic_file *f);

/* Flushes, fsyncs, closes, renames the temporary over the target. 0, or -1 with err (the
 * temporary is removed, the target untouched). Frees f. */
int sc_atomic_commit(sc_atomic_file *f, char *err, size_t errsize);

/* Closes and removes the temporary; the target is untouched. Frees f. NULL is a no-op. */
void sc_atomic_abort(sc_atomic_file *f);

SC_END_DECLS

#endif
