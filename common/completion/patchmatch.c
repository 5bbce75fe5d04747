/* PatchMatch search of image completion: for every patch that meets the
 * hole, the best patch of known pixels (Barnes et al. 2009), made
 * independent of the thread count.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"
#include "engine/rng.h"
#include "engine/ssd.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* Random streams of ts_random. */
enum { STREAM_START = 20, STREAM_LOCAL, STREAM_GLOBAL };

float
ts_heal_patch_distance (const TsHealLevel *l, size_t centre, size_t source, float bound)
{
  size_t w = l->width, h = l->height, sw = l->source_width, r = l->radius;
  size_t cx = centre % w, cy = centre / w, sx = source % sw, sy = source / sw;
  size_t x0 = cx >= r ? cx - r : 0, x1 = cx + r < w ? cx + r : w - 1;
  size_t y0 = cy >= r ? cy - r : 0, y1 = cy + r < h ? cy + r : h - 1;
  size_t count = (x1 - x0 + 1) * TS_CHANNELS;
  float acc[4] = { 0, 0, 0, 0 };

  for (size_t y = y0; y <= y1; y++)
    {
      const float *t = l->target + (y * w + x0) * TS_CHANNELS;
      const float *s = l->source + (((sy + y - cy) * sw) + sx + x0 - cx) * TS_CHANNELS;
      ts_lanes_add (acc, t, s, count);
      if (TS_LANES_TOTAL (acc) > bound)
        break;
    }
  return TS_LANES_TOTAL (acc);
}

static int32_t
random_valid (const TsHealLevel *l, uint32_t seed, uint32_t level_number, uint32_t iteration,
              size_t centre, uint32_t stream)
{
  uint64_t r = ts_random (seed, level_number, iteration, centre, stream);
  return l->valid_list[ts_random_below (r, l->valid_count)];
}

void
ts_heal_random_matches (TsHealLevel *l, uint32_t seed, uint32_t level_number)
{
#pragma omp parallel for schedule(static) if (l->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) l->active_count; i++)
    l->nnf[i] = random_valid (l, seed, level_number, 0, (size_t) l->active[i], STREAM_START);
}

void
ts_heal_upsample_matches (const TsHealLevel *coarse, TsHealLevel *fine, uint32_t seed,
                          uint32_t level_number)
{
  size_t w = fine->width, sw = fine->source_width, sh = fine->source_height;

#pragma omp parallel for schedule(static) if (fine->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) fine->active_count; i++)
    {
      size_t p = (size_t) fine->active[i], x = p % w, y = p / w;
      size_t px = x / 2 < coarse->width ? x / 2 : coarse->width - 1;
      size_t py = y / 2 < coarse->height ? y / 2 : coarse->height - 1;
      int32_t parent = coarse->active_index[py * coarse->width + px];
      int32_t match = -1;

      if (parent >= 0)
        {
          size_t s = (size_t) coarse->nnf[parent];
          size_t sx = 2 * (s % coarse->source_width) + (x & 1);
          size_t sy = 2 * (s / coarse->source_width) + (y & 1);
          if (sx < sw && sy < sh && fine->valid[sy * sw + sx])
            match = (int32_t) (sy * sw + sx);
        }
      fine->nnf[i] = match >= 0 ? match : random_valid (fine, seed, level_number, 0, p, STREAM_START);
    }
}

void
ts_heal_update_distances (TsHealLevel *l, TsCancel *cancel)
{
#pragma omp parallel for schedule(dynamic, 64) if (l->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) l->active_count; i++)
    {
      if ((i & 255) == 0 && ts_cancel_poll (cancel))
        continue;
      l->dist[i] = ts_heal_patch_distance (l, (size_t) l->active[i], (size_t) l->nnf[i], FLT_MAX) +
                   (l->flatness ? l->flatness[l->nnf[i]] : 0.0f);
    }
}

typedef struct
{
  int32_t match;
  float   dist;
} Best;

static void
try_match (const TsHealLevel *l, size_t centre, int32_t candidate, Best *best)
{
  float d;

  if (candidate < 0 || candidate == best->match || !l->valid[candidate])
    return;
  float penalty = l->flatness ? l->flatness[candidate] : 0.0f;
  if (penalty >= best->dist)
    return;
  d = ts_heal_patch_distance (l, centre, (size_t) candidate, best->dist - penalty) + penalty;
  if (d < best->dist)
    {
      best->match = candidate;
      best->dist = d;
    }
}

/* The match a neighbour's match suggests for `centre`: the same offset.
 * `neighbour_match` is -1 when the neighbour is not active. */
static int32_t
shifted (const TsHealLevel *l, int32_t neighbour_match, ptrdiff_t dx, ptrdiff_t dy)
{
  size_t sw = l->source_width, sh = l->source_height;
  ptrdiff_t sx, sy;

  if (neighbour_match < 0)
    return -1;
  sx = (ptrdiff_t) ((size_t) neighbour_match % sw) + dx;
  sy = (ptrdiff_t) ((size_t) neighbour_match / sw) + dy;
  if (sx < 0 || sy < 0 || sx >= (ptrdiff_t) sw || sy >= (ptrdiff_t) sh)
    return -1;
  return (int32_t) ((size_t) sy * sw + (size_t) sx);
}

static int32_t
match_at (const TsHealLevel *l, const int32_t *nnf, size_t x, size_t y)
{
  int32_t i = l->active_index[y * l->width + x];
  return i >= 0 ? nnf[i] : -1;
}

/* Improves the matches of one active centre. */
static void
search_centre (TsHealLevel *l, const int32_t *before, size_t i, bool along_x, ptrdiff_t step,
               uint32_t seed, uint32_t level_number, uint32_t pass, size_t global_tries)
{
  size_t w = l->width, h = l->height, sw = l->source_width, sh = l->source_height;
  size_t p = (size_t) l->active[i], x = p % w, y = p / w;
  Best best = { l->nnf[i], l->dist[i] };
  ptrdiff_t nx = (ptrdiff_t) x + step, ny = (ptrdiff_t) y + step;

  /* Along the scanned line: this pass's matches; across it: the matches
   * as they were before the pass (another thread owns those lines). */
  if (nx >= 0 && nx < (ptrdiff_t) w)
    try_match (l, p, shifted (l, match_at (l, along_x ? l->nnf : before, (size_t) nx, y), -step, 0),
               &best);
  if (ny >= 0 && ny < (ptrdiff_t) h)
    try_match (l, p, shifted (l, match_at (l, along_x ? before : l->nnf, x, (size_t) ny), 0, -step),
               &best);
  /* Random search in shrinking windows around the best match. */
  for (size_t radius = sw > sh ? sw : sh, t = 0; radius >= 1; radius /= 2, t++)
    {
      uint64_t r = ts_random (seed, level_number, pass, p * 64 + t, STREAM_LOCAL);
      size_t bx = (size_t) best.match % sw, by = (size_t) best.match / sw;
      size_t lx = bx > radius ? bx - radius : 0, hx = bx + radius < sw ? bx + radius : sw - 1;
      size_t ly = by > radius ? by - radius : 0, hy = by + radius < sh ? by + radius : sh - 1;
      size_t cx = lx + ts_random_below (r & 0xffffffffu, hx - lx + 1);
      size_t cy = ly + ts_random_below (r >> 32, hy - ly + 1);
      try_match (l, p, (int32_t) (cy * sw + cx), &best);
    }
  /* Anywhere in the allowed source: finds structure that neither the
   * neighbours' offsets nor the local windows reach. */
  for (size_t t = 0; t < global_tries; t++)
    try_match (l, p, random_valid (l, seed, level_number, pass, p * 64 + 63 - t, STREAM_GLOBAL),
               &best);
  l->nnf[i] = best.match;
  l->dist[i] = best.dist;
}

/* One line (a row or a column) of active centres, in the pass's
 * direction: passes 0 and 1 scan rows forwards and backwards, 2 and 3
 * columns, so matches spread every way within four passes. */
static void
search_line (TsHealLevel *l, const int32_t *before, size_t line, uint32_t seed,
             uint32_t level_number, uint32_t pass, size_t global_tries)
{
  bool along_x = (pass & 2) == 0, forward = (pass & 1) == 0;
  ptrdiff_t step = forward ? -1 : 1;   /* towards the neighbour already visited */
  size_t n = along_x ? l->width : l->height;

  for (size_t k = 0; k < n; k++)
    {
      size_t t = forward ? k : n - 1 - k;
      size_t p = along_x ? line * l->width + t : t * l->width + line;
      int32_t i = l->active_index[p];
      if (i >= 0)
        search_centre (l, before, (size_t) i, along_x, step, seed, level_number, pass, global_tries);
    }
}

TsStatus
ts_heal_search_pass (TsHealLevel *l, uint32_t seed, uint32_t level_number, uint32_t pass,
                     size_t global_tries, TsCancel *cancel)
{
  int32_t *before = malloc ((l->active_count ? l->active_count : 1) * sizeof (int32_t));

  if (!before)
    return TS_ERROR_OUT_OF_MEMORY;
  memcpy (before, l->nnf, l->active_count * sizeof (int32_t));
  size_t lines = (pass & 2) == 0 ? l->height : l->width;
#pragma omp parallel for schedule(dynamic, 1) if (l->active_count >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t line = 0; line < (ptrdiff_t) lines; line++)
    {
      if (ts_cancel_poll (cancel))
        continue;
      search_line (l, before, (size_t) line, seed, level_number, pass, global_tries);
    }
  free (before);
  return ts_cancel_requested (cancel) ? TS_ERROR_CANCELLED : TS_OK;
}
