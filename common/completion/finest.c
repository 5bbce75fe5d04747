/* The finest level of image completion: the part of the image that
 * matters (the hole's bounds grown by the context), in working form.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"
#include "engine/image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static size_t
grow_down (size_t v, size_t by)
{
  return v > by ? v - by : 0;
}

static size_t
grow_up (size_t v, size_t by, size_t limit)
{
  return limit - v > by ? v + by : limit;
}

void
ts_heal_region (const TsHealParams *params, size_t width, size_t height, size_t x0, size_t y0,
                size_t x1, size_t y1, size_t *rx0, size_t *ry0, size_t *rx1, size_t *ry1)
{
  size_t r, rf, margin;

  if (!params || params->context == 0)
    {
      *rx0 = *ry0 = 0;
      *rx1 = width;
      *ry1 = height;
      return;
    }
  /* Source centres lie within the context; their patches one radius
   * farther (the coarser levels' patches cover twice as much). */
  r = ts_heal_coarse_radius (params);
  rf = ts_heal_fine_radius (params);
  margin = params->context + 2 * (r > rf ? r : rf);
  *rx0 = grow_down (x0, margin);
  *ry0 = grow_down (y0, margin);
  *rx1 = grow_up (x1 < width ? x1 : width, margin, width);
  *ry1 = grow_up (y1 < height ? y1 : height, margin, height);
}

bool
ts_heal_hole_bounds (const uint8_t *hole, size_t w, size_t h, size_t *x0, size_t *y0, size_t *x1,
                     size_t *y1)
{
  *x0 = w;
  *y0 = h;
  *x1 = *y1 = 0;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      if (hole[y * w + x])
        {
          *x0 = x < *x0 ? x : *x0;
          *x1 = x + 1 > *x1 ? x + 1 : *x1;
          *y0 = y < *y0 ? y : *y0;
          *y1 = y + 1;
        }
  return *x1 > 0;
}

/* Lab values beyond this are no colours; clamped, squared sums of
 * patches stay finite whatever a float file holds. */
#define TS_HEAL_MAX_LAB 1000.0f

/* Working form of a pixel (see ts_image_to_working). */
static void
to_working (const float *in, float *out)
{
  for (int c = 0; c < TS_CHANNELS; c++)
    out[c] = isfinite (in[c]) ? fmaxf (-TS_HEAL_MAX_LAB, fminf (TS_HEAL_MAX_LAB, in[c])) : 0.0f;
  out[3] = (out[3] < 0.0f ? 0.0f : out[3] > 1.0f ? 1.0f : out[3]) * TS_ALPHA_SCALE;
}

static TsStatus
load_source (const TsImage *source, TsHealLevel *l)
{
  size_t n = source->width * source->height;

  l->source_own = malloc (n * TS_CHANNELS * sizeof (float));
  l->source_known = malloc (n);
  if (!l->source_own || !l->source_known)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t p = 0; p < n; p++)
    {
      to_working (source->pixels + p * TS_CHANNELS, l->source_own + p * TS_CHANNELS);
      l->source_known[p] = l->source_own[p * TS_CHANNELS + 3] > 0.0f;
    }
  l->source = l->source_own;
  l->source_width = source->width;
  l->source_height = source->height;
  return TS_OK;
}

TsStatus
ts_heal_prepare_finest (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
                        const TsImage *source, TsHealLevel *l, TsHealArea *area, TsHealCrop *crop)
{
  size_t hx0, hy0, hx1, hy1, w, h;
  TsStatus status;

  memset (l, 0, sizeof *l);
  memset (area, 0, sizeof *area);
  memset (crop, 0, sizeof *crop);
  if (!ts_heal_hole_bounds (hole, image->width, image->height, &hx0, &hy0, &hx1, &hy1))
    {
      crop->empty = true;
      return TS_OK;
    }
  ts_heal_region (params, image->width, image->height, hx0, hy0, hx1, hy1, &crop->x0, &crop->y0,
                  &crop->x1, &crop->y1);
  w = crop->x1 - crop->x0;
  h = crop->y1 - crop->y0;
  l->width = w;
  l->height = h;
  l->radius = ts_heal_fine_radius (params);
  l->target = malloc (w * h * TS_CHANNELS * sizeof (float));
  l->hole = malloc (w * h);
  if (!l->target || !l->hole)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = y * w + x, q = (y + crop->y0) * image->width + x + crop->x0;
        l->hole[p] = hole[q] != 0;
        to_working (image->pixels + q * TS_CHANNELS, l->target + p * TS_CHANNELS);
        if (l->hole[p])
          memset (l->target + p * TS_CHANNELS, 0, TS_CHANNELS * sizeof (float));
      }

  area->sample_from = TS_HEAL_ALL_AROUND;
  if (source)
    {
      /* Another image: all of it may serve. */
      status = load_source (source, l);
      area->x1 = source->width;
      area->y1 = source->height;
    }
  else
    {
      size_t c = params->context ? params->context : SIZE_MAX / 4;
      status = TS_OK;
      l->source = l->target;
      l->source_width = w;
      l->source_height = h;
      area->hx0 = hx0 - crop->x0;
      area->hy0 = hy0 - crop->y0;
      area->hx1 = hx1 - crop->x0;
      area->hy1 = hy1 - crop->y0;
      area->x0 = grow_down (area->hx0, c);
      area->y0 = grow_down (area->hy0, c);
      area->x1 = grow_up (area->hx1, c, w);
      area->y1 = grow_up (area->hy1, c, h);
      area->sample_from = params->sample_from;
    }
  if (status == TS_OK)
    status = ts_heal_level_index (l, area);
  return status;
}
