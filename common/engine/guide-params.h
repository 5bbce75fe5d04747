/* Guides: checks, label tables and memory (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDE_PARAMS_H
#define TS_GUIDE_PARAMS_H

#include "texsynth.h"

/* Bytes of the guides of a synthesis: the caller's, or the lattice guide
 * a plain synthesis may build. */
double   ts_guides_estimate_bytes (const TsParams *params, const TsImage *exemplar);
/* Whether ts_synthesize grows the output in layers (guide-layers.c):
 * guides that count (weight above 0), compared as labels, edges not
 * blended. */
bool     ts_guide_layers_apply (const TsParams *params, const TsImage *exemplar);
/* Checks params->guides, if any, against the output and the exemplar. */
TsStatus ts_guides_validate (const TsParams *params, const TsImage *exemplar, TsError *error);
/* Distinct guide values of `n` pixels into `table` (max entries of
 * `channels` floats); false if there are more than `max`. */
bool     ts_guide_find_labels (const float *values, size_t n, size_t channels, float *table,
                               size_t max, size_t *count);
/* Index of the entry of `table` nearest to `value`. */
uint8_t  ts_guide_nearest_label (const float *table, size_t count, size_t channels,
                                 const float *value);

#endif
