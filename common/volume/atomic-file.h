/* Atomic replacement of a file (internal: the engine's volume writers and
 * the ops' PNG sets).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_ATOMIC_FILE_H
#define TS_ATOMIC_FILE_H

#include "texsynth.h"

#include <stdio.h>

/* A file being written under a temporary name beside its target. */
typedef struct
{
  const char *path;       /* the target */
  char       *temp_path;  /* malloc'd; NULL once renamed or removed */
  FILE       *file;
} TsAtomicFile;

/* Create the temporary file. On failure nothing exists on disk. */
TsStatus ts_atomic_open (TsAtomicFile *f, const char *path, TsError *error);
/* Append bytes; on failure the caller must call ts_atomic_abort. */
TsStatus ts_atomic_write (TsAtomicFile *f, const void *data, size_t bytes, TsError *error);
/* Flush, fsync, close and rename over the target. On failure the
 * temporary file is removed and the target left as it was. */
TsStatus ts_atomic_commit (TsAtomicFile *f, TsError *error);
/* Close and remove the temporary file (after a failed write). */
void     ts_atomic_abort (TsAtomicFile *f);

/* The same steps for a writer that takes a file name, not a FILE (an
 * image saver). ts_atomic_reserve creates the empty temporary file beside
 * `path` and returns its name (malloc'd), or NULL with `error` filled. */
char *ts_atomic_reserve (const char *path, TsError *error);
/* Give the written temporary file, open as `fd`, the mode the target
 * keeps (or a new file's) and sync it to disk; 0 or an errno value. */
int   ts_atomic_seal (int fd, const char *target);
/* After renaming temporary files over their targets: make the renames
 * into the folder of `path` durable (best effort). */
void  ts_atomic_sync_folder (const char *path);

#endif
