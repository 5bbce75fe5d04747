/* The k-coherence search core shared by the 2D and solid M-steps: early
 * abandoned patch distances and visit stamps against duplicate candidates
 * (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_KCOHERENCE_H
#define TS_KCOHERENCE_H

#include "clones.h"
#include "guide.h"
#include "image.h"
#include "indexing.h"
#include "mrpm.h"
#include "ssd.h"

#include <math.h>
#include <stdint.h>

typedef struct
{
  const TsImage *exemplar;
  size_t         patch, radius;
  const float   *neighbourhood;  /* gathered output neighbourhood, patch^2 pixels */
  const float   *penalty;        /* occurrence penalty per centre, or NULL */
  uint32_t      *stamp;          /* per exemplar pixel: last visit       */
  uint32_t       visit;
  float          best;
  int32_t        best_centre;
  TsGuideQuery  *guide;          /* target guide around the neighbourhood, or NULL */
  /* Per exemplar pixel, 1 where a window centred there crosses the
   * exemplar's border, or NULL when every centre tried keeps its window
   * inside; then `mirrored` is the exemplar with a margin of `radius`
   * pixels mirrored around it. */
  const uint8_t *clipped;
  const float   *mirrored;
  size_t         margin;         /* least distance of a centre from the border */
} TsSearch;

/* Sum of squared differences of the gathered neighbourhood `a` against
 * the window whose first pixel is `b` in an image `stride` pixels wide,
 * abandoned (returning >= bound) as soon as a row pushes it past `bound`. */
TS_CLONE_INLINE float
ts_window_ssd (const float *a, const float *b, size_t patch, size_t stride, float bound)
{
  float sum = 0.0f;

  for (size_t row = 0; row < patch; row++)
    {
      sum += ts_pixels_ssd (a, b, patch);
      if (sum >= bound)
        return sum;
      a += patch * TS_CHANNELS;
      b += stride * TS_CHANNELS;
    }
  return sum;
}

/* The distance to the exemplar neighbourhood centred at pixel `index`,
 * whose window lies inside the exemplar. */
TS_CLONE_INLINE float
ts_search_ssd_bounded (const TsSearch *s, size_t index, float bound)
{
  size_t w = s->exemplar->width;
  return ts_window_ssd (s->neighbourhood, s->exemplar->pixels + (index - s->radius * (w + 1)) * TS_CHANNELS,
                        s->patch, w, bound);
}

/* The same for a window that crosses the exemplar's border, read from the
 * exemplar mirrored beyond it (s->mirrored): a shape the border cuts is
 * matched as continuing, not as ending in a straight edge. */
TS_VECTOR_CLONES static float
ts_search_ssd_clipped (const TsSearch *s, size_t index, float bound)
{
  size_t w = s->exemplar->width, stride = w + 2 * s->radius;
  /* With a margin of the radius, the window's first pixel in the mirrored
   * image has the centre's exemplar coordinates. */
  return ts_window_ssd (s->neighbourhood, s->mirrored + ((index / w) * stride + index % w) * TS_CHANNELS,
                        s->patch, stride, bound);
}

TS_CLONE_INLINE float
ts_search_ssd (const TsSearch *s, size_t index, float bound)
{
  if (s->clipped && s->clipped[index])
    return ts_search_ssd_clipped (s, index, bound);
  return ts_search_ssd_bounded (s, index, bound);
}

/* Tries the exemplar neighbourhood centred at pixel `index`, at least
 * s->margin from the border. */
TS_CLONE_INLINE void
ts_search_consider_centre (TsSearch *s, size_t index)
{
  float d;

  if (s->stamp[index] == s->visit)
    return;
  s->stamp[index] = s->visit;
  if (s->exemplar->pixels[index * TS_CHANNELS + 3] <= 0.0f)
    return;
  if (s->penalty || s->guide)
    {
      float extra = s->penalty ? s->penalty[index] : 0.0f;
      if (s->guide)
        {
          size_t w = s->exemplar->width;
          extra += ts_guide_cost (s->guide, index % w, index / w, s->best - extra);
        }
      if (extra >= s->best)
        return;
      d = extra + ts_search_ssd (s, index, s->best - extra);
    }
  else
    d = ts_search_ssd (s, index, s->best);
  if (d < s->best)
    {
      s->best = d;
      s->best_centre = (int32_t) index;
    }
}

/* Tries the exemplar neighbourhood centred at (x, y), clamped to the
 * margin. */
static inline void
ts_search_consider (TsSearch *s, ptrdiff_t x, ptrdiff_t y)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  size_t qx = ts_clamp_centre (x, w, s->margin), qy = ts_clamp_centre (y, h, s->margin);
  ts_search_consider_centre (s, qy * w + qx);
}

/* Starts a new search: a fresh visit stamp (clearing the stamps when the
 * counter wraps) and no best match yet. */
static inline void
ts_search_begin (TsSearch *s, size_t exemplar_pixels)
{
  if (++s->visit == 0)
    {
      for (size_t i = 0; i < exemplar_pixels; i++)
        s->stamp[i] = 0;
      s->visit = 1;
    }
  s->best = (float) INFINITY;
  s->best_centre = -1;
}

#endif
