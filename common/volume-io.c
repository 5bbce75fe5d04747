/* Atomic file replacement, checked reading and format detection for the
 * volume files.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "volume-io.h"

#include "schedule.h" /* ts_fail */

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* --- writing ------------------------------------------------------------ */

/* The mode a newly created file would get (mkstemp makes 0600 files):
 * the old file's, or 0666 less the umask. The umask is read from /proc
 * because umask() can only be queried by changing it, which would race
 * with other threads. */
static mode_t
new_file_mode (const char *path)
{
  struct stat st;
  mode_t mask = 022;
  FILE *status;
  char line[128];

  if (stat (path, &st) == 0 && S_ISREG (st.st_mode))
    return st.st_mode & 07777;
  status = fopen ("/proc/self/status", "r");
  if (status)
    {
      while (fgets (line, sizeof line, status))
        if (strncmp (line, "Umask:", 6) == 0)
          {
            mask = (mode_t) strtoul (line + 6, NULL, 8);
            break;
          }
      fclose (status);
    }
  return 0666 & ~mask;
}

static TsStatus
write_failure (const char *path, int errnum, TsError *error)
{
  return ts_fail (error, TS_ERROR_IO, "cannot write '%s': %s", path, strerror (errnum));
}

TsStatus
ts_atomic_open (TsAtomicFile *f, const char *path, TsError *error)
{
  static const char suffix[] = ".tmp-XXXXXX";
  size_t length;
  int fd;

  f->path = path;
  f->temp_path = NULL;
  f->file = NULL;
  if (!path || !*path)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no file name given");

  length = strlen (path);
  f->temp_path = malloc (length + sizeof suffix);
  if (!f->temp_path)
    return ts_fail (error, TS_ERROR_OUT_OF_MEMORY, "out of memory writing '%s'", path);
  memcpy (f->temp_path, path, length);
  memcpy (f->temp_path + length, suffix, sizeof suffix);

  fd = mkstemp (f->temp_path);
  if (fd < 0)
    {
      int errnum = errno;
      free (f->temp_path);
      f->temp_path = NULL;
      return write_failure (path, errnum, error);
    }
  f->file = fdopen (fd, "wb");
  if (!f->file)
    {
      int errnum = errno;
      close (fd);
      ts_atomic_abort (f);
      return write_failure (path, errnum, error);
    }
  return TS_OK;
}

TsStatus
ts_atomic_write (TsAtomicFile *f, const void *data, size_t bytes, TsError *error)
{
  errno = 0;
  if (bytes && fwrite (data, 1, bytes, f->file) != bytes)
    return write_failure (f->path, errno ? errno : EIO, error);
  return TS_OK;
}

void
ts_atomic_abort (TsAtomicFile *f)
{
  if (f->file)
    fclose (f->file);
  f->file = NULL;
  if (f->temp_path)
    {
      unlink (f->temp_path);
      free (f->temp_path);
    }
  f->temp_path = NULL;
}

/* Make the rename itself durable; best effort, the data already is. */
static void
sync_folder (const char *path)
{
  const char *slash = strrchr (path, '/');
  char *folder;
  int fd;

  if (!slash)
    folder = strdup (".");
  else if (slash == path)
    folder = strdup ("/");
  else
    {
      folder = malloc ((size_t) (slash - path) + 1);
      if (folder)
        {
          memcpy (folder, path, (size_t) (slash - path));
          folder[slash - path] = '\0';
        }
    }
  if (!folder)
    return;
  fd = open (folder, O_RDONLY);
  if (fd >= 0)
    {
      fsync (fd);
      close (fd);
    }
  free (folder);
}

TsStatus
ts_atomic_commit (TsAtomicFile *f, TsError *error)
{
  int errnum = 0;

  errno = 0;
  if (fflush (f->file) != 0 || ferror (f->file))
    errnum = errno ? errno : EIO;
  else if (fchmod (fileno (f->file), new_file_mode (f->path)) != 0)
    errnum = errno;
  else if (fsync (fileno (f->file)) != 0)
    errnum = errno;

  /* fclose may report a delayed write error (NFS) as well. */
  if (fclose (f->file) != 0 && !errnum)
    errnum = errno ? errno : EIO;
  f->file = NULL;
  if (!errnum && rename (f->temp_path, f->path) != 0)
    errnum = errno;
  if (errnum)
    {
      ts_atomic_abort (f);
      return write_failure (f->path, errnum, error);
    }
  free (f->temp_path);
  f->temp_path = NULL;
  sync_folder (f->path);
  return TS_OK;
}

/* --- reading ------------------------------------------------------------ */

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

void
ts_input_close (TsInputFile *f)
{
  if (f->file)
    fclose (f->file);
  f->file = NULL;
}

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
