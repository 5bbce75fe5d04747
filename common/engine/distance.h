/* Exact Euclidean distance transforms (Felzenszwalb and Huttenlocher
 * 2012) of grids of up to three dimensions, x fastest. Shared by the
 * tileable planner (distance to a cut) and the solid engine (distance to
 * a phase boundary).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_DISTANCE_H
#define TS_DISTANCE_H

#include "engine/error.h"

#include <stdbool.h>
#include <stddef.h>

/* The distance of a sample with no feature in reach. */
#define TS_DISTANCE_FAR 1e20f

/* In place: `grid` (dims[0] x dims[1] x dims[2] samples) holds 0 on the
 * features and TS_DISTANCE_FAR elsewhere; afterwards each sample holds
 * its distance to the nearest feature, or TS_DISTANCE_FAR if there is
 * none. An axis with wrap[axis] repeats (the nearest feature may lie
 * across the border). */
TsStatus ts_distance_transform (float *grid, const size_t dims[3], const bool wrap[3]);

#endif
