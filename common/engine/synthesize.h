/* The texture optimization over the whole output (internal): plain, or
 * guided by values, by the exemplar's lattice or by labels with blended
 * edges.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SYNTHESIZE_H
#define TS_SYNTHESIZE_H

#include "texsynth.h"

/* ts_synthesize's work for validated `params` and an output of their
 * size; same contract otherwise. */
TsStatus ts_synthesize_optimized (const TsParams *params, const TsImage *exemplar,
                                  TsImage *output, TsProgressFunc progress, void *user_data,
                                  TsError *error);

/* As ts_synthesize_optimized, for a caller that needs only the output
 * pixels `needed` marks (one byte per output pixel, non-zero = needed):
 * each level optimizes those and the neighbourhoods around them
 * (active-region.h); the rest keep their start, a rougher texture. */
TsStatus ts_synthesize_needed (const TsParams *params, const TsImage *exemplar,
                               const uint8_t *needed, TsImage *output, TsProgressFunc progress,
                               void *user_data, TsError *error);

#endif
