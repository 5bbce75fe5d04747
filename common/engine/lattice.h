/* A near-regular exemplar's lattice (its periods), estimated from the
 * autocorrelation of its lightness (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_LATTICE_H
#define TS_LATTICE_H

#include "guide.h"
#include "pyramid.h"

/* The least autocorrelation of a period: below it the repeat is too
 * weak to call the exemplar near-regular (the lattice measure's own
 * threshold, tools/lattice-metrics.h). */
#define TS_LATTICE_LEAST_PEAK 0.3

typedef struct
{
  size_t vectors;      /* 0: no lattice; 1: one period (stripes); 2: a lattice */
  double vector[2][2]; /* (x, y) of each period, level-0 exemplar pixels;
                          with 2, a reduced basis (the shortest pair)      */
  double strength;     /* autocorrelation at the first period, 0 .. 1   */
} TsLatticeEstimate;

/* Estimates the lattice of the exemplar whose working pyramid is
 * `pyramid` (0 vectors when it has none). */
TsStatus ts_lattice_estimate (const TsPyramid *pyramid, TsLatticeEstimate *out);

/* The lattice as a guide (lattice-guide.c): each exemplar pixel's phase
 * in its lattice, and the same phases laid evenly over the output, so
 * the synthesis keeps the periods where they fall in the exemplar. A
 * tileable output's lattice is bent to a whole number of periods. */
TsStatus ts_lattice_guide_build (const TsLatticeEstimate *lattice, const TsPyramid *pyramid,
                                 size_t out_w, size_t out_h, bool wrap_x, bool wrap_y,
                                 TsGuidePyramid *guides);

#endif
