/* Size checks every volume reader and writer makes before touching
 * memory or disk.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "formats.h"

#include "engine/error.h"

#include <stdint.h>

bool
ts_volume_bytes (size_t size, size_t channels, size_t *bytes)
{
  size_t total = channels;

  for (int i = 0; i < 3; i++)
    {
      if (size && total > SIZE_MAX / size)
        return false;
      total *= size;
    }
  *bytes = total;
  return true;
}

TsStatus
ts_volume_check_size (const char *path, uint64_t size, unsigned channels,
                      size_t max_bytes, size_t *bytes, TsError *error)
{
  if (size == 0)
    return ts_fail (error, TS_ERROR_BAD_FILE, "'%s' is malformed: its volume size is 0", path);
  if (size > TS_VOLUME_MAX_SIZE)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is malformed or unsupported: its volume size %llu exceeds %d",
                    path, (unsigned long long) size, TS_VOLUME_MAX_SIZE);
  if (!ts_volume_bytes ((size_t) size, channels, bytes))
    return ts_fail (error, TS_ERROR_TOO_LARGE,
                    "'%s' is too large: %llu^3 voxels of %u bytes do not fit in memory",
                    path, (unsigned long long) size, channels);
  if (max_bytes && *bytes > max_bytes)
    return ts_fail (error, TS_ERROR_TOO_LARGE,
                    "'%s' is too large: its %llu^3 voxels would need %.1f MiB, more than "
                    "the %.1f MiB allowed", path, (unsigned long long) size,
                    (double) *bytes / 1048576.0, (double) max_bytes / 1048576.0);
  return TS_OK;
}

TsStatus
ts_volume_check_writable (const TsVolume8 *v, TsError *error)
{
  size_t bytes;

  if (!v || !v->voxels)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no volume to write");
  if (v->size == 0 || v->size > TS_VOLUME_MAX_SIZE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the volume size %zu is outside 1..%d", v->size, TS_VOLUME_MAX_SIZE);
  if (v->channels < 1 || v->channels > 4)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "a volume has 1 to 4 channels, not %u", v->channels);
  if (!ts_volume_bytes (v->size, v->channels, &bytes))
    return ts_fail (error, TS_ERROR_TOO_LARGE, "the volume is too large for this machine");
  return TS_OK;
}
