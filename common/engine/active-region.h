/* The part of an output level worth optimizing when the caller needs
 * only some of the output's pixels (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_ACTIVE_REGION_H
#define TS_ACTIVE_REGION_H

#include "texsynth.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct
{
  uint8_t *pixels;   /* per level pixel: the E-step updates it          */
  uint8_t *centres;  /* per level pixel: the M-step matches a window there */
} TsActiveRegion;

/* For the level of size w x h that is `level` halvings of an output of
 * out_w x out_h whose pixels `needed` marks (non-zero), with windows of
 * the given radius: the pixels within 4 radii of a needed one (what the
 * windows voting for a needed pixel read, and what the windows voting
 * for those read), and the centres of the windows that cover such a
 * pixel (within 5 radii). Squares, across wrapped sides. */
TsStatus ts_active_region_init (TsActiveRegion *region, const uint8_t *needed, size_t out_w,
                                size_t out_h, size_t level, size_t w, size_t h, size_t radius,
                                bool wrap_x, bool wrap_y);
void     ts_active_region_free (TsActiveRegion *region);

/* True if any pixel of the rectangle [x0, x1) x [y0, y1) (clipped to the
 * level) is in `mask`. */
bool     ts_active_any (const uint8_t *mask, size_t w, size_t h, size_t x0, size_t y0,
                        size_t x1, size_t y1);

#endif
