/* Gaussian pyramids of working images (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_PYRAMID_H
#define TS_PYRAMID_H

#include "image.h"

typedef struct
{
  size_t   levels;  /* number of images; levels[0] is the finest */
  TsImage *level;
} TsPyramid;

/* Number of levels so that the coarsest shorter side is about
 * `coarsest_side` pixels (never below it by more than half), at least 1. */
size_t   ts_pyramid_depth_for (size_t width, size_t height, size_t coarsest_side);

/* One reduction: 5-tap binomial filter (mirrored borders), then every
 * other row and column; output is ceil(w/2) x ceil(h/2). Lab is averaged
 * weighted by alpha so transparent pixels don't bleed colour. */
TsStatus ts_pyramid_reduce (const TsImage *in, TsImage *out);

/* A side of `side` pixels at pyramid level `level`: halved, rounded up,
 * `level` times (the output's size there as ts_pyramid_reduce's). */
static inline size_t
ts_level_side (size_t side, size_t level)
{
  return (side + ((size_t) 1 << level) - 1) >> level;
}

/* Copies `base` into level 0 and reduces `levels - 1` times. */
TsStatus ts_pyramid_build (const TsImage *base, size_t levels, TsPyramid *pyramid);
void     ts_pyramid_free (TsPyramid *pyramid);

#endif
