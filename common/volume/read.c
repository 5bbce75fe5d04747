/* Reading a volume file: the format is recognised by its magic bytes and
 * handed to that format's reader.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "formats.h"
#include "input-file.h"

#include "engine/error.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void
ts_volume8_clear (TsVolume8 *v)
{
  if (!v)
    return;
  free (v->voxels);
  memset (v, 0, sizeof *v);
}

TsStatus
ts_volume_read (const char     *path,
                size_t          max_bytes,
                TsVolume8      *v,
                TsVolumeFormat *format,
                TsError        *error)
{
  TsInputFile f;
  uint8_t magic[4];
  TsStatus status;

  if (!v)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no volume to read into");
  memset (v, 0, sizeof *v);
  status = ts_input_open (&f, path, error);
  if (status != TS_OK)
    return status;

  if (f.length < sizeof magic)
    status = ts_fail (error, TS_ERROR_BAD_FILE,
                      "'%s' is not a volume file: it is only %llu bytes long",
                      path, (unsigned long long) f.length);
  else
    status = ts_input_read (&f, magic, sizeof magic, error);
  if (status == TS_OK && fseek (f.file, 0, SEEK_SET) != 0)
    status = ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", path, strerror (errno));

  if (status == TS_OK)
    {
      if (memcmp (magic, "VOLU", 4) == 0)
        {
          status = ts_volume_read_vol_file (&f, max_bytes, v, error);
          if (format && status == TS_OK)
            *format = TS_VOLUME_FORMAT_VOL;
        }
      else if (memcmp (magic, "DDS ", 4) == 0)
        {
          status = ts_volume_read_dds_file (&f, max_bytes, v, error);
          if (format && status == TS_OK)
            *format = TS_VOLUME_FORMAT_DDS;
        }
      else
        status = ts_fail (error, TS_ERROR_BAD_FILE,
                          "'%s' is not a volume file: it starts with neither \"VOLU\" (.vol) "
                          "nor \"DDS \" (.dds)", path);
    }
  ts_input_close (&f);
  if (status != TS_OK)
    ts_volume8_clear (v);
  return status;
}
