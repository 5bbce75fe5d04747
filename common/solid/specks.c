/* Specks: once the finest level is done, each
 * 3D piece of at most TS_SOLID_SPECK_VOXELS face-connected voxels on one
 * side of the phase split (phase-split.c) takes the values of a face
 * neighbour on the other side. Why: the E-step's lone-voxel rule
 * (estep.c) sees one voxel's face neighbours only, so pieces of two to
 * four voxels stayed. Most lie in stones whose tone is near the split,
 * where copies of lighter and darker exemplar stones meet; a real solid
 * shades such stones smoothly.
 * Each replaced voxel copies its neighbour's exemplar pixel and source,
 * so aligned maps stay aligned.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <stdlib.h>

/* A speck is what a slice shows as a piece of at most 4 pixels
 * (benchmarks/phase-thickness.h), so 3D pieces up to the same count go.
 * Larger bounds removed hardly more: the slices' specks left are cuts
 * through larger pieces, which are real features. */
#define TS_SOLID_SPECK_VOXELS 4

/* Face neighbour `k` (0..5) of voxel p, as the E-step sees it
 * (solid.h): mirrored at the border, a neighbour inside is found twice,
 * which neither step below minds. */
static size_t
face_neighbour (const TsSolidLevel *level, size_t p, int k)
{
  size_t n = level->n, xyz[3] = { p % n, p / n % n, p / n / n };

  return ts_solid_face_neighbour (level, xyz, k / 2, k & 1);
}

/* Marks p's piece in `speck` if it has at most `max_voxels` voxels. A
 * later start inside a large piece explores it again, at most
 * max_voxels + 1 voxels each time. */
static void
classify_piece (const TsSolidLevel *level, const uint8_t *light, uint8_t *speck, size_t p,
                size_t *piece, size_t max_voxels)
{
  size_t count = 1;

  piece[0] = p;
  for (size_t i = 0; i < count && count <= max_voxels; i++)
    for (int k = 0; k < 6 && count <= max_voxels; k++)
      {
        size_t q = face_neighbour (level, piece[i], k);
        bool known = false;
        if (light[q] != light[p])
          continue;
        for (size_t j = 0; j < count && !known; j++)
          known = piece[j] == q;
        if (!known)
          piece[count++] = q;
      }
  if (count <= max_voxels)
    for (size_t i = 0; i < count; i++)
      speck[piece[i]] = 1;
}

TsStatus
ts_solid_remove_specks (TsSolidLevel *level)
{
  size_t n = level->n, voxels = n * n * n, max_voxels = TS_SOLID_SPECK_VOXELS;
  /* With an exemplar per orientation, the first one's split, as for
   * the cells' tones (cell-tone.c). */
  float split = ts_solid_first_view (level)->phase_split;
  uint8_t *light = malloc (voxels), *speck = calloc (voxels, 1);
  size_t *piece = malloc ((max_voxels + 1) * sizeof (size_t));

  if (!light || !speck || !piece)
    {
      free (light);
      free (speck);
      free (piece);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t p = 0; p < voxels; p++)
    light[p] = level->value[p * TS_CHANNELS] >= split;
  for (size_t p = 0; p < voxels; p++)
    if (!speck[p])
      classify_piece (level, light, speck, p, piece, max_voxels);
  /* Only specks change and only other voxels are read: any order, any
   * thread count gives the same volume. */
#pragma omp parallel for schedule(static) if (n >= TS_SOLID_PARALLEL_EDGE)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) voxels; i++)
    {
      size_t p = (size_t) i;
      if (!speck[p])
        continue;
      for (int k = 0; k < 6; k++)
        {
          size_t q = face_neighbour (level, p, k);
          if (light[q] == light[p] || speck[q])
            continue;
          ts_solid_copy_voxel (level, p, q);
          break;
        }
    }
  free (light);
  free (speck);
  free (piece);
  return TS_OK;
}
