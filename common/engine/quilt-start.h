/* Patch-based start of the coarsest level: image quilting with
 * minimum-error boundary cuts (Efros & Freeman 2001) over source
 * coordinates (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_QUILT_START_H
#define TS_QUILT_START_H

#include "level.h"

/* Fills state->source (state->width x state->height) with large exemplar
 * patches, each placed where its overlap with the patches already laid
 * agrees best, so a near-regular exemplar's lattice continues across
 * them. Deterministic for (seed, level) at any thread count. Returns
 * TS_OK, TS_ERROR_OUT_OF_MEMORY or TS_ERROR_CANCELLED. */
TsStatus ts_quilt_start (TsLevelState *state, uint32_t seed, uint32_t level);

#endif
