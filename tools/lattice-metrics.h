/* The lattice measure (texsynth-measure --lattice): does a result keep
 * the repeat of a near-regular exemplar (bricks, weaves, tiles)? Pure
 * C11, no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Autocorrelation. For an image of w x h pixels with lightness L (the
 * Lab L channel; a, b and alpha are ignored), let m be the mean of L over
 * the image, f = L - m and v the mean of f^2. For an offset d = (dx, dy)
 * the overlap is the set of pixels p with p and p + d both inside the
 * image, N(d) = (w - |dx|) * (h - |dy|) pixels, and
 *
 *     R(d) = (sum over the overlap of f(p) * f(p + d)) / (N(d) * v),
 *
 * so R(0) = 1, R(-d) = R(d), and R(d) is near 1 where the image repeats
 * at offset d, near 0 where it does not. An image with v = 0 (one
 * lightness) has R(d) = 0 for every d != 0: it has no lattice.
 *
 * Peaks. The offsets looked at in an image are those of length 6 to 60
 * pixels with |dx| <= w / 2 and |dy| <= h / 2 (the overlap at least half
 * the image each way), in the half-plane dy > 0 or (dy = 0, dx > 0),
 * since R(-d) = R(d). A peak is such an offset where R(d) > 0 and R is a
 * local maximum over its 8 neighbouring offsets (wherever they lie):
 * greater than the neighbours before it in row order (dy, then dx), at
 * least equal to those after, so a plateau gives one peak. The exemplar's
 * peaks are its TS_LATTICE_PEAKS highest (values within 1e-9 are ties:
 * the shorter offset first, then row order); its strength is the highest peak's R, 0 if it has none. An
 * exemplar is near-regular when its strength is at least
 * TS_LATTICE_NEAR_REGULAR.
 *
 * Lattice. The result's R at each of the exemplar's peak offsets over the
 * exemplar's R there, averaged over the peaks: about 1 when the result
 * keeps the exemplar's lattice, about 0 when it is lost. Defined only for
 * near-regular exemplars (NAN otherwise). The result must hold every peak
 * offset as the exemplar does: |dx| <= its width / 2, |dy| <= its
 * height / 2.
 *
 * The exemplar's R is computed at all offsets at once through an FFT of
 * the zero-padded image; the peak values and the result's R directly at
 * the peak offsets, so an image measured against itself gives exactly 1.
 */
#ifndef TS_LATTICE_METRICS_H
#define TS_LATTICE_METRICS_H

#include "metrics.h"

#define TS_LATTICE_MIN_LAG 6          /* shortest peak offset, pixels       */
#define TS_LATTICE_MAX_LAG 60         /* longest peak offset, pixels        */
#define TS_LATTICE_PEAKS 4            /* the exemplar's peaks compared      */
#define TS_LATTICE_NEAR_REGULAR 0.3   /* least strength of a near-regular one */
/* smallest exemplar side: room for offsets of TS_LATTICE_MIN_LAG */
#define TS_LATTICE_MIN_SIDE (2 * TS_LATTICE_MIN_LAG)

typedef struct
{
  int    dx, dy;
  double exemplar; /* the exemplar's R at (dx, dy)                 */
  double result;   /* the result's, NAN until ts_lattice_result    */
} TsLatticePeak;

typedef struct
{
  size_t        n_peaks;                /* 0 .. TS_LATTICE_PEAKS        */
  TsLatticePeak peak[TS_LATTICE_PEAKS]; /* highest first                */
  double        strength;               /* peak[0].exemplar, 0 if none  */
  double        lattice;                /* mean ratio; NAN unless near-regular
                                           and a result was measured    */
} TsLattice;

/* R of `image` at (dx, dy), summed directly; NAN if the overlap is empty. */
double ts_lattice_autocorrelation (const TsImage *image, int dx, int dy);

/* R of `image` at every offset with |dx| <= radius_x and |dy| <= radius_y
 * (each radius at least 0 and less than that side), through an FFT:
 * map[(dy + radius_y) * (2 * radius_x + 1) + dx + radius_x]. */
TsMeasureStatus ts_lattice_autocorrelation_map (const TsImage *image, int radius_x, int radius_y,
                                                double *map);

/* The exemplar's peaks and strength (TS_MEASURE_TOO_SMALL if a side is
 * below TS_LATTICE_MIN_SIDE); results and lattice are left NAN. */
TsMeasureStatus ts_lattice_exemplar (const TsImage *exemplar, TsLattice *out);

/* Whether the exemplar is near-regular (strength >= TS_LATTICE_NEAR_REGULAR). */
bool ts_lattice_near_regular (const TsLattice *lattice);

/* The smallest result that holds every peak offset of `lattice`. */
void ts_lattice_min_result_size (const TsLattice *lattice, size_t *width, size_t *height);

/* Fills each peak's result and the lattice figure (NAN unless
 * near-regular) from `result`; TS_MEASURE_TOO_SMALL if it is smaller than
 * ts_lattice_min_result_size, and `lattice` is then left as it was. */
TsMeasureStatus ts_lattice_result (const TsImage *result, TsLattice *lattice);

#endif
