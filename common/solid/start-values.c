/* The start values of a level: each voxel's value from its orientations'
 * sources, and opaque sources where a start would copy transparency.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/rng.h"

#include <math.h>
#include <string.h>

/* The voxel's value: of its orientations' source colours, the one
 * closest to their mean (a sharp start that agrees with most of them). */
void
ts_solid_value_from_sources (TsSolidLevel *l, size_t p)
{
  const float *colour[TS_SOLID_AXES];
  float mean[TS_CHANNELS] = { 0, 0, 0, 0 }, best = INFINITY;
  int count = 0, chosen = -1;

  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      colour[a] = NULL;
      if (!l->source[a])
        continue;
      colour[a] = l->view[a].exemplar->pixels + (size_t) l->source[a][p] * TS_CHANNELS;
      for (int c = 0; c < TS_CHANNELS; c++)
        mean[c] += colour[a][c];
      count++;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      float d = 0.0f;
      if (!colour[a])
        continue;
      for (int c = 0; c < TS_CHANNELS; c++)
        {
          float e = colour[a][c] - mean[c] / (float) count;
          d += e * e;
        }
      if (d < best)
        {
          best = d;
          chosen = a;
        }
    }
  memcpy (l->value + p * TS_CHANNELS, colour[chosen], TS_CHANNELS * sizeof (float));
  if (l->chosen)
    l->chosen[p] = ts_solid_source_pack (chosen, (uint32_t) l->source[chosen][p]);
}

/* Opaque source at exemplar (sx, sy), mirrored inside; a random opaque
 * pixel where that is transparent. */
int32_t
ts_solid_opaque_source (const TsSolidView *view, size_t sx, size_t sy, uint64_t random)
{
  const TsImage *ex = view->exemplar;
  size_t s;

  sx = sx < ex->width ? sx : ex->width - 1 - (sx - ex->width) % ex->width;
  sy = sy < ex->height ? sy : ex->height - 1 - (sy - ex->height) % ex->height;
  s = sy * ex->width + sx;
  if (ex->pixels[s * TS_CHANNELS + 3] > 0.0f)
    return (int32_t) s;
  return view->opaque[ts_random_below (random, view->opaque_count)];
}
