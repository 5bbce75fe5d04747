/* Two figures of a two-phase solid's slices (solid-shapes), the phases
 * split at the middle of the exemplar's 5th and 95th lightness
 * percentiles: how thick their bodies are against the exemplar's, and how
 * many specks they hold.
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

/* Specks per 1000 pixels over every x, y and z slice of `volume` (n^3
 * Lab + alpha, periodic), split by `exemplar`'s lightness. False if out
 * of memory. */
bool phase_specks (const TsImage *exemplar, const float *volume, size_t n, double *per_thousand);

/* Sections: pieces of the light phase larger than a speck (stones between
 * mortar, spots on a dark ground). Their number per slice over every x,
 * y and z slice of `volume`, over the exemplar's own (n x n, wrapped):
 * where stones merge or the mortar fails to close it falls below 1, where
 * they break into fragments it rises. False if out of memory or if the
 * exemplar is not n x n. */
bool phase_sections (const TsImage *exemplar, const float *volume, size_t n, double *ratio);

/* The lightness spread within sections (root mean square deviation from
 * each section's own mean) over every x, y and z slice of `volume`, over
 * the exemplar's: where a stone's section copies several exemplar stones
 * of different tones it rises. False as phase_sections. */
bool phase_tone_spread (const TsImage *exemplar, const float *volume, size_t n, double *ratio);

#endif
