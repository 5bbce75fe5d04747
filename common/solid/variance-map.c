/* Every exemplar neighbourhood's colour variance and the level's flat
 * variance, worked out once per pass for the M-step's vote weights
 * (mstep.c match_error).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <stdlib.h>
#include <string.h>

/* Variance (summed over L, a, b) of an exemplar neighbourhood at which
 * its vote's error counts half, at the finest level: a spread of about
 * 22 L* units, a clearly textured patch, so flat patches keep nearly
 * their full error and edges count at a fraction. Absolute, not scaled
 * to the exemplar's contrast: chosen on the truth solids (docs/design.md,
 * Known limits). */
#define TS_SOLID_FLAT_VARIANCE 500.0f
/* At the coarser levels, the flat variance is this many times the
 * exemplar's median neighbourhood variance, so it follows each
 * exemplar's contrast: a neighbourhood twice as varied as the typical
 * one has its error halved. An absolute value there suited low-contrast
 * exemplars and blunted high-contrast ones. */
#define TS_SOLID_COARSE_FLAT_FACTOR 2.0f

/* Summed-area tables would be faster, but the sums of squares of Lab
 * values lose too many digits in float; a direct double sum per
 * neighbourhood is exact enough and runs once per pass. */
static float
neighbourhood_variance (const TsImage *ex, size_t cx, size_t cy, size_t radius)
{
  size_t count = 0;
  double sum[3] = { 0.0, 0.0, 0.0 }, squares = 0.0, mean_squares = 0.0;

  for (size_t y = cy - radius; y <= cy + radius; y++)
    for (size_t x = cx - radius; x <= cx + radius; x++)
      {
        const float *p = ts_image_pixel (ex, x, y);
        for (int c = 0; c < 3; c++)
          {
            sum[c] += p[c];
            squares += (double) p[c] * p[c];
          }
        count++;
      }
  for (int c = 0; c < 3; c++)
    mean_squares += sum[c] * sum[c];
  return (float) ((squares - mean_squares / (double) count) / (double) count);
}

TsStatus
ts_solid_variance_map_build (const TsImage *ex, size_t radius, bool coarse, TsSolidVarianceMap *map)
{
  size_t w = ex->width, h = ex->height, inner = 0;
  float *sorted;

  ts_solid_variance_map_free (map);
  map->flat = TS_SOLID_FLAT_VARIANCE;
  if (w <= 2 * radius || h <= 2 * radius)
    return TS_OK; /* no whole neighbourhood: no match to weigh */
  map->variance = calloc (w * h, sizeof (float));
  sorted = coarse ? malloc ((w - 2 * radius) * (h - 2 * radius) * sizeof (float)) : NULL;
  if (!map->variance || (coarse && !sorted))
    {
      free (sorted);
      ts_solid_variance_map_free (map);
      return TS_ERROR_OUT_OF_MEMORY;
    }
#pragma omp parallel for schedule(static) if (w * h >= 128 * 128)
  for (ptrdiff_t y = (ptrdiff_t) radius; y < (ptrdiff_t) (h - radius); y++)
    for (size_t x = radius; x + radius < w; x++)
      map->variance[(size_t) y * w + x] = neighbourhood_variance (ex, x, (size_t) y, radius);
  if (coarse)
    {
      for (size_t y = radius; y + radius < h; y++)
        for (size_t x = radius; x + radius < w; x++)
          sorted[inner++] = map->variance[y * w + x];
      qsort (sorted, inner, sizeof (float), ts_solid_compare_floats);
      if (sorted[(inner - 1) / 2] > 0.0f)
        map->flat = TS_SOLID_COARSE_FLAT_FACTOR * sorted[(inner - 1) / 2];
      free (sorted);
    }
  return TS_OK;
}

void
ts_solid_variance_map_free (TsSolidVarianceMap *map)
{
  free (map->variance);
  memset (map, 0, sizeof *map);
}
