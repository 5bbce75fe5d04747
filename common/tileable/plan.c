/* The plan of a tileable image: where the bands lie, the distance to
 * their cuts, and the optimization's starting source map and preserve
 * weights.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "plan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Preserve rises over this fraction of the narrower band, on both sides
 * of a join (and joins move inwards as far): wider is freer to heal, but
 * lets the optimization alter more of what was exact (0.7 gave
 * worse seams on the shared exemplars; 0.35 much the same). */
#define TS_TILEABLE_TRANSITION 0.5
#define TS_TILEABLE_FAR 1e20
/* Bounds the search for joins (and its memory) in huge images. */
#define TS_TILEABLE_MAX_REACH 256

static size_t
band_for (double fraction, size_t side)
{
  size_t band = (size_t) lround (fraction * (double) side);
  size_t most = side / 4;

  if (band < 2)
    band = 2;
  return band < most ? band : most;
}

/* A join may move up to half the band towards the edge: the other half
 * keeps the shifted content unbroken across the wrap edge. */
static size_t
reach_for (size_t band)
{
  size_t reach = band / 2;
  return reach < TS_TILEABLE_MAX_REACH ? reach : TS_TILEABLE_MAX_REACH;
}

void
ts_tileable_plan_init (const TsTileableParams *params, const TsImage *input,
                       TsTileablePlan *plan)
{
  size_t narrow;

  memset (plan, 0, sizeof *plan);
  plan->width = input->width;
  plan->height = input->height;
  plan->wrap_x = ts_tileable_wraps_x (params->direction);
  plan->wrap_y = ts_tileable_wraps_y (params->direction);
  plan->band_x = plan->wrap_x ? band_for (params->seam_width, input->width) : 0;
  plan->band_y = plan->wrap_y ? band_for (params->seam_width, input->height) : 0;
  narrow = !plan->wrap_y ? plan->band_x
           : !plan->wrap_x ? plan->band_y
           : (plan->band_x < plan->band_y ? plan->band_x : plan->band_y);
  plan->transition = fmin (TS_TILEABLE_MAX_REACH,
                           fmax (2.0, TS_TILEABLE_TRANSITION * (double) narrow));
  plan->reach_x = reach_for (plan->band_x);
  plan->reach_y = reach_for (plan->band_y);
}

void
ts_tileable_plan_clear (TsTileablePlan *plan)
{
  free (plan->band_mask);
  plan->band_mask = NULL;
}

bool
ts_tileable_in_band (const TsTileablePlan *plan, size_t x, size_t y)
{
  if (plan->band_mask)
    return plan->band_mask[y * plan->width + x] != 0;
  return (plan->wrap_x && (x < plan->band_x || x >= plan->width - plan->band_x)) ||
         (plan->wrap_y && (y < plan->band_y || y >= plan->height - plan->band_y));
}

/* Where the parabolas of samples q and p of f meet. */
static double
intersection (const double *f, size_t q, size_t p)
{
  double a = (double) q, b = (double) p;
  return ((f[q] + a * a) - (f[p] + b * b)) / (2.0 * a - 2.0 * b);
}

/* Felzenszwalb & Huttenlocher's 1D squared distance transform of f into d
 * (n samples); v and z are scratch of n and n + 1 entries. */
static void
distance_1d (const double *f, size_t n, double *d, size_t *v, double *z)
{
  size_t k = 0;

  v[0] = 0;
  z[0] = -INFINITY;
  z[1] = INFINITY;
  for (size_t q = 1; q < n; q++)
    {
      double s = intersection (f, q, v[k]);
      /* z[0] is -infinity, so k never goes below 0. */
      while (s <= z[k])
        s = intersection (f, q, v[--k]);
      k++;
      v[k] = q;
      z[k] = s;
      z[k + 1] = INFINITY;
    }
  k = 0;
  for (size_t q = 0; q < n; q++)
    {
      while (z[k + 1] < (double) q)
        k++;
      double t = (double) q - (double) v[k];
      d[q] = t * t + f[v[k]];
    }
}

/* Squared distance transform along one line of n samples read and written
 * with `stride`, wrapping by running over three periods. */
static void
distance_line (double *line, size_t n, size_t stride, bool wrap, double *f, double *d,
               size_t *v, double *z)
{
  size_t copies = wrap ? 3 : 1, m = n * copies;

  for (size_t i = 0; i < m; i++)
    f[i] = line[(i % n) * stride];
  distance_1d (f, m, d, v, z);
  for (size_t i = 0; i < n; i++)
    line[i * stride] = d[(copies / 2) * n + i];
}

TsStatus
ts_tileable_distance (const unsigned char *mask, size_t width, size_t height, bool wrap_x,
                      bool wrap_y, float *distance)
{
  size_t n = width * height, longest = 3 * (width > height ? width : height);
  double *grid = malloc (n * sizeof (double));
  double *f = malloc (longest * sizeof (double)), *d = malloc (longest * sizeof (double));
  double *z = malloc ((longest + 1) * sizeof (double));
  size_t *v = malloc (longest * sizeof (size_t));
  TsStatus status = TS_OK;

  if (!grid || !f || !d || !z || !v)
    status = TS_ERROR_OUT_OF_MEMORY;
  else
    {
      for (size_t i = 0; i < n; i++)
        grid[i] = mask[i] ? 0.0 : TS_TILEABLE_FAR;
      for (size_t y = 0; y < height; y++)
        distance_line (grid + y * width, width, 1, wrap_x, f, d, v, z);
      for (size_t x = 0; x < width; x++)
        distance_line (grid + x, height, width, wrap_y, f, d, v, z);
      for (size_t i = 0; i < n; i++)
        distance[i] = grid[i] >= TS_TILEABLE_FAR ? (float) TS_TILEABLE_FAR : (float) sqrt (grid[i]);
    }
  free (grid);
  free (f);
  free (d);
  free (z);
  free (v);
  return status;
}

/* Source (x, y) of output pixel (x, y) at the start. */
static void
start_source (const TsTileablePlan *plan, size_t x, size_t y, size_t *sx, size_t *sy)
{
  if (ts_tileable_in_band (plan, x, y))
    {
      *sx = (x + plan->shift_x) % plan->width;
      *sy = (y + plan->shift_y) % plan->height;
    }
  else
    {
      *sx = x;
      *sy = y;
    }
}

/* Marks both pixels of every 4-neighbour pair whose sources do not
 * continue each other (a cut in the start map). */
static void
mark_cuts (const TsTileablePlan *plan, const int32_t *source, unsigned char *cut)
{
  size_t w = plan->width, h = plan->height;

  memset (cut, 0, w * h);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = y * w + x;
        if (x + 1 < w || plan->wrap_x)
          {
            size_t q = y * w + (x + 1) % w;
            if (source[2 * q] != source[2 * p] + 1 || source[2 * q + 1] != source[2 * p + 1])
              cut[p] = cut[q] = 1;
          }
        if (y + 1 < h || plan->wrap_y)
          {
            size_t q = ((y + 1) % h) * w + x;
            if (source[2 * q] != source[2 * p] || source[2 * q + 1] != source[2 * p + 1] + 1)
              cut[p] = cut[q] = 1;
          }
      }
}

TsStatus
ts_tileable_maps (const TsTileablePlan *plan, int32_t *source, float *preserve)
{
  size_t w = plan->width, h = plan->height, n = w * h;
  unsigned char *cut = calloc (n, 1);
  TsStatus status;

  if (!cut)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t sx, sy;
        start_source (plan, x, y, &sx, &sy);
        source[2 * (y * w + x)] = (int32_t) sx;
        source[2 * (y * w + x) + 1] = (int32_t) sy;
      }
  mark_cuts (plan, source, cut);
  status = ts_tileable_distance (cut, w, h, plan->wrap_x, plan->wrap_y, preserve);
  if (status == TS_OK)
    for (size_t i = 0; i < n; i++)
      {
        /* Smooth rise: the optimization fades from free to bound. */
        double t = fmin (1.0, (double) preserve[i] / plan->transition);
        preserve[i] = (float) (t * t * (3.0 - 2.0 * t));
      }
  free (cut);
  return status;
}
