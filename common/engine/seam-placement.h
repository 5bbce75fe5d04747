/* Where a wrap-around result's tile edges go (internal). A tileable result
 * is a torus: every cyclic shift of it tiles equally well, so the edges can
 * be put where the synthesis is most coherent, i.e. where the votes of
 * overlapping neighbourhoods agreed best.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SEAM_PLACEMENT_H
#define TS_SEAM_PLACEMENT_H

#include "image.h"

/* Shift (0 .. n-1) along each wrapping axis that puts the edge through the
 * lowest total `disagreement` (one value per pixel) within `band` pixels. */
TsStatus ts_seam_best_shift (const float *disagreement, size_t width, size_t height,
                             bool wrap_x, bool wrap_y, size_t band,
                             size_t *shift_x, size_t *shift_y);

/* Rolls `pixels` (width x height items of `item_size` bytes) so that
 * (shift_x, shift_y) moves to the origin. */
TsStatus ts_seam_roll (void *pixels, size_t width, size_t height, size_t item_size,
                       size_t shift_x, size_t shift_y);

#endif
