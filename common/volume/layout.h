/* Geometry of the images cut from a solid texture, shared by the volume
 * ops and the file formats.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Voxels lie x fastest, then y, then z. A slice orthogonal to an axis is
 * a size x size image whose (u, v) = (column, row) are:
 *   axis X: (y, z)   axis Y: (x, z)   axis Z: (x, y).
 * An atlas holds all `size` slices of one axis in one image: a row-major
 * grid of columns = ceil(sqrt(size)) and rows = ceil(size / columns)
 * cells, slice i at column i % columns, row i / columns; cells without a
 * slice are zero (transparent).
 *
 * `axis` is 0, 1 or 2 for x, y or z (the values of TsAxis).
 */
#ifndef TS_VOLUME_LAYOUT_H
#define TS_VOLUME_LAYOUT_H

#include "texsynth.h"

/* The grid of an atlas of `size` slices (size >= 1). */
void ts_volume_atlas_grid (size_t size, size_t *columns, size_t *rows);

/* The atlas image's width and height in pixels: columns * size, rows * size. */
void ts_volume_atlas_extent (size_t size, size_t *width, size_t *height);

/* The voxel shown at (u, v) of slice `index` orthogonal to `axis`, as a
 * voxel number (multiply by the voxel's bytes for an offset). */
size_t ts_volume_slice_voxel (size_t size, int axis, size_t index, size_t u, size_t v);

/* Copy slice `index` orthogonal to `axis` into `out`, a size x size image
 * of `bytes_per_voxel`-byte pixels, row-major. Works for any voxel type
 * (16 for the engine's Lab+alpha floats, 1..4 for 8-bit volumes).
 * TS_ERROR_INVALID_ARGUMENT if axis is not 0..2 or index >= size. */
TsStatus ts_volume_extract_slice (const void *voxels, size_t size, size_t bytes_per_voxel,
                                  int axis, size_t index, void *out);

/* Copy all slices orthogonal to `axis` into `out`, an atlas image of
 * ts_volume_atlas_extent's size, row-major; unused cells are zeroed. */
TsStatus ts_volume_extract_atlas (const void *voxels, size_t size, size_t bytes_per_voxel,
                                  int axis, void *out);

#endif /* TS_VOLUME_LAYOUT_H */
