/* The seam figure across the wrap-around edges and, as a control, across
 * interior lines of the same slices (solid-shapes).
 *
 * Why: one line's figure varies with the features that happen to cross
 * it. In 64^3 blobs the interior lines of one volume span 0.73-1.18, so
 * a seam over 1.10 means a seam only when the wrap stands out from the
 * lines inside.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SEAM_PLANES_H
#define TS_SEAM_PLANES_H

#include "texsynth.h"

/* Lines per slice side: the wrap and SEAM_PLANES - 1 interior lines. */
#define SEAM_PLANES 8

/* planes[k]: slice_figures' seam with the slices rolled by k n / SEAM_PLANES
 * along both in-slice axes, so planes[0] is the seam itself; false if out
 * of memory or a measure fails. */
bool seam_planes (const TsImage *exemplar, const float *volume, size_t n,
                  double planes[SEAM_PLANES]);

#endif
