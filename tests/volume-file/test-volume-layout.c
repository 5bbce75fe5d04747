/* Slices and atlases of volumes: grid sizes and every pixel against
 * voxels computed by hand, for 8-bit and Lab float voxels.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "test-util.h"
#include "volume/layout.h"

#include <stdlib.h>
#include <string.h>

/* A voxel that encodes its own coordinates: floats exactly; bytes
 * uniquely in their first byte for sizes up to 6. */
static void
voxel_value (size_t x, size_t y, size_t z, size_t bpv, unsigned char *out)
{
  if (bpv == 16)
    {
      float f[4] = { (float) x, (float) y, (float) z, 1.0f };
      memcpy (out, f, sizeof f);
      return;
    }
  for (size_t c = 0; c < bpv; c++)
    out[c] = (unsigned char) (x + 6 * y + 36 * z + 50 * c);
}

static unsigned char *
make_volume (size_t size, size_t bpv)
{
  unsigned char *voxels = malloc (size * size * size * bpv);

  if (!voxels)
    abort ();
  for (size_t z = 0; z < size; z++)
    for (size_t y = 0; y < size; y++)
      for (size_t x = 0; x < size; x++)
        voxel_value (x, y, z, bpv, voxels + ((z * size + y) * size + x) * bpv);
  return voxels;
}

/* The voxel at (u, v) of slice `index`, from the definition:
 * X: (u, v) = (y, z); Y: (x, z); Z: (x, y). */
static void
expected (int axis, size_t index, size_t u, size_t v, size_t bpv, unsigned char *out)
{
  if (axis == 0)
    voxel_value (index, u, v, bpv, out);
  else if (axis == 1)
    voxel_value (u, index, v, bpv, out);
  else
    voxel_value (u, v, index, bpv, out);
}

static void
test_grid (void)
{
  struct { size_t size, columns, rows; } cases[] = {
    { 1, 1, 1 }, { 2, 2, 1 }, { 3, 2, 2 }, { 4, 2, 2 }, { 5, 3, 2 }, { 10, 4, 3 },
    { 16, 4, 4 }, { 17, 5, 4 }, { 128, 12, 11 }, { 256, 16, 16 }, { 512, 23, 23 },
  };

  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      size_t columns, rows, width, height;
      ts_volume_atlas_grid (cases[i].size, &columns, &rows);
      ts_volume_atlas_extent (cases[i].size, &width, &height);
      CHECK (columns == cases[i].columns && rows == cases[i].rows,
             "size %zu: grid %zux%zu, expected %zux%zu", cases[i].size, columns, rows,
             cases[i].columns, cases[i].rows);
      CHECK (width == columns * cases[i].size && height == rows * cases[i].size,
             "size %zu: extent %zux%zu", cases[i].size, width, height);
    }
}

static void
test_slices (size_t size, size_t bpv)
{
  unsigned char *voxels = make_volume (size, bpv);
  unsigned char *slice = malloc (size * size * bpv);
  unsigned char want[16];

  for (int axis = 0; axis < 3; axis++)
    for (size_t index = 0; index < size; index += size / 3 + 1)
      {
        int bad = 0;
        CHECK (ts_volume_extract_slice (voxels, size, bpv, axis, index, slice) == TS_OK,
               "axis %d index %zu", axis, index);
        for (size_t v = 0; v < size; v++)
          for (size_t u = 0; u < size; u++)
            {
              expected (axis, index, u, v, bpv, want);
              bad += memcmp (slice + (v * size + u) * bpv, want, bpv) != 0;
              bad += memcmp (voxels + ts_volume_slice_voxel (size, axis, index, u, v) * bpv,
                             want, bpv) != 0;
            }
        CHECK (bad == 0, "size %zu, %zu bytes/voxel, axis %d, index %zu: %d wrong pixels",
               size, bpv, axis, index, bad);
      }

  CHECK (ts_volume_extract_slice (voxels, size, bpv, 0, size, slice)
         == TS_ERROR_INVALID_ARGUMENT, "index = size accepted");
  CHECK (ts_volume_extract_slice (voxels, size, bpv, 3, 0, slice)
         == TS_ERROR_INVALID_ARGUMENT, "axis 3 accepted");
  CHECK (ts_volume_extract_slice (voxels, size, bpv, -1, 0, slice)
         == TS_ERROR_INVALID_ARGUMENT, "axis -1 accepted");
  free (slice);
  free (voxels);
}

static void
test_atlas (size_t size, size_t bpv)
{
  unsigned char *voxels = make_volume (size, bpv);
  size_t columns, rows, width, height;
  unsigned char *atlas, want[16], zero[16] = { 0 };

  ts_volume_atlas_grid (size, &columns, &rows);
  ts_volume_atlas_extent (size, &width, &height);
  atlas = malloc (width * height * bpv);
  for (int axis = 0; axis < 3; axis++)
    {
      int bad = 0, unused = 0;
      memset (atlas, 0xab, width * height * bpv);
      CHECK (ts_volume_extract_atlas (voxels, size, bpv, axis, atlas) == TS_OK, "atlas");
      for (size_t py = 0; py < height; py++)
        for (size_t px = 0; px < width; px++)
          {
            size_t i = (py / size) * columns + px / size;
            const unsigned char *p = atlas + (py * width + px) * bpv;
            if (i >= size)
              unused += memcmp (p, zero, bpv) != 0;
            else
              {
                expected (axis, i, px % size, py % size, bpv, want);
                bad += memcmp (p, want, bpv) != 0;
              }
          }
      CHECK (bad == 0 && unused == 0,
             "atlas of %zu, %zu bytes/voxel, axis %d: %d wrong pixels, %d non-zero unused",
             size, bpv, axis, bad, unused);
    }
  free (atlas);
  free (voxels);
}

int
main (void)
{
  test_grid ();
  for (size_t bpv = 1; bpv <= 4; bpv++)
    {
      test_slices (6, bpv);
      test_atlas (5, bpv);
    }
  test_slices (16, 16);   /* the engine's Lab+alpha floats */
  test_atlas (5, 16);
  test_atlas (4, 3);      /* a square grid: no unused cells */
  test_atlas (10, 16);
  return test_finish ("test-volume-layout");
}
