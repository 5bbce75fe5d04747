/* File plumbing shared by the volume readers and writers (internal):
 * atomic replacement of a file, checked reads, little-endian fields.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_VOLUME_IO_H
#define TS_VOLUME_IO_H

#include "volume-file.h"

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
void     ts_input_close (TsInputFile *f);

/* Format readers, called with the file positioned at its start and the
 * magic already checked; they fill `v` only on success. */
TsStatus ts_volume_read_vol_file (TsInputFile *f, size_t max_bytes, TsVolume8 *v, TsError *error);
TsStatus ts_volume_read_dds_file (TsInputFile *f, size_t max_bytes, TsVolume8 *v, TsError *error);

/* Checks every reader makes before allocating: sane cube size, voxel
 * bytes representable and within `max_bytes` (0: no cap). */
TsStatus ts_volume_check_size (const char *path, uint64_t size, unsigned channels,
                               size_t max_bytes, size_t *bytes, TsError *error);

/* Checks every writer makes: voxels present, size 1..TS_VOLUME_MAX_SIZE,
 * 1 to 4 channels. */
TsStatus ts_volume_check_writable (const TsVolume8 *v, TsError *error);

static inline void
ts_put_le32 (uint8_t *p, uint32_t value)
{
  p[0] = (uint8_t) value;
  p[1] = (uint8_t) (value >> 8);
  p[2] = (uint8_t) (value >> 16);
  p[3] = (uint8_t) (value >> 24);
}

static inline uint32_t
ts_get_le32 (const uint8_t *p)
{
  return (uint32_t) p[0] | (uint32_t) p[1] << 8 | (uint32_t) p[2] << 16 | (uint32_t) p[3] << 24;
}

#endif
