/* The k-coherence search core shared by the 2D and solid M-steps: early
 * abandoned patch distances, visit stamps against duplicate candidates,
 * and proposals from neighbours' sources (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_KCOHERENCE_H
#define TS_KCOHERENCE_H

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
} TsSearch;

/* Sum of squared differences, abandoned (returning >= bound) as soon as a
 * row pushes it past `bound`. */
static inline float
ts_search_ssd_bounded (const TsSearch *s, size_t qx, size_t qy, float bound)
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
static inline void
ts_search_consider (TsSearch *s, ptrdiff_t x, ptrdiff_t y)
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
  if (s->penalty || s->guide)
    {
      float extra = s->penalty ? s->penalty[index] : 0.0f;
      if (s->guide)
        extra += ts_guide_cost (s->guide, qx, qy, s->best - extra);
      if (extra >= s->best)
        return;
      d = extra + ts_search_ssd_bounded (s, qx, qy, s->best - extra);
    }
  else
    d = ts_search_ssd_bounded (s, qx, qy, s->best);
  if (d < s->best)
    {
      s->best = d;
      s->best_centre = (int32_t) index;
    }
}

/* The exemplar pixel `source`, shifted by (-dx, -dy), as a proposed centre,
 * and its first `k_use` k-coherence neighbours. */
static inline void
ts_search_propose (TsSearch *s, const TsCandidateSet *cands, size_t k_use, int32_t source,
                   ptrdiff_t dx, ptrdiff_t dy)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  ptrdiff_t cx = (ptrdiff_t) ((size_t) source % w) - dx;
  ptrdiff_t cy = (ptrdiff_t) ((size_t) source / w) - dy;
  size_t lx, ly;
  const int32_t *list;

  ts_search_consider (s, cx, cy);
  lx = cx < 0 ? 0 : (cx >= (ptrdiff_t) w ? w - 1 : (size_t) cx);
  ly = cy < 0 ? 0 : (cy >= (ptrdiff_t) h ? h - 1 : (size_t) cy);
  list = cands->index + (ly * w + lx) * cands->k;
  for (size_t i = 0; i < k_use && i < cands->k && list[i] >= 0; i++)
    ts_search_consider (s, (ptrdiff_t) ((size_t) list[i] % w), (ptrdiff_t) ((size_t) list[i] / w));
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
