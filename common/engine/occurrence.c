/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "occurrence.h"

#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

TsStatus
ts_occurrence_init (TsOccurrence *occ, const TsImage *ex, float strength)
{
  size_t n = ts_image_pixel_count (ex), opaque = 0;
  double mean[3] = { 0, 0, 0 }, var = 0;

  memset (occ, 0, sizeof *occ);
  occ->width = ex->width;
  occ->height = ex->height;
  occ->penalty = calloc (n, sizeof (float));
  occ->integral = calloc ((ex->width + 1) * (ex->height + 1), sizeof (double));
  if (!occ->penalty || !occ->integral)
    {
      ts_occurrence_free (occ);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        for (int c = 0; c < 3; c++)
          mean[c] += ex->pixels[i * TS_CHANNELS + c];
        opaque++;
      }
  if (opaque == 0)
    return TS_OK;
  for (int c = 0; c < 3; c++)
    mean[c] /= (double) opaque;
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      for (int c = 0; c < 3; c++)
        {
          double d = ex->pixels[i * TS_CHANNELS + c] - mean[c];
          var += d * d;
        }
  occ->scale = strength * (float) (var / (double) opaque);
  return TS_OK;
}

void
ts_occurrence_free (TsOccurrence *occ)
{
  free (occ->penalty);
  free (occ->integral);
  occ->penalty = NULL;
  occ->integral = NULL;
}

void
ts_occurrence_count (const int32_t *source, const uint8_t *mask, size_t count, uint32_t *usage,
                     size_t exemplar_pixels)
{
  size_t threads = 1;
  uint32_t *partial = NULL;

#ifdef _OPENMP
  threads = (size_t) omp_get_max_threads ();
#endif
  /* Per-thread counts, then their sums: whole numbers, so the same on any
   * number of threads. Only worth it when the output is larger than the
   * counts; serial without the memory. */
  if (threads > 1 && exemplar_pixels * threads <= count)
    partial = calloc (exemplar_pixels * threads, sizeof (uint32_t));
  if (!partial)
    {
      memset (usage, 0, exemplar_pixels * sizeof (uint32_t));
      for (size_t i = 0; i < count; i++)
        if (source[i] >= 0 && (!mask || mask[i]))
          usage[source[i]]++;
      return;
    }
#pragma omp parallel num_threads ((int) threads)
  {
    size_t t = 0, n = threads;
#ifdef _OPENMP
    t = (size_t) omp_get_thread_num ();
    n = (size_t) omp_get_num_threads ();
#endif
    uint32_t *mine = partial + t * exemplar_pixels;
    for (size_t i = count * t / n; i < count * (t + 1) / n; i++)
      if (source[i] >= 0 && (!mask || mask[i]))
        mine[source[i]]++;
#pragma omp barrier
#pragma omp for schedule(static)
    for (ptrdiff_t i = 0; i < (ptrdiff_t) exemplar_pixels; i++)
      {
        uint32_t sum = 0;
        for (size_t u = 0; u < n; u++)
          sum += partial[u * exemplar_pixels + (size_t) i];
        usage[i] = sum;
      }
  }
  free (partial);
}

void
ts_occurrence_update (TsOccurrence *occ, const uint32_t *usage, size_t count,
                      size_t patch, size_t opaque_pixels)
{
  size_t w = occ->width, h = occ->height, stride = w + 1, r = patch / 2;
  double *sat = occ->integral;
  double expected = (double) count / (double) (opaque_pixels ? opaque_pixels : 1);
  float per_pixel = occ->scale * (float) (patch * patch);

  /* Prefix sums along rows, then columns: the sums are whole numbers far
   * below 2^53, so any order gives the same table. */
  memset (sat, 0, stride * sizeof (double));
#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    {
      double *row = sat + ((size_t) y + 1) * stride;
      row[0] = 0.0;
      for (size_t x = 0; x < w; x++)
        row[x + 1] = row[x] + (double) usage[(size_t) y * w + x];
    }
  for (size_t y = 1; y <= h; y++)
    for (size_t x = 1; x <= w; x++)
      sat[y * stride + x] += sat[(y - 1) * stride + x];

#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t x0 = x >= r ? x - r : 0, y0 = (size_t) y >= r ? (size_t) y - r : 0;
        size_t x1 = x + r + 1 < w ? x + r + 1 : w, y1 = (size_t) y + r + 1 < h ? (size_t) y + r + 1 : h;
        double used = sat[y1 * stride + x1] - sat[y0 * stride + x1] - sat[y1 * stride + x0]
                      + sat[y0 * stride + x0];
        double ratio = used / ((double) ((x1 - x0) * (y1 - y0)) * expected);
        occ->penalty[(size_t) y * w + x] = ratio > 1.0 ? per_pixel * (float) (ratio - 1.0) : 0.0f;
      }
}
