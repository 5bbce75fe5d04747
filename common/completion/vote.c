/* Filling the hole's pixels: the first guess from the border inwards,
 * from a coarser level, and the votes of the matched patches.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A change of a pixel's value (squared Lab distance) that counts. */
#define TS_HEAL_CHANGE 1.0f
/* Patches covering one pixel at most. */
#define TS_HEAL_MAX_COVER (TS_MAX_PATCH_SIZE * TS_MAX_PATCH_SIZE)

TsStatus
ts_heal_fill_from_border (TsHealLevel *l)
{
  size_t w = l->width, h = l->height, n = w * h, left = 0;
  uint8_t *done = malloc (n ? n : 1), *next = malloc (n ? n : 1);

  if (!done || !next)
    {
      free (done);
      free (next);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t p = 0; p < n; p++)
    {
      done[p] = !l->hole[p];
      left += l->hole[p] != 0;
    }
  /* Ring by ring; a ring reads only the pixels done before it, so the
   * order within a ring does not matter. */
  while (left > 0)
    {
      size_t filled = 0;
      memcpy (next, done, n);
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          {
            float sum[TS_CHANNELS] = { 0 };
            size_t count = 0, p = y * w + x;
            if (done[p])
              continue;
            for (size_t yy = y > 0 ? y - 1 : 0; yy <= y + 1 && yy < h; yy++)
              for (size_t xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < w; xx++)
                if (done[yy * w + xx])
                  {
                    for (int c = 0; c < TS_CHANNELS; c++)
                      sum[c] += l->target[(yy * w + xx) * TS_CHANNELS + c];
                    count++;
                  }
            if (count == 0)
              continue;
            for (int c = 0; c < TS_CHANNELS; c++)
              l->target[p * TS_CHANNELS + c] = sum[c] / (float) count;
            next[p] = 1;
            filled++;
          }
      memcpy (done, next, n);
      if (filled == 0)
        break;   /* no known pixel at all: validation prevents it */
      left -= filled;
    }
  free (done);
  free (next);
  return TS_OK;
}

void
ts_heal_upsample_target (const TsHealLevel *coarse, TsHealLevel *fine)
{
  size_t w = fine->width;

#pragma omp parallel for schedule(static) if (fine->width * fine->height >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) fine->height; y++)
    for (size_t x = 0; x < w; x++)
      if (fine->hole[(size_t) y * w + x])
        {
          size_t px = x / 2 < coarse->width ? x / 2 : coarse->width - 1;
          size_t py = (size_t) y / 2 < coarse->height ? (size_t) y / 2 : coarse->height - 1;
          memcpy (fine->target + ((size_t) y * w + x) * TS_CHANNELS,
                  coarse->target + (py * coarse->width + px) * TS_CHANNELS,
                  TS_CHANNELS * sizeof (float));
        }
}

static size_t
patch_pixels (const TsHealLevel *l, size_t centre)
{
  size_t w = l->width, h = l->height, r = l->radius, cx = centre % w, cy = centre / w;
  size_t x0 = cx >= r ? cx - r : 0, x1 = cx + r < w ? cx + r : w - 1;
  size_t y0 = cy >= r ? cy - r : 0, y1 = cy + r < h ? cy + r : h - 1;
  return (x1 - x0 + 1) * (y1 - y0 + 1);
}

/* Wexler et al.'s vote weights: exp(-d / 2 sigma^2), d the match's mean
 * squared difference per pixel and sigma^2 the mean of d over the level,
 * so poor matches count less whatever the image's contrast. */
static float *
vote_weights (const TsHealLevel *l)
{
  float *weight = malloc ((l->active_count ? l->active_count : 1) * sizeof (float));
  double total = 0.0, sigma2;

  if (!weight)
    return NULL;
  for (size_t i = 0; i < l->active_count; i++)
    {
      weight[i] = l->dist[i] / (float) patch_pixels (l, (size_t) l->active[i]);
      total += weight[i];   /* in order: the same sum at any thread count */
    }
  sigma2 = l->active_count ? total / (double) l->active_count : 1.0;
  if (!(sigma2 > 1e-6))
    sigma2 = 1e-6;
#pragma omp parallel for schedule(static) if (l->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) l->active_count; i++)
    weight[i] = ((float) exp (-(double) weight[i] / (2.0 * sigma2)) + 1e-6f) * l->confidence[i];
  return weight;
}

/* The proposal with the most weight behind it among the patches covering
 * pixel (x, y) (its index in the source): patches that agree on the copy
 * add up, so the pixel joins the copy most of its neighbourhood shows (a
 * real pixel, where a mean of disagreeing proposals would blur, and more
 * whole copies than the single best-weighted patch gives). Ties go to
 * the first in raster order, so the choice is the same at any thread
 * count. */
static int32_t
best_proposal (const TsHealLevel *l, const float *weight, size_t x, size_t y)
{
  size_t w = l->width, h = l->height, sw = l->source_width, r = l->radius;
  size_t x0 = x >= r ? x - r : 0, x1 = x + r < w ? x + r : w - 1;
  size_t y0 = y >= r ? y - r : 0, y1 = y + r < h ? y + r : h - 1;
  int32_t cand[TS_HEAL_MAX_COVER];
  float sum[TS_HEAL_MAX_COVER], best = -1.0f;
  size_t distinct = 0, last = 0;
  int32_t choice = -1;

  /* Every centre within the radius is active: its patch holds p. */
  for (size_t cy = y0; cy <= y1; cy++)
    for (size_t cx = x0; cx <= x1; cx++)
      {
        int32_t i = l->active_index[cy * w + cx];
        size_t s = (size_t) l->nnf[i], k = last;
        int32_t c = (int32_t) ((s / sw + y - cy) * sw + s % sw + x - cx);
        if (k >= distinct || cand[k] != c)   /* neighbours mostly agree: try the last first */
          for (k = 0; k < distinct && cand[k] != c;)
            k++;
        if (k == distinct)
          {
            cand[distinct] = c;
            sum[distinct++] = 0.0f;
          }
        sum[k] += weight[i];
        last = k;
      }
  for (size_t k = 0; k < distinct; k++)
    if (sum[k] > best)
      {
        best = sum[k];
        choice = cand[k];
      }
  return choice;
}

/* The weighted mean of the proposals for pixel p, into `mean`. */
static void
mean_proposal (const TsHealLevel *l, const float *weight, size_t x, size_t y, float *mean)
{
  size_t w = l->width, h = l->height, sw = l->source_width, r = l->radius;
  size_t x0 = x >= r ? x - r : 0, x1 = x + r < w ? x + r : w - 1;
  size_t y0 = y >= r ? y - r : 0, y1 = y + r < h ? y + r : h - 1;
  double sum[TS_CHANNELS] = { 0 }, wsum = 0.0;

  for (size_t cy = y0; cy <= y1; cy++)
    for (size_t cx = x0; cx <= x1; cx++)
      {
        int32_t i = l->active_index[cy * w + cx];
        size_t s = (size_t) l->nnf[i];
        size_t q = (s / sw + y - cy) * sw + s % sw + x - cx;
        for (int c = 0; c < TS_CHANNELS; c++)
          sum[c] += (double) weight[i] * l->source[q * TS_CHANNELS + c];
        wsum += weight[i];
      }
  for (int c = 0; c < TS_CHANNELS; c++)
    mean[c] = (float) (sum[c] / wsum);
}

size_t
ts_heal_vote (TsHealLevel *l, bool pick, int32_t *picked, TsCancel *cancel)
{
  size_t w = l->width, h = l->height, changed = 0;
  float *weight = vote_weights (l);

  if (!weight)
    return SIZE_MAX;
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : changed) if (l->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t yy = 0; yy < (ptrdiff_t) h; yy++)
    {
      size_t y = (size_t) yy;
      if (ts_cancel_poll (cancel))
        continue;
      for (size_t x = 0; x < w; x++)
        {
          size_t p = y * w + x;
          float value[TS_CHANNELS], *t = l->target + p * TS_CHANNELS, diff = 0.0f;

          if (!l->hole[p])
            continue;
          if (pick)
            {
              int32_t choice = best_proposal (l, weight, x, y);
              memcpy (value, l->source + (size_t) choice * TS_CHANNELS, sizeof value);
              if (picked)
                {
                  changed += choice != picked[p];
                  picked[p] = choice;
                }
            }
          else
            mean_proposal (l, weight, x, y, value);
          for (int c = 0; c < TS_CHANNELS; c++)
            diff += (t[c] - value[c]) * (t[c] - value[c]);
          if (!picked)
            changed += diff > TS_HEAL_CHANGE;
          memcpy (t, value, sizeof value);
        }
    }
  free (weight);
  return changed;
}
