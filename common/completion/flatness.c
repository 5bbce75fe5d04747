/* The flatness penalty of source patches (see ts_heal_flatness).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"

#include <math.h>
#include <stdlib.h>

/* Weight of the penalty: per patch pixel, (missing mean |grad L|)^2 times
 * this. Without it fills come out flatter than their surroundings; too
 * strong, and it picks busy sources that show at the hole's outline.
 * 1.5 brings the fill's sharpness to about the surroundings'.
 * Fitted to the bundled heal cases (docs/design.md, Known limits). */
#define TS_HEAL_FLATNESS_WEIGHT 1.5

static double
lightness_gradient (const float *pixels, size_t p, size_t w)
{
  double gx = 0.5 * ((double) pixels[(p + 1) * TS_CHANNELS] - pixels[(p - 1) * TS_CHANNELS]);
  double gy = 0.5 * ((double) pixels[(p + w) * TS_CHANNELS] - pixels[(p - w) * TS_CHANNELS]);
  return sqrt (gx * gx + gy * gy);
}

/* Mean |grad L| of the known pixels just around the hole (the band of
 * active centres, not the whole area: a blurred background must not be
 * pushed towards sharp things elsewhere in the image); `fallback` when
 * the band is empty. */
static double
surroundings_gradient (const TsHealLevel *l, double fallback)
{
  size_t w = l->width, h = l->height, count = 0;
  double sum = 0.0;

  for (size_t y = 1; y + 1 < h; y++)
    for (size_t x = 1; x + 1 < w; x++)
      {
        size_t p = y * w + x;
        if (l->active_index[p] < 0 || l->hole[p] || l->hole[p - 1] || l->hole[p + 1] ||
            l->hole[p - w] || l->hole[p + w])
          continue;
        sum += lightness_gradient (l->target, p, w);
        count++;
      }
  return count ? sum / (double) count : fallback;
}

TsStatus
ts_heal_flatness (TsHealLevel *l)
{
  size_t sw = l->source_width, sh = l->source_height, r = l->radius, n = sw * sh;
  size_t side = 2 * r + 1, stride = sw + 1;
  double *sum = calloc ((sw + 1) * (sh + 1), sizeof (double)), total = 0.0, wanted;

  l->flatness = calloc (n ? n : 1, sizeof (float));
  if (!sum || !l->flatness)
    {
      free (sum);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  /* An integral image of |grad L| gives each patch's mean at once. */
  for (size_t y = 0; y < sh; y++)
    for (size_t x = 0; x < sw; x++)
      {
        size_t p = y * sw + x;
        double g = x > 0 && x + 1 < sw && y > 0 && y + 1 < sh
                     ? lightness_gradient (l->source, p, sw) : 0.0;
        sum[(y + 1) * stride + x + 1] = g + sum[y * stride + x + 1] + sum[(y + 1) * stride + x] -
                                        sum[y * stride + x];
      }
  for (size_t i = 0; i < l->valid_count; i++)
    {
      size_t p = (size_t) l->valid_list[i], x = p % sw, y = p / sw;
      size_t x0 = x - r, y0 = y - r, x1 = x + r + 1, y1 = y + r + 1;
      double g = (sum[y1 * stride + x1] - sum[y0 * stride + x1] - sum[y1 * stride + x0] +
                  sum[y0 * stride + x0]) / (double) (side * side);
      l->flatness[p] = (float) g;
      total += g;
    }
  wanted = surroundings_gradient (l, l->valid_count ? total / (double) l->valid_count : 0.0);
  for (size_t i = 0; i < l->valid_count; i++)
    {
      size_t p = (size_t) l->valid_list[i];
      double lack = wanted - l->flatness[p];
      l->flatness[p] = lack > 0.0 ? (float) (TS_HEAL_FLATNESS_WEIGHT * (double) (side * side) *
                                             lack * lack) : 0.0f;
    }
  free (sum);
  return TS_OK;
}
