/* Measures of guided synthesis (texsynth-measure --exemplar-guide,
 * --target-guide, --style-target). Pure C11 (+ optional OpenMP), no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * label fidelity    every result pixel whose 7x7 window lies inside the
 *                   result takes the label of the exemplar pixel at the
 *                   centre of its nearest exemplar window; the share of
 *                   those more than TS_LABEL_EDGE_MARGIN px from a label
 *                   edge of the target whose label is the target's there.
 * label edge offset the mean distance (px) from each edge pixel of the
 *                   target's labels to the nearest edge pixel of the
 *                   result's, and back, averaged (each capped at
 *                   TS_LABEL_EDGE_SEARCH).
 * region coherence  per label, the coherence (metrics.h) of the judged
 *                   pixels of that label: mean RMS distance of their
 *                   windows to the nearest exemplar window.
 * style correlation correlation of the result's lightness with the
 *                   target's, both blurred by a Gaussian of
 *                   TS_STYLE_BLUR_SIGMA px: the result's large-scale
 *                   lightness follows the target's at 1.
 */
#ifndef TS_GUIDED_METRICS_H
#define TS_GUIDED_METRICS_H

#include "metrics.h"

#include <stdint.h>

#define TS_LABEL_MAX 32
#define TS_LABEL_NONE 255
/* A window that straddles a label edge matches either side. */
#define TS_LABEL_EDGE_MARGIN TS_MEASURE_RADIUS
#define TS_LABEL_EDGE_SEARCH 16
/* Larger than the grains and strokes of a texture, smaller than a
 * picture's shapes. */
#define TS_STYLE_BLUR_SIGMA 4.0

typedef struct
{
  double fidelity;
  double edge_offset;
  size_t labels;
  double region_coherence[TS_LABEL_MAX]; /* NAN for a label with no judged pixel */
} TsLabelMeasures;

/* Labels of two guide images: each distinct colour of `exemplar_guide`
 * is a label (in order of first appearance); every target pixel takes the
 * nearest. False if the exemplar guide has more than TS_LABEL_MAX. */
bool ts_guide_label_maps (const TsImage *exemplar_guide, const TsImage *target_guide,
                          uint8_t *exemplar_labels, uint8_t *target_labels, size_t *labels);

/* `exemplar_labels` has the exemplar's size, `target_labels` the result's. */
TsMeasureStatus ts_measure_labels (const TsImage *exemplar, const uint8_t *exemplar_labels,
                                   const TsImage *result, const uint8_t *target_labels,
                                   size_t labels, TsLabelMeasures *out);

/* `target` has the result's size. */
TsMeasureStatus ts_measure_style_correlation (const TsImage *target, const TsImage *result,
                                              double *correlation);

#endif
