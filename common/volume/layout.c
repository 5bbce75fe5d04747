/* Slices and atlases of a solid texture (see layout.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "layout.h"

#include <string.h>

/* Plain ints, as in the header: 0, 1, 2 = x, y, z. */
enum { AXIS_X, AXIS_Y, AXIS_Z };

void
ts_volume_atlas_grid (size_t size, size_t *columns, size_t *rows)
{
  size_t c = 1;

  /* Integer ceil(sqrt(size)): no floating-point rounding at squares. */
  while (c * c < size)
    c++;
  *columns = c;
  *rows = size ? (size + c - 1) / c : 0;
}

void
ts_volume_atlas_extent (size_t size, size_t *width, size_t *height)
{
  size_t columns, rows;

  ts_volume_atlas_grid (size, &columns, &rows);
  *width = columns * size;
  *height = rows * size;
}

size_t
ts_volume_slice_voxel (size_t size, int axis, size_t index, size_t u, size_t v)
{
  switch (axis)
    {
    case AXIS_X: return (v * size + u) * size + index;     /* (y, z) = (u, v) */
    case AXIS_Y: return (v * size + index) * size + u;     /* (x, z) = (u, v) */
    default:        return (index * size + v) * size + u;     /* (x, y) = (u, v) */
    }
}

/* One slice into an image whose rows are `stride` bytes apart. */
static void
copy_slice (const unsigned char *voxels, size_t size, size_t bpv, int axis, size_t index,
            unsigned char *out, size_t stride)
{
  for (size_t v = 0; v < size; v++)
    {
      unsigned char *row = out + v * stride;

      if (axis == AXIS_Z || axis == AXIS_Y)
        {
          /* Rows of these slices are contiguous runs of x. */
          memcpy (row, voxels + ts_volume_slice_voxel (size, axis, index, 0, v) * bpv,
                  size * bpv);
          continue;
        }
      for (size_t u = 0; u < size; u++)
        memcpy (row + u * bpv, voxels + ts_volume_slice_voxel (size, axis, index, u, v) * bpv,
                bpv);
    }
}

static bool
valid (const void *voxels, size_t size, size_t bytes_per_voxel, int axis, const void *out)
{
  return voxels && out && size > 0 && bytes_per_voxel > 0 && axis >= AXIS_X
         && axis <= AXIS_Z;
}

TsStatus
ts_volume_extract_slice (const void *voxels, size_t size, size_t bytes_per_voxel,
                         int axis, size_t index, void *out)
{
  if (!valid (voxels, size, bytes_per_voxel, axis, out) || index >= size)
    return TS_ERROR_INVALID_ARGUMENT;
  copy_slice (voxels, size, bytes_per_voxel, axis, index, out, size * bytes_per_voxel);
  return TS_OK;
}

TsStatus
ts_volume_extract_atlas (const void *voxels, size_t size, size_t bytes_per_voxel,
                         int axis, void *out)
{
  size_t columns, rows, stride;
  unsigned char *image = out;

  if (!valid (voxels, size, bytes_per_voxel, axis, out))
    return TS_ERROR_INVALID_ARGUMENT;
  ts_volume_atlas_grid (size, &columns, &rows);
  stride = columns * size * bytes_per_voxel;
  memset (image, 0, stride * rows * size);
  for (size_t i = 0; i < size; i++)
    copy_slice (voxels, size, bytes_per_voxel, axis, i,
                image + (i / columns) * size * stride + (i % columns) * size * bytes_per_voxel,
                stride);
  return TS_OK;
}
