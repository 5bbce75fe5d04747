/* The sources an output level starts from (internal): a quilt, random
 * blocks, a guide's blocks, an initial map, or the coarser level's.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_LEVEL_START_H
#define TS_LEVEL_START_H

#include "level.h"

/* Indices of the opaque pixels of an exemplar level. */
TsStatus ts_level_list_opaque (const TsImage *ex, int32_t **list, size_t *count);

/* Source coordinates and preserve weights of params' initial map,
 * resampled to `level` of size w x h (nearest sample; weights averaged
 * over the block). */
TsStatus ts_level_initial (const TsParams *params, const TsImage *ex_level, size_t level,
                           size_t w, size_t h, int32_t **source, float **preserve);

/* Starting sources of a level: at the coarsest level (`coarser` NULL) the
 * guide's blocks under a guide, else a quilt of large exemplar patches
 * (random exemplar blocks of side `block` where an initial map replaces
 * it anyway); at the others the children of the coarser level's sources
 * (coarser_w wide, on an exemplar level coarser_ex_w wide). */
TsStatus ts_level_start_sources (TsLevelState *state, const TsParams *params, size_t level,
                                 size_t block, const int32_t *coarser, size_t coarser_w,
                                 size_t coarser_ex_w);

#endif
