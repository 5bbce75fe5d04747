/* Where the bands of a tileable image end: minimum-cost cuts
 * (ts_tileable_place_cuts).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Each side of the kept picture is a strip of pixels across which the
 * join may run. The join is a path along pixel boundaries from one end of
 * the strip to the other; crossing between pixels p and q costs
 * |A(p) - B(p)|^2 + |A(q) - B(q)|^2, A the kept picture and B the shifted
 * content (Kwatra et al. 2003's seam cost). The cheapest path is a
 * shortest path in the dual grid (Dijkstra), free in shape: it can follow
 * a mortar line around a brick's corner, which a path with one position
 * per row cannot.
 */
#include "cuts.h"
#include "engine/image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Per crossed boundary, so that in flat areas the join is short and stays
 * near its nominal place (in squared Lab units per pixel of distance). */
#define TS_CUT_LENGTH_COST 1e-3
#define TS_CUT_OFFSET_COST 1e-4
/* Closest a join comes to a wrap edge, if the band is that wide: a 7x7
 * neighbourhood straddling the edge then lies in unbroken content. */
#define TS_CUT_EDGE_MARGIN 7

typedef struct
{
  const TsImage        *image;
  const TsTileablePlan *plan;
  bool                  vertical;  /* the join runs down the rows (a left or
                                      right side); else along the columns */
  bool                  band_low;  /* the band lies below the strip in u   */
  size_t                lo, hi;    /* pixels of the strip across it (u)    */
  size_t                length;    /* pixels along it (v)                  */
  size_t                nominal;   /* boundary u of the straight join      */
  double               *cost;      /* per strip pixel incl. one either side */
} Strip;

static size_t
edge_distance (size_t i, size_t n)
{
  return i < n - 1 - i ? i : n - 1 - i;
}

/* Squared difference between the kept picture and the shifted content at
 * (u, v); zero where the other band covers the pixel whatever this join
 * does (its own join cannot reach there). */
static double
join_cost (const Strip *s, size_t u, size_t v)
{
  const TsTileablePlan *plan = s->plan;
  size_t x = s->vertical ? u : v, y = s->vertical ? v : u;
  const float *a = ts_image_pixel (s->image, x, y);
  const float *b = ts_image_pixel (s->image, (x + plan->shift_x) % plan->width,
                                   (y + plan->shift_y) % plan->height);
  double sum = 0.0;

  if (s->vertical && plan->wrap_y && edge_distance (y, plan->height) + plan->reach_y < plan->band_y)
    return 0.0;
  if (!s->vertical && plan->wrap_x && edge_distance (x, plan->width) + plan->reach_x < plan->band_x)
    return 0.0;
  for (int c = 0; c < TS_CHANNELS; c++)
    {
      double d = (double) a[c] - (double) b[c];
      sum += d * d;
    }
  return sum;
}

/* Cost of pixel (u, v), u in [lo - 1, hi + 1]. */
static double
pixel (const Strip *s, size_t u, size_t v)
{
  return s->cost[v * (s->hi - s->lo + 3) + (u + 1 - s->lo)];
}

typedef struct
{
  double dist;
  size_t node;
} Entry;

/* A binary min-heap of (dist, node); ties by node, so runs repeat. */
typedef struct
{
  Entry *e;
  size_t n, capacity;
} Heap;

static bool
before (Entry a, Entry b)
{
  return a.dist < b.dist || (a.dist == b.dist && a.node < b.node);
}

static bool
heap_push (Heap *h, double dist, size_t node)
{
  if (h->n == h->capacity)
    {
      size_t capacity = h->capacity ? 2 * h->capacity : 256;
      Entry *e = realloc (h->e, capacity * sizeof (Entry));
      if (!e)
        return false;
      h->e = e;
      h->capacity = capacity;
    }
  size_t i = h->n++;
  h->e[i] = (Entry) { dist, node };
  while (i > 0 && before (h->e[i], h->e[(i - 1) / 2]))
    {
      Entry t = h->e[i];
      h->e[i] = h->e[(i - 1) / 2];
      h->e[(i - 1) / 2] = t;
      i = (i - 1) / 2;
    }
  return true;
}

static Entry
heap_pop (Heap *h)
{
  Entry top = h->e[0];
  size_t i = 0;

  h->e[0] = h->e[--h->n];
  for (;;)
    {
      size_t l = 2 * i + 1, r = l + 1, m = i;
      if (l < h->n && before (h->e[l], h->e[m]))
        m = l;
      if (r < h->n && before (h->e[r], h->e[m]))
        m = r;
      if (m == i)
        break;
      Entry t = h->e[i];
      h->e[i] = h->e[m];
      h->e[m] = t;
      i = m;
    }
  return top;
}

/* Dual grid: corner (cu, v), cu in [lo, hi + 1], v in [0, length]; node
 * (v * columns + cu - lo). A step along v at cu runs between pixels
 * (cu - 1, row) and (cu, row); a step along u at v between (col, v - 1)
 * and (col, v). Marks the steps of the cheapest path from v = 0 to
 * v = length in `cross_u` (boundary left of pixel (u, row)) and `cross_v`
 * (boundary above pixel (col, v)). */
static TsStatus
shortest_join (const Strip *s, unsigned char *cross_u, unsigned char *cross_v)
{
  size_t columns = s->hi - s->lo + 2, nodes = columns * (s->length + 1);
  double *dist = malloc (nodes * sizeof (double));
  size_t *from = malloc (nodes * sizeof (size_t));
  Heap heap = { NULL, 0, 0 };
  TsStatus status = TS_OK;
  size_t end = nodes;

  if (!dist || !from)
    status = TS_ERROR_OUT_OF_MEMORY;
  for (size_t i = 0; status == TS_OK && i < nodes; i++)
    {
      dist[i] = INFINITY;
      from[i] = nodes;
    }
  for (size_t j = 0; status == TS_OK && j < columns; j++)
    {
      dist[j] = 0.0;
      if (!heap_push (&heap, 0.0, j))
        status = TS_ERROR_OUT_OF_MEMORY;
    }
  while (status == TS_OK && heap.n > 0)
    {
      Entry top = heap_pop (&heap);
      size_t cu = top.node % columns + s->lo, v = top.node / columns;
      if (top.dist > dist[top.node])
        continue;
      if (v == s->length)
        {
          end = top.node;
          break;
        }
      /* Neighbours: (cu, v +- 1) and, inside, (cu +- 1, v). */
      for (int k = 0; k < 4; k++)
        {
          size_t nu = cu, nv = v;
          double step;
          if (k == 0 || k == 1)
            {
              if (k == 1 && v == 0)
                continue;
              nv = k == 0 ? v + 1 : v - 1;
              size_t row = k == 0 ? v : v - 1;
              step = pixel (s, cu - 1, row) + pixel (s, cu, row);
            }
          else
            {
              if (v == 0 || (k == 2 && cu == s->lo) || (k == 3 && cu == s->hi + 1))
                continue;
              nu = k == 2 ? cu - 1 : cu + 1;
              size_t col = k == 2 ? cu - 1 : cu;
              step = pixel (s, col, v - 1) + pixel (s, col, v);
            }
          step += TS_CUT_LENGTH_COST + TS_CUT_OFFSET_COST * fabs ((double) nu - (double) s->nominal);
          size_t next = nv * columns + (nu - s->lo);
          if (top.dist + step < dist[next])
            {
              dist[next] = top.dist + step;
              from[next] = top.node;
              if (!heap_push (&heap, dist[next], next))
                status = TS_ERROR_OUT_OF_MEMORY;
            }
        }
    }
  if (status == TS_OK && end == nodes)
    status = TS_ERROR_INVALID_ARGUMENT;  /* cannot happen: the grid is connected */
  for (size_t node = end; status == TS_OK && from[node] != nodes; node = from[node])
    {
      size_t a = node, b = from[node];
      size_t au = a % columns + s->lo, av = a / columns, bu = b % columns + s->lo, bv = b / columns;
      if (au == bu)
        cross_u[(av < bv ? av : bv) * columns + (au - s->lo)] = 1;
      else
        cross_v[av * columns + ((au < bu ? au : bu) - s->lo)] = 1;
    }
  free (dist);
  free (from);
  free (heap.e);
  return status;
}

/* Labels the band side of the join: the strip pixels connected to the
 * band's end of the strip without crossing the path, plus everything
 * beyond that end. */
static TsStatus
label (const Strip *s, const unsigned char *cross_u, const unsigned char *cross_v,
       unsigned char *band)
{
  size_t columns = s->hi - s->lo + 2, width = s->hi - s->lo + 1, count = width * s->length;
  size_t *queue = malloc (count * sizeof (size_t)), head = 0, tail = 0;
  unsigned char *seen = calloc (count, 1);
  const TsTileablePlan *plan = s->plan;

  if (!queue || !seen)
    {
      free (queue);
      free (seen);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t v = 0; v < s->length; v++)
    {
      size_t u = s->band_low ? s->lo : s->hi, edge = s->band_low ? 0 : width;
      if (!cross_u[v * columns + edge])
        {
          seen[v * width + (u - s->lo)] = 1;
          queue[tail++] = v * width + (u - s->lo);
        }
    }
  while (head < tail)
    {
      size_t i = queue[head++], j = i % width, v = i / width;
      /* Left, right (boundary index j and j + 1), up, down. */
      if (j > 0 && !cross_u[v * columns + j] && !seen[i - 1])
        seen[queue[tail++] = i - 1] = 1;
      if (j + 1 < width && !cross_u[v * columns + j + 1] && !seen[i + 1])
        seen[queue[tail++] = i + 1] = 1;
      if (v > 0 && !cross_v[v * columns + j] && !seen[i - width])
        seen[queue[tail++] = i - width] = 1;
      if (v + 1 < s->length && !cross_v[(v + 1) * columns + j] && !seen[i + width])
        seen[queue[tail++] = i + width] = 1;
    }
  for (size_t v = 0; v < s->length; v++)
    {
      size_t n_u = s->vertical ? plan->width : plan->height;
      for (size_t u = 0; u < n_u; u++)
        {
          bool in = u < s->lo ? s->band_low
                    : u > s->hi ? !s->band_low
                    : seen[v * width + (u - s->lo)];
          if (in)
            band[s->vertical ? v * plan->width + u : u * plan->width + v] = 1;
        }
    }
  free (queue);
  free (seen);
  return TS_OK;
}

/* One side: the band ends at `nominal` (the first pixel past the band on
 * the kept side is `nominal` for a low band, the last kept one
 * `nominal - 1` for a high band), moved within [min, max]. */
static TsStatus
place (const TsImage *image, const TsTileablePlan *plan, bool vertical, bool band_low,
       size_t nominal, size_t min, size_t max, unsigned char *band)
{
  size_t reach_out = vertical ? plan->reach_x : plan->reach_y;
  size_t reach_in = (size_t) plan->transition;
  size_t out_lo = band_low ? reach_out : reach_in, out_hi = band_low ? reach_in : reach_out;
  Strip s = { image, plan, vertical, band_low, 0, 0, vertical ? plan->height : plan->width,
              nominal, NULL };
  size_t n_u = vertical ? plan->width : plan->height;
  unsigned char *cross_u, *cross_v;
  TsStatus status;

  /* Pixels lo .. hi may fall on either side; lo - 1 and hi + 1 exist. */
  s.lo = nominal > min + out_lo ? nominal - out_lo : min;
  s.hi = nominal + out_hi <= max ? nominal + out_hi - 1 : max - 1;
  if (s.lo < 1)
    s.lo = 1;
  if (s.hi + 2 > n_u)
    s.hi = n_u - 2;
  if (s.hi < s.lo)
    s.hi = s.lo;
  size_t columns = s.hi - s.lo + 2, wide = s.hi - s.lo + 3;
  s.cost = malloc (wide * s.length * sizeof (double));
  cross_u = calloc (columns * (s.length + 1), 1);
  cross_v = calloc (columns * (s.length + 1), 1);
  if (!s.cost || !cross_u || !cross_v)
    status = TS_ERROR_OUT_OF_MEMORY;
  else
    {
      for (size_t v = 0; v < s.length; v++)
        for (size_t u = s.lo - 1; u <= s.hi + 1; u++)
          s.cost[v * wide + (u + 1 - s.lo)] = join_cost (&s, u, v);
      status = shortest_join (&s, cross_u, cross_v);
      if (status == TS_OK)
        status = label (&s, cross_u, cross_v, band);
    }
  free (s.cost);
  free (cross_u);
  free (cross_v);
  return status;
}

TsStatus
ts_tileable_place_cuts (const TsImage *input, TsTileablePlan *plan)
{
  size_t w = plan->width, h = plan->height;
  TsStatus status = TS_OK;

  free (plan->band_mask);
  plan->band_mask = calloc (w * h, 1);
  if (!plan->band_mask)
    return TS_ERROR_OUT_OF_MEMORY;
  /* Each join stays on its own side of the middle and, where the band
   * allows, a neighbourhood's width from the wrap edge, which so lies
   * inside unbroken content. */
  if (plan->wrap_x)
    {
      size_t margin = plan->band_x < TS_CUT_EDGE_MARGIN ? plan->band_x : TS_CUT_EDGE_MARGIN;
      status = place (input, plan, true, true, plan->band_x, margin, w / 2, plan->band_mask);
      if (status == TS_OK)
        status = place (input, plan, true, false, w - plan->band_x, w / 2, w - margin,
                        plan->band_mask);
    }
  if (plan->wrap_y && status == TS_OK)
    {
      size_t margin = plan->band_y < TS_CUT_EDGE_MARGIN ? plan->band_y : TS_CUT_EDGE_MARGIN;
      status = place (input, plan, false, true, plan->band_y, margin, h / 2, plan->band_mask);
      if (status == TS_OK)
        status = place (input, plan, false, false, h - plan->band_y, h / 2, h - margin,
                        plan->band_mask);
    }
  if (status != TS_OK)
    ts_tileable_plan_clear (plan);
  return status;
}
