/* Histogram matching for solid synthesis (Kopf et al. 2007): a vote's
 * weight falls with the excess, in the volume, of the bins its colour
 * falls in, so the volume keeps the exemplars' colour distribution
 * instead of collapsing onto a few features.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>
#include <string.h>

static size_t
bin_of (const TsSolidHistogram *h, int channel, float v)
{
  float b = (v - h->lo[channel]) * h->scale[channel];
  if (!(b > 0.0f))
    return 0;
  return b >= TS_SOLID_HISTOGRAM_BINS - 1 ? TS_SOLID_HISTOGRAM_BINS - 1 : (size_t) b;
}

/* Distinct constrained exemplars only: one passed for several
 * orientations counts once. */
static bool
first_use (const TsSolidLevel *level, int a)
{
  return level->view[a].exemplar != NULL && ts_solid_view_owner (level, a) == a;
}

void
ts_solid_histogram_init (TsSolidHistogram *h, const TsSolidLevel *level)
{
  float hi[3];
  size_t n3 = level->n * level->n * level->n;
  int exemplars = 0;

  memset (h, 0, sizeof *h);
  for (int c = 0; c < 3; c++)
    {
      h->lo[c] = (float) INFINITY;
      hi[c] = -(float) INFINITY;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsImage *ex = level->view[a].exemplar;
      if (!first_use (level, a))
        continue;
      for (size_t i = 0; i < ts_image_pixel_count (ex); i++)
        {
          const float *p = ex->pixels + i * TS_CHANNELS;
          if (p[3] <= 0.0f)
            continue;
          for (int c = 0; c < 3; c++)
            {
              h->lo[c] = p[c] < h->lo[c] ? p[c] : h->lo[c];
              hi[c] = p[c] > hi[c] ? p[c] : hi[c];
            }
        }
    }
  for (int c = 0; c < 3; c++)
    h->scale[c] = hi[c] > h->lo[c] ? (float) TS_SOLID_HISTOGRAM_BINS / (hi[c] - h->lo[c]) : 0.0f;

  /* Target: the mean of the exemplars' densities (mean 1 per bin). */
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsImage *ex = level->view[a].exemplar;
      float density[3][TS_SOLID_HISTOGRAM_BINS];
      size_t opaque = 0;
      if (!first_use (level, a))
        continue;
      memset (density, 0, sizeof density);
      for (size_t i = 0; i < ts_image_pixel_count (ex); i++)
        {
          const float *p = ex->pixels + i * TS_CHANNELS;
          if (p[3] <= 0.0f)
            continue;
          opaque++;
          for (int c = 0; c < 3; c++)
            density[c][bin_of (h, c, p[c])] += 1.0f;
        }
      for (int c = 0; c < 3 && opaque > 0; c++)
        for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
          h->target[c][b] += density[c][b] * (float) TS_SOLID_HISTOGRAM_BINS / (float) opaque;
      exemplars++;
    }
  for (int c = 0; c < 3 && exemplars > 0; c++)
    for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
      h->target[c][b] /= (float) exemplars;

  for (size_t v = 0; v < n3; v++)
    {
      const float *p = level->value + v * TS_CHANNELS;
      if (p[3] <= 0.0f)
        continue;
      h->total++;
      for (int c = 0; c < 3; c++)
        h->count[c][bin_of (h, c, p[c])]++;
    }
}

void
ts_solid_histogram_move (const TsSolidHistogram *h, TsSolidHistogramDelta delta,
                         const float *before, const float *after)
{
  if (before[3] > 0.0f)
    for (int c = 0; c < 3; c++)
      delta[c][bin_of (h, c, before[c])]--;
  if (after[3] > 0.0f)
    for (int c = 0; c < 3; c++)
      delta[c][bin_of (h, c, after[c])]++;
}

void
ts_solid_histogram_apply (TsSolidHistogram *h, TsSolidHistogramDelta delta)
{
  for (int c = 0; c < 3; c++)
    for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
      {
        h->count[c][b] += delta[c][b];
        delta[c][b] = 0;
      }
  /* Every voxel's alpha enters all three channels alike. */
  h->total = 0;
  for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
    h->total += h->count[0][b];
}

void
ts_solid_histogram_excess (const TsSolidHistogram *h, TsSolidLevel *level)
{
  float excess[3][TS_SOLID_HISTOGRAM_BINS];

  for (int c = 0; c < 3; c++)
    for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
      {
        float density = h->total > 0
                        ? (float) h->count[c][b] * (float) TS_SOLID_HISTOGRAM_BINS / (float) h->total
                        : 0.0f;
        float e = density - h->target[c][b];
        excess[c][b] = e > 0.0f ? e : 0.0f;
      }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsImage *ex = level->view[a].exemplar;
      float *out = level->view[a].excess;
      /* Views of one exemplar share its excess: computed once. */
      if (!out || !first_use (level, a))
        continue;
#pragma omp parallel for schedule(static)
      for (ptrdiff_t i = 0; i < (ptrdiff_t) ts_image_pixel_count (ex); i++)
        {
          const float *p = ex->pixels + (size_t) i * TS_CHANNELS;
          float sum = 0.0f;
          for (int c = 0; c < 3; c++)
            sum += excess[c][bin_of (h, c, p[c])];
          out[i] = sum;
        }
    }
}
