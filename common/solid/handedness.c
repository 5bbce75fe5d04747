/* Which way round one orientation reads its exemplar.
 *
 * A slice has no handedness of its own: the face x = 0 of a cube, seen
 * from outside, is the mirror image of the face x = n. Which way round
 * each orientation reads the exemplar is a convention, and with one
 * image on all three orientations it decides whether the exemplar's
 * diagonal lines can be sheets of the solid at all. Lines rising at 45°
 * in the image (gradients along (1, 1), y down) show in the slices
 * across x, y and z at once as the sheets x + y + z = c. Falling lines
 * (gradients along (1, -1)) cannot: in the slices across z they need
 * sheets with normal (a, -a, c), across x (a, b, -b), across y (a, b, -a),
 * so a = b = c = 0. The orientations then fight over every vein, and the
 * volume keeps blotches with axis-aligned edges. Read mirrored across x,
 * falling lines are the sheets x - y - z = c, and the slices keep
 * clearly fewer axis-aligned edges. Mirroring across y would serve as
 * well in principle; x read a little better on the one bundled veined
 * exemplar, a choice fitted to it (docs/design.md, Known limits). Any
 * sheets cut three of the six face-diagonal planes along an axis.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>

/* The energy-weighted sin 2t of the lightness gradient's angle t (Sobel,
 * image y down) over the opaque 3x3 neighbourhoods, from -1 (every edge
 * falls at 45°) to 1 (every edge rises at 45°); 0 without gradients. */
double
ts_solid_diagonal_bias (const TsImage *ex)
{
  size_t w = ex->width, h = ex->height;
  double total = 0.0, diagonal = 0.0;

  for (size_t y = 1; y + 1 < h; y++)
    for (size_t x = 1; x + 1 < w; x++)
      {
        double gx, gy;
        if (!ts_solid_sobel (ex, x, y, &gx, &gy))
          continue;
        total += gx * gx + gy * gy;
        diagonal += 2.0 * gx * gy;
      }
  return total > 0.0 ? diagonal / total : 0.0;
}

void
ts_solid_mirror_image (TsImage *image)
{
  for (size_t y = 0; y < image->height; y++)
    {
      float *row = image->pixels + y * image->width * TS_CHANNELS;
      for (size_t x = 0, r = image->width - 1; x < r; x++, r--)
        for (int c = 0; c < TS_CHANNELS; c++)
          {
            float t = row[x * TS_CHANNELS + c];
            row[x * TS_CHANNELS + c] = row[r * TS_CHANNELS + c];
            row[r * TS_CHANNELS + c] = t;
          }
    }
}

void
ts_solid_unmirror_sources (TsSolidSource *sources, size_t voxels, int axis, size_t width)
{
  for (size_t p = 0; p < voxels; p++)
    if (ts_solid_source_axis (sources[p]) == axis)
      {
        uint32_t s = ts_solid_source_index (sources[p]);
        uint32_t x = (uint32_t) (s % width), row = (uint32_t) (s - x);
        sources[p] = ts_solid_source_pack (axis, row + (uint32_t) width - 1 - x);
      }
}
