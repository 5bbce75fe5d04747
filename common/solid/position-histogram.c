/* Position histogram matching for solid synthesis (Chen & Wang 2010): a
 * vote's weight also falls with how much more often than uniformly its
 * source pixel is already copied into the volume, so the finest level
 * spreads its copies over the whole exemplar instead of repeating the
 * pixels that match everywhere (stone insides, the blobs' background).
 * Why: repeated copies of the best-matching pixels make a volume
 * blander than its exemplar; spread out, the volume keeps its
 * sharpness and the cells' mortar network erodes less.
 *
 * The counts are counted once per level and then kept up to date by the
 * E-step (ts_solid_position_move), as the colour histogram is: exact
 * integers, so the same at any thread count and in any update order.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <string.h>

/* Views that share an exemplar share its counts (synthesize.c), so a
 * source's orientation finds them directly. */
void
ts_solid_position_count (TsSolidLevel *level)
{
  size_t voxels = level->n * level->n * level->n;

  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsSolidView *view = &level->view[a];
      if (view->exemplar && view->position_count && ts_solid_view_owner (level, a) == a)
        memset (view->position_count, 0,
                ts_image_pixel_count (view->exemplar) * sizeof (uint32_t));
    }
  for (size_t p = 0; p < voxels; p++)
    {
      uint32_t *count = level->view[ts_solid_source_axis (level->chosen[p])].position_count;
      if (count)
        count[ts_solid_source_index (level->chosen[p])]++;
    }
}

void
ts_solid_position_move (TsSolidLevel *level, TsSolidSource before, TsSolidSource after)
{
  uint32_t *from = level->view[ts_solid_source_axis (before)].position_count;
  uint32_t *to = level->view[ts_solid_source_axis (after)].position_count;
  size_t i = ts_solid_source_index (before), j = ts_solid_source_index (after);

  if (from)
    {
#pragma omp atomic update
      from[i]--;
    }
  if (to)
    {
#pragma omp atomic update
      to[j]++;
    }
}

void
ts_solid_position_excess (TsSolidLevel *level)
{
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsSolidView *view = &level->view[a];
      if (!view->exemplar || !view->excess || !view->position_count
          || ts_solid_view_owner (level, a) != a)
        continue;
      size_t pixels = ts_image_pixel_count (view->exemplar);
      double total = 0.0;
      for (size_t i = 0; i < pixels; i++)
        total += (double) view->position_count[i];
      if (total <= 0.0)
        continue;
      /* Uniform use: every opaque pixel copied equally often. */
      float uniform = (float) (total / (double) view->opaque_count);
      for (size_t i = 0; i < pixels; i++)
        {
          float over = (float) view->position_count[i] / uniform - 1.0f;
          if (over > 0.0f)
            view->excess[i] += level->position_weight * over;
        }
    }
}
