/* The plan of a tileable image: where the bands lie, the distance to
 * their cuts, and the optimization's starting source map and preserve
 * weights.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "plan.h"
#include "engine/distance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Preserve rises over this fraction of the narrower band, on both sides
 * of a join (and joins move inwards as far): wider is freer to heal, but
 * lets the optimization alter more of what was exact; half the band
 * balances the two, and the seams change little around it. */
#define TS_TILEABLE_TRANSITION 0.5
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

TsStatus
ts_tileable_distance (const unsigned char *mask, size_t width, size_t height, bool wrap_x,
                      bool wrap_y, float *distance)
{
  size_t n = width * height, dims[3] = { width, height, 1 };
  bool wrap[3] = { wrap_x, wrap_y, false };

  for (size_t i = 0; i < n; i++)
    distance[i] = mask[i] ? 0.0f : TS_DISTANCE_FAR;
  return ts_distance_transform (distance, dims, wrap);
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
