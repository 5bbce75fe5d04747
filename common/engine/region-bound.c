/* A bound on the area of coherent regions. Texture optimization rewards
 * coherence: neighbours propose the offsets of their sources, so a copied
 * region grows as long as its seams cost more than its interior, and on
 * large outputs or regular exemplars it ends as most of the exemplar
 * pasted whole. The bound keeps each region to a stated share of the
 * exemplar; the M-step makes the pixels beyond it take another offset.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "region-bound.h"

#include <stdlib.h>

/* A quarter of the exemplar: a result then shows at least four pieces of
 * the exemplar side by side wherever it is as large as the exemplar. */
#define TS_REGION_FRACTION 0.25

TsStatus
ts_region_bound_init (TsRegionBound *bound, size_t width, size_t height,
                      size_t exemplar_width, size_t exemplar_height)
{
  double area = TS_REGION_FRACTION * (double) exemplar_width * (double) exemplar_height;

  bound->width = width;
  bound->height = height;
  bound->max_area = area < 1.0 ? 1 : (size_t) area;
  bound->flags = calloc (width * height, 1);
  bound->queue = malloc (width * height * sizeof (uint32_t));
  if (!bound->flags || !bound->queue)
    {
      ts_region_bound_free (bound);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  return TS_OK;
}

void
ts_region_bound_free (TsRegionBound *bound)
{
  free (bound->flags);
  free (bound->queue);
  bound->flags = NULL;
  bound->queue = NULL;
}

/* True if output pixel q, one step (dx, dy) from p, continues p's copy. */
static inline bool
continues (const int32_t *source, size_t p, size_t q, int dx, int dy, size_t exemplar_width)
{
  int32_t a = source[p], b = source[q];
  size_t ax, bx;

  if (a < 0 || b < 0)
    return false;
  ax = (size_t) a % exemplar_width;
  bx = (size_t) b % exemplar_width;
  return (ptrdiff_t) bx - (ptrdiff_t) ax == dx
         && (ptrdiff_t) ((size_t) b / exemplar_width) - (ptrdiff_t) ((size_t) a / exemplar_width) == dy;
}

void
ts_region_bound_mark (TsRegionBound *bound, const int32_t *source, size_t exemplar_width,
                      bool wrap_x, bool wrap_y)
{
  size_t w = bound->width, h = bound->height, n = w * h;
  uint8_t *flags = bound->flags;
  static const int steps[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };

  for (size_t p = 0; p < n; p++)
    flags[p] = 0;
  for (size_t first = 0; first < n; first++)
    {
      size_t head = 0, tail = 0;
      if (flags[first] & TS_REGION_SEEN)
        continue;
      flags[first] |= TS_REGION_SEEN;
      bound->queue[tail++] = (uint32_t) first;
      while (head < tail)
        {
          size_t p = bound->queue[head++], x = p % w, y = p / w;
          if (head > bound->max_area)
            flags[p] |= TS_REGION_CUT;
          for (int k = 0; k < 4; k++)
            {
              ptrdiff_t nx = (ptrdiff_t) x + steps[k][0], ny = (ptrdiff_t) y + steps[k][1];
              size_t q;
              if (nx < 0 || nx >= (ptrdiff_t) w)
                {
                  if (!wrap_x)
                    continue;
                  nx = nx < 0 ? (ptrdiff_t) w - 1 : 0;
                }
              if (ny < 0 || ny >= (ptrdiff_t) h)
                {
                  if (!wrap_y)
                    continue;
                  ny = ny < 0 ? (ptrdiff_t) h - 1 : 0;
                }
              q = (size_t) ny * w + (size_t) nx;
              if (!(flags[q] & TS_REGION_SEEN)
                  && continues (source, p, q, steps[k][0], steps[k][1], exemplar_width))
                {
                  flags[q] |= TS_REGION_SEEN;
                  bound->queue[tail++] = (uint32_t) q;
                }
            }
        }
    }
}
