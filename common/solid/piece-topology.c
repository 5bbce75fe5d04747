/* Pieces kept apart, at the finest level with the phase guide, for
 * exemplars whose light phase lies in separate stones (stones in
 * mortar; ts_solid_exemplar_stones): the E-step does not turn a joint
 * voxel into stone where that would join two stones its neighbourhood
 * holds apart (estep.c). Stones and joints part at the exemplar's joint
 * split (phase-plan.c), so dark stones are stones too. Why: the walls
 * cut at the start's necks (neck-walls.c) split the start into stones,
 * but the slice neighbourhoods draw new necks through the joints, and
 * after the level's first iteration nearly all the light voxels were
 * one piece again, where a real solid's largest stone holds a tiny
 * share.
 *
 * The test is digital topology's local one: the 6-connected components
 * of piece voxels in the voxel's 18-neighbourhood that touch one of its
 * faces; two or more, and the voxel would be a neck between them. A
 * voxel that joins a piece from one side only, or fills a dent, passes,
 * so the joints may still thin and move; they are only not cut.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <stdlib.h>

/* The 3 x 3 x 3 block around the voxel, by (dx + 1) + 3 (dy + 1) +
 * 9 (dz + 1); the six faces' offsets. */
#define BLOCK 27
static const int face_of_block[6] = { 12, 14, 10, 16, 4, 22 };

/* Which of the block's 18-neighbourhood voxels are of the piece phase:
 * only those known (outside the current batch) and inside the volume. */
static void
piece_block (const TsSolidLevel *level, const size_t xyz[3], const uint8_t *batch_of,
             uint8_t batch, float split, bool light_pieces, bool piece[BLOCK])
{
  size_t n = level->n;

  for (int k = 0; k < BLOCK; k++)
    {
      int d[3] = { k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1 };
      int corner = abs (d[0]) + abs (d[1]) + abs (d[2]);
      size_t q[3];
      bool inside = corner == 1 || corner == 2;

      for (int a = 0; a < 3 && inside; a++)
        {
          ptrdiff_t c = (ptrdiff_t) xyz[a] + d[a];
          inside = level->periodic || (c >= 0 && c < (ptrdiff_t) n);
          q[a] = ts_border_index (c, n, level->periodic);
        }
      piece[k] = false;
      if (!inside)
        continue;
      size_t qi = (q[2] * n + q[1]) * n + q[0];
      if (batch_of[qi] != batch)
        piece[k] = ts_solid_is_light (level->value + qi * TS_CHANNELS, split) == light_pieces;
    }
}

bool
ts_solid_joins_pieces (const TsSolidLevel *level, const size_t xyz[3], const uint8_t *batch_of,
                       uint8_t batch, float split, bool light_pieces)
{
  bool piece[BLOCK], seen[BLOCK] = { false };
  int stack[BLOCK], components = 0;

  piece_block (level, xyz, batch_of, batch, split, light_pieces, piece);
  for (int f = 0; f < 6 && components < 2; f++)
    {
      int top = 0;
      if (!piece[face_of_block[f]] || seen[face_of_block[f]])
        continue;
      seen[face_of_block[f]] = true;
      stack[top++] = face_of_block[f];
      while (top > 0)
        {
          int k = stack[--top];
          int c[3] = { k % 3, k / 3 % 3, k / 9 };
          for (int a = 0; a < 3; a++)
            for (int step = -1; step <= 1; step += 2)
              {
                int e[3] = { c[0], c[1], c[2] };
                e[a] += step;
                if (e[a] < 0 || e[a] > 2)
                  continue;
                int j = e[0] + 3 * e[1] + 9 * e[2];
                if (piece[j] && !seen[j])
                  {
                    seen[j] = true;
                    stack[top++] = j;
                  }
              }
        }
      components++;
    }
  return components >= 2;
}
