/* Exact nearest-neighbour search among square Lab windows of an image
 * (window-grid.h), for the quality measures of texsynth-measure.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * The index rotates window vectors by PCA and keeps, per window, its first
 * few principal coordinates plus the norm of the rest ("lifted"
 * coordinates). Euclidean distance between lifted points is a lower bound
 * of the true distance (rotation keeps distances; by the triangle
 * inequality the rest differs by at least the difference of norms), so a
 * kd-tree over lifted points with exact bounds, followed by the exact SSD
 * on the image for survivors, gives the exact nearest neighbour. Identical
 * windows are indexed once (the one with the smallest grid index). */
#ifndef TS_PATCH_SEARCH_H
#define TS_PATCH_SEARCH_H

#include "window-grid.h"

/* Most principal coordinates an index keeps per window: bounds its
 * memory; the measures ask for fewer (metrics.c). */
#define TS_SEARCH_MAX_LIFT 32
#define TS_SEARCH_NONE ((size_t) -1)

typedef struct TsPatchIndex TsPatchIndex;

/* Indexes every window of `grid` (which must stay valid, with its image,
 * while the index lives) with `lift_dims` (8, 16 or 32) lifted coordinates:
 * more make bounds tighter (fewer exact SSDs) but cost more per window.
 * Returns NULL if out of memory, if lift_dims is not one of those, or if
 * the grid has no windows or more than UINT32_MAX - 1. Uses OpenMP. */
TsPatchIndex *ts_patch_index_new (const TsWindowGrid *grid, int lift_dims);
void          ts_patch_index_free (TsPatchIndex *index);

/* Exact nearest window to the gathered window `vec`: returns its grid index
 * and stores its SSD in `*ssd`. `guess` (a grid index, or TS_SEARCH_NONE)
 * is tried first; a good guess only makes the search faster. Ties may
 * return any of the nearest windows. Thread-safe. */
size_t ts_patch_index_nearest (const TsPatchIndex *index, const float *vec,
                               size_t guess, float *ssd);

/* The smallest grid index whose window has SSD < `max_ssd` to `vec`, or
 * TS_SEARCH_NONE if none has. Thread-safe. */
size_t ts_patch_index_first_within (const TsPatchIndex *index, const float *vec,
                                    float max_ssd);

/* Some grid index whose window has SSD < `max_ssd` to `vec` (the first
 * found: cheaper), or TS_SEARCH_NONE. Thread-safe. */
size_t ts_patch_index_any_within (const TsPatchIndex *index, const float *vec, float max_ssd);

#endif
