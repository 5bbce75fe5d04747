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

/* Link bits, set per pass before the regions are labelled: the pixel
 * continues its copy into its right / lower neighbour. A step left or
 * up is the neighbour's link. */
enum
{
  LINK_RIGHT = 4,
  LINK_DOWN  = 8
};

/* True if source b is the exemplar pixel right of source a / below it. */
static inline bool
continues_right (int32_t a, int32_t b, size_t exemplar_width)
{
  return a >= 0 && b == a + 1 && (size_t) b % exemplar_width != 0;
}

static inline bool
continues_down (int32_t a, int32_t b, size_t exemplar_width)
{
  return a >= 0 && b >= 0 && (size_t) b == (size_t) a + exemplar_width;
}

/* Every pixel's links, on all threads (the labelling after it is serial:
 * it only tests these bits). Clears the other flags too. */
static void
set_links (uint8_t *flags, const int32_t *source, size_t w, size_t h, size_t exemplar_width)
{
#pragma omp parallel for schedule(static)
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = y * w + x;
        uint8_t links = 0;
        if (x + 1 < w && continues_right (source[p], source[p + 1], exemplar_width))
          links |= LINK_RIGHT;
        if (y + 1 < h && continues_down (source[p], source[p + w], exemplar_width))
          links |= LINK_DOWN;
        flags[p] = links;
      }
}

void
ts_region_bound_mark (TsRegionBound *bound, const int32_t *source, size_t exemplar_width)
{
  size_t w = bound->width, h = bound->height, n = w * h;
  uint8_t *flags = bound->flags;

  set_links (flags, source, w, h, exemplar_width);
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
          /* Right, left, down, up: the order fixes which pixels are
           * beyond the bound. A link is only set towards a neighbour
           * inside the level, so `next` is read only where linked. */
          size_t next[4] = { p + 1, p - 1, p + w, p - w };
          bool linked[4] = { (flags[p] & LINK_RIGHT) != 0,
                             x > 0 && (flags[p - 1] & LINK_RIGHT),
                             (flags[p] & LINK_DOWN) != 0,
                             y > 0 && (flags[p - w] & LINK_DOWN) };
          if (head > bound->max_area)
            flags[p] |= TS_REGION_CUT;
          for (int k = 0; k < 4; k++)
            if (linked[k] && !(flags[next[k]] & TS_REGION_SEEN))
              {
                flags[next[k]] |= TS_REGION_SEEN;
                bound->queue[tail++] = (uint32_t) next[k];
              }
        }
    }
}
