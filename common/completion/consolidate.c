/* Making the finest level's picks coherent: every hole pixel's copy
 * offset is a label, and local moves shorten and cheapen the seams
 * between copies (the energy of Kwatra et al. 2003's graph-cut seams and
 * Pritch et al. 2009's shift-map), see ts_heal_consolidate.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* Cost of a neighbour the copy cannot show (outside the source or
 * unknown there): far above any Lab mismatch of real pixels. */
#define TS_HEAL_SEAM_UNKNOWN 1e5f

/* Weight of a mismatch with a known neighbour against one between two
 * copies: the outline shows against the original, so it decides first.
 * Fitted to the bundled heal cases (docs/design.md, Known limits). */
#define TS_HEAL_SEAM_OUTLINE 4.0f

/* Pixels whose copy offsets a pixel weighs: those up to this far (a 5x5
 * window): a little wider than the 4-neighbours, so a label settles on
 * what its surroundings show, not only its next pixels, which gave
 * slightly better seams. */
#define TS_HEAL_REACH 2
#define TS_HEAL_REACH_SIDE (2 * TS_HEAL_REACH + 1)
static const int nx4[4] = { 1, -1, 0, 0 }, ny4[4] = { 0, 0, 1, -1 };

/* The source pixel at (x, y), or NULL when outside or unknown. */
static const float *
source_at (const TsHealLevel *l, ptrdiff_t x, ptrdiff_t y)
{
  size_t sw = l->source_width, s;

  if (x < 0 || y < 0 || x >= (ptrdiff_t) sw || y >= (ptrdiff_t) l->source_height)
    return NULL;
  s = (size_t) y * sw + (size_t) x;
  if (l->source_known ? !l->source_known[s]
                      : l->hole[s] != 0 || !(l->source[s * TS_CHANNELS + 3] > 0.0f))
    return NULL;
  return l->source + s * TS_CHANNELS;
}

static float
squared (const float *a, const float *b)
{
  float d = 0.0f;
  if (!a || !b)
    return TS_HEAL_SEAM_UNKNOWN;
  for (int c = 0; c < 3; c++)
    d += (a[c] - b[c]) * (a[c] - b[c]);
  return d;
}

/* Seam cost of hole pixel (x, y) copied with offset (ox, oy) against its
 * four neighbours as they are: 0 beside a pixel of the same copy; beside
 * another copy, how much the two copies disagree on both pixels; beside a
 * known pixel, how much what lay beside the copy's source differs from it. */
static float
seam_cost (const TsHealLevel *l, const uint8_t *usable, const int32_t *picked, size_t x, size_t y,
           ptrdiff_t ox, ptrdiff_t oy)
{
  size_t w = l->width, h = l->height, sw = l->source_width;
  ptrdiff_t px = (ptrdiff_t) x, py = (ptrdiff_t) y;
  const float *mine = source_at (l, px + ox, py + oy);
  float cost = 0.0f;

  if (!mine || !usable[(size_t) (py + oy) * sw + (size_t) (px + ox)])
    return FLT_MAX;
  for (int k = 0; k < 4; k++)
    {
      ptrdiff_t qx = px + nx4[k], qy = py + ny4[k];
      size_t q;
      if (qx < 0 || qy < 0 || qx >= (ptrdiff_t) w || qy >= (ptrdiff_t) h)
        continue;
      q = (size_t) qy * w + (size_t) qx;
      if (!l->hole[q])
        cost += TS_HEAL_SEAM_OUTLINE * squared (source_at (l, qx + ox, qy + oy), l->target + q * TS_CHANNELS);
      else
        {
          ptrdiff_t qox = (ptrdiff_t) ((size_t) picked[q] % sw) - qx;
          ptrdiff_t qoy = (ptrdiff_t) ((size_t) picked[q] / sw) - qy;
          if (qox == ox && qoy == oy)
            continue;
          cost += squared (mine, source_at (l, px + qox, py + qoy)) +
                  squared (source_at (l, qx + ox, qy + oy), source_at (l, qx + qox, qy + qoy));
        }
    }
  return cost;
}

/* Source pixels in a valid source patch: those the votes may copy
 * (known, and within the context and sides allowed), the valid centres
 * grown by the patch radius (separable max). NULL if out of memory. */
static uint8_t *
usable_pixels (const TsHealLevel *l)
{
  size_t sw = l->source_width, sh = l->source_height, n = sw * sh, r = l->radius;
  uint8_t *rows = calloc (n ? n : 1, 1), *usable = calloc (n ? n : 1, 1);

  if (!rows || !usable)
    {
      free (rows);
      free (usable);
      return NULL;
    }
  for (size_t i = 0; i < l->valid_count; i++)
    {
      size_t s = (size_t) l->valid_list[i], x = s % sw, y = s / sw;
      memset (rows + y * sw + x - r, 1, 2 * r + 1);   /* valid centres lie r inside */
    }
  for (size_t y = 0; y < sh; y++)
    for (size_t x = 0; x < sw; x++)
      if (rows[y * sw + x])
        for (size_t yy = y - r; yy <= y + r; yy++)
          if (yy < sh)
            usable[yy * sw + x] = 1;
  free (rows);
  return usable;
}

size_t
ts_heal_consolidate (const TsHealLevel *l, int32_t *picked, size_t sweeps)
{
  size_t w = l->width, h = l->height, sw = l->source_width, moved = 0, swept = 0;
  size_t bx0, by0, bx1, by1;
  uint8_t *usable = usable_pixels (l);

  if (!usable)
    return SIZE_MAX;

  /* Only the hole's bounding box holds labels. */
  ts_heal_hole_bounds (l->hole, w, h, &bx0, &by0, &bx1, &by1);
  /* Red-black sweeps in raster order (a pixel's seams read its
   * 4-neighbours, of the other colour). One thread: as in the
   * gradient blend, the barriers between short sweeps cost more than
   * they save once other processes share the cores. */
  for (size_t sweep = 0; sweep < 2 * sweeps; sweep++)
    {
      size_t colour = sweep & 1, changed = 0;
      for (size_t y = by0; y < by1; y++)
        for (size_t x = bx0 + ((y + bx0 + colour) & 1); x < bx1; x += 2)
          {
            size_t p = y * w + x;
            ptrdiff_t ox, oy, best_ox, best_oy;
            float best;
            if (!l->hole[p])
              continue;
            ptrdiff_t cur_ox, cur_oy;
            best_ox = cur_ox = ox = (ptrdiff_t) ((size_t) picked[p] % sw) - (ptrdiff_t) x;
            best_oy = cur_oy = oy = (ptrdiff_t) ((size_t) picked[p] / sw) - (ptrdiff_t) y;
            best = seam_cost (l, usable, picked, x, y, ox, oy);
            /* Candidates: the offsets of the hole pixels within
             * TS_HEAL_REACH, each weighed once. */
            ptrdiff_t tried[2 * TS_HEAL_REACH_SIDE * TS_HEAL_REACH_SIDE];
            size_t count = 0;
            for (size_t k = 0; k < TS_HEAL_REACH_SIDE * TS_HEAL_REACH_SIDE; k++)
              {
                ptrdiff_t qx = (ptrdiff_t) (x + k % TS_HEAL_REACH_SIDE) - TS_HEAL_REACH;
                ptrdiff_t qy = (ptrdiff_t) (y + k / TS_HEAL_REACH_SIDE) - TS_HEAL_REACH;
                size_t q, j = 0;
                float c;
                if (qx < 0 || qy < 0 || qx >= (ptrdiff_t) w || qy >= (ptrdiff_t) h)
                  continue;
                q = (size_t) qy * w + (size_t) qx;
                if (!l->hole[q] || q == p)
                  continue;
                ox = (ptrdiff_t) ((size_t) picked[q] % sw) - qx;
                oy = (ptrdiff_t) ((size_t) picked[q] / sw) - qy;
                while (j < count && (tried[2 * j] != ox || tried[2 * j + 1] != oy))
                  j++;
                if (j < count || (ox == cur_ox && oy == cur_oy))
                  continue;
                tried[2 * count] = ox;
                tried[2 * count++ + 1] = oy;
                c = seam_cost (l, usable, picked, x, y, ox, oy);
                if (c < best)
                  {
                    best = c;
                    best_ox = ox;
                    best_oy = oy;
                  }
              }
            int32_t now = (int32_t) (((ptrdiff_t) y + best_oy) * (ptrdiff_t) sw + (ptrdiff_t) x + best_ox);
            if (now != picked[p])
              {
                picked[p] = now;
                changed++;
              }
          }
      moved += changed;
      swept += changed;
      if (colour == 1)
        {
          if (swept == 0)
            break;
          swept = 0;
        }
    }
  free (usable);
  return moved;
}
