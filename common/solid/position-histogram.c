/* Position histogram matching for solid synthesis (Chen & Wang 2010): a
 * vote's weight also falls with how much more often than uniformly its
 * source pixel is already copied into the volume, so the finest level
 * spreads its copies over the whole exemplar instead of repeating the
 * pixels that match everywhere (stone insides, the blobs' background).
 * Why: 64^3 seeds 1-6 then miss 2 of issue 14's 90 checks instead of 4,
 * and 128^3 cells keep their sharpness (0.94-0.97 x the truth's instead
 * of 0.90-0.96) with their mortar network less eroded.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <string.h>

void
ts_solid_position_excess (TsSolidLevel *level)
{
  size_t voxels = level->n * level->n * level->n;
  double total[TS_SOLID_AXES] = { 0.0, 0.0, 0.0 };
  int owner[TS_SOLID_AXES];

  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsSolidView *view = &level->view[a];
      owner[a] = ts_solid_view_owner (level, a);
      if (view->exemplar && view->position_count && owner[a] == a)
        memset (view->position_count, 0,
                ts_image_pixel_count (view->exemplar) * sizeof (uint32_t));
    }
  for (size_t p = 0; p < voxels; p++)
    {
      int a = owner[ts_solid_source_axis (level->chosen[p])];
      uint32_t *count = level->view[a].position_count;
      if (count)
        {
          count[ts_solid_source_index (level->chosen[p])]++;
          total[a] += 1.0;
        }
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      const TsSolidView *view = &level->view[a];
      if (!view->exemplar || !view->excess || !view->position_count
          || owner[a] != a || total[a] <= 0.0)
        continue;
      /* Uniform use: every opaque pixel copied equally often. */
      float uniform = (float) (total[a] / (double) view->opaque_count);
      size_t pixels = ts_image_pixel_count (view->exemplar);
      for (size_t i = 0; i < pixels; i++)
        {
          float over = (float) view->position_count[i] / uniform - 1.0f;
          if (over > 0.0f)
            view->excess[i] += level->position_weight * over;
        }
    }
}
