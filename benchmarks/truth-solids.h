/* Ground-truth solids (truth-solids*.c): periodic, isotropic volumes
 * whose slices in every direction are samples of one and the same 2D
 * texture, against which synthesised solids are judged.
 *
 * Kinds, by family:
 *   separate pieces   beads (balls of one size), droplets (balls of many
 *                     sizes), ellipsoids (grains at random orientations),
 *                     terrazzo (angular chips of five stones)
 *   overlapping ones  balls (many sizes on a plain ground), rods (fibres
 *                     at random orientations)
 *   networks          cells (light stones in dark joints), foam (dark
 *                     cells in light walls), sponge (pores in a solid)
 *   random media      blobs (spots with a rim), grains (granite speckle),
 *                     twophase, threephase (thresholded noise)
 *   continuous tones  marble (veins and drifting shades)
 *
 * The tuning half (TRUTH_SOLID_TUNING) is what engine defaults are chosen
 * on; the checking half (TRUTH_SOLID_CHECKING) only reports how they
 * generalise. Each half holds pieces, networks and random media.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_TRUTH_SOLIDS_H
#define TS_TRUTH_SOLIDS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define TRUTH_SOLID_TUNING "cells", "blobs", "grains", "balls", "terrazzo", "ellipsoids", "sponge", "marble"
#define TRUTH_SOLID_CHECKING "foam", "beads", "droplets", "rods", "twophase", "threephase"
#define TRUTH_SOLID_KINDS TRUTH_SOLID_TUNING, TRUTH_SOLID_CHECKING

/* Fills `rgb` (n^3 voxels, 3 bytes each, x fastest) with the periodic
 * solid `kind` for `seed`; false for an unknown kind or out of memory. */
bool truth_solid_render (const char *kind, size_t n, uint32_t seed, uint8_t *rgb);

/* Every kind's name, tuning half first, ending with NULL. */
const char *const *truth_solid_kinds (void);

#endif
