/* Volume files (.vol, .dds): exact bytes, round trips, hostile input and
 * atomic writing.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "test-util.h"
#include "volume/volume.h"
#include "volume/formats.h"
#include "engine/rng.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#define SIZE 16

static char dir[] = "/tmp/texsynth-volume-file-XXXXXX";

static uint8_t
pattern (size_t x, size_t y, size_t z, unsigned c)
{
  return (uint8_t) (x * 7 + y * 13 + z * 29 + c * 61 + x * y);
}

static TsVolume8
make_volume (size_t size, unsigned channels)
{
  TsVolume8 v = { size, channels, true, malloc (size * size * size * channels) };

  if (!v.voxels)
    abort ();
  for (size_t z = 0; z < size; z++)
    for (size_t y = 0; y < size; y++)
      for (size_t x = 0; x < size; x++)
        for (unsigned c = 0; c < channels; c++)
          v.voxels[((z * size + y) * size + x) * channels + c] = pattern (x, y, z, c);
  return v;
}

#define PATH_SIZE 512

/* `name` in the scratch folder. */
static void
scratch_path (char path[PATH_SIZE], const char *name)
{
  snprintf (path, PATH_SIZE, "%s/%s", dir, name);
}

static uint8_t *
read_all (const char *path, size_t *length)
{
  FILE *f = fopen (path, "rb");
  uint8_t *data;
  long end;

  *length = 0;
  if (!f)
    return NULL;
  fseek (f, 0, SEEK_END);
  end = ftell (f);
  fseek (f, 0, SEEK_SET);
  data = malloc ((size_t) end + 1);
  if (data && fread (data, 1, (size_t) end, f) != (size_t) end)
    {
      free (data);
      data = NULL;
    }
  fclose (f);
  *length = (size_t) end;
  return data;
}

static void
write_all (const char *path, const void *data, size_t length)
{
  FILE *f = fopen (path, "wb");
  if (!f || (length && fwrite (data, 1, length, f) != length) || fclose (f) != 0)
    {
      fprintf (stderr, "cannot write test file %s\n", path);
      exit (1);
    }
}

/* Only the expected entries may be left in the scratch folder. */
static int
count_entries (void)
{
  DIR *d = opendir (dir);
  struct dirent *e;
  int n = 0;

  while (d && (e = readdir (d)))
    if (strcmp (e->d_name, ".") && strcmp (e->d_name, ".."))
      n++;
  if (d)
    closedir (d);
  return n;
}

/* A read that must fail with `status`, leave `v` zeroed and explain. */
static void
expect_read_failure (const char *path, TsStatus status, const char *fragment, const char *what)
{
  TsVolume8 v = { 99, 9, true, (uint8_t *) &v };
  TsError error = { TS_OK, "" };
  TsStatus got = ts_volume_read (path, 0, &v, NULL, &error);

  CHECK (got == status, "%s: status %d, expected %d (%s)", what, got, status, error.message);
  CHECK (error.status == got && error.message[0], "%s: no message", what);
  CHECK (!fragment || strstr (error.message, fragment), "%s: message '%s' lacks '%s'", what,
         error.message, fragment);
  CHECK (v.voxels == NULL && v.size == 0 && v.channels == 0, "%s: volume not zeroed", what);
}

static void
test_vol_bytes (void)
{
  TsVolume8 v = make_volume (SIZE, 4), back;
  TsError error;
  TsVolumeFormat format = TS_VOLUME_FORMAT_DDS;
  char path[PATH_SIZE];
  scratch_path (path, "pattern.vol");
  size_t length;
  uint8_t *data;

  CHECK (ts_volume_write_vol (path, "pattern", &v, &error) == TS_OK, "%s", error.message);
  data = read_all (path, &length);
  CHECK (data && length == 4096 + SIZE * SIZE * SIZE * 4, ".vol length %zu", length);
  if (data && length >= 4096)
    {
      CHECK (memcmp (data, "VOLU", 4) == 0, "magic");
      CHECK (ts_get_le32 (data + 4) == 4, "version %u", ts_get_le32 (data + 4));
      CHECK (strcmp ((char *) data + 8, "pattern") == 0, "name");
      CHECK (data[264] == 1 && data[265] == 0 && data[266] == 0 && data[267] == 0, "wrap");
      CHECK (ts_get_le32 (data + 268) == SIZE, "size field");
      CHECK (ts_get_le32 (data + 272) == 4, "channels field");
      CHECK (ts_get_le32 (data + 276) == 1, "bytes per channel field");
      for (size_t i = 280; i < 4096; i++)
        if (data[i])
          {
            CHECK (0, "padding byte %zu is %u", i, data[i]);
            break;
          }
      CHECK (memcmp (data + 4096, v.voxels, SIZE * SIZE * SIZE * 4) == 0, "voxel bytes");
    }
  free (data);

  CHECK (ts_volume_read (path, 0, &back, &format, &error) == TS_OK, "%s", error.message);
  CHECK (format == TS_VOLUME_FORMAT_VOL && back.size == SIZE && back.channels == 4 && back.wrap,
         "read header");
  CHECK (back.voxels && memcmp (back.voxels, v.voxels, SIZE * SIZE * SIZE * 4) == 0, "voxels");
  ts_volume8_clear (&back);
  ts_volume8_clear (&v);

  /* Every channel count, without wrap, and a name longer than the field. */
  for (unsigned channels = 1; channels <= 3; channels++)
    {
      char name[400];
      memset (name, 'n', sizeof name - 1);
      name[sizeof name - 1] = '\0';
      v = make_volume (5, channels);
      v.wrap = false;
      CHECK (ts_volume_write_vol (path, name, &v, &error) == TS_OK, "%s", error.message);
      data = read_all (path, &length);
      CHECK (data && length == 4096 + 125 * channels && data[8 + 254] == 'n' && data[8 + 255] == 0,
             "%u channels: length or name", channels);
      free (data);
      CHECK (ts_volume_read (path, 0, &back, NULL, &error) == TS_OK, "%s", error.message);
      CHECK (back.size == 5 && back.channels == channels && !back.wrap
             && memcmp (back.voxels, v.voxels, 125 * channels) == 0, "%u channels", channels);
      ts_volume8_clear (&back);
      ts_volume8_clear (&v);
    }
  unlink (path);
}

static void
test_dds_bytes (void)
{
  TsVolume8 v = make_volume (SIZE, 4), back;
  TsError error;
  TsVolumeFormat format = TS_VOLUME_FORMAT_VOL;
  char path[PATH_SIZE];
  scratch_path (path, "pattern.dds");
  size_t length;
  uint8_t *data;

  CHECK (ts_volume_write_dds (path, &v, &error) == TS_OK, "%s", error.message);
  data = read_all (path, &length);
  CHECK (data && length == 148 + SIZE * SIZE * SIZE * 4, ".dds length %zu", length);
  if (data && length >= 148)
    {
      CHECK (memcmp (data, "DDS ", 4) == 0, "magic");
      CHECK (ts_get_le32 (data + 4) == 124, "header size");
      CHECK (ts_get_le32 (data + 8) == 0x80100f, "flags 0x%x", ts_get_le32 (data + 8));
      CHECK (ts_get_le32 (data + 12) == SIZE && ts_get_le32 (data + 16) == SIZE, "height, width");
      CHECK (ts_get_le32 (data + 20) == SIZE * 4, "pitch");
      CHECK (ts_get_le32 (data + 24) == SIZE, "depth");
      CHECK (ts_get_le32 (data + 76) == 32 && ts_get_le32 (data + 80) == 0x4
             && memcmp (data + 84, "DX10", 4) == 0, "pixel format");
      CHECK (ts_get_le32 (data + 108) == 0x1008 && ts_get_le32 (data + 112) == 0x200000, "caps");
      CHECK (ts_get_le32 (data + 128) == 28 && ts_get_le32 (data + 132) == 4
             && ts_get_le32 (data + 136) == 0 && ts_get_le32 (data + 140) == 1
             && ts_get_le32 (data + 144) == 0, "DX10 header");
      CHECK (memcmp (data + 148, v.voxels, SIZE * SIZE * SIZE * 4) == 0, "voxel bytes");
    }

  CHECK (ts_volume_read (path, 0, &back, &format, &error) == TS_OK, "%s", error.message);
  CHECK (format == TS_VOLUME_FORMAT_DDS && back.size == SIZE && back.channels == 4, "header");
  CHECK (back.voxels && memcmp (back.voxels, v.voxels, SIZE * SIZE * SIZE * 4) == 0, "voxels");
  ts_volume8_clear (&back);

  /* Legacy header, BGRA masks: the reader must swap to RGBA. */
  if (data && length >= 148)
    {
      size_t n = SIZE * SIZE * SIZE;
      /* Room for the DX10 variants below; zeroed so every byte written is set. */
      uint8_t *legacy = calloc (148 + n * 4, 1);
      if (!legacy)
        abort ();
      memcpy (legacy, data, 128);
      ts_put_le32 (legacy + 80, 0x41); /* DDPF_RGB | DDPF_ALPHAPIXELS */
      memset (legacy + 84, 0, 4);
      ts_put_le32 (legacy + 88, 32);
      ts_put_le32 (legacy + 92, 0xff0000);
      ts_put_le32 (legacy + 96, 0xff00);
      ts_put_le32 (legacy + 100, 0xff);
      ts_put_le32 (legacy + 104, 0xff000000u);
      for (size_t i = 0; i < n; i++)
        {
          const uint8_t *p = v.voxels + i * 4;
          uint8_t *q = legacy + 128 + i * 4;
          q[0] = p[2]; q[1] = p[1]; q[2] = p[0]; q[3] = p[3];
        }
      write_all (path, legacy, 128 + n * 4);
      CHECK (ts_volume_read (path, 0, &back, NULL, &error) == TS_OK, "legacy: %s", error.message);
      CHECK (back.voxels && memcmp (back.voxels, v.voxels, n * 4) == 0, "legacy BGRA voxels");
      ts_volume8_clear (&back);

      /* Refused kinds of DDS, each with a message naming what it is. */
      memcpy (legacy + 84, "DXT1", 4);
      ts_put_le32 (legacy + 80, 0x4);
      write_all (path, legacy, 128 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "DXT1", "DXT1 volume");
      memcpy (legacy, data, 148);
      ts_put_le32 (legacy + 132, 3);
      write_all (path, legacy, 148 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "2D", "2D DX10 texture");
      memcpy (legacy, data, 148);
      ts_put_le32 (legacy + 140, 2);
      write_all (path, legacy, 148 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "array", "texture array");
      memcpy (legacy, data, 148);
      ts_put_le32 (legacy + 112, 0x200 | 0xfc00);
      write_all (path, legacy, 148 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "cube map", "cube map");
      memcpy (legacy, data, 148);
      ts_put_le32 (legacy + 128, 71); /* BC1 */
      write_all (path, legacy, 148 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "format 71", "BC1 format");
      memcpy (legacy, data, 148);
      ts_put_le32 (legacy + 24, SIZE / 2);
      write_all (path, legacy, 148 + n * 4);
      expect_read_failure (path, TS_ERROR_BAD_FILE, "16x16x8", "non-cubic volume");
      free (legacy);
    }
  free (data);
  ts_volume8_clear (&v);

  /* Fewer channels are expanded to RGBA. */
  for (unsigned channels = 1; channels <= 3; channels++)
    {
      v = make_volume (4, channels);
      CHECK (ts_volume_write_dds (path, &v, &error) == TS_OK, "%s", error.message);
      CHECK (ts_volume_read (path, 0, &back, NULL, &error) == TS_OK, "%s", error.message);
      for (size_t i = 0; back.voxels && i < 64; i++)
        {
          const uint8_t *p = v.voxels + i * channels, *q = back.voxels + i * 4;
          uint8_t expect[4] = { p[0], p[channels >= 3 ? 1 : 0], p[channels >= 3 ? 2 : 0],
                                channels == 2 ? p[1] : 255 };
          if (memcmp (q, expect, 4))
            {
              CHECK (0, "%u channels expanded wrongly at voxel %zu", channels, i);
              break;
            }
        }
      ts_volume8_clear (&back);
      ts_volume8_clear (&v);
    }
  unlink (path);
}

/* Every truncation of the header region and some of the data. */
static void
test_truncation (const char *name, bool dds)
{
  TsVolume8 v = make_volume (SIZE, 4);
  char path[PATH_SIZE];
  scratch_path (path, name);
  char cut[PATH_SIZE];
  scratch_path (cut, "cut");
  TsError error;
  size_t length, header = dds ? 148 : 4096, total;
  uint8_t *data;

  if ((dds ? ts_volume_write_dds (path, &v, &error) : ts_volume_write_vol (path, NULL, &v, &error))
      != TS_OK)
    {
      CHECK (0, "%s", error.message);
      ts_volume8_clear (&v);
      return;
    }
  data = read_all (path, &total);
  for (length = 0; data && length < total; length += length < header + 2 ? 1 : 997)
    {
      char what[64];
      snprintf (what, sizeof what, "%s cut to %zu bytes", name, length);
      write_all (cut, data, length);
      /* Below 4 bytes nothing says what the file is. */
      expect_read_failure (cut, TS_ERROR_BAD_FILE, length < 4 ? "bytes long" : "truncated", what);
    }
  write_all (cut, data, total - 1);
  expect_read_failure (cut, TS_ERROR_BAD_FILE, "truncated", "one byte short");
  unlink (cut);
  unlink (path);
  free (data);
  ts_volume8_clear (&v);
}

/* Header fields that announce impossible or unsupported volumes. */
static void
test_bad_headers (void)
{
  uint8_t header[4096 + 64] = { 0 };
  char path[PATH_SIZE];
  scratch_path (path, "bad.vol");
  TsVolume8 v;
  TsError error;
  struct { size_t offset; uint32_t value; TsStatus status; const char *fragment; } cases[] = {
    { 268, 0, TS_ERROR_BAD_FILE, "size is 0" },
    { 268, 4097, TS_ERROR_BAD_FILE, "exceeds 4096" },
    { 268, 0xffffffffu, TS_ERROR_BAD_FILE, "exceeds 4096" },
    { 268, 4096, TS_ERROR_BAD_FILE, "truncated" },   /* 256 GiB announced */
    { 268, 1500, TS_ERROR_BAD_FILE, "truncated" },   /* 13.5 GB */
    { 272, 0, TS_ERROR_BAD_FILE, "channels" },
    { 272, 5, TS_ERROR_BAD_FILE, "channels" },
    { 272, 0x80000000u, TS_ERROR_BAD_FILE, "channels" },
    { 276, 2, TS_ERROR_BAD_FILE, "bytes per channel" },
    { 4, 3, TS_ERROR_BAD_FILE, "version 3" },
  };

  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      char what[64];
      memset (header, 0, sizeof header);
      memcpy (header, "VOLU", 4);
      ts_put_le32 (header + 4, 4);
      ts_put_le32 (header + 268, 2);
      ts_put_le32 (header + 272, 4);
      ts_put_le32 (header + 276, 1);
      ts_put_le32 (header + cases[i].offset, cases[i].value);
      write_all (path, header, sizeof header);
      snprintf (what, sizeof what, "field %zu = %lu", cases[i].offset,
                (unsigned long) cases[i].value);
      expect_read_failure (path, cases[i].status, cases[i].fragment, what);
    }

  /* A 2^3 RGBA volume fits the 64 data bytes; a cap below 32 refuses it. */
  ts_put_le32 (header + 4, 4);
  ts_put_le32 (header + 268, 2);
  ts_put_le32 (header + 272, 4);
  ts_put_le32 (header + 276, 1);
  write_all (path, header, sizeof header);
  CHECK (ts_volume_read (path, 32, &v, NULL, &error) == TS_OK, "within cap: %s", error.message);
  ts_volume8_clear (&v);
  CHECK (ts_volume_read (path, 31, &v, NULL, &error) == TS_ERROR_TOO_LARGE
         && strstr (error.message, "too large") && !v.voxels, "over the cap: %s", error.message);

  write_all (path, "VOLV and more bytes", 19);
  expect_read_failure (path, TS_ERROR_BAD_FILE, "VOLU", "wrong magic");
  expect_read_failure (dir, TS_ERROR_IO, strerror (EISDIR), "a directory");
  scratch_path (path, "missing.vol");
  expect_read_failure (path, TS_ERROR_IO, strerror (ENOENT), "missing");
  expect_read_failure ("", TS_ERROR_INVALID_ARGUMENT, NULL, "empty path");
  /* A FIFO without a writer: refused at once instead of waiting. */
  scratch_path (path, "fifo.vol");
  if (mkfifo (path, 0600) == 0)
    {
      expect_read_failure (path, TS_ERROR_IO, "not a regular file", "a FIFO");
      unlink (path);
    }
  scratch_path (path, "bad.vol");
  expect_read_failure ("/dev/zero", TS_ERROR_IO, "not a regular file", "a device");
  unlink (path);
}

/* Random files and randomly damaged headers: any status, never a crash,
 * and the result is either a consistent volume or nothing. */
static void
test_random_bytes (void)
{
  TsVolume8 good = make_volume (4, 4);
  char path[PATH_SIZE];
  scratch_path (path, "random");
  uint8_t base[2][4096 + 256];
  uint8_t data[4096 + 256];
  uint32_t state = 12345;
  size_t base_length[2];
  TsError error;
  int ok = 0;

  for (int format = 0; format < 2; format++)
    {
      uint8_t *bytes;
      if (format ? ts_volume_write_dds (path, &good, &error)
                 : ts_volume_write_vol (path, NULL, &good, &error))
        CHECK (0, "%s", error.message);
      bytes = read_all (path, &base_length[format]);
      memcpy (base[format], bytes, base_length[format]);
      free (bytes);
    }
  for (int trial = 0; trial < 3000; trial++)
    {
      size_t length;
      TsVolume8 v;
      TsStatus status;

      if (trial % 3 == 0)
        {
          length = ts_lcg_next24 (&state) % sizeof data;
          for (size_t i = 0; i < length; i++)
            data[i] = (uint8_t) ts_lcg_next24 (&state);
          if (length >= 4 && trial % 2)
            memcpy (data, trial % 4 == 1 ? "VOLU" : "DDS ", 4);
        }
      else
        {
          int format = trial % 3 - 1;
          size_t header = format ? 148 : 280;
          length = base_length[format];
          memcpy (data, base[format], length);
          for (int flips = 1 + (int) (ts_lcg_next24 (&state) % 4); flips > 0; flips--)
            data[4 + ts_lcg_next24 (&state) % (header - 4)] = (uint8_t) ts_lcg_next24 (&state);
        }
      write_all (path, data, length);
      status = ts_volume_read (path, 1 << 20, &v, NULL, &error);
      if (status == TS_OK)
        {
          ok++;
          CHECK (v.voxels && v.size >= 1 && v.size <= 64 && v.channels >= 1 && v.channels <= 4,
                 "trial %d: inconsistent volume", trial);
          ts_volume8_clear (&v);
        }
      else
        CHECK (!v.voxels && v.size == 0 && error.message[0], "trial %d: failure not clean", trial);
    }
  printf ("random files: %d of 3000 read as volumes (damaged but self-consistent headers)\n", ok);
  unlink (path);
  ts_volume8_clear (&good);
}

/* Failed writes leave the old file byte-identical and no temporary file. */
static void
test_atomic_writes (void)
{
  TsVolume8 v = make_volume (SIZE, 4), other = make_volume (SIZE, 2);
  char target[PATH_SIZE];
  scratch_path (target, "keep.vol");
  char file_as_folder[PATH_SIZE + 8], missing_folder[PATH_SIZE];
  size_t before_length, after_length;
  uint8_t *before, *after;
  struct rlimit old_limit, limit;
  TsError error;
  TsStatus status;
  int entries;

  CHECK (ts_volume_write_vol (target, "keep", &v, &error) == TS_OK, "%s", error.message);
  before = read_all (target, &before_length);
  entries = count_entries ();

  scratch_path (missing_folder, "no/such/folder.vol");
  status = ts_volume_write_vol (missing_folder, NULL, &v, &error);
  CHECK (status == TS_ERROR_IO && strstr (error.message, "cannot write '")
         && strstr (error.message, "no/such/folder.vol") && strstr (error.message, strerror (ENOENT)),
         "missing folder: %s", error.message);
  snprintf (file_as_folder, sizeof file_as_folder, "%s/x.dds", target);
  status = ts_volume_write_dds (file_as_folder, &v, &error);
  CHECK (status == TS_ERROR_IO && strstr (error.message, strerror (ENOTDIR)),
         "file as folder: %s", error.message);
  status = ts_volume_write_vol ("/proc/texsynth-test.vol", NULL, &v, &error);
  CHECK (status == TS_ERROR_IO && strstr (error.message, "/proc/texsynth-test.vol"),
         "unwritable folder: %s", error.message);
  status = ts_volume_write_vol (dir, NULL, &v, &error);
  CHECK (status == TS_ERROR_IO && strstr (error.message, strerror (EISDIR)),
         "a folder as target: %s", error.message);
  other.channels = 5;
  CHECK (ts_volume_write_vol (target, NULL, &other, &error) == TS_ERROR_BAD_PARAMETER,
         "5 channels: %s", error.message);
  other.channels = 2;

  /* A full disk: the file size limit makes writes fail with EFBIG. */
  signal (SIGXFSZ, SIG_IGN);
  getrlimit (RLIMIT_FSIZE, &old_limit);
  limit = old_limit;
  for (rlim_t cap = 0; cap <= 8192; cap += 4000)
    {
      limit.rlim_cur = cap;
      if (setrlimit (RLIMIT_FSIZE, &limit) != 0)
        {
          CHECK (0, "setrlimit: %s", strerror (errno));
          break;
        }
      status = ts_volume_write_vol (target, NULL, &other, &error);
      setrlimit (RLIMIT_FSIZE, &old_limit);
      CHECK (status == TS_ERROR_IO && strstr (error.message, strerror (EFBIG)),
             ".vol with a %lu-byte limit: %s", (unsigned long) cap, error.message);
      limit.rlim_cur = cap;
      setrlimit (RLIMIT_FSIZE, &limit);
      status = ts_volume_write_dds (target, &other, &error);
      setrlimit (RLIMIT_FSIZE, &old_limit);
      CHECK (status == TS_ERROR_IO && strstr (error.message, strerror (EFBIG)),
             ".dds with a %lu-byte limit: %s", (unsigned long) cap, error.message);
    }
  signal (SIGXFSZ, SIG_DFL);

  after = read_all (target, &after_length);
  CHECK (before && after && before_length == after_length
         && memcmp (before, after, before_length) == 0, "the old file changed");
  CHECK (count_entries () == entries, "%d entries left in the folder, expected %d",
         count_entries (), entries);

  /* A successful write replaces it. */
  CHECK (ts_volume_write_vol (target, NULL, &other, &error) == TS_OK, "%s", error.message);
  free (after);
  after = read_all (target, &after_length);
  CHECK (after_length == 4096 + SIZE * SIZE * SIZE * 2, "replaced file length %zu", after_length);
  CHECK (count_entries () == entries, "temporary file left after success");
  unlink (target);
  free (before);
  free (after);
  ts_volume8_clear (&v);
  ts_volume8_clear (&other);
}

int
main (void)
{
  struct rlimit limit;

  if (!mkdtemp (dir))
    {
      fprintf (stderr, "mkdtemp: %s\n", strerror (errno));
      return 1;
    }
  /* Hostile headers announce up to 256 GiB: a reader that allocated
   * before checking would fail with "out of memory" instead of the
   * expected message under this cap on the address space. */
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  /* (Sanitizers reserve terabytes of shadow memory.) */
  limit.rlim_cur = limit.rlim_max = (rlim_t) 1 << 32;
  if (setrlimit (RLIMIT_AS, &limit) != 0)
    fprintf (stderr, "note: cannot cap the address space: %s\n", strerror (errno));
#else
  (void) limit;
#endif

  test_vol_bytes ();
  test_dds_bytes ();
  test_truncation ("trunc.vol", false);
  test_truncation ("trunc.dds", true);
  test_bad_headers ();
  test_random_bytes ();
  test_atomic_writes ();

  CHECK (count_entries () == 0, "files left in %s", dir);
  if (count_entries () == 0)
    rmdir (dir);
  return test_finish ("test-volume-file");
}
