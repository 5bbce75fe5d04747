/* Histogram matching (Kopf et al. 2007): lowers the weight of votes whose
 * colour is over-represented in the output compared with the exemplar
 * (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_HISTOGRAM_H
#define TS_HISTOGRAM_H

#include "image.h"

/* Bins per channel: fine enough to tell the colours of a texture's
 * phases apart, coarse enough that every bin of a small exemplar holds
 * enough pixels for a steady density. */
#define TS_HISTOGRAM_BINS 32

typedef struct
{
  float lo[3], scale[3];                      /* bin = (v - lo) * scale       */
  float exemplar[3][TS_HISTOGRAM_BINS];       /* densities (mean 1 per bin)   */
  float excess[3][TS_HISTOGRAM_BINS];         /* max(0, output - exemplar)    */
  const TsImage *source;                      /* the exemplar                 */
  float *factor;                              /* vote weight factor of each
                                                 exemplar pixel, in (0, 1]    */
} TsHistogram;

/* Bins from the exemplar's opaque pixels; keeps a pointer to it. */
TsStatus ts_histogram_init (TsHistogram *histogram, const TsImage *exemplar);
void     ts_histogram_free (TsHistogram *histogram);
/* Recomputes the output side from `usage` (how many output pixels copy
 * each exemplar pixel; see ts_occurrence_count), and the factor of every
 * exemplar pixel. */
/* Makes the exemplar side the exemplar's pixels weighted by `wanted`
 * (one non-negative weight per pixel) instead of each counted once: the
 * histogram a guide asks for. */
void     ts_histogram_set_wanted (TsHistogram *histogram, const float *wanted);
void     ts_histogram_update (TsHistogram *histogram, const uint32_t *usage);

static inline size_t
ts_histogram_bin (const TsHistogram *h, int channel, float v)
{
  float b = (v - h->lo[channel]) * h->scale[channel];
  if (!(b > 0.0f))
    return 0;
  return b >= TS_HISTOGRAM_BINS - 1 ? TS_HISTOGRAM_BINS - 1 : (size_t) b;
}

/* Weight multiplier in (0, 1] of a vote with colour `lab`. */
static inline float
ts_histogram_factor (const TsHistogram *h, const float *lab)
{
  float excess = 0.0f;
  for (int c = 0; c < 3; c++)
    excess += h->excess[c][ts_histogram_bin (h, c, lab[c])];
  return 1.0f / (1.0f + excess);
}

#endif
