/* Solid E-step: each voxel becomes the vote, over the matched slice
 * neighbourhoods of all three orientations covering it, closest to their
 * robust weighted mean; each orientation's source follows its own vote
 * closest to that mean, so the next search stays coherent.
 *
 * Histogram matching acts twice: Kopf et al.'s weight 1 / (1 + excess)
 * moves the mean, and the choice of the vote closest to it adds a penalty
 * growing with the square of the excess. The weight alone cannot stop a
 * voxel whose votes all carry an over-represented colour from keeping it,
 * and exemplars with large uniform areas (cracked earth) collapsed to one
 * flat colour; squared, the penalty leaves near-target histograms alone.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>
#include <string.h>

/* Enough for three orientations of (w / spacing)^2 votes each at every
 * automatic neighbourhood size; more (tiny mirrored volumes) are
 * gathered a second time instead. */
#define TS_SOLID_LOCAL_VOTES 384
/* Squared working-unit distance added per squared unit of excess. */
#define TS_SOLID_HISTOGRAM_CHOICE 30.0f
/* Mean-shift steps from the weighted mean towards the mode of the votes,
 * and the kernel's squared width (working units, Lab for colour). */
#define TS_SOLID_MODE_STEPS 3
#define TS_SOLID_MODE_WIDTH2 100.0f
/* Squared distance from the mode within which the heaviest vote wins:
 * 10 Lab units (5 gave 128^3 cells axis-edges 1.21 and sharpness 0.60,
 * 10 gives 1.12 and 0.67). */
#define TS_SOLID_MODE_CHOICE2 100.0f

typedef struct
{
  int32_t source;
  uint8_t axis;
  float   weight;
} Vote;

typedef struct
{
  float   sum[TS_CHANNELS];
  float   weight;
  float   mean[TS_CHANNELS];
  bool    choosing;
  bool    overflow;
  size_t  count;
  /* Second pass: the closest vote overall and per orientation, and
   * among the votes near the mode, the heaviest. */
  float   best_distance;
  int32_t best_source;
  int     best_axis;
  float   axis_distance[TS_SOLID_AXES];
  int32_t axis_source[TS_SOLID_AXES];
  float   heaviest;
  int32_t heaviest_source;
  int     heaviest_axis;
  float   axis_heaviest[TS_SOLID_AXES];
  int32_t axis_heaviest_source[TS_SOLID_AXES];
  Vote    list[TS_SOLID_LOCAL_VOTES];
} Votes;

static void
choose (Votes *v, const TsSolidView *view, const float *value, int axis, int32_t source,
        float weight)
{
  float d = 0.0f;
  for (int c = 0; c < TS_CHANNELS; c++)
    {
      float e = value[c] - v->mean[c];
      d += e * e;
    }
  if (view->excess)
    d += TS_SOLID_HISTOGRAM_CHOICE * view->excess[source] * view->excess[source];
  if (d < v->axis_distance[axis])
    {
      v->axis_distance[axis] = d;
      v->axis_source[axis] = source;
    }
  if (d < v->best_distance)
    {
      v->best_distance = d;
      v->best_source = source;
      v->best_axis = axis;
    }
  /* Of the votes at the mode, the one from the best-matched neighbourhood:
   * neighbouring voxels then take the same neighbourhood's pixels, which
   * keeps the exemplar's fine grain instead of its local average. */
  if (d < TS_SOLID_MODE_CHOICE2)
    {
      if (weight > v->axis_heaviest[axis])
        {
          v->axis_heaviest[axis] = weight;
          v->axis_heaviest_source[axis] = source;
        }
      if (weight > v->heaviest)
        {
          v->heaviest = weight;
          v->heaviest_source = source;
          v->heaviest_axis = axis;
        }
    }
}

static void
add_vote (Votes *v, const TsSolidView *view, int axis, int32_t source, float weight)
{
  const float *value = view->exemplar->pixels + (size_t) source * TS_CHANNELS;

  if (view->excess)
    weight /= 1.0f + view->excess[source];
  if (value[3] <= 0.0f || !(weight > 0.0f))
    return;
  if (v->choosing)
    {
      choose (v, view, value, axis, source, weight);
      return;
    }
  for (int c = 0; c < TS_CHANNELS; c++)
    v->sum[c] += weight * value[c];
  v->weight += weight;
  if (v->count < TS_SOLID_LOCAL_VOTES)
    v->list[v->count++] = (Vote) { source, (uint8_t) axis, weight };
  else
    v->overflow = true;
}

/* Votes of orientation `axis` for the voxel at in-slice (pu, pv) of slice t. */
static void
collect_axis (Votes *v, const TsSolidLevel *level, int axis, const TsAxisGrid *gu,
              const TsAxisGrid *gv, const TsSolidMatch *matches, size_t t, size_t pu, size_t pv)
{
  const TsSolidView *view = &level->view[axis];
  size_t ew = view->exemplar->width, n = level->n, cu = gu->centres, cv = gv->centres;

  for (size_t iv = gv->virtual_start[pv]; iv < gv->virtual_start[pv + 1]; iv++)
    {
      ptrdiff_t tv = gv->virtual_coord[iv];
      size_t jv_lo, jv_hi;
      if (!ts_axis_grid_covering (gv, tv, &jv_lo, &jv_hi))
        continue;
      for (size_t iu = gu->virtual_start[pu]; iu < gu->virtual_start[pu + 1]; iu++)
        {
          ptrdiff_t tu = gu->virtual_coord[iu];
          size_t ju_lo, ju_hi;
          if (!ts_axis_grid_covering (gu, tu, &ju_lo, &ju_hi))
            continue;
          for (size_t jv = jv_lo; jv <= jv_hi; jv++)
            {
              ptrdiff_t dv = tv - ts_axis_grid_centre (gv, jv);
              for (size_t ju = ju_lo; ju <= ju_hi; ju++)
                {
                  const TsSolidMatch *m = &matches[ts_solid_match_index (axis, n, cu, cv, t, ju, jv)];
                  if (m->centre < 0)
                    continue;
                  ptrdiff_t du = tu - ts_axis_grid_centre (gu, ju);
                  add_vote (v, view, axis, m->centre + (int32_t) (dv * (ptrdiff_t) ew + du), m->weight);
                }
            }
        }
    }
}

static void
collect (Votes *v, const TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
         TsSolidMatch *const matches[TS_SOLID_AXES], const size_t xyz[3])
{
  for (int axis = 0; axis < TS_SOLID_AXES; axis++)
    {
      int u, w;
      if (!level->view[axis].exemplar)
        continue;
      ts_solid_plane_axes (axis, &u, &w);
      collect_axis (v, level, axis, gu, gv, matches[axis], xyz[axis], xyz[u], xyz[w]);
    }
}

/* Moves the mean to the nearest mode of the votes (mean shift with a
 * Cauchy kernel). Where the votes split between two colours, at an
 * edge, the mean lies between them and the vote nearest it is an
 * in-between pixel: edges widen and the volume blurs. The mode is one of
 * the two sides. */
static void
seek_mode (Votes *v, const TsSolidLevel *level)
{
  for (int step = 0; step < TS_SOLID_MODE_STEPS; step++)
    {
      float sum[TS_CHANNELS] = { 0, 0, 0, 0 }, weight = 0.0f;
      for (size_t i = 0; i < v->count; i++)
        {
          const float *value = level->view[v->list[i].axis].exemplar->pixels
                               + (size_t) v->list[i].source * TS_CHANNELS;
          float d = 0.0f, k;
          for (int c = 0; c < TS_CHANNELS; c++)
            d += (value[c] - v->mean[c]) * (value[c] - v->mean[c]);
          k = v->list[i].weight / (1.0f + d / TS_SOLID_MODE_WIDTH2);
          for (int c = 0; c < TS_CHANNELS; c++)
            sum[c] += k * value[c];
          weight += k;
        }
      if (!(weight > 0.0f))
        return;
      for (int c = 0; c < TS_CHANNELS; c++)
        v->mean[c] = sum[c] / weight;
    }
}

/* New value and sources of voxel `p`; false if nothing voted for it. */
static bool
vote_voxel (const TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
            TsSolidMatch *const matches[TS_SOLID_AXES], const size_t xyz[3], Votes *v)
{
  memset (v->sum, 0, sizeof v->sum);
  v->weight = 0.0f;
  v->choosing = false;
  v->overflow = false;
  v->count = 0;
  collect (v, level, gu, gv, matches, xyz);
  if (!(v->weight > 0.0f))
    return false;
  for (int c = 0; c < TS_CHANNELS; c++)
    v->mean[c] = v->sum[c] / v->weight;
  if (!v->overflow)
    seek_mode (v, level);
  v->choosing = true;
  v->best_distance = (float) INFINITY;
  v->best_source = -1;
  v->best_axis = 0;
  v->heaviest = 0.0f;
  v->heaviest_source = -1;
  v->heaviest_axis = 0;
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      v->axis_distance[a] = (float) INFINITY;
      v->axis_source[a] = -1;
      v->axis_heaviest[a] = 0.0f;
      v->axis_heaviest_source[a] = -1;
    }
  if (v->overflow)
    collect (v, level, gu, gv, matches, xyz);
  else
    for (size_t i = 0; i < v->count; i++)
      {
        const TsSolidView *view = &level->view[v->list[i].axis];
        choose (v, view, view->exemplar->pixels + (size_t) v->list[i].source * TS_CHANNELS,
                v->list[i].axis, v->list[i].source, v->list[i].weight);
      }
  if (v->heaviest_source >= 0)
    {
      v->best_source = v->heaviest_source;
      v->best_axis = v->heaviest_axis;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (v->axis_heaviest_source[a] >= 0)
      v->axis_source[a] = v->axis_heaviest_source[a];
  return v->best_source >= 0;
}

size_t
ts_solid_estep (TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
                TsSolidMatch *const matches[TS_SOLID_AXES], const uint8_t *batch_of,
                uint8_t batch, const TsSolidHistogram *histogram, TsSolidHistogramDelta delta)
{
  size_t n = level->n, changed = 0;

#pragma omp parallel reduction(+:changed) if (n >= TS_SOLID_PARALLEL_EDGE)
  {
    TsSolidHistogramDelta local;
    Votes v;

    memset (local, 0, sizeof local);
#pragma omp for schedule(static)
    for (ptrdiff_t zy = 0; zy < (ptrdiff_t) (n * n); zy++)
      for (size_t x = 0; x < n; x++)
        {
          size_t p = (size_t) zy * n + x;
          size_t xyz[3] = { x, (size_t) zy % n, (size_t) zy / n };
          float *value = level->value + p * TS_CHANNELS;
          const float *chosen;

          if (batch_of[p] != batch || !vote_voxel (level, gu, gv, matches, xyz, &v))
            continue;
          for (int a = 0; a < TS_SOLID_AXES; a++)
            if (level->source[a] && v.axis_source[a] >= 0)
              level->source[a][p] = v.axis_source[a];
          chosen = level->view[v.best_axis].exemplar->pixels + (size_t) v.best_source * TS_CHANNELS;
          if (memcmp (value, chosen, TS_CHANNELS * sizeof (float)) == 0)
            continue;
          changed++;
          if (histogram)
            ts_solid_histogram_move (histogram, local, value, chosen);
          memcpy (value, chosen, TS_CHANNELS * sizeof (float));
        }
#pragma omp critical (ts_solid_histogram_delta)
    for (int c = 0; c < 3; c++)
      for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
        delta[c][b] += local[c][b];
  }
  return changed;
}
