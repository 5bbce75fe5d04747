/* M-step: k-coherence search of the best exemplar neighbourhood for each
 * output neighbourhood centre.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "level.h"
#include "indexing.h"
#include "rng.h"
#include "ssd.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Kwatra et al.'s robust energy exponent. */
#define TS_ENERGY_EXPONENT 0.8f

typedef struct
{
  const TsImage *exemplar;
  size_t         patch, radius;
  const float   *neighbourhood;  /* gathered output neighbourhood        */
  const float   *penalty;        /* occurrence penalty per centre, or NULL */
  uint32_t      *stamp;          /* per exemplar pixel: last visit       */
  uint32_t       visit;
  float          best;
  int32_t        best_centre;
} Search;

/* Sum of squared differences, abandoned (returning >= bound) as soon as a
 * row pushes it past `bound`. */
static float
ssd_bounded (const Search *s, size_t qx, size_t qy, float bound)
{
  size_t row_floats = s->patch * TS_CHANNELS;
  const float *a = s->neighbourhood;
  float sum = 0.0f;

  for (size_t row = 0; row < s->patch; row++)
    {
      const float *b = ts_image_pixel (s->exemplar, qx - s->radius, qy - s->radius + row);
      float lane[TS_CHANNELS] = { 0.0f, 0.0f, 0.0f, 0.0f };
      ts_lanes_add (lane, a, b, row_floats);
      sum += TS_LANES_TOTAL (lane);
      if (sum >= bound)
        return sum;
      a += row_floats;
    }
  return sum;
}

/* Tries the exemplar neighbourhood centred at (x, y), clamped inside. */
static void
consider (Search *s, ptrdiff_t x, ptrdiff_t y)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  size_t qx = ts_clamp_centre (x, w, s->radius), qy = ts_clamp_centre (y, h, s->radius);
  size_t index = qy * w + qx;
  float d;

  if (s->stamp[index] == s->visit)
    return;
  s->stamp[index] = s->visit;
  if (ts_image_pixel (s->exemplar, qx, qy)[3] <= 0.0f)
    return;
  if (s->penalty)
    {
      float extra = s->penalty[index];
      if (extra >= s->best)
        return;
      d = extra + ssd_bounded (s, qx, qy, s->best - extra);
    }
  else
    d = ssd_bounded (s, qx, qy, s->best);
  if (d < s->best)
    {
      s->best = d;
      s->best_centre = (int32_t) index;
    }
}

/* The exemplar pixel `source`, shifted by (-dx, -dy), as a proposed centre,
 * and its k-coherence neighbours. */
static void
propose (Search *s, const TsCandidateSet *cands, size_t k_use, int32_t source,
         ptrdiff_t dx, ptrdiff_t dy)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  ptrdiff_t cx = (ptrdiff_t) ((size_t) source % w) - dx;
  ptrdiff_t cy = (ptrdiff_t) ((size_t) source / w) - dy;
  size_t lx, ly;
  const int32_t *list;

  consider (s, cx, cy);
  lx = cx < 0 ? 0 : (cx >= (ptrdiff_t) w ? w - 1 : (size_t) cx);
  ly = cy < 0 ? 0 : (cy >= (ptrdiff_t) h ? h - 1 : (size_t) cy);
  list = cands->index + (ly * w + lx) * cands->k;
  for (size_t i = 0; i < k_use && i < cands->k && list[i] >= 0; i++)
    consider (s, (ptrdiff_t) ((size_t) list[i] % w), (ptrdiff_t) ((size_t) list[i] / w));
}

static void
gather (const TsLevelState *state, ptrdiff_t cx, ptrdiff_t cy, size_t radius, float *out)
{
  for (ptrdiff_t dy = -(ptrdiff_t) radius; dy <= (ptrdiff_t) radius; dy++)
    {
      size_t y = ts_border_index (cy + dy, state->height, state->wrap_y);
      for (ptrdiff_t dx = -(ptrdiff_t) radius; dx <= (ptrdiff_t) radius; dx++)
        {
          size_t x = ts_border_index (cx + dx, state->width, state->wrap_x);
          memcpy (out, ts_image_pixel (&state->output, x, y), TS_CHANNELS * sizeof (float));
          out += TS_CHANNELS;
        }
    }
}

/* True if every pixel of the neighbourhood is fully preserved: its match
 * could only vote for pixels that never change. */
static bool
frozen (const TsLevelState *state, ptrdiff_t cx, ptrdiff_t cy, size_t radius)
{
  for (ptrdiff_t dy = -(ptrdiff_t) radius; dy <= (ptrdiff_t) radius; dy++)
    {
      size_t y = ts_border_index (cy + dy, state->height, state->wrap_y);
      for (ptrdiff_t dx = -(ptrdiff_t) radius; dx <= (ptrdiff_t) radius; dx++)
        if (state->preserve[y * state->width + ts_border_index (cx + dx, state->width, state->wrap_x)] < 1.0f)
          return false;
    }
  return true;
}

static void
search_centre (Search *s, const TsLevelState *state, const TsPass *pass, size_t k_use,
               uint32_t seed_stream, ptrdiff_t cx, ptrdiff_t cy, size_t centre_index)
{
  ptrdiff_t r = (ptrdiff_t) s->radius, step = (ptrdiff_t) pass->propose_step;
  ptrdiff_t first = -(r / step) * step;
  size_t own = (size_t) cy * state->width + (size_t) cx;

  /* The centre's own source first: usually the best, so the early abort
   * of every later candidate has a tight bound. */
  if (state->source[own] >= 0)
    propose (s, state->candidates, k_use, state->source[own], 0, 0);
  for (ptrdiff_t dy = first; dy <= r; dy += step)
    {
      size_t y = ts_border_index (cy + dy, state->height, state->wrap_y);
      for (ptrdiff_t dx = first; dx <= r; dx += step)
        {
          size_t x = ts_border_index (cx + dx, state->width, state->wrap_x);
          int32_t source = state->source[y * state->width + x];
          if (source >= 0)
            propose (s, state->candidates, k_use, source, dx, dy);
        }
    }
  if (state->preserve_source)
    {
      size_t y = (size_t) cy, x = (size_t) cx;
      propose (s, state->candidates, k_use, state->preserve_source[y * state->width + x], 0, 0);
    }
  if (s->best_centre < 0)
    {
      /* Nothing usable around (transparent sources): a random opaque
       * pixel keeps the search going. */
      uint64_t r64 = ts_random (seed_stream, 0, 0, centre_index, 7);
      int32_t q = state->opaque[ts_random_below (r64, state->opaque_count)];
      propose (s, state->candidates, 0, q, 0, 0);
    }
}

TsStatus
ts_mstep (const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
          const TsPass *pass, size_t k_use, uint32_t seed_stream, TsMatch *matches)
{
  const TsImage *ex = state->exemplar;
  size_t radius = pass->patch / 2, count = gx->centres * gy->centres;
  size_t ex_pixels = ts_image_pixel_count (ex);
  float pixels_per_patch = (float) (pass->patch * pass->patch);
  int failed = 0;

#pragma omp parallel
  {
    Search s = { ex, pass->patch, radius, NULL, state->penalty, NULL, 0, 0.0f, -1 };
    float *neighbourhood = malloc (pass->patch * pass->patch * TS_CHANNELS * sizeof (float));
    s.stamp = calloc (ex_pixels, sizeof (uint32_t));
    s.neighbourhood = neighbourhood;
    if (!neighbourhood || !s.stamp)
      {
#pragma omp atomic write
        failed = 1;
      }

#pragma omp for schedule(dynamic, 8)
    for (ptrdiff_t i = 0; i < (ptrdiff_t) count; i++)
      {
        int stop;
#pragma omp atomic read
        stop = failed;
        if (stop)
          continue;
        size_t jx = (size_t) i % gx->centres, jy = (size_t) i / gx->centres;
        ptrdiff_t cx = ts_axis_grid_centre (gx, jx), cy = ts_axis_grid_centre (gy, jy);

        if (state->preserve && frozen (state, cx, cy, radius))
          {
            matches[i].centre = -1;
            matches[i].distance = 0.0f;
            matches[i].weight = 0.0f;
            continue;
          }
        gather (state, cx, cy, radius, neighbourhood);
        if (++s.visit == 0)
          {
            memset (s.stamp, 0, ex_pixels * sizeof (uint32_t));
            s.visit = 1;
          }
        s.best = INFINITY;
        s.best_centre = -1;
        search_centre (&s, state, pass, k_use, seed_stream, cx, cy, (size_t) i);
        matches[i].centre = s.best_centre;
        matches[i].distance = s.best;
        /* |x - z|^(r-2) on the per-pixel RMS distance; the epsilon bounds
         * the weight of perfect matches. */
        matches[i].weight = powf (s.best / pixels_per_patch + 1e-2f,
                                  (TS_ENERGY_EXPONENT - 2.0f) * 0.5f);
      }
    free (neighbourhood);
    free (s.stamp);
  }
  return failed ? TS_ERROR_OUT_OF_MEMORY : TS_OK;
}
