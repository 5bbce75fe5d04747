/* Cell tones: each of the truth's stones has one tone, but a cell whose
 * voxels copy several exemplar stones shows two or three, split by seams
 * no wall explains (128^3 cells: lightness spread within slice sections
 * 1.03-1.10 x the exemplar's, the truth's 0.95-1.04). The E-step weighs
 * down a vote whose stone's tone differs from its cell's mean as the
 * M-step left it (estep.c); cells then settle on one tone (spread
 * 0.88-0.94 x: now flatter than the truth's, whose stones hold smooth
 * blotches of 3D noise; README, stop 41). The stones' tones come with
 * their sections (cell-guide.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>
#include <string.h>

/* The first orientation with an exemplar: there is always one. */
static const TsSolidView *
first_view (const TsSolidLevel *l)
{
  for (int a = 0; a < TS_SOLID_AXES - 1; a++)
    if (l->view[a].exemplar)
      return &l->view[a];
  return &l->view[TS_SOLID_AXES - 1];
}

void
ts_solid_cell_tones (TsSolidCellGuide *g, TsSolidLevel *level)
{
  size_t voxels = g->field_edge * g->field_edge * g->field_edge;
  const float *value = level->value;
  float split = first_view (level)->phase_split;
  double *sum = g->tone_sum;
  uint32_t *count = g->tone_count;

  memset (sum, 0, g->seed_count * sizeof (double));
  memset (count, 0, g->seed_count * sizeof (uint32_t));
  /* In voxel order, so the sums are the same at any thread count. */
  for (size_t i = 0; i < voxels; i++)
    {
      float l = value[i * TS_CHANNELS];
      if (l > split)
        {
          sum[g->cell_of[i]] += l;
          count[g->cell_of[i]]++;
        }
    }
  for (size_t c = 0; c < g->seed_count; c++)
    g->cell_tone[c] = count[c] ? (float) (sum[c] / count[c]) : NAN;
  level->cell_tone = g->cell_tone;
}
