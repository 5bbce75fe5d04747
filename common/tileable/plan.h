/* Making an existing image tileable: the plan (bands, source map,
 * preserve weights) behind ts_make_tileable (internal; tests use it).
 * cuts.c and shift.c refine a plan; make-tileable.c drives them.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * The pixels within about `band` of a wrap edge are replaced by the
 * input's own content, shifted by (shift_x, shift_y) so that a piece of
 * the image's interior straddles the edge: the edge then lies inside
 * coherent, unbroken content, and structure continues across it. The new
 * discontinuities ("cuts") are where the kept picture meets the shifted
 * content, placed where the two agree best, and, when both axes wrap,
 * one across each band where the shifted content itself wraps. Texture
 * optimization re-synthesises them at every pyramid level, free at a cut
 * (preserve 0) and ever more bound to the start farther away (preserve 1
 * from `transition` pixels on, which keeps everything else exactly).
 */
#ifndef TS_TILEABLE_PLAN_H
#define TS_TILEABLE_PLAN_H

#include "texsynth.h"

typedef struct
{
  size_t  width, height;
  bool    wrap_x, wrap_y;
  size_t  band_x, band_y;    /* nominal half-widths of the bands; 0 if no wrap */
  size_t  shift_x, shift_y;  /* exemplar offset of the band content       */
  double  transition;        /* distance from a cut where preserve hits 1 */
  size_t  reach_x, reach_y;  /* how far a join may move towards the edge  */
  /* 1 where the band (shifted content) is, per pixel; NULL = straight
   * bands of the nominal width. Set by ts_tileable_place_cuts. */
  unsigned char *band_mask;
} TsTileablePlan;

static inline bool
ts_tileable_wraps_x (TsTileableDirection direction)
{
  return direction != TS_TILEABLE_VERTICAL;
}

static inline bool
ts_tileable_wraps_y (TsTileableDirection direction)
{
  return direction != TS_TILEABLE_HORIZONTAL;
}

/* Bands and transition of `params` for `input` (validated), with no
 * shift and straight cuts yet. */
void     ts_tileable_plan_init (const TsTileableParams *params, const TsImage *input,
                                TsTileablePlan *plan);
void     ts_tileable_plan_clear (TsTileablePlan *plan);

/* True if (x, y) lies in a band (is replaced). */
bool     ts_tileable_in_band (const TsTileablePlan *plan, size_t x, size_t y);

/* The start of the optimization: 2 int32 per pixel (x, y) of the input
 * to copy, identity outside the bands, and one preserve weight per pixel. */
TsStatus ts_tileable_maps (const TsTileablePlan *plan, int32_t *source, float *preserve);

/* Euclidean distance of every pixel to the nearest nonzero `mask` pixel,
 * wrapping along the wrapping axes; a huge value if there is none. */
TsStatus ts_tileable_distance (const unsigned char *mask, size_t width, size_t height,
                               bool wrap_x, bool wrap_y, float *distance);

#endif
