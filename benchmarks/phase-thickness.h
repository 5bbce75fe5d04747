/* Figures of a two-phase solid's slices (solid-shapes), the phases split
 * at the middle of the exemplar's 5th and 95th lightness percentiles: how
 * thick their bodies are against the exemplar's, how many specks they
 * hold, how many sections and how even their tones.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_PHASE_THICKNESS_H
#define TS_PHASE_THICKNESS_H

#include "texsynth.h"

#include <stdbool.h>

/* Erosions by the 4-neighbour cross: a body survives two if it is at
 * least five pixels across. */
#define PHASE_EROSIONS 2

/* The ratio for `volume` (n^3 Lab + alpha, periodic) against `exemplar`
 * (Lab + alpha), the phases split at the middle of the exemplar's 5th
 * and 95th lightness percentiles; NAN where the exemplar has no body
 * that thick. False if out of memory. */
bool phase_thickness (const TsImage *exemplar, const float *volume, size_t n, double *ratio);

/* A speck: a 4-connected piece of either phase of at most this many
 * pixels, in a slice that wraps around. */
#define PHASE_SPECK_PIXELS 4

/* The figures of every x, y and z slice of `volume` (n^3 Lab + alpha,
 * periodic), its phases split by `exemplar`'s lightness, from one pass:
 * - specks: specks per 1000 pixels;
 * - sections: pieces of the light phase larger than a speck (stones
 *   between mortar, spots on a dark ground), their number per slice over
 *   the exemplar's own (n x n, wrapped): where stones merge or the mortar
 *   fails to close it falls below 1, where they break into fragments it
 *   rises;
 * - tones: the lightness spread within those sections (root mean square
 *   deviation from each section's own mean), over the exemplar's: where a
 *   stone's section copies several exemplar stones of different tones it
 *   rises, where stones are flatter than the exemplar's it falls;
 * - shades: the spread of those sections' mean lightness (pixel-weighted
 *   root mean square deviation from the mean of all), over the
 *   exemplar's: where stones take one middling tone each it falls;
 * - grain: the mean lightness step between 4-neighbours of the same
 *   phase, over the exemplar's, in the light [0] and the dark [1] phase:
 *   where neighbouring pixels copy unrelated sources it rises, in
 *   stones as in joints.
 * Sections, tones, shades and grain are NAN unless the exemplar is
 * n x n. */
typedef struct
{
  double specks, sections, tones, shades, grain[2];
} PhaseFigures;

/* False if out of memory. */
bool phase_figures (const TsImage *exemplar, const float *volume, size_t n, PhaseFigures *figures);

#endif
