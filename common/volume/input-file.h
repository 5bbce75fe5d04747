/* Checked reading of a regular file (internal to the volume readers).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_INPUT_FILE_H
#define TS_INPUT_FILE_H

#include "texsynth.h"

#include <stdio.h>

/* A regular file opened for reading, with its length. */
typedef struct
{
  const char *path;
  FILE       *file;
  uint64_t    length;
} TsInputFile;

TsStatus ts_input_open (TsInputFile *f, const char *path, TsError *error);
/* Read exactly `bytes`; a short read is TS_ERROR_BAD_FILE (truncated). */
TsStatus ts_input_read (TsInputFile *f, void *data, size_t bytes, TsError *error);
/* Allocate `bytes` with malloc and read them into *data; on failure
 * *data is NULL and nothing stays allocated. */
TsStatus ts_input_read_new (TsInputFile *f, size_t bytes, void **data, TsError *error);
void     ts_input_close (TsInputFile *f);

#endif
