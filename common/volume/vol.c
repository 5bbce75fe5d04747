/* The .vol solid-texture format of Kopf et al. 2007's viewers: a
 * 4096-byte header laid out as the little-endian C struct
 *   { char magic[4] = "VOLU"; int32 version = 4; char name[256]; bool wrap;
 *     int32 size; int32 channels; int32 bytes_per_channel = 1; }
 * with natural alignment (offsets 0, 4, 8, 264, 268, 272, 276), zero
 * padded, then size^3 * channels bytes, x fastest, then y, then z.
 * Fields are (de)serialised byte by byte, never as a struct, so the
 * files are the same on any compiler and byte order.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "formats.h"

#include "atomic-file.h"
#include "engine/error.h"

#include <string.h>

TsStatus
ts_volume_write_vol (const char      *path,
                     const char      *name,
                     const TsVolume8 *v,
                     TsError         *error)
{
  uint8_t header[TS_VOL_HEADER_SIZE] = { 0 };
  TsAtomicFile f;
  size_t bytes = 0;
  TsStatus status;

  status = ts_volume_check_writable (v, error);
  if (status != TS_OK)
    return status;
  ts_volume_bytes (v->size, v->channels, &bytes);

  memcpy (header + TS_VOL_OFFSET_MAGIC, "VOLU", 4);
  ts_put_le32 (header + TS_VOL_OFFSET_VERSION, TS_VOL_VERSION);
  if (name)
    {
      /* Keep the terminating NUL the viewers expect. */
      size_t length = strlen (name);
      if (length > TS_VOL_NAME_SIZE - 1)
        length = TS_VOL_NAME_SIZE - 1;
      memcpy (header + TS_VOL_OFFSET_NAME, name, length);
    }
  header[TS_VOL_OFFSET_WRAP] = v->wrap ? 1 : 0;
  ts_put_le32 (header + TS_VOL_OFFSET_SIZE, (uint32_t) v->size);
  ts_put_le32 (header + TS_VOL_OFFSET_CHANNELS, v->channels);
  ts_put_le32 (header + TS_VOL_OFFSET_BYTES_PER_CHANNEL, 1);

  status = ts_atomic_open (&f, path, error);
  if (status != TS_OK)
    return status;
  status = ts_atomic_write (&f, header, sizeof header, error);
  if (status == TS_OK)
    status = ts_atomic_write (&f, v->voxels, bytes, error);
  if (status != TS_OK)
    {
      ts_atomic_abort (&f);
      return status;
    }
  return ts_atomic_commit (&f, error);
}

TsStatus
ts_volume_read_vol_file (TsInputFile *f, size_t max_bytes, TsVolume8 *v, TsError *error)
{
  uint8_t header[TS_VOL_HEADER_SIZE];
  uint32_t version, size, channels, bytes_per_channel;
  size_t bytes;
  TsStatus status;
  void *data;

  if (f->length < TS_VOL_HEADER_SIZE)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is truncated: a .vol header is %d bytes, the file has only %llu",
                    f->path, TS_VOL_HEADER_SIZE, (unsigned long long) f->length);
  status = ts_input_read (f, header, sizeof header, error);
  if (status != TS_OK)
    return status;

  version = ts_get_le32 (header + TS_VOL_OFFSET_VERSION);
  size = ts_get_le32 (header + TS_VOL_OFFSET_SIZE);
  channels = ts_get_le32 (header + TS_VOL_OFFSET_CHANNELS);
  bytes_per_channel = ts_get_le32 (header + TS_VOL_OFFSET_BYTES_PER_CHANNEL);
  if (version != TS_VOL_VERSION)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is a .vol file of version %lu; only version %d is supported",
                    f->path, (unsigned long) version, TS_VOL_VERSION);
  if (channels < 1 || channels > 4)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is malformed: %lu channels (a .vol file has 1 to 4)",
                    f->path, (unsigned long) channels);
  if (bytes_per_channel != 1)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' has %lu bytes per channel; only 8-bit (1 byte) volumes are supported",
                    f->path, (unsigned long) bytes_per_channel);
  /* An int32 field: a "negative" size reads as a huge one and is refused. */
  status = ts_volume_check_size (f->path, size, channels, max_bytes, &bytes, error);
  if (status != TS_OK)
    return status;
  if (f->length - TS_VOL_HEADER_SIZE < bytes)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is truncated: its header announces %lu^3 voxels of %lu channels "
                    "(%zu bytes) but only %llu bytes follow the header",
                    f->path, (unsigned long) size, (unsigned long) channels, bytes,
                    (unsigned long long) (f->length - TS_VOL_HEADER_SIZE));

  status = ts_input_read_new (f, bytes, &data, error);
  if (status != TS_OK)
    return status;
  v->voxels = data;
  v->size = size;
  v->channels = channels;
  v->wrap = header[TS_VOL_OFFSET_WRAP] != 0;
  return TS_OK;
}
