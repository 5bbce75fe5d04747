/* Checked reading of a regular file of known length.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "input-file.h"

#include "engine/error.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

TsStatus
ts_input_open (TsInputFile *f, const char *path, TsError *error)
{
  struct stat st;
  int fd, flags;

  f->path = path;
  f->file = NULL;
  f->length = 0;
  if (!path || !*path)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no file name given");
  /* O_NONBLOCK: opening a FIFO must not wait for a writer; it is then
   * refused as not a regular file. */
  fd = open (path, O_RDONLY | O_NONBLOCK);
  if (fd < 0)
    return ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", path, strerror (errno));
  if (fstat (fd, &st) != 0)
    {
      int errnum = errno;
      close (fd);
      return ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", path, strerror (errnum));
    }
  if (!S_ISREG (st.st_mode))
    {
      close (fd);
      return ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", path,
                      S_ISDIR (st.st_mode) ? strerror (EISDIR) : "not a regular file");
    }
  flags = fcntl (fd, F_GETFL);
  if (flags == -1 || fcntl (fd, F_SETFL, flags & ~O_NONBLOCK) == -1
      || !(f->file = fdopen (fd, "rb")))
    {
      int errnum = errno;
      close (fd);
      return ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", path, strerror (errnum));
    }
  f->length = (uint64_t) st.st_size;
  return TS_OK;
}

TsStatus
ts_input_read (TsInputFile *f, void *data, size_t bytes, TsError *error)
{
  if (bytes && fread (data, 1, bytes, f->file) != bytes)
    {
      if (ferror (f->file))
        return ts_fail (error, TS_ERROR_IO, "cannot read '%s': %s", f->path,
                        strerror (errno ? errno : EIO));
      return ts_fail (error, TS_ERROR_BAD_FILE, "'%s' is truncated", f->path);
    }
  return TS_OK;
}

TsStatus
ts_input_read_new (TsInputFile *f, size_t bytes, void **data, TsError *error)
{
  TsStatus status;

  *data = malloc (bytes);
  if (!*data)
    return ts_fail (error, TS_ERROR_OUT_OF_MEMORY,
                    "out of memory reading '%s' (%.1f MiB)", f->path, (double) bytes / 1048576.0);
  status = ts_input_read (f, *data, bytes, error);
  if (status != TS_OK)
    {
      free (*data);
      *data = NULL;
    }
  return status;
}

void
ts_input_close (TsInputFile *f)
{
  if (f->file)
    fclose (f->file);
  f->file = NULL;
}
