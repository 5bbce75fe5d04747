/* Quality measures of a healed image against the original and its hole
 * (texsynth-measure --heal). Pure C11 (+ optional OpenMP), no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * In CIE Lab (L, a, b; alpha ignored but for "outside changed"), 7x7
 * windows, "near" = known pixels within TS_HEAL_MEASURE_NEAR pixels
 * (Chebyshev) of the hole:
 *
 * coherence     mean distance (RMS Lab per value, as metrics.h) from every
 *               result window at least half in the hole to the nearest
 *               hole-free original window centred near the hole;
 * completeness  the same from every such original window to the nearest
 *               of those result windows;
 * fill_bds      coherence + completeness (bidirectional similarity);
 * boundary      mean Lab step across the hole's outline (horizontal and
 *               vertical pairs, one pixel in the hole) over the mean step
 *               between near known neighbours; about 1 = invisible outline;
 * boundary_original  the same figure for the original image;
 * sharpness     mean |grad L| (central differences) in the hole over that
 *               of the near known pixels; < 1 = the fill is blurrier;
 * outside_changed  pixels outside the hole whose L, a, b differ by more
 *               than TS_HEAL_MEASURE_SAME (alpha by a hundredth of it): a
 *               lossless change of bit depth (8-bit file, 16-bit result)
 *               does not count; the tests check bytes for bit-identity.
 */
#ifndef TS_HEAL_METRICS_H
#define TS_HEAL_METRICS_H

#include "metrics.h"

#include <stdint.h>

/* The surroundings a fill is judged against: near enough to be what
 * the eye compares it with, wide enough to hold several texture
 * features. */
#define TS_HEAL_MEASURE_NEAR 64
/* Far below one 8-bit step (about 0.4 L*), far above float rounding. */
#define TS_HEAL_MEASURE_SAME 0.01f

typedef struct
{
  double coherence;
  double completeness;
  double fill_bds;
  double boundary;
  double boundary_original;
  double sharpness;
  double sharpness_original; /* the same figure for the original image */
  size_t outside_changed;
  size_t hole_pixels;
} TsHealMeasures;

/* `hole`: one byte per pixel, non-zero = healed. The two images must have
 * the same size (else TS_MEASURE_TOO_SMALL), and the hole must hold a
 * window at least half in it and leave a hole-free window near it. */
TsMeasureStatus ts_measure_heal (const TsImage *original, const TsImage *result,
                                 const uint8_t *hole, TsHealMeasures *out);

#endif
