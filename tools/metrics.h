/* Quality measures of a synthesised texture against its exemplar
 * (texsynth-measure). Pure C11 (+ optional OpenMP), no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Images are TsImage (CIE Lab + alpha floats); only L, a, b are compared,
 * alpha is ignored. A "distance" between two 7x7 windows is the RMS Lab
 * difference per value, sqrt(SSD / (49 * 3)), in Lab units (about 1 is a
 * just noticeable difference).
 *
 * coherence     mean, over result windows centred at every 2nd pixel in x
 *               and y, of the distance to the nearest exemplar window
 *               (exemplar windows lie inside the exemplar; result windows
 *               lie inside the result, or wrap around along wrapping axes).
 *               0 = every part of the result appears in the exemplar.
 * completeness  the same from exemplar windows (every 2nd pixel) to the
 *               nearest result window (every pixel, wrapping likewise).
 *               0 = all of the exemplar appears in the result.
 * seam          only if an axis wraps: (mean distance of the result
 *               windows that cross a wrapping edge + 0.5) / (mean distance
 *               of the others + 0.5). About 1 = seamless. The 0.5 (below a
 *               visible difference) keeps exact copies at 1 instead of 0/0.
 *               NAN if one of the two groups is empty.
 * copy          area of the largest result region copied verbatim, over
 *               the number of 5x5 windows inside the exemplar,
 *               (w - 4) * (h - 4): 1 = the exemplar was pasted whole,
 *               near 0 = synthesised. See metrics.c for the region rule.
 * sharpness     mean |grad L| of the result over that of the exemplar,
 *               central differences on pixels with both neighbours inside
 *               the image. 1 = as sharp, < 1 blurrier.
 * axis edges    the share of an image's gradient energy (Sobel on L,
 *               |grad|^2) whose direction lies within 10 degrees of the
 *               image axes, the result's over the exemplar's. An isotropic
 *               texture has about 0.22 (40 of 180 degrees); axis-aligned
 *               blocks, seams and dashes push it up. 1 = no more
 *               axis-aligned than the exemplar.
 */
#ifndef TS_METRICS_H
#define TS_METRICS_H

#include "texsynth.h"

#define TS_MEASURE_RADIUS 3       /* 7x7 windows                      */
#define TS_MEASURE_STEP 2         /* query windows at every 2nd pixel */
#define TS_MEASURE_MIN_SIDE 7     /* smallest image side accepted     */
#define TS_MEASURE_SEAM_FLOOR 0.01 /* Lab units added to both seam means, so two
                                     exact copies (0 / 0) read as seamless */
#define TS_COPY_RADIUS 2          /* 5x5 windows for copy detection   */
#define TS_COPY_MAX_RMS 1.0       /* "verbatim": RMS Lab difference below this */
#define TS_AXIS_EDGE_DEGREES 10.0 /* "axis-aligned": gradient this close to x or y */

typedef enum
{
  TS_MEASURE_OK = 0,
  TS_MEASURE_TOO_SMALL,     /* an image side is < TS_MEASURE_MIN_SIDE */
  TS_MEASURE_OUT_OF_MEMORY
} TsMeasureStatus;

typedef struct
{
  double coherence;
  double completeness;
  double seam;        /* NAN unless wrap_x or wrap_y */
  double copy;
  double sharpness;
  double axis_edges;          /* result's share over the exemplar's */
  double axis_edges_exemplar; /* the shares themselves               */
  double axis_edges_result;
  double anisotropy_exemplar; /* see ts_measure_anisotropy            */
} TsMeasures;

/* Coherence (and seam, if an axis wraps; else NAN). */
TsMeasureStatus ts_measure_coherence (const TsImage *exemplar, const TsImage *result,
                                      bool wrap_x, bool wrap_y,
                                      double *coherence, double *seam);

TsMeasureStatus ts_measure_completeness (const TsImage *exemplar, const TsImage *result,
                                         bool wrap_x, bool wrap_y, double *completeness);

TsMeasureStatus ts_measure_copy (const TsImage *exemplar, const TsImage *result,
                                 bool wrap_x, bool wrap_y, double *copy);

TsMeasureStatus ts_measure_sharpness (const TsImage *exemplar, const TsImage *result,
                                      double *sharpness);

/* Share of `image`'s gradient energy within TS_AXIS_EDGE_DEGREES of the
 * axes (NAN for a flat image). */
TsMeasureStatus ts_measure_axis_edge_share (const TsImage *image, double *share);

/* How strongly `image`'s edges favour some orientations: the larger of
 * the second and fourth circular moments of its gradient angles,
 * weighted by gradient energy. 0 when the energy is spread evenly over
 * all directions, 1 when all of it points one way or along a grid's two
 * (NAN for a flat image). The axis-edge share of a solid's slices
 * compares like with like only on exemplars near 0. */
TsMeasureStatus ts_measure_anisotropy (const TsImage *image, double *anisotropy);

/* All of the above. `wrap_x` / `wrap_y`: the result tiles along that axis
 * (texsynth-measure --tileable). */
TsMeasureStatus ts_measure_all (const TsImage *exemplar, const TsImage *result,
                                bool wrap_x, bool wrap_y, TsMeasures *out);

#endif
