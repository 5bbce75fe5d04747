/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "histogram.h"

#include <stdlib.h>
#include <string.h>

/* Densities of the opaque pixels of `image`, each counted `usage[i]`
 * times (once if `usage` is NULL), normalised so a uniform histogram is 1
 * in every bin. Counts are whole numbers, exact in float up to 2^24 (a
 * 4096x4096 output) whatever the order of the sum. */
static void
count (const TsHistogram *h, const TsImage *image, const uint32_t *usage,
       float out[3][TS_HISTOGRAM_BINS])
{
  size_t n = ts_image_pixel_count (image), used = 0;

  memset (out, 0, sizeof (float) * 3 * TS_HISTOGRAM_BINS);
  for (size_t i = 0; i < n; i++)
    {
      const float *p = image->pixels + i * TS_CHANNELS;
      size_t times = usage ? usage[i] : 1;
      if (p[3] <= 0.0f || times == 0)
        continue;
      for (int c = 0; c < 3; c++)
        out[c][ts_histogram_bin (h, c, p[c])] += (float) times;
      used += times;
    }
  if (used == 0)
    return;
  for (int c = 0; c < 3; c++)
    for (size_t b = 0; b < TS_HISTOGRAM_BINS; b++)
      out[c][b] *= (float) TS_HISTOGRAM_BINS / (float) used;
}

TsStatus
ts_histogram_init (TsHistogram *h, const TsImage *exemplar)
{
  size_t n = ts_image_pixel_count (exemplar);
  float lo[3] = { 1e30f, 1e30f, 1e30f }, hi[3] = { -1e30f, -1e30f, -1e30f };

  for (size_t i = 0; i < n; i++)
    {
      const float *p = exemplar->pixels + i * TS_CHANNELS;
      if (p[3] <= 0.0f)
        continue;
      for (int c = 0; c < 3; c++)
        {
          lo[c] = p[c] < lo[c] ? p[c] : lo[c];
          hi[c] = p[c] > hi[c] ? p[c] : hi[c];
        }
    }
  for (int c = 0; c < 3; c++)
    {
      float range = hi[c] > lo[c] ? hi[c] - lo[c] : 1.0f;
      h->lo[c] = lo[c] <= hi[c] ? lo[c] : 0.0f;
      h->scale[c] = (float) TS_HISTOGRAM_BINS / range;
    }
  count (h, exemplar, NULL, h->exemplar);
  memset (h->excess, 0, sizeof h->excess);
  h->source = exemplar;
  h->factor = malloc ((n ? n : 1) * sizeof (float));
  if (!h->factor)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t i = 0; i < n; i++)
    h->factor[i] = 1.0f;
  return TS_OK;
}

void
ts_histogram_free (TsHistogram *h)
{
  free (h->factor);
  h->factor = NULL;
}

void
ts_histogram_set_wanted (TsHistogram *h, const float *wanted)
{
  size_t n = ts_image_pixel_count (h->source);
  double total = 0.0;

  memset (h->exemplar, 0, sizeof h->exemplar);
  for (size_t i = 0; i < n; i++)
    {
      const float *p = h->source->pixels + i * TS_CHANNELS;
      if (p[3] <= 0.0f || !(wanted[i] > 0.0f))
        continue;
      for (int c = 0; c < 3; c++)
        h->exemplar[c][ts_histogram_bin (h, c, p[c])] += wanted[i];
      total += wanted[i];
    }
  if (total <= 0.0)
    return;
  for (int c = 0; c < 3; c++)
    for (size_t b = 0; b < TS_HISTOGRAM_BINS; b++)
      h->exemplar[c][b] = (float) (h->exemplar[c][b] * TS_HISTOGRAM_BINS / total);
}

void
ts_histogram_update (TsHistogram *h, const uint32_t *usage)
{
  float density[3][TS_HISTOGRAM_BINS];

  count (h, h->source, usage, density);
  for (int c = 0; c < 3; c++)
    for (size_t b = 0; b < TS_HISTOGRAM_BINS; b++)
      {
        float d = density[c][b] - h->exemplar[c][b];
        h->excess[c][b] = d > 0.0f ? d : 0.0f;
      }
  /* Per exemplar pixel once, instead of per vote. */
  size_t n = ts_image_pixel_count (h->source);
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) n; i++)
    h->factor[i] = ts_histogram_factor (h, h->source->pixels + i * TS_CHANNELS);
}
