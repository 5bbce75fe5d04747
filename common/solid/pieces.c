/* The 4-connected pieces of a 2D mask, for the cell guide's stone
 * sections (cell-guide.c) and the phase guide's gate (phase-guide.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <stdlib.h>

TsStatus
ts_solid_mask_pieces (const uint8_t *mask, size_t w, size_t h, TsSolidPieceFunc piece, void *data)
{
  size_t count = w * h;
  uint8_t *seen = calloc (count, 1);
  size_t *stack = malloc (count * sizeof (size_t));
  size_t *member = malloc (count * sizeof (size_t));

  if (!seen || !stack || !member)
    {
      free (seen);
      free (stack);
      free (member);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < count; i++)
    {
      size_t top = 0, area = 0;
      if (!mask[i] || seen[i])
        continue;
      seen[i] = 1;
      stack[top++] = i;
      while (top > 0)
        {
          size_t p = stack[--top], x = p % w, y = p / w;
          size_t next[4] = { x > 0 ? p - 1 : p, x + 1 < w ? p + 1 : p, y > 0 ? p - w : p,
                             y + 1 < h ? p + w : p };
          member[area++] = p;
          for (int k = 0; k < 4; k++)
            if (mask[next[k]] && !seen[next[k]])
              {
                seen[next[k]] = 1;
                stack[top++] = next[k];
              }
        }
      piece (member, area, data);
    }
  free (seen);
  free (stack);
  free (member);
  return TS_OK;
}
