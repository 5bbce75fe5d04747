/* The volume formats' readers and the checks they share (internal):
 * the dispatcher (read.c) calls the readers; the readers and writers
 * call the checks, never the dispatcher.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_VOLUME_FORMATS_H
#define TS_VOLUME_FORMATS_H

#include "volume.h"
#include "input-file.h"

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
