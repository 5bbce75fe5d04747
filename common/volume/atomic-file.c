/* Atomic replacement of a file: written under a temporary name, synced
 * and renamed over its target, so readers see the old file or the new one.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "atomic-file.h"

#include "engine/error.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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

/* Creates the temporary file beside `path`: its name (malloc'd) in
 * `temp_path` and its descriptor in `fd`. On failure nothing exists. */
static TsStatus
create_temp (const char *path, char **temp_path, int *fd, TsError *error)
{
  static const char suffix[] = ".tmp-XXXXXX";
  size_t length;

  *temp_path = NULL;
  if (!path || !*path)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no file name given");

  length = strlen (path);
  *temp_path = malloc (length + sizeof suffix);
  if (!*temp_path)
    return ts_fail (error, TS_ERROR_OUT_OF_MEMORY, "out of memory writing '%s'", path);
  memcpy (*temp_path, path, length);
  memcpy (*temp_path + length, suffix, sizeof suffix);

  *fd = mkstemp (*temp_path);
  if (*fd < 0)
    {
      int errnum = errno;
      free (*temp_path);
      *temp_path = NULL;
      return write_failure (path, errnum, error);
    }
  return TS_OK;
}

TsStatus
ts_atomic_open (TsAtomicFile *f, const char *path, TsError *error)
{
  TsStatus status;
  int fd;

  f->path = path;
  f->temp_path = NULL;
  f->file = NULL;
  status = create_temp (path, &f->temp_path, &fd, error);
  if (status != TS_OK)
    return status;
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

/* Best effort: the data already is durable. */
void
ts_atomic_sync_folder (const char *path)
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

char *
ts_atomic_reserve (const char *path, TsError *error)
{
  char *temp_path;
  int fd;

  if (create_temp (path, &temp_path, &fd, error) != TS_OK)
    return NULL;
  close (fd);
  return temp_path;
}

int
ts_atomic_seal (int fd, const char *target)
{
  if (fchmod (fd, new_file_mode (target)) != 0 || fsync (fd) != 0)
    return errno;
  return 0;
}

TsStatus
ts_atomic_commit (TsAtomicFile *f, TsError *error)
{
  int errnum = 0;

  errno = 0;
  if (fflush (f->file) != 0 || ferror (f->file))
    errnum = errno ? errno : EIO;
  else
    errnum = ts_atomic_seal (fileno (f->file), f->path);

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
  ts_atomic_sync_folder (f->path);
  return TS_OK;
}
