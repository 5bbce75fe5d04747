/* Quality figures of a solid's slices against its exemplar, without GEGL:
 * the middle slices across x, y and z and the diagonal plane x = z (and
 * the sharpness and the largest edge anisotropy over every x, y and z
 * slice),
 * measured with the texsynth-measure library (solid-shapes and the
 * solid shape tests).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SLICE_FIGURES_H
#define TS_SLICE_FIGURES_H

#include "texsynth.h"

#include <stdint.h>

/* Slices the figures are taken on: x, y, z, diagonal. */
#define SLICE_KINDS 4
/* Slices per axis the seam is averaged over (as quality-solid.py). */
#define SLICE_SEAM_SLICES 4

typedef struct
{
  /* Per slice kind (x, y, z, diagonal). */
  double coherence[SLICE_KINDS], completeness[SLICE_KINDS];
  double sharpness[SLICE_KINDS], axis_edges[SLICE_KINDS];
  /* Medians over the four, and the mean seam across the wrap-around
   * edges of SLICE_SEAM_SLICES slices per axis. */
  double median_coherence, median_completeness, median_sharpness, median_axis_edges;
  double worst_axis_edges; /* the largest of the four */
  double seam;
  /* Sharpness averaged over every slice across x, y and z (3n slices):
   * one slice's gradient varies by about 8 % from slice to slice in the
   * truth's blobs, so this tells engines apart more reliably. */
  double all_slices_sharpness;
  /* The largest edge anisotropy (metrics.h) of any x, y or z slice: a
   * band of streaks extruded along one direction, diagonal included,
   * which axis-edges does not see: with a 16^3 coarsest level, 128^3
   * cells (seed 4) reach 0.59, against the truth's 0.21 and 0.18
   * with today's levels, while their coherence looked better. */
  double worst_slice_anisotropy;
} SliceFigures;

/* sRGB bytes to the engine's Lab + alpha (D65), opaque. */
void slice_rgb8_to_lab (const uint8_t *rgb, size_t count, float *lab);

/* The truth solid `name` (truth-solids.h) at n^3 for `seed`, in Lab +
 * alpha; NULL if unknown or out of memory. Free it with free(). */
float *slice_truth_lab (const char *name, size_t n, uint32_t seed);

/* The slice across `axis` (0, 1, 2) at `index` of an n^3 Lab + alpha
 * volume, or with axis 3 the plane x = z (u along (1, 0, 1) at unit
 * spacing, bilinear, v along y). `out` holds n x n pixels. */
void slice_cut (const float *volume, size_t n, int axis, size_t index, TsImage *out);

/* Figures of `volume` (n^3, periodic) against `exemplar`; false if out
 * of memory. */
bool slice_figures (const TsImage *exemplar, const float *volume, size_t n, SliceFigures *out);

#endif
