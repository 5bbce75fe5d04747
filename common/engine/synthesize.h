/* The texture optimization over the whole output (internal): plain, or
 * guided by values, by the exemplar's lattice or by labels with blended
 * edges.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SYNTHESIZE_H
#define TS_SYNTHESIZE_H

#include "texsynth.h"
#include "mrpm.h"

/* ts_synthesize's work for validated `params` and an output of their
 * size; same contract otherwise. */
TsStatus ts_synthesize_optimized (const TsParams *params, const TsImage *exemplar,
                                  TsImage *output, TsProgressFunc progress, void *user_data,
                                  TsError *error);

/* What syntheses from one exemplar with the same quality can share: each
 * level's MRPM candidate sets, made by the first that needs them. Start
 * zeroed; one memo per exemplar. */
typedef struct
{
  size_t          levels;
  TsCandidateSet *sets;
} TsExemplarMemo;

void     ts_exemplar_memo_free (TsExemplarMemo *memo);

/* As ts_synthesize_optimized, for a caller that needs only the output
 * pixels `needed` marks (one byte per output pixel, non-zero = needed;
 * NULL: all): each level optimizes those and the neighbourhoods around
 * them (active-region.h); the rest keep their start, a rougher texture.
 * With a `memo` (or NULL), the exemplar's candidate sets are kept there
 * for the next synthesis from it; the results are the same. */
TsStatus ts_synthesize_needed (const TsParams *params, const TsImage *exemplar,
                               const uint8_t *needed, TsExemplarMemo *memo, TsImage *output,
                               TsProgressFunc progress, void *user_data, TsError *error);

#endif
