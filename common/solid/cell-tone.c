/* Cell tones: a real stone has one tone, but a cell whose voxels copy
 * several exemplar stones shows two or three, split by seams no wall
 * explains, and its sections spread wider in lightness than the
 * exemplar's. The E-step weighs
 * down a vote whose stone's tone differs from its cell's (estep.c);
 * cells then settle on one tone.
 *
 * A cell's tone is its light voxels' mean lightness as the M-step left
 * it (above the joint split: a dark stone's cell has no voxel above the
 * phase split, and would go untoned), matched by rank to
 * the exemplar's stone tones: the cell of the q-th quantile (by light
 * voxels) takes the tone of the q-th quantile of
 * the exemplar's stone pixels. The mean alone regresses to the middle,
 * since a cell's voxels first copy stones of many tones, and the
 * stones' tones would spread less than the exemplar's; ranking keeps
 * their spread. The stones' tones come with their sections
 * (cell-guide.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct TsSolidRankedCell
{
  float    tone;
  uint32_t cell;
};

/* By tone, then by cell: the same order at any thread count. */
static int
by_tone (const void *a, const void *b)
{
  const struct TsSolidRankedCell *x = a, *y = b;
  if (x->tone != y->tone)
    return x->tone < y->tone ? -1 : 1;
  return (x->cell > y->cell) - (x->cell < y->cell);
}

TsStatus
ts_solid_cell_tone_exemplar (TsSolidCellGuide *g, const float *stone_tone, size_t pixels)
{
  size_t stones = 0;
  float *grown;

  for (size_t i = 0; i < pixels; i++)
    stones += !isnan (stone_tone[i]);
  if (!stones)
    return TS_OK;
  grown = realloc (g->shades, (g->shade_count + stones) * sizeof (float));
  if (!grown)
    return TS_ERROR_OUT_OF_MEMORY;
  g->shades = grown;
  for (size_t i = 0; i < pixels; i++)
    if (!isnan (stone_tone[i]))
      g->shades[g->shade_count++] = stone_tone[i];
  return TS_OK;
}

TsStatus
ts_solid_cell_tone_alloc (TsSolidCellGuide *g)
{
  if (g->shade_count)
    qsort (g->shades, g->shade_count, sizeof (float), ts_solid_compare_floats);
  g->cell_tone = malloc (g->seed_count * sizeof (float));
  g->tone_sum = malloc (g->seed_count * sizeof (double));
  g->tone_count = malloc (g->seed_count * sizeof (uint32_t));
  g->ranked = malloc (g->seed_count * sizeof (struct TsSolidRankedCell));
  return g->cell_tone && g->tone_sum && g->tone_count && g->ranked ? TS_OK
                                                                   : TS_ERROR_OUT_OF_MEMORY;
}

/* Moves each cell's tone to the shade of its rank among the cells. */
static void
match_shades (TsSolidCellGuide *g)
{
  size_t cells = 0;
  double total = 0.0, below = 0.0;

  for (size_t c = 0; c < g->seed_count; c++)
    if (g->tone_count[c])
      {
        g->ranked[cells].tone = g->cell_tone[c];
        g->ranked[cells++].cell = (uint32_t) c;
        total += g->tone_count[c];
      }
  qsort (g->ranked, cells, sizeof *g->ranked, by_tone);
  for (size_t k = 0; k < cells; k++)
    {
      uint32_t c = g->ranked[k].cell;
      size_t at = (size_t) ((below + 0.5 * g->tone_count[c]) / total * (double) g->shade_count);
      g->cell_tone[c] = g->shades[at < g->shade_count ? at : g->shade_count - 1];
      below += g->tone_count[c];
    }
}

const TsSolidView *
ts_solid_first_view (const TsSolidLevel *l)
{
  int given[TS_SOLID_AXES];

  for (int a = 0; a < TS_SOLID_AXES; a++)
    given[a] = l->view[a].exemplar ? 0 : -1;
  return &l->view[ts_solid_first_axis (given)];
}

void
ts_solid_cell_tones (TsSolidCellGuide *g, TsSolidLevel *level)
{
  size_t voxels = g->field_edge * g->field_edge * g->field_edge;
  const float *value = level->value;
  float split = ts_solid_first_view (level)->joint_split;
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
  if (g->shade_count)
    match_shades (g);
  level->cell_tone = g->cell_tone;
}
