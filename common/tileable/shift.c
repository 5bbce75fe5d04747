/* Choice of the offset of the content that replaces the bands of a
 * tileable image (ts_tileable_choose_shift), coarse to fine.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "shift.h"
#include "engine/image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The exhaustive search runs on a copy whose longer side is at most
 * this: every shift of a 64 x 64 copy is cheap to try, and it still
 * shows the texture's large features. */
#define TS_SHIFT_COARSEST_SIDE 64
/* Finer levels try the doubled coarser shift +- this: one coarse pixel
 * of rounding either way, and a little room to move. */
#define TS_SHIFT_REFINE 2
/* Halvings from the coarsest copy up: 64 x 2^16 is beyond any image. */
#define TS_SHIFT_MAX_LEVELS 16
/* Weight of the detail term against the mismatch term (about 1 for
 * unrelated content): band content 20% less detailed than what it
 * replaces costs as much as a mismatch 0.16 worse. Without it the search
 * favours flat pieces, which match anything but dull the edges: a
 * textured image could lose a sixth of its sharpness. */
#define TS_SHIFT_DETAIL_WEIGHT 4.0

typedef struct
{
  TsImage        image;  /* box-filtered working image (level 0: a view) */
  unsigned char *zone;   /* pixels near a cut, whose cost counts         */
  unsigned char *band;   /* pixels whose content is replaced             */
  float         *detail; /* |grad L| per pixel                           */
  double         mismatch_scale, detail_scale;  /* normalise the cost   */
  size_t         band_x, band_y;   /* band half-widths at this level     */
  double         cut_weight;       /* zone pixels per pixel of cut line  */
  bool           both;             /* both axes wrap: bands have inner cuts */
  size_t         lo_x, hi_x, lo_y, hi_y;  /* allowed shifts at this level */
} ShiftLevel;

/* Mean of the 2x2 blocks of `in` (the last row/column alone if odd). */
static TsStatus
halve (const ShiftLevel *in, ShiftLevel *out)
{
  size_t w = (in->image.width + 1) / 2, h = (in->image.height + 1) / 2;
  TsStatus status = ts_image_alloc (&out->image, w, h);

  out->zone = status == TS_OK ? calloc (w * h, 1) : NULL;
  out->band = status == TS_OK ? calloc (w * h, 1) : NULL;
  if (status != TS_OK || !out->zone || !out->band)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        float *o = ts_image_pixel (&out->image, x, y);
        size_t count = 0;
        for (size_t by = 2 * y; by < 2 * y + 2 && by < in->image.height; by++)
          for (size_t bx = 2 * x; bx < 2 * x + 2 && bx < in->image.width; bx++, count++)
            {
              const float *p = ts_image_pixel (&in->image, bx, by);
              for (int c = 0; c < TS_CHANNELS; c++)
                o[c] += p[c];
              out->zone[y * w + x] |= in->zone[by * in->image.width + bx];
              out->band[y * w + x] |= in->band[by * in->image.width + bx];
            }
        for (int c = 0; c < TS_CHANNELS; c++)
          o[c] /= (float) count;
      }
  out->band_x = (in->band_x + 1) / 2;
  out->band_y = (in->band_y + 1) / 2;
  out->cut_weight = in->cut_weight / 2.0;
  out->both = in->both;
  out->lo_x = (in->lo_x + 1) / 2;
  out->hi_x = in->hi_x / 2;
  out->lo_y = (in->lo_y + 1) / 2;
  out->hi_y = in->hi_y / 2;
  if (out->hi_x < out->lo_x)
    out->hi_x = out->lo_x;
  if (out->hi_y < out->lo_y)
    out->hi_y = out->lo_y;
  return TS_OK;
}

/* |grad L| of the full-size image (central differences, wrapping); a
 * coarser level gets the block means, so fine detail still counts there. */
static TsStatus
detail_map (ShiftLevel *level, const ShiftLevel *finer)
{
  const TsImage *im = &level->image;
  size_t w = im->width, h = im->height;

  level->detail = malloc (w * h * sizeof (float));
  if (!level->detail)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double sum = 0.0;
        size_t count = 0;
        if (!finer)
          {
            double gx = ts_image_pixel (im, (x + 1) % w, y)[0] - ts_image_pixel (im, (x + w - 1) % w, y)[0];
            double gy = ts_image_pixel (im, x, (y + 1) % h)[0] - ts_image_pixel (im, x, (y + h - 1) % h)[0];
            sum = 0.5 * sqrt (gx * gx + gy * gy);
            count = 1;
          }
        else
          for (size_t by = 2 * y; by < 2 * y + 2 && by < finer->image.height; by++)
            for (size_t bx = 2 * x; bx < 2 * x + 2 && bx < finer->image.width; bx++, count++)
              sum += finer->detail[by * finer->image.width + bx];
        level->detail[y * w + x] = (float) (sum / (double) count);
      }
  return TS_OK;
}

/* Scales that make the two parts of the cost comparable at every level:
 * the mismatch over that of two unrelated pixels, the detail of the new
 * band content over that of the content it replaces (so the image as a
 * whole stays as sharp). */
static void
scales (ShiftLevel *level)
{
  const TsImage *im = &level->image;
  size_t n = im->width * im->height, zone = 0;
  double mean[TS_CHANNELS] = { 0 }, variance = 0.0, detail = 0.0;

  for (size_t i = 0; i < n; i++)
    for (int c = 0; c < TS_CHANNELS; c++)
      mean[c] += im->pixels[i * TS_CHANNELS + c] / (double) n;
  for (size_t i = 0; i < n; i++)
    {
      for (int c = 0; c < TS_CHANNELS; c++)
        {
          double d = im->pixels[i * TS_CHANNELS + c] - mean[c];
          variance += d * d / (double) n;
        }
      if (level->band[i])
        detail += level->detail[i];
      zone += level->zone[i];
    }
  level->mismatch_scale = 1.0 / (fmax (1.0, (double) zone) * fmax (1e-6, 2.0 * variance));
  level->detail_scale = 1.0 / fmax (1e-6, detail);
}

static double
pixel_difference (const float *a, const float *b)
{
  double sum = 0.0;
  for (int c = 0; c < TS_CHANNELS; c++)
    {
      double d = (double) a[c] - (double) b[c];
      sum += d * d;
    }
  return sum;
}

static size_t
edge_distance (size_t i, size_t n)
{
  return i < n - 1 - i ? i : n - 1 - i;
}

/* When both axes wrap, each band is a loop around the torus and needs
 * one cut across it: where the shifted source itself wraps, so the image's
 * own opposite edges meet there (x = w - sx in the top/bottom band,
 * y = h - sy in the left/right band). Their squared differences. */
static double
inner_cuts (const ShiftLevel *level, size_t sx, size_t sy)
{
  const TsImage *im = &level->image;
  size_t w = im->width, h = im->height;
  double sum = 0.0;

  for (size_t y = 0; y < h; y++)
    if (edge_distance (y, h) < level->band_y)
      {
        size_t ty = (y + sy) % h;
        sum += pixel_difference (ts_image_pixel (im, w - 1, ty), ts_image_pixel (im, 0, ty));
      }
  for (size_t x = 0; x < w; x++)
    if (edge_distance (x, w) < level->band_x)
      {
        size_t tx = (x + sx) % w;
        sum += pixel_difference (ts_image_pixel (im, tx, h - 1), ts_image_pixel (im, tx, 0));
      }
  return sum;
}

/* Cost of shift (sx, sy): the squared difference between the image and
 * its shifted self near the cuts, where the optimization must reconcile
 * them, plus how far the detail of the new band content is from the
 * image's: a flat piece matches everything, but would blur the edges. */
static double
shift_cost (const ShiftLevel *level, size_t sx, size_t sy)
{
  const TsImage *im = &level->image;
  size_t w = im->width, h = im->height;
  double mismatch = 0.0, detail = 0.0;

  for (size_t y = 0; y < h; y++)
    {
      size_t ty = (y + sy) % h;
      const float *row = ts_image_pixel (im, 0, ty);
      for (size_t x = 0; x < w; x++)
        {
          size_t i = y * w + x, tx = (x + sx) % w;
          if (level->band[i])
            detail += level->detail[ty * w + tx];
          if (!level->zone[i])
            continue;
          mismatch += pixel_difference (im->pixels + i * TS_CHANNELS, row + tx * TS_CHANNELS);
        }
    }
  if (level->both)
    mismatch += level->cut_weight * inner_cuts (level, sx, sy);
  detail = detail * level->detail_scale - 1.0;
  return mismatch * level->mismatch_scale + TS_SHIFT_DETAIL_WEIGHT * detail * detail;
}

/* Best shift of the level within [lo, hi] on both axes, ties to the first
 * in raster order (deterministic). */
static void
search (const ShiftLevel *level, size_t lo_x, size_t hi_x, size_t lo_y, size_t hi_y,
        size_t *best_x, size_t *best_y)
{
  double best = INFINITY;

  for (size_t sy = lo_y; sy <= hi_y; sy++)
    for (size_t sx = lo_x; sx <= hi_x; sx++)
      {
        double cost = shift_cost (level, sx, sy);
        if (cost < best)
          {
            best = cost;
            *best_x = sx;
            *best_y = sy;
          }
      }
}

static size_t
clamp_range (ptrdiff_t v, size_t lo, size_t hi)
{
  return v < (ptrdiff_t) lo ? lo : (v > (ptrdiff_t) hi ? hi : (size_t) v);
}

/* Allowed shifts along an axis of n pixels with bands of half-width
 * `band`: the content comes from the middle half (far from the band it
 * replaces) and never wraps within a band; 0 if the axis does not wrap. */
static void
allowed (bool wrap, size_t n, size_t band, size_t *lo, size_t *hi)
{
  *lo = *hi = 0;
  if (!wrap)
    return;
  *lo = n / 4 > band ? n / 4 : band;
  *hi = n - *lo;
  if (*hi < *lo)
    *lo = *hi = n / 2;
}

TsStatus
ts_tileable_choose_shift (const TsImage *input, TsTileablePlan *plan)
{
  ShiftLevel level[TS_SHIFT_MAX_LEVELS];
  size_t levels = 1, w = plan->width, h = plan->height, n = w * h;
  size_t sx = 0, sy = 0;
  unsigned char *boundary = calloc (n, 1);
  float *distance = malloc (n * sizeof (float));
  TsStatus status = TS_OK;

  memset (level, 0, sizeof level);
  level[0].image = *input;
  level[0].zone = malloc (n);
  level[0].band = malloc (n);
  if (!boundary || !distance || !level[0].zone || !level[0].band)
    status = TS_ERROR_OUT_OF_MEMORY;
  if (status == TS_OK)
    {
      /* The zone: pixels within the transition of where a band meets the
       * kept picture. */
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          {
            bool in = ts_tileable_in_band (plan, x, y);
            level[0].band[y * w + x] = in;
            bool right = (x + 1 < w || plan->wrap_x) && ts_tileable_in_band (plan, (x + 1) % w, y) != in;
            bool down = (y + 1 < h || plan->wrap_y) && ts_tileable_in_band (plan, x, (y + 1) % h) != in;
            boundary[y * w + x] = right || down;
          }
      status = ts_tileable_distance (boundary, w, h, plan->wrap_x, plan->wrap_y, distance);
    }
  if (status == TS_OK)
    {
      for (size_t i = 0; i < n; i++)
        level[0].zone[i] = distance[i] <= plan->transition;
      level[0].band_x = plan->band_x;
      level[0].band_y = plan->band_y;
      /* A cut line stands for the zone on both sides of it. */
      level[0].cut_weight = 2.0 * plan->transition;
      level[0].both = plan->wrap_x && plan->wrap_y;
      allowed (plan->wrap_x, w, plan->band_x, &level[0].lo_x, &level[0].hi_x);
      allowed (plan->wrap_y, h, plan->band_y, &level[0].lo_y, &level[0].hi_y);
    }
  while (status == TS_OK && levels < TS_SHIFT_MAX_LEVELS &&
         (level[levels - 1].image.width > TS_SHIFT_COARSEST_SIDE ||
          level[levels - 1].image.height > TS_SHIFT_COARSEST_SIDE))
    {
      status = halve (&level[levels - 1], &level[levels]);
      levels++;
    }
  for (size_t l = 0; l < levels && status == TS_OK; l++)
    {
      status = detail_map (&level[l], l > 0 ? &level[l - 1] : NULL);
      if (status == TS_OK)
        scales (&level[l]);
    }
  if (status == TS_OK)
    {
      const ShiftLevel *top = &level[levels - 1];
      search (top, top->lo_x, top->hi_x, top->lo_y, top->hi_y, &sx, &sy);
      for (size_t l = levels - 1; l-- > 0;)
        {
          const ShiftLevel *lv = &level[l];
          ptrdiff_t cx = 2 * (ptrdiff_t) sx, cy = 2 * (ptrdiff_t) sy, r = TS_SHIFT_REFINE;
          search (lv, clamp_range (cx - r, lv->lo_x, lv->hi_x), clamp_range (cx + r, lv->lo_x, lv->hi_x),
                  clamp_range (cy - r, lv->lo_y, lv->hi_y), clamp_range (cy + r, lv->lo_y, lv->hi_y),
                  &sx, &sy);
        }
      plan->shift_x = sx;
      plan->shift_y = sy;
    }
  for (size_t l = 1; l < levels; l++)
    ts_image_free (&level[l].image);
  for (size_t l = 0; l < levels; l++)
    {
      free (level[l].zone);
      free (level[l].band);
      free (level[l].detail);
    }
  free (boundary);
  free (distance);
  return status;
}
