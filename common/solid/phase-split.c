/* The lightness between an exemplar's two phases (solid.h), for the
 * E-step's lone-voxel rule (estep.c). A histogram of lightness instead of
 * a sort: exemplars may hold millions of pixels, and this runs per level.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

/* Bins per unit of CIE L (0-100). */
#define TS_PHASE_BINS_PER_L 10
#define TS_PHASE_BINS (100 * TS_PHASE_BINS_PER_L + 1)

float
ts_solid_phase_split (const TsImage *ex)
{
  size_t count[TS_PHASE_BINS] = { 0 }, opaque = 0, below = 0;
  size_t pixels = ts_image_pixel_count (ex);
  float low = 0.0f, high = 100.0f;
  bool low_found = false;

  for (size_t i = 0; i < pixels; i++)
    {
      const float *p = ex->pixels + i * TS_CHANNELS;
      float bin = p[0] * (float) TS_PHASE_BINS_PER_L;
      if (!(p[3] > 0.0f))
        continue;
      /* Out-of-range and NaN lightness go to the end bins. */
      bin = bin > 0.0f ? bin : 0.0f;
      bin = bin < (float) (TS_PHASE_BINS - 1) ? bin : (float) (TS_PHASE_BINS - 1);
      count[(size_t) bin]++;
      opaque++;
    }
  if (opaque == 0)
    return 50.0f;
  for (size_t b = 0; b < TS_PHASE_BINS; b++)
    {
      below += count[b];
      if (!low_found && below > opaque / 20)
        {
          low = (float) b / (float) TS_PHASE_BINS_PER_L;
          low_found = true;
        }
      if (below > opaque - 1 - opaque / 20)
        {
          high = (float) b / (float) TS_PHASE_BINS_PER_L;
          break;
        }
    }
  return 0.5f * (low + high);
}
