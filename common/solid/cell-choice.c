/* The automatic choice of the cell structure (TS_CELL_STRUCTURE_AUTO):
 * on for opaque exemplars whose light phase lies in separate stones
 * (phase-guide.c's gate of the default path) parted by thin dark joints
 * that run in every direction, not along the axes.
 * Why all three: the stones gate alone also takes round pebbles in wide
 * dark gaps, lit reliefs and weaves, which the tessellation turns into
 * polygons; thin joints alone also take wood grain and woven cloth,
 * whose light phase is one piece. Tiles and bricks in rows have thin
 * grout too, but keep their grid only without the structure: their
 * edges lie along the axes, which cells' walls do not.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/distance.h"

#include <math.h>
#include <stdlib.h>

/* A joint pixel this close to a stone (pixels, Euclidean) is within a
 * joint at most about three pixels wide: a crack or a mortar line, not
 * the wide gap around a pebble. Wider joints keep the structure off
 * (docs/design.md, Known limits). */
#define TS_THIN_JOINT_DISTANCE 1.5f
/* The share of the joints' middle line that must be that thin: most of
 * it, leaving room for the wider spots where joints meet. Cells read
 * over 0.9, other stones-in-ground kinds under 0.45. */
#define TS_THIN_JOINT_SHARE 0.75
/* Dark pieces smaller than this (4-connected pixels) are specks in the
 * stones, not joints: a joint runs between stones for many pixels. */
#define TS_JOINT_MIN_PIXELS 8
/* Cells lay out their walls in every direction: at most this share of
 * the gradient energy may lie within TS_AXIS_DEGREES of the axes. Edges
 * in every direction put 0.22 there, grids in rows over 0.9; the bound
 * between is fitted to the bundled exemplars (photographed cells up to
 * 0.31, bricks and coursed walls 0.50); see docs/design.md, Known
 * limits. */
#define TS_CELLS_MAX_AXIS_SHARE 0.40
#define TS_AXIS_DEGREES 10.0
/* tan (TS_AXIS_DEGREES): a gradient within it of an axis has its smaller
 * component at most this share of its larger one. */
#define TS_AXIS_SLOPE 0.17632698070846498

typedef struct
{
  float *distance; /* the joints' pixels' distances; specks' set to 0 */
} Specks;

static void
clear_speck (const size_t *pixels, size_t area, void *data)
{
  Specks *s = data;

  for (size_t i = 0; area < TS_JOINT_MIN_PIXELS && i < area; i++)
    s->distance[pixels[i]] = 0.0f;
}

/* Whether a joint pixel is on the joint's middle line: no 8-neighbour
 * lies farther from the stones. */
static bool
on_middle_line (const float *distance, size_t w, size_t h, size_t x, size_t y)
{
  float d = distance[y * w + x];

  for (int dy = -1; dy <= 1; dy++)
    for (int dx = -1; dx <= 1; dx++)
      {
        ptrdiff_t nx = (ptrdiff_t) x + dx, ny = (ptrdiff_t) y + dy;
        if (nx < 0 || ny < 0 || nx >= (ptrdiff_t) w || ny >= (ptrdiff_t) h)
          continue;
        if (distance[(size_t) ny * w + (size_t) nx] > d)
          return false;
      }
  return true;
}

/* The share of the middle line of the dark pixels below `joint` that
 * lies within TS_THIN_JOINT_DISTANCE of a light pixel, in *share (0 with
 * no joints). */
static TsStatus
thin_joint_share (const TsImage *ex, float joint, double *share)
{
  size_t w = ex->width, h = ex->height, count = w * h, middle = 0, thin = 0;
  size_t dims[3] = { w, h, 1 };
  bool wrap[3] = { false, false, false };
  float *distance = malloc (count * sizeof (float));
  uint8_t *dark = malloc (count);
  TsStatus status = distance && dark ? TS_OK : TS_ERROR_OUT_OF_MEMORY;

  *share = 0.0;
  for (size_t i = 0; i < count && status == TS_OK; i++)
    {
      dark[i] = !ts_solid_is_light (ex->pixels + i * TS_CHANNELS, joint);
      distance[i] = dark[i] ? TS_DISTANCE_FAR : 0.0f;
    }
  if (status == TS_OK)
    status = ts_distance_transform (distance, dims, wrap);
  if (status == TS_OK)
    {
      Specks specks = { distance };
      status = ts_solid_mask_pieces (dark, w, h, clear_speck, &specks);
    }
  for (size_t y = 0; y < h && status == TS_OK; y++)
    for (size_t x = 0; x < w; x++)
      {
        float d = distance[y * w + x];
        /* FAR: an exemplar without light pixels has no stones to part. */
        if (d <= 0.0f || d >= TS_DISTANCE_FAR || !on_middle_line (distance, w, h, x, y))
          continue;
        middle++;
        thin += d <= TS_THIN_JOINT_DISTANCE;
      }
  if (status == TS_OK && middle > 0)
    *share = (double) thin / (double) middle;
  free (distance);
  free (dark);
  return status;
}

/* The share of the lightness's gradient energy (Sobel) whose direction
 * lies within TS_AXIS_DEGREES of the image axes. */
static double
axis_edge_share (const TsImage *ex)
{
  double total = 0.0, axis = 0.0;

  for (size_t y = 1; y + 1 < ex->height; y++)
    for (size_t x = 1; x + 1 < ex->width; x++)
      {
        double gx, gy, energy;
        if (!ts_solid_sobel (ex, x, y, &gx, &gy))
          continue;
        energy = gx * gx + gy * gy;
        total += energy;
        if (fmin (fabs (gx), fabs (gy)) <= TS_AXIS_SLOPE * fmax (fabs (gx), fabs (gy)))
          axis += energy;
      }
  return total > 0.0 ? axis / total : 0.0;
}

bool
ts_solid_fully_opaque (const TsImage *ex)
{
  size_t count = ts_image_pixel_count (ex);

  for (size_t i = 0; i < count; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] < 1.0f)
      return false;
  return true;
}

TsStatus
ts_solid_cells_in_joints (const TsImage *ex, bool *cells, double *thin_share, double *axis_share)
{
  float phase, joint;
  bool stones = false;
  TsStatus status = TS_OK;

  *cells = false;
  *thin_share = *axis_share = 0.0;
  if (!ex || !ex->pixels || ex->width == 0 || ex->height == 0 || !ts_solid_fully_opaque (ex))
    return TS_OK;
  ts_solid_splits (ex, &phase, &joint);
  if (ts_solid_phase_in_pieces (ex, phase) == TS_SOLID_LIGHT_PIECES)
    status = ts_solid_exemplar_stones (ex, phase, &stones);
  if (status == TS_OK && stones)
    status = thin_joint_share (ex, joint, thin_share);
  if (status == TS_OK && stones)
    *axis_share = axis_edge_share (ex);
  *cells = status == TS_OK && stones && *thin_share >= TS_THIN_JOINT_SHARE
           && *axis_share <= TS_CELLS_MAX_AXIS_SHARE;
  return status;
}

bool
ts_solid_uses_cell_structure (const TsSolidParams *params, const TsImage *const exemplars[3])
{
  bool cells = false;

  if (!params || params->cell_structure != TS_CELL_STRUCTURE_AUTO)
    return params && params->cell_structure == TS_CELL_STRUCTURE_ON;
  if (!exemplars)
    return false;
  /* Every orientation's exemplar must be cells: the guide's walls cross
   * all three. The same image given twice is looked at once. */
  for (int a = 0; a < 3; a++)
    {
      double thin, axis;
      bool seen = false;
      if (!exemplars[a])
        continue;
      for (int b = 0; b < a; b++)
        seen = seen || exemplars[b] == exemplars[a];
      if (seen)
        continue;
      if (ts_solid_cells_in_joints (exemplars[a], &cells, &thin, &axis) != TS_OK || !cells)
        return false;
    }
  return cells;
}
