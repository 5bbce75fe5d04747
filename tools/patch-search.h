/* Exact nearest-neighbour search among square Lab windows of an image,
 * for the quality measures of texsynth-measure.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A window is the (2r+1)^2 pixels around a centre, L, a and b only (alpha
 * is ignored); distances are sums of squared differences (SSD) over those
 * 3 (2r+1)^2 values. Windows either lie inside the image or, along a
 * wrapping axis, wrap around its edges.
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

#include "texsynth.h"

/* Most principal coordinates an index keeps per window: bounds its
 * memory; the measures ask for fewer (metrics.c). */
#define TS_SEARCH_MAX_LIFT 32
#define TS_SEARCH_MAX_RADIUS 7
#define TS_SEARCH_NONE ((size_t) -1)

/* A regular grid of window centres: centre i is
 * (x0 + (i % nx) * step, y0 + (i / nx) * step). Along an axis that does not
 * wrap, every window of the grid must lie inside the image. */
typedef struct
{
  const TsImage *image;
  int    radius;  /* 1 .. TS_SEARCH_MAX_RADIUS */
  bool   wrap_x;
  bool   wrap_y;
  size_t x0, y0;
  size_t nx, ny;
  size_t step;
} TsWindowGrid;

/* Floats in one gathered window: 3 (2r+1)^2. */
size_t ts_grid_dims (const TsWindowGrid *grid);
size_t ts_grid_count (const TsWindowGrid *grid);
void   ts_grid_centre (const TsWindowGrid *grid, size_t i, size_t *x, size_t *y);

/* Copies window i (row by row, L a b per pixel) to `vec`. */
void ts_grid_gather (const TsWindowGrid *grid, size_t i, float *vec);

/* SSD between a gathered window and window i of `grid`, summed row by row
 * in a fixed order; stops early and returns a partial sum > `limit` as soon
 * as it exceeds `limit`. */
float ts_grid_ssd (const float *vec, const TsWindowGrid *grid, size_t i, float limit);

/* Mean (dims) and `head` orthonormal leading principal directions of the
 * grid's windows, as the first `head` columns of `basis` (dims x stride;
 * both arrays zero-filled by the caller), by subspace iteration on the covariance of a
 * deterministic sample. Only orthonormality matters for exactness; closer
 * principal axes only make searches faster. False if out of memory. */
bool ts_grid_pca (const TsWindowGrid *grid, size_t head, size_t stride, double *mean,
                  double *basis);

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
