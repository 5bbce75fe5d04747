/* Square Lab windows of an image on a regular grid of centres: gathering,
 * distances and their principal directions (the vectors patch-search.h
 * indexes).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A window is the (2r+1)^2 pixels around a centre, L, a and b only (alpha
 * is ignored); distances are sums of squared differences (SSD) over those
 * 3 (2r+1)^2 values. Windows either lie inside the image or, along a
 * wrapping axis, wrap around its edges. */
#ifndef TS_WINDOW_GRID_H
#define TS_WINDOW_GRID_H

#include "texsynth.h"

#define TS_SEARCH_MAX_RADIUS 7

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

#endif
