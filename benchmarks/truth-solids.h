/* Ground-truth solids (truth-solids.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_TRUTH_SOLIDS_H
#define TS_TRUTH_SOLIDS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Fills `rgb` (n^3 voxels, 3 bytes each, x fastest) with the periodic
 * solid `kind` ("cells", "blobs" or "grains"); false for another kind. */
bool truth_solid_render (const char *kind, size_t n, uint32_t seed, uint8_t *rgb);

#endif
