/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "level.h"
#include "indexing.h"

#include <stdlib.h>

TsStatus
ts_axis_grid_init (TsAxisGrid *grid, size_t n, size_t radius, size_t spacing,
                   size_t offset, bool wrap)
{
  size_t span = n + 2 * radius;

  grid->n = n;
  grid->radius = radius;
  grid->spacing = spacing;
  grid->offset = offset % spacing;
  if (grid->offset >= n)
    grid->offset = 0;
  grid->centres = (n - grid->offset + spacing - 1) / spacing;
  grid->virtual_start = calloc (n + 1, sizeof (size_t));
  grid->virtual_coord = malloc (span * sizeof (ptrdiff_t));
  grid->cover_lo = malloc (span * sizeof (size_t));
  grid->cover_hi = malloc (span * sizeof (size_t));
  if (!grid->virtual_start || !grid->virtual_coord || !grid->cover_lo || !grid->cover_hi)
    {
      ts_axis_grid_free (grid);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  /* Counting sort of the virtual coordinates -r .. n-1+r by the real
   * coordinate they map to; each list ends up in increasing order. */
  for (size_t i = 0; i < span; i++)
    grid->virtual_start[ts_border_index ((ptrdiff_t) i - (ptrdiff_t) radius, n, wrap) + 1]++;
  for (size_t p = 0; p < n; p++)
    grid->virtual_start[p + 1] += grid->virtual_start[p];
  {
    size_t *fill = calloc (n, sizeof (size_t));
    if (!fill)
      {
        ts_axis_grid_free (grid);
        return TS_ERROR_OUT_OF_MEMORY;
      }
    for (size_t i = 0; i < span; i++)
      {
        ptrdiff_t t = (ptrdiff_t) i - (ptrdiff_t) radius;
        size_t p = ts_border_index (t, n, wrap);
        grid->virtual_coord[grid->virtual_start[p] + fill[p]++] = t;
      }
    free (fill);
  }
  for (size_t i = 0; i < span; i++)
    if (!ts_axis_grid_covering (grid, grid->virtual_coord[i], &grid->cover_lo[i], &grid->cover_hi[i]))
      {
        grid->cover_lo[i] = 1;
        grid->cover_hi[i] = 0;
      }
  return TS_OK;
}

void
ts_axis_grid_free (TsAxisGrid *grid)
{
  free (grid->virtual_start);
  free (grid->virtual_coord);
  free (grid->cover_lo);
  free (grid->cover_hi);
  grid->virtual_start = NULL;
  grid->virtual_coord = NULL;
  grid->cover_lo = NULL;
  grid->cover_hi = NULL;
}
