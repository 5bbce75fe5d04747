/* A bound on the area of coherent regions. Texture optimization rewards
 * coherence: neighbours propose the offsets of their sources, so a copied
 * region grows as long as its seams cost more than its interior, and on
 * large outputs or regular exemplars it ends as most of the exemplar
 * pasted whole. The bound keeps each region to a stated share of the
 * exemplar; the M-step makes the pixels beyond it take another offset.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "region-bound.h"

#include <stdlib.h>
#ifdef _OPENMP
#include <omp.h>
#endif

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
  bound->links = malloc (width * height);
  bound->queue = malloc (width * height * sizeof (uint32_t));
  bound->parent = malloc (width * height * sizeof (uint32_t));
  /* Each large region has more than max_area pixels. */
  bound->large = malloc ((width * height / (bound->max_area + 1) + 1) * sizeof (size_t));
  if (!bound->flags || !bound->links || !bound->queue || !bound->parent || !bound->large)
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
  free (bound->links);
  free (bound->queue);
  free (bound->parent);
  free (bound->large);
  bound->flags = bound->links = NULL;
  bound->queue = bound->parent = NULL;
  bound->large = NULL;
}

/* Link bits, set per pass before the regions are labelled: the pixel
 * continues its copy into its right / lower neighbour. A step left or
 * up is the neighbour's link. */
enum
{
  LINK_RIGHT = 1,
  LINK_DOWN  = 2
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

/* Every pixel's links, on all threads; clears the flags too. */
static void
set_links (uint8_t *links, uint8_t *flags, const int32_t *source, size_t w, size_t h,
           size_t exemplar_width)
{
#pragma omp parallel for schedule(static)
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = y * w + x;
        uint8_t link = 0;
        if (x + 1 < w && continues_right (source[p], source[p + 1], exemplar_width))
          link |= LINK_RIGHT;
        if (y + 1 < h && continues_down (source[p], source[p + w], exemplar_width))
          link |= LINK_DOWN;
        links[p] = link;
        flags[p] = 0;
      }
}

/* The root of p's set, halving the path on the way. */
static inline uint32_t
find_root (uint32_t *parent, uint32_t p)
{
  while (parent[p] != p)
    {
      parent[p] = parent[parent[p]];
      p = parent[p];
    }
  return p;
}

/* Joins the sets of a and b. The root stays the set's first pixel in
 * raster order, where a serial scan would start its breadth-first walk;
 * `size` (valid at roots) adds up. */
static inline void
unite (uint32_t *parent, uint32_t *size, uint32_t a, uint32_t b)
{
  uint32_t ra = find_root (parent, a), rb = find_root (parent, b);
  if (ra == rb)
    return;
  if (rb < ra)
    {
      uint32_t t = ra;
      ra = rb;
      rb = t;
    }
  parent[rb] = ra;
  size[ra] += size[rb];
}

/* Cuts the pixels of the region whose first pixel is `first` beyond the
 * first max_area reached breadth-first from it; `queue` has room for the
 * whole region. */
static void
cut_region (TsRegionBound *bound, size_t first, uint32_t *queue)
{
  size_t w = bound->width, head = 0, tail = 0;
  const uint8_t *links = bound->links;
  uint8_t *flags = bound->flags;

  flags[first] = TS_REGION_SEEN;
  queue[tail++] = (uint32_t) first;
  while (head < tail)
    {
      size_t p = queue[head++], x = p % w, y = p / w;
      /* Right, left, down, up: the order fixes which pixels are beyond
       * the bound. A link is only set towards a neighbour inside the
       * level, so `next` is read only where linked. */
      size_t next[4] = { p + 1, p - 1, p + w, p - w };
      bool linked[4] = { (links[p] & LINK_RIGHT) != 0,
                         x > 0 && (links[p - 1] & LINK_RIGHT),
                         (links[p] & LINK_DOWN) != 0,
                         y > 0 && (links[p - w] & LINK_DOWN) };
      if (head > bound->max_area)
        flags[p] |= TS_REGION_CUT;
      for (int k = 0; k < 4; k++)
        if (linked[k] && !(flags[next[k]] & TS_REGION_SEEN))
          {
            flags[next[k]] |= TS_REGION_SEEN;
            queue[tail++] = (uint32_t) next[k];
          }
    }
}

void
ts_region_bound_mark (TsRegionBound *bound, const int32_t *source, size_t exemplar_width)
{
  size_t w = bound->width, h = bound->height, n = w * h, strips = 1, large = 0;
  uint32_t *parent = bound->parent, *size = bound->queue;
  const uint8_t *links = bound->links;

  set_links (bound->links, bound->flags, source, w, h, exemplar_width);
  /* The regions as sets: each thread joins them within its own rows, then
   * one joins them across the rows where two threads' parts meet. The
   * sets, their roots and sizes are the same for any split. */
#pragma omp parallel
  {
    size_t t = 0, count = 1;
#ifdef _OPENMP
    t = (size_t) omp_get_thread_num ();
    count = (size_t) omp_get_num_threads ();
#endif
    size_t y0 = h * t / count, y1 = h * (t + 1) / count;
    if (t == 0)
      strips = count;
    for (size_t y = y0; y < y1; y++)
      for (size_t x = 0; x < w; x++)
        {
          size_t p = y * w + x;
          bool left = x > 0 && (links[p - 1] & LINK_RIGHT);
          if (left)
            {
              /* A run along the row joins its left neighbour's set. */
              uint32_t root = find_root (parent, (uint32_t) (p - 1));
              parent[p] = root;
              size[root]++;
            }
          else
            {
              parent[p] = (uint32_t) p;
              size[p] = 1;
            }
          /* Joined from above unless the left neighbour already joined
           * the upper neighbour's row run from above. */
          if (y > y0 && (links[p - w] & LINK_DOWN)
              && !(left && (links[p - 1 - w] & LINK_DOWN) && (links[p - 1 - w] & LINK_RIGHT)))
            unite (parent, size, (uint32_t) (p - w), (uint32_t) p);
        }
  }
  for (size_t s = 1; s < strips; s++)
    {
      size_t y = h * s / strips;
      for (size_t x = 0; y > 0 && x < w; x++)
        if (links[(y - 1) * w + x] & LINK_DOWN)
          unite (parent, size, (uint32_t) ((y - 1) * w + x), (uint32_t) (y * w + x));
    }

  /* Only regions larger than the bound have pixels to cut: their roots
   * in raster order, then each one's part of `queue`, which held the
   * sizes until now. They share no pixel, so all threads walk them. */
  size_t threads = 1;
#ifdef _OPENMP
  threads = (size_t) omp_get_max_threads ();
#endif
  size_t *found = calloc (threads + 1, sizeof (size_t));
  if (!found)
    threads = 1;   /* too short of memory for the counts: one pass */
#pragma omp parallel num_threads ((int) threads)
  {
    size_t t = 0, count = 1, at = 0;
#ifdef _OPENMP
    t = (size_t) omp_get_thread_num ();
    count = (size_t) omp_get_num_threads ();
#endif
    size_t p0 = n * t / count, p1 = n * (t + 1) / count;
    if (found)
      {
        for (size_t p = p0; p < p1; p++)
          found[t + 1] += parent[p] == p && size[p] > bound->max_area;
#pragma omp barrier
        /* Thread t's roots go after those of the threads before it. */
        for (size_t u = 0; u <= t; u++)
          at += found[u];
      }
    for (size_t p = p0; p < p1; p++)
      if (parent[p] == p && size[p] > bound->max_area)
        bound->large[at++] = p;
    if (t + 1 == count)
      large = at;
  }
  free (found);
  size_t offset = 0;
  for (size_t i = 0; i < large; i++)
    {
      size_t root = bound->large[i], region = size[root];
      parent[root] = (uint32_t) offset;   /* roots are read no more */
      offset += region;
    }
#pragma omp parallel for schedule(dynamic, 1)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) large; i++)
    cut_region (bound, bound->large[i], bound->queue + parent[bound->large[i]]);
}
