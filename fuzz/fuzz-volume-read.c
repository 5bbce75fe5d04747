/* libFuzzer target: the volume file readers (ts_volume_read: .vol and
 * DDS) on arbitrary file contents. The reader takes a path, so each
 * input is written to an in-memory file (memfd) and read through
 * /proc/self/fd. A failure must leave the volume zeroed with a message;
 * a success must give a volume whose every voxel byte can be read.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#define _GNU_SOURCE
#include "volume/volume.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

/* Large enough for the seeds, small enough that hostile sizes are
 * refused by the cap rather than by running out of memory. */
#define MAX_VOXEL_BYTES ((size_t) 64 << 20)

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  int fd = memfd_create ("volume", 0);
  char path[64];
  TsVolume8 v;
  TsVolumeFormat format;
  TsError error = { TS_OK, "" };
  TsStatus status;

  if (fd < 0)
    abort ();
  for (size_t done = 0; done < size;)
    {
      ssize_t n = write (fd, data + done, size - done);
      if (n <= 0)
        abort ();
      done += (size_t) n;
    }
  snprintf (path, sizeof path, "/proc/self/fd/%d", fd);
  status = ts_volume_read (path, MAX_VOXEL_BYTES, &v, &format, &error);
  if (status == TS_OK)
    {
      size_t bytes;
      volatile unsigned sum = 0;
      if (!v.voxels || v.size == 0 || v.size > TS_VOLUME_MAX_SIZE || v.channels < 1 ||
          v.channels > 4 || !ts_volume_bytes (v.size, v.channels, &bytes) || bytes > MAX_VOXEL_BYTES)
        abort ();
      for (size_t i = 0; i < bytes; i++)
        sum += v.voxels[i];
      (void) sum;
      ts_volume8_clear (&v);
    }
  else if (v.voxels || v.size || error.message[0] == '\0')
    abort ();
  close (fd);
  return 0;
}
