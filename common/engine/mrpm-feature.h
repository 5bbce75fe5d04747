/* Features MRPM compares: a patch at a pyramid level plus smaller patches
 * around the same place at up to two coarser levels, and the per-level PCA
 * basis the search ranks them in (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_MRPM_FEATURE_H
#define TS_MRPM_FEATURE_H

#include "pyramid.h"
#include "ssd.h"

/* Most principal axes a feature keeps: bounds the fixed-size sums in
 * the projection. */
#define MAX_PCA 32

typedef struct
{
  const TsImage *img[3]; /* level, level + 1, level + 2 */
  size_t nlev;           /* levels in use                */
  size_t r, rc;          /* radius at the level / coarser levels */
  size_t dims;
} TsMrpmFeature;

/* patch_size and levels_compared as in TsMrpmOptions (mrpm.h). */
void ts_mrpm_feature_setup (const TsPyramid *pyramid, size_t level, size_t patch_size,
                            size_t levels_compared, TsMrpmFeature *f);
void ts_mrpm_feature_extract (const TsMrpmFeature *f, size_t x, size_t y, float *out);
float ts_mrpm_feature_distance (const TsMrpmFeature *f, size_t ax, size_t ay, size_t bx, size_t by, float bound);
TsStatus ts_mrpm_pca_basis (const TsMrpmFeature *f, const int32_t *list, size_t n, size_t width, size_t m, float *basis);

#endif
