/* Guides: defaults, checks, labels or values, memory.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide-params.h"
#include "error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* AUTO takes labels when at least this share of the target's pixels is
 * exactly one of the exemplar guide's values: a flat-colour map, maybe
 * with smoothed edges, rather than a continuous one that happens to have
 * few levels in the exemplar. */
#define TS_GUIDE_LABEL_SHARE 0.5

void
ts_guides_init (TsGuides *guides)
{
  memset (guides, 0, sizeof *guides);
  guides->channels = 1;
  guides->compare = TS_GUIDE_AUTO;
  guides->weight = TS_DEFAULT_GUIDE_WEIGHT;
}

bool
ts_guide_find_labels (const float *values, size_t n, size_t channels, float *table, size_t max,
                      size_t *count)
{
  size_t found = 0, last = 0;

  for (size_t i = 0; i < n; i++)
    {
      const float *v = values + i * channels;
      size_t j;
      /* Runs of one label are common: try the last match first. */
      if (found > 0 && memcmp (table + last * channels, v, channels * sizeof (float)) == 0)
        continue;
      for (j = 0; j < found && memcmp (table + j * channels, v, channels * sizeof (float)) != 0; j++)
        ;
      if (j == found)
        {
          if (found == max)
            return false;
          memcpy (table + found * channels, v, channels * sizeof (float));
          found++;
        }
      last = j;
    }
  *count = found;
  return true;
}

uint8_t
ts_guide_nearest_label (const float *table, size_t count, size_t channels, const float *value)
{
  size_t best = 0;
  float best_d = INFINITY;

  for (size_t j = 0; j < count; j++)
    {
      float d = 0.0f;
      for (size_t c = 0; c < channels; c++)
        {
          float e = table[j * channels + c] - value[c];
          d += e * e;
        }
      if (d < best_d)
        {
          best_d = d;
          best = j;
        }
    }
  return (uint8_t) best;
}

bool
ts_guides_use_labels (const TsParams *params, const TsImage *exemplar)
{
  const TsGuides *g = params->guides;
  float table[TS_MAX_GUIDE_LABELS * TS_MAX_GUIDE_CHANNELS];
  size_t count, n = params->output_width * params->output_height, matching = 0;

  if (!g || !g->exemplar_guide || g->compare == TS_GUIDE_VALUES)
    return false;
  if (g->compare == TS_GUIDE_LABELS)
    return true;
  if (!ts_guide_find_labels (g->exemplar_guide, exemplar->width * exemplar->height, g->channels,
                             table, TS_MAX_GUIDE_LABELS, &count))
    return false;
  for (size_t i = 0; i < n; i++)
    {
      const float *v = g->target_guide + i * g->channels;
      for (size_t j = 0; j < count; j++)
        if (memcmp (table + j * g->channels, v, g->channels * sizeof (float)) == 0)
          {
            matching++;
            break;
          }
    }
  return (double) matching >= TS_GUIDE_LABEL_SHARE * (double) n;
}

bool
ts_guide_layers_apply (const TsParams *params, const TsImage *exemplar)
{
  return params->guides && !params->guides->blend_edges && params->guides->weight > 0.0 &&
         ts_guides_use_labels (params, exemplar);
}

static bool
all_finite (const float *values, size_t count)
{
  for (size_t i = 0; i < count; i++)
    if (!isfinite (values[i]))
      return false;
  return true;
}

TsStatus
ts_guides_validate (const TsParams *params, const TsImage *exemplar, TsError *error)
{
  const TsGuides *g = params->guides;
  float table[TS_MAX_GUIDE_LABELS * TS_MAX_GUIDE_CHANNELS];
  size_t count;

  if (!g)
    return TS_OK;
  if (!g->target_guide)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "guided synthesis needs a target guide");
  if (g->channels < 1 || g->channels > TS_MAX_GUIDE_CHANNELS)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "guides must have 1 to %d channels, got %zu",
                    TS_MAX_GUIDE_CHANNELS, g->channels);
  if (!(g->weight >= 0.0 && g->weight <= TS_MAX_GUIDE_WEIGHT))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "the guide weight must be 0 to %g, got %g",
                    TS_MAX_GUIDE_WEIGHT, g->weight);
  if (g->compare != TS_GUIDE_AUTO && g->compare != TS_GUIDE_LABELS && g->compare != TS_GUIDE_VALUES)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "unknown way of comparing guides (%d)",
                    (int) g->compare);
  if (params->initial_source)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "guides and an initial source map cannot be combined");
  if (!all_finite (g->target_guide, params->output_width * params->output_height * g->channels))
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the target guide holds values that are not finite numbers (NaN or infinity)");
  if (!g->exemplar_guide)
    {
      if (g->channels != 1)
        return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                        "without an exemplar guide (style transfer) the target guide must have "
                        "one channel, its lightness; got %zu", g->channels);
      if (g->compare == TS_GUIDE_LABELS)
        return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                        "without an exemplar guide (style transfer) the guides are lightness "
                        "and cannot be compared as labels");
      return TS_OK;
    }
  if (!all_finite (g->exemplar_guide, exemplar->width * exemplar->height * g->channels))
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the exemplar guide holds values that are not finite numbers (NaN or infinity)");
  if (g->compare == TS_GUIDE_LABELS &&
      !ts_guide_find_labels (g->exemplar_guide, exemplar->width * exemplar->height, g->channels,
                             table, TS_MAX_GUIDE_LABELS, &count))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the exemplar guide has more than %d distinct values: too many to compare "
                    "as labels; compare them as values", TS_MAX_GUIDE_LABELS);
  return TS_OK;
}

double
ts_guides_estimate_bytes (const TsParams *params, const TsImage *exemplar)
{
  double ex = (double) exemplar->width * (double) exemplar->height;
  double out = (double) params->output_width * (double) params->output_height;

  if (!params->guides && params->initial_source)
    return 0.0;
  /* A lattice guide, if the exemplar has one (lattice.h): value planes
   * of every level but the finest, the exemplar grouped by phase, and
   * the estimate's FFT of at most 1024x1024 complex doubles. */
  double lattice = (ex + out) * 16.0 / 3.0 + ex * 4.0 + fmin (4.0 * ex, 1024.0 * 1024.0) * 16.0;
  if (ts_guide_layers_apply (params, exemplar))
    /* Layers: their sources, both label maps, one layer's result,
     * sources and needed pixels, one layer's exemplar, the lattice guide
     * a layer's plain synthesis may build, that synthesis's active
     * region (active-region.c: two masks and two temporaries) and the
     * label's candidate sets of every level (quality + 3 per level
     * coarser, a quarter of the pixels); it needs no more than a plain
     * one of the output's size otherwise. */
    return out * 8.0 + (out + ex) + out * (16.0 + 8.0 + 1.0) + ex * 16.0 + lattice + out * 4.0
           + ex * 4.0 * (4.0 / 3.0 * (double) params->quality + 2.0);
  if (!params->guides)
    return lattice;
  /* Value pyramids of both guides (labels take less), the exemplar's
   * pixels grouped by bin, and a level's builder copy. */
  return (ex + out) * 16.0 * 4.0 / 3.0 + ex * 4.0 + (ex + out) * 16.0;
}
