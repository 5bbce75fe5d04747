/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "seam-placement.h"
#include "indexing.h"

#include <stdlib.h>
#include <string.h>

/* Index of the cyclic window of `band` entries (centred on the edge
 * before it) with the lowest sum; the first such on ties. */
static size_t
best_edge (const double *profile, size_t n, size_t band)
{
  size_t best = 0;
  double best_cost = 0;

  for (size_t s = 0; s < n; s++)
    {
      double cost = 0;
      for (size_t i = 0; i < band; i++)
        cost += profile[ts_wrap ((ptrdiff_t) s - (ptrdiff_t) (band / 2) + (ptrdiff_t) i, n)];
      if (s == 0 || cost < best_cost)
        {
          best = s;
          best_cost = cost;
        }
    }
  return best;
}

TsStatus
ts_seam_best_shift (const float *disagreement, size_t width, size_t height,
                    bool wrap_x, bool wrap_y, size_t band, size_t *shift_x, size_t *shift_y)
{
  double *columns = calloc (width, sizeof (double)), *rows = calloc (height, sizeof (double));

  *shift_x = *shift_y = 0;
  if (!columns || !rows)
    {
      free (columns);
      free (rows);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t y = 0; y < height; y++)
    for (size_t x = 0; x < width; x++)
      {
        double d = disagreement[y * width + x];
        columns[x] += d;
        rows[y] += d;
      }
  if (wrap_x)
    *shift_x = best_edge (columns, width, band < width ? band : width);
  if (wrap_y)
    *shift_y = best_edge (rows, height, band < height ? band : height);
  free (columns);
  free (rows);
  return TS_OK;
}

TsStatus
ts_seam_roll (void *pixels, size_t width, size_t height, size_t item_size,
              size_t shift_x, size_t shift_y)
{
  size_t row = width * item_size;
  unsigned char *copy, *data = pixels;

  if (shift_x == 0 && shift_y == 0)
    return TS_OK;
  copy = malloc (row * height);
  if (!copy)
    return TS_ERROR_OUT_OF_MEMORY;
  memcpy (copy, data, row * height);
  for (size_t y = 0; y < height; y++)
    {
      const unsigned char *src = copy + ((y + shift_y) % height) * row;
      unsigned char *dst = data + y * row;
      memcpy (dst, src + shift_x * item_size, (width - shift_x) * item_size);
      memcpy (dst + (width - shift_x) * item_size, src, shift_x * item_size);
    }
  free (copy);
  return TS_OK;
}
