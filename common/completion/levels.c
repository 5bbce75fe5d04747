/* Image completion pyramid: coarser levels, valid source centres, active
 * target centres and the hole's depth.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"
#include "engine/image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void
ts_heal_level_free (TsHealLevel *level)
{
  free (level->target);
  free (level->hole);
  free (level->source_own);
  free (level->source_known);
  free (level->valid);
  free (level->valid_list);
  free (level->active);
  free (level->active_index);
  free (level->nnf);
  free (level->dist);
  free (level->confidence);
  free (level->flatness);
  memset (level, 0, sizeof *level);
}

/* 2x2 block means of `in` (odd sides: the last row/column repeats);
 * `known` (may be NULL) marks the pixels that count; a block with an
 * unknown pixel is unknown in `known_out` and left 0. */
static void
downsample_pixels (const float *in, const uint8_t *unknown, size_t w, size_t h, float *out,
                   uint8_t *unknown_out, size_t cw, size_t ch)
{
#pragma omp parallel for schedule(static) if (cw * ch >= 4 * TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) ch; y++)
    for (size_t x = 0; x < cw; x++)
      {
        size_t xs[2] = { 2 * x, 2 * x + 1 < w ? 2 * x + 1 : 2 * x };
        size_t ys[2] = { 2 * (size_t) y, 2 * (size_t) y + 1 < h ? 2 * (size_t) y + 1 : 2 * (size_t) y };
        float sum[TS_CHANNELS] = { 0 };
        bool any_unknown = false;
        for (int j = 0; j < 2; j++)
          for (int i = 0; i < 2; i++)
            {
              size_t p = ys[j] * w + xs[i];
              any_unknown |= unknown[p] != 0;
              for (int c = 0; c < TS_CHANNELS; c++)
                sum[c] += in[p * TS_CHANNELS + c];
            }
        size_t q = (size_t) y * cw + x;
        unknown_out[q] = any_unknown;
        for (int c = 0; c < TS_CHANNELS; c++)
          out[q * TS_CHANNELS + c] = any_unknown ? 0.0f : 0.25f * sum[c];
      }
}

TsStatus
ts_heal_level_downsample (const TsHealLevel *fine, TsHealLevel *coarse)
{
  size_t cw = (fine->width + 1) / 2, ch = (fine->height + 1) / 2;

  memset (coarse, 0, sizeof *coarse);
  coarse->width = cw;
  coarse->height = ch;
  coarse->target = malloc (cw * ch * TS_CHANNELS * sizeof (float));
  coarse->hole = malloc (cw * ch);
  if (!coarse->target || !coarse->hole)
    return TS_ERROR_OUT_OF_MEMORY;
  downsample_pixels (fine->target, fine->hole, fine->width, fine->height, coarse->target,
                     coarse->hole, cw, ch);
  coarse->source = coarse->target;
  coarse->source_width = cw;
  coarse->source_height = ch;
  if (fine->source_own)
    {
      size_t sw = (fine->source_width + 1) / 2, sh = (fine->source_height + 1) / 2;
      coarse->source_own = malloc (sw * sh * TS_CHANNELS * sizeof (float));
      coarse->source_known = malloc (sw * sh);
      if (!coarse->source_own || !coarse->source_known)
        return TS_ERROR_OUT_OF_MEMORY;
      /* source_known holds 1 = known; downsample_pixels wants 1 = unknown. */
      uint8_t *unknown = malloc (fine->source_width * fine->source_height);
      if (!unknown)
        return TS_ERROR_OUT_OF_MEMORY;
      for (size_t i = 0; i < fine->source_width * fine->source_height; i++)
        unknown[i] = !fine->source_known[i];
      downsample_pixels (fine->source_own, unknown, fine->source_width, fine->source_height,
                         coarse->source_own, coarse->source_known, sw, sh);
      free (unknown);
      for (size_t i = 0; i < sw * sh; i++)
        coarse->source_known[i] = !coarse->source_known[i];
      coarse->source = coarse->source_own;
      coarse->source_width = sw;
      coarse->source_height = sh;
    }
  return TS_OK;
}

static bool
in_area (const TsHealArea *a, size_t x, size_t y)
{
  if (x < a->x0 || x >= a->x1 || y < a->y0 || y >= a->y1)
    return false;
  switch (a->sample_from)
    {
    case TS_HEAL_SIDES: return x < a->hx0 || x >= a->hx1;
    case TS_HEAL_ABOVE_BELOW: return y < a->hy0 || y >= a->hy1;
    default: return true;
    }
}

/* Valid centres: an integral image of unknown (or fully transparent)
 * source pixels answers "is this whole patch usable" in constant time. */
static TsStatus
index_sources (TsHealLevel *l, const TsHealArea *area)
{
  size_t sw = l->source_width, sh = l->source_height, r = l->radius, n = sw * sh, c = 0;
  uint32_t *sum = calloc ((sw + 1) * (sh + 1), sizeof (uint32_t));

  l->valid = calloc (n, 1);
  l->valid_list = malloc ((n ? n : 1) * sizeof (int32_t));
  if (!sum || !l->valid || !l->valid_list)
    {
      free (sum);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t y = 0; y < sh; y++)
    for (size_t x = 0; x < sw; x++)
      {
        size_t p = y * sw + x;
        /* A fully transparent pixel has no colour to give, here as in
         * a separate source: uncrop must not copy a layer's own holes
         * into the new border. */
        uint32_t unknown = l->source_known ? !l->source_known[p]
                                           : l->hole[p] != 0 || !(l->source[p * TS_CHANNELS + 3] > 0.0f);
        sum[(y + 1) * (sw + 1) + x + 1] = unknown + sum[y * (sw + 1) + x + 1] +
                                          sum[(y + 1) * (sw + 1) + x] - sum[y * (sw + 1) + x];
      }
  for (size_t y = r; y + r < sh; y++)
    for (size_t x = r; x + r < sw; x++)
      {
        size_t x0 = x - r, y0 = y - r, x1 = x + r + 1, y1 = y + r + 1;
        uint32_t unknown = sum[y1 * (sw + 1) + x1] - sum[y0 * (sw + 1) + x1] -
                           sum[y1 * (sw + 1) + x0] + sum[y0 * (sw + 1) + x0];
        if (unknown == 0 && in_area (area, x, y))
          {
            l->valid[y * sw + x] = 1;
            l->valid_list[c++] = (int32_t) (y * sw + x);
          }
      }
  l->valid_count = c;
  free (sum);
  return TS_OK;
}

/* Active centres: the hole grown by the patch radius (separable max). */
static TsStatus
index_targets (TsHealLevel *l)
{
  size_t w = l->width, h = l->height, r = l->radius, n = w * h, c = 0;
  uint8_t *rows = calloc (n ? n : 1, 1);

  l->active_index = malloc ((n ? n : 1) * sizeof (int32_t));
  if (!rows || !l->active_index)
    {
      free (rows);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  l->hole_pixels = 0;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      if (l->hole[y * w + x])
        {
          size_t a = x >= r ? x - r : 0, b = x + r < w ? x + r : w - 1;
          memset (rows + y * w + a, 1, b - a + 1);
          l->hole_pixels++;
        }
  for (size_t y = 0; y < h; y++)
    {
      for (size_t x = 0; x < w; x++)
        {
          size_t a = y >= r ? y - r : 0, b = y + r < h ? y + r : h - 1;
          bool hit = false;
          for (size_t yy = a; yy <= b && !hit; yy++)
            hit = rows[yy * w + x] != 0;
          l->active_index[y * w + x] = hit ? (int32_t) c++ : -1;
        }
    }
  l->active_count = c;
  free (rows);
  l->active = malloc ((c ? c : 1) * sizeof (int32_t));
  l->nnf = malloc ((c ? c : 1) * sizeof (int32_t));
  l->dist = malloc ((c ? c : 1) * sizeof (float));
  if (!l->active || !l->nnf || !l->dist)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t p = 0; p < n; p++)
    if (l->active_index[p] >= 0)
      l->active[l->active_index[p]] = (int32_t) p;
  return TS_OK;
}

/* Wexler et al.'s confidence of a patch: it falls by TS_HEAL_CONFIDENCE_BASE
 * per pixel its centre lies inside the hole, so the patches anchored in
 * known pixels decide the pixels near the hole's outline. */
static TsStatus
confidences (TsHealLevel *l)
{
  uint32_t *d = ts_heal_distance_to_known (l);

  l->confidence = malloc ((l->active_count ? l->active_count : 1) * sizeof (float));
  if (!d || !l->confidence)
    {
      free (d);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < l->active_count; i++)
    l->confidence[i] = powf (TS_HEAL_CONFIDENCE_BASE, -(float) d[l->active[i]]);
  free (d);
  return TS_OK;
}

TsStatus
ts_heal_level_index (TsHealLevel *level, const TsHealArea *area)
{
  TsStatus status = index_sources (level, area);
  if (status == TS_OK)
    status = index_targets (level);
  if (status == TS_OK)
    status = ts_heal_flatness (level);
  return status == TS_OK ? confidences (level) : status;
}

uint32_t *
ts_heal_distance_to_known (const TsHealLevel *l)
{
  size_t w = l->width, h = l->height, n = w * h;
  uint32_t *d = malloc ((n ? n : 1) * sizeof (uint32_t));

  if (!d)
    return NULL;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        uint32_t v = l->hole[y * w + x] ? UINT32_MAX - 1 : 0;
        if (v)
          {
            if (x > 0 && d[y * w + x - 1] + 1 < v) v = d[y * w + x - 1] + 1;
            if (y > 0)
              for (size_t xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < w; xx++)
                if (d[(y - 1) * w + xx] + 1 < v)
                  v = d[(y - 1) * w + xx] + 1;
          }
        d[y * w + x] = v;
      }
  for (size_t y = h; y-- > 0;)
    for (size_t x = w; x-- > 0;)
      {
        uint32_t v = d[y * w + x];
        if (v)
          {
            if (x + 1 < w && d[y * w + x + 1] + 1 < v) v = d[y * w + x + 1] + 1;
            if (y + 1 < h)
              for (size_t xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < w; xx++)
                if (d[(y + 1) * w + xx] + 1 < v)
                  v = d[(y + 1) * w + xx] + 1;
            d[y * w + x] = v;
          }
      }
  return d;
}

size_t
ts_heal_hole_depth (const TsHealLevel *l)
{
  uint32_t *d = ts_heal_distance_to_known (l);
  size_t deepest = 0;

  if (!d)   /* only chooses the level count: a guess from the image will do */
    return (l->width < l->height ? l->width : l->height) / 2;
  for (size_t p = 0; p < l->width * l->height; p++)
    if (d[p] > deepest)
      deepest = d[p];
  free (d);
  return deepest;
}
