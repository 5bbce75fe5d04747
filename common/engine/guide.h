/* Guides down the pyramid and their share of the neighbourhood distance
 * (internal): texture by numbers and style transfer.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDE_H
#define TS_GUIDE_H

#include "guide-params.h"
#include "image.h"
#include "pyramid.h"
#include "ssd.h"

#include <math.h>
#include <stdint.h>

/* Value guides fall into this many bins of the exemplar guide's range
 * for the proposals: a bin is narrow enough that its texture fits the
 * value, wide enough to hold many exemplar pixels. */
#define TS_GUIDE_VALUE_BINS 32
/* Exemplar positions of the right guide proposed per neighbourhood, on
 * top of the k-coherence candidates: they let a region far from any
 * neighbour of its label still find that label's texture. */
#define TS_GUIDE_PROPOSALS 4
/* A lattice guide groups the exemplar by phase cell, this many steps
 * per period: a step of a sixth of a period is well within what the
 * neighbourhoods' own match corrects. */
#define TS_LATTICE_PHASE_BINS 6
/* Every pixel of a phase cell continues the lattice: one proposal per
 * neighbourhood finds the right phase as well as four (and costs a
 * quarter as much). */
#define TS_LATTICE_PROPOSALS 1
/* A style transfer's guide weighs this much of its weight at the
 * finest level, and TS_STYLE_COARSE_WEIGHT times it at the coarser
 * ones, and its votes fall off twice as sharply with the tone
 * (TS_STYLE_VOTE_SHARPNESS): the coarser levels lay out the tones, the
 * votes keep them, and at the finest level a strong guide would pick
 * the grain by its tone. The finest weight was chosen on the tuning
 * half of benchmarks/style-transfer.sh before the guide had a contrast
 * channel; the coarse weight, doubled with it, won back the layout the
 * contrast took while the cost read the whole neighbourhood
 * (test-guided's case, seeds 1-8: blurred-lightness correlation
 * 0.902-0.914 from 0.889-0.909 at 2). */
#define TS_STYLE_FINEST_WEIGHT 0.25
#define TS_STYLE_COARSE_WEIGHT 4.0
#define TS_STYLE_VOTE_SHARPNESS (2.0 * TS_GUIDE_VOTE_SHARPNESS)
/* At the finest level a style transfer proposes only this many exemplar
 * pixels of the right tone per neighbourhood: its coarser levels have
 * placed the tones, and the coherent candidates carry them. */
#define TS_STYLE_FINEST_PROPOSALS 1
/* In the E-step a vote whose guide disagrees with the pixel's counts
 * exp(-TS_GUIDE_VOTE_SHARPNESS * weight) as much as one that agrees (2 %
 * at weight 1): thin parts of the target that most neighbourhoods around
 * them miss still take their own texture. */
#define TS_GUIDE_VOTE_SHARPNESS 4.0

/* One level of a guide: labels (one byte per pixel) or values (a
 * TsImage whose first `channels` floats per pixel are the guide, the
 * rest 0, so distances run on the same four lanes as colours). */
typedef struct
{
  size_t   width, height;
  uint8_t *label;
  TsImage  value;
} TsGuidePlane;

/* The guides of every level, built once per synthesis. */
typedef struct
{
  bool          labels;
  bool          style;     /* style transfer: both guides blurred lightness */
  bool          lattice;   /* the exemplar's own lattice (lattice-guide.c),
                              not a layout the caller gave             */
  size_t        channels;  /* of a value guide, up to TS_CHANNELS */
  size_t        bin_channels; /* the first ones, whose mean is the bin key */
  size_t        label_count;
  double        weight;
  size_t        levels;
  TsGuidePlane *exemplar;  /* levels entries, sizes of the exemplar pyramid */
  TsGuidePlane *target;    /* levels entries, sizes of the output levels    */
  float         bin_low, bin_high; /* values: range of the exemplar's bin key */
} TsGuidePyramid;

/* What one level's search needs: the planes, the cost of a disagreeing
 * pixel and the exemplar pixels grouped by guide (label or value bin). */
typedef struct
{
  const TsGuidePlane *exemplar, *target;
  bool     labels;
  bool     lattice;     /* see TsGuidePyramid */
  size_t   channels;    /* of a value guide */
  size_t   bin_channels; /* see TsGuidePyramid */
  bool     centre_only; /* the cost reads the neighbourhood's centre alone */
  float    cost;        /* per disagreeing label, or per squared value unit */
  size_t   bins;
  float    bin_low, bin_scale;
  size_t  *bin_start;   /* bins + 1 offsets into bin_member              */
  int32_t *bin_member;  /* opaque exemplar pixels, grouped by bin        */
  size_t  *bin_nearest; /* for each bin, the nearest bin with members    */
  float    vote_mismatch; /* labels: factor of a disagreeing vote          */
  float    vote_scale;    /* values: exp(-vote_scale * d^2) is the factor    */
  size_t   proposals;     /* exemplar pixels of the right guide proposed
                             per neighbourhood                            */
  float   *packed;        /* values: the exemplar guide's `channels` floats
                             per pixel and nothing else, for the cost      */
} TsGuideLevel;

/* One thread's target guide around the neighbourhood being matched. */
typedef struct
{
  const TsGuideLevel *level;
  size_t   patch, radius;
  uint8_t *labels;  /* labels: patch^2                         */
  float   *values;  /* values: patch^2 * channels, packed      */
} TsGuideQuery;

/* Builds the guides of params->guides (validated) for `pyramid`, the
 * working exemplar pyramid of `exemplar`. */
TsStatus ts_guide_pyramid_build (const TsParams *params, const TsImage *exemplar,
                                 const TsPyramid *pyramid, TsGuidePyramid *guides);
void     ts_guide_pyramid_free (TsGuidePyramid *guides);
/* Empty planes for `levels` levels in `guides` (zeroed by the caller). */
TsStatus ts_guide_planes_alloc (TsGuidePyramid *guides, size_t levels);

/* The search data of `level`, whose working exemplar is `ex`. */
TsStatus ts_guide_level_init (const TsGuidePyramid *guides, size_t level, const TsImage *ex,
                              TsGuideLevel *out);
void     ts_guide_level_free (TsGuideLevel *level);

/* Random exemplar blocks of side `block` as the coarsest level's start,
 * each drawn from the exemplar pixels whose guide matches the target's. */
void     ts_guide_start_blocks (const TsGuideLevel *guide, const TsImage *ex, int32_t *source,
                                size_t width, size_t height, uint32_t seed, size_t level,
                                size_t block);

TsStatus ts_guide_query_init (TsGuideQuery *q, const TsGuideLevel *level, size_t patch);
void     ts_guide_query_free (TsGuideQuery *q);
/* Reads the target guide around output centre (cx, cy) into `q`. */
void     ts_guide_query_gather (TsGuideQuery *q, ptrdiff_t cx, ptrdiff_t cy, bool wrap_x,
                                bool wrap_y);
/* The bin of the target guide at output pixel (x, y), one with members. */
size_t   ts_guide_target_bin (const TsGuideLevel *g, size_t x, size_t y);

/* Sum of squared differences of `n` floats, in four lanes (a fixed
 * order, so the same total wherever it is used): a value guide has one
 * to three channels, and packed they take a quarter to three quarters
 * of the work of four-channel pixels. */
static inline float
ts_guide_floats_ssd (const float *a, const float *b, size_t n)
{
  float lane[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  size_t i = 0;
  for (; i + 4 <= n; i += 4)
    ts_lanes_add (lane, a + i, b + i, 4);
  for (; i < n; i++)
    {
      float d = a[i] - b[i];
      lane[0] += d * d;
    }
  return TS_LANES_TOTAL (lane);
}

/* Guide share of the distance of the exemplar neighbourhood centred at
 * (qx, qy) (inside); may stop early once it reaches `bound`. */
static inline float
ts_guide_cost (const TsGuideQuery *q, size_t qx, size_t qy, float bound)
{
  const TsGuideLevel *g = q->level;
  size_t w = g->exemplar->width, p = q->patch, x0 = qx - q->radius, y0 = qy - q->radius;
  float sum = 0.0f;

  if (g->labels)
    {
      const uint8_t *t = q->labels;
      for (size_t row = 0; row < p; row++, t += p)
        {
          const uint8_t *e = g->exemplar->label + (y0 + row) * w + x0;
          unsigned differ = 0;
          for (size_t i = 0; i < p; i++)
            differ += e[i] != t[i];
          sum += g->cost * (float) differ;
          if (sum >= bound)
            break;
        }
      return sum;
    }
  if (g->centre_only)
    {
      /* A lattice's phases grow alike over the target and the exemplar,
       * so their difference is the same at every pixel of the
       * neighbourhood; a style guide is blurred as wide as the
       * neighbourhood, so its centre stands for it: the centre's
       * difference, p^2 times. */
      size_t centre = q->radius * p + q->radius;
      return g->cost * (float) (p * p) *
             ts_guide_floats_ssd (q->values + centre * g->channels,
                                  g->packed + (qy * w + qx) * g->channels, g->channels);
    }
  size_t row_floats = p * g->channels;
  const float *t = q->values, *e = g->packed + (y0 * w + x0) * g->channels;
  for (size_t row = 0; row < p; row++, t += row_floats, e += w * g->channels)
    {
      sum += g->cost * ts_guide_floats_ssd (t, e, row_floats);
      if (sum >= bound)
        break;
    }
  return sum;
}

/* E-step weight factor of a vote for exemplar pixel `source` at output
 * pixel p (both indices at this level). */
static inline float
ts_guide_vote_factor (const TsGuideLevel *g, size_t p, int32_t source)
{
  if (g->labels)
    return g->target->label[p] == g->exemplar->label[source] ? 1.0f : g->vote_mismatch;
  const float *t = g->target->value.pixels + p * TS_CHANNELS;
  const float *e = g->exemplar->value.pixels + (size_t) source * TS_CHANNELS;
  float d = 0.0f;
  for (size_t c = 0; c < g->channels; c++)
    d += (t[c] - e[c]) * (t[c] - e[c]);
  return expf (-g->vote_scale * d);
}

/* Per exemplar pixel, how much the target wants it used, relative to the
 * others: its bin's share of the target over its bin's share of the
 * exemplar (histogram matching's aim under a guide). */
void     ts_guide_wanted_usage (const TsGuideLevel *g, const TsImage *ex, float *wanted);

#endif
