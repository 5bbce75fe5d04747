/* Shape measures of an image's phases (texsynth-measure --shapes): the
 * microstructure descriptors used to judge a 3D texture from its 2D
 * slices. Pure C11, no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Phases: k-means (k = 2 or 3) on the exemplar's Lab colours, started
 * from the mean colours of k equal-count bands of its lightness, so the
 * same exemplar always gives the same centres. Every image is then split
 * with those centres (each pixel to the nearest), phase 0 the darkest.
 *
 * Per phase:
 * fraction   the share of the image's pixels in the phase.
 * s2[r]      two-point correlation: the probability that two pixels r
 *            apart (r = 1 .. TS_SHAPE_MAX_LAG) both lie in the phase,
 *            the mean of its value along rows and along columns. Windows
 *            do not wrap: only pairs inside the image count (NAN where r
 *            is not less than both sides). s2[0] is the fraction.
 * chords     the mean length of the maximal runs of the phase along rows
 *            and along columns (runs cut by the image's edge count as
 *            they are seen); NAN if the phase is absent.
 * solidity   over the phase's connected components (4-connected: pixels
 *            sharing a side) of at least TS_SHAPE_MIN_COMPONENT pixels,
 *            the area-weighted mean of area / convex-hull area, the hull
 *            taken around the corners of the pixel squares: exactly 1 for
 *            an axis-aligned rectangle, near 1 for a digital disc. NAN if
 *            no component is large enough.
 */
#ifndef TS_SHAPE_METRICS_H
#define TS_SHAPE_METRICS_H

#include "metrics.h"

#include <stdint.h>

#define TS_SHAPE_MAX_PHASES 3
#define TS_SHAPE_DEFAULT_PHASES 2
#define TS_SHAPE_MAX_LAG 32       /* s2 for r = 1 .. 32 pixels */
#define TS_SHAPE_MIN_COMPONENT 12 /* smaller components are left out of solidity */

typedef struct
{
  int    phases;
  double centre[TS_SHAPE_MAX_PHASES][3]; /* Lab, by increasing L */
} TsPhaseCentres;

typedef struct
{
  double fraction;
  double s2[TS_SHAPE_MAX_LAG + 1];
  double chord_rows, chord_columns;
  double solidity;
  size_t components; /* those of at least TS_SHAPE_MIN_COMPONENT pixels */
} TsPhaseShape;

/* The phases' centres from the exemplar's colours; `phases` is 2 or 3
 * (TS_MEASURE_TOO_SMALL if the image has fewer pixels than phases). */
TsMeasureStatus ts_shape_centres (const TsImage *exemplar, int phases, TsPhaseCentres *out);

/* Each pixel's phase (0 .. phases - 1): width x height bytes, row by row. */
void ts_shape_label (const TsImage *image, const TsPhaseCentres *centres, uint8_t *labels);

/* The measures of every phase of a labelled image (out[phases]). */
TsMeasureStatus ts_shape_measure_labels (const uint8_t *labels, size_t width, size_t height, int phases,
                                         TsPhaseShape *out);

/* ts_shape_label then ts_shape_measure_labels. */
TsMeasureStatus ts_shape_measure (const TsImage *image, const TsPhaseCentres *centres, TsPhaseShape *out);

#endif
