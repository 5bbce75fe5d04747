/* Atomic replacement of a file (internal to the volume writers).
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

#endif
