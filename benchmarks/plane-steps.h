/* A lattice of planes in a solid (solid-shapes): how much larger the
 * colour steps between neighbouring voxel planes are on a grid of
 * planes than between the others.
 *
 * Why: a coarse-to-fine engine can leave the cells of its coarser levels
 * in the volume as axis-aligned blocks. No slice figure sees them, as
 * they shift the gradient only on one plane in several; averaged over
 * the planes of a period they stand out.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_PLANE_STEPS_H
#define TS_PLANE_STEPS_H

#include <stdbool.h>
#include <stddef.h>

/* Over the periods 2, 4 and 8, the mean squared Lab step across the
 * planes at multiples of the period divided by that across the other
 * planes (each axis's steps over its mean step, the three axes pooled):
 * the one of the three farthest from 1, above or below. About 1 for a
 * solid without a lattice. `volume` is n^3 Lab +
 * alpha, periodic. False if out of memory. */
bool plane_step_lattice (const float *volume, size_t n, double *ratio);

#endif
