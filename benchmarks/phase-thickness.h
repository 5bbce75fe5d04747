/* How thick the bodies of a two-phase solid's slices are against its
 * exemplar's (solid-shapes): the share of the minority phase that
 * survives PHASE_EROSIONS in-slice erosions, over every x, y and z
 * slice, divided by the exemplar's share.
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

#endif
