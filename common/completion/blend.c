/* Hiding the hole's outline: a smooth colour correction of the copied
 * pixels along it (see ts_heal_outline_offsets).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Width of the corrected band inside the hole, in pixels. */
#define TS_HEAL_BLEND_BAND 6

/* Mismatch at one outline pixel p of the hole: mean over its known
 * 4-neighbours k of k minus the source pixel beside p's copy. */
static bool
outline_mismatch (const TsHealLevel *l, const int32_t *picked, size_t x, size_t y, float *delta)
{
  static const int dx[4] = { 1, -1, 0, 0 }, dy[4] = { 0, 0, 1, -1 };
  size_t w = l->width, h = l->height, sw = l->source_width, sh = l->source_height;
  size_t s = (size_t) picked[y * w + x], sx = s % sw, sy = s / sw, count = 0;

  delta[0] = delta[1] = delta[2] = 0.0f;
  for (int k = 0; k < 4; k++)
    {
      ptrdiff_t kx = (ptrdiff_t) x + dx[k], ky = (ptrdiff_t) y + dy[k];
      ptrdiff_t tx = (ptrdiff_t) sx + dx[k], ty = (ptrdiff_t) sy + dy[k];
      const float *known, *beside;
      if (kx < 0 || ky < 0 || kx >= (ptrdiff_t) w || ky >= (ptrdiff_t) h ||
          l->hole[(size_t) ky * w + (size_t) kx])
        continue;
      if (tx < 0 || ty < 0 || tx >= (ptrdiff_t) sw || ty >= (ptrdiff_t) sh)
        tx = (ptrdiff_t) sx, ty = (ptrdiff_t) sy;
      known = l->target + ((size_t) ky * w + (size_t) kx) * TS_CHANNELS;
      beside = l->source + ((size_t) ty * sw + (size_t) tx) * TS_CHANNELS;
      for (int c = 0; c < 3; c++)
        delta[c] += known[c] - beside[c];
      count++;
    }
  for (int c = 0; c < 3 && count; c++)
    delta[c] /= (float) count;
  return count > 0;
}

TsStatus
ts_heal_outline_offsets (const TsHealLevel *l, const int32_t *picked, float *offset)
{
  size_t w = l->width, h = l->height, n = w * h;
  const ptrdiff_t band = TS_HEAL_BLEND_BAND;
  const float sigma2 = 0.25f * (float) (band * band);
  uint32_t *dist = ts_heal_distance_to_known (l);
  float *delta = malloc ((n ? n : 1) * 3 * sizeof (float));
  uint8_t *on_outline = calloc (n ? n : 1, 1);

  if (!dist || !delta || !on_outline)
    {
      free (dist);
      free (delta);
      free (on_outline);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  memset (offset, 0, n * 3 * sizeof (float));
#pragma omp parallel for schedule(static) if (l->hole_pixels >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (size_t x = 0; x < w; x++)
      if (l->hole[(size_t) y * w + x] && dist[(size_t) y * w + x] == 1)
        on_outline[(size_t) y * w + x] =
          outline_mismatch (l, picked, x, (size_t) y, delta + ((size_t) y * w + x) * 3);
  /* Each band pixel: the Gaussian-weighted mean mismatch of the outline
   * pixels around it, fading linearly with its depth into the hole. */
#pragma omp parallel for schedule(dynamic, 4) if (l->hole_pixels >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (ptrdiff_t x = 0; x < (ptrdiff_t) w; x++)
      {
        size_t p = (size_t) y * w + (size_t) x;
        double sum[3] = { 0, 0, 0 }, wsum = 0.0;
        float fade;
        if (!l->hole[p] || dist[p] > (uint32_t) band)
          continue;
        for (ptrdiff_t yy = y - band; yy <= y + band; yy++)
          for (ptrdiff_t xx = x - band; xx <= x + band; xx++)
            {
              size_t q;
              float g;
              if (xx < 0 || yy < 0 || xx >= (ptrdiff_t) w || yy >= (ptrdiff_t) h)
                continue;
              q = (size_t) yy * w + (size_t) xx;
              if (!on_outline[q])
                continue;
              g = expf (-(float) ((xx - x) * (xx - x) + (yy - y) * (yy - y)) / (2.0f * sigma2));
              for (int c = 0; c < 3; c++)
                sum[c] += (double) g * delta[q * 3 + c];
              wsum += g;
            }
        if (wsum <= 0.0)
          continue;
        fade = 1.0f - (float) (dist[p] - 1) / (float) band;
        for (int c = 0; c < 3; c++)
          offset[p * 3 + c] = fade * (float) (sum[c] / wsum);
      }
  free (dist);
  free (delta);
  free (on_outline);
  return TS_OK;
}
