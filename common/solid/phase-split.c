/* The lightness between an exemplar's two phases (solid.h), for the
 * E-step's lone-voxel rule (estep.c), and the lower one that bounds the
 * joints for the cell guide (cell-guide.c). A histogram of lightness
 * instead of a sort: exemplars may hold millions of pixels, and this
 * runs per level.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

/* Bins per unit of CIE L (0-100): a tenth of a unit, far below a
 * visible step, so the percentiles are as good as a sort's. */
#define TS_PHASE_BINS_PER_L 10
#define TS_PHASE_BINS (100 * TS_PHASE_BINS_PER_L + 1)
/* Where the joint split lies between the 5th and the 95th percentile.
 * Joints are darker than the darkest stone, so they sit low in the
 * range; midway falls inside the stones' own lightness, and the darkest
 * stones and the others' dark rims count as mortar (thick, grainy
 * joints, no dark stones). A quarter suits mortar that spans about the
 * lowest third of the range, as the cells truth's does: fitted to the
 * bundled exemplars; see docs/design.md, Known limits. */
#define TS_JOINT_SHARE 0.25f

/* The 5th and 95th lightness percentiles of the opaque pixels; false if
 * there are none. */
static bool
percentiles (const TsImage *ex, float *low_out, float *high_out)
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
    return false;
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
  *low_out = low;
  *high_out = high;
  return true;
}

void
ts_solid_splits (const TsImage *ex, float *phase, float *joint)
{
  float low, high;

  if (!percentiles (ex, &low, &high))
    {
      *phase = 50.0f;
      *joint = 25.0f;
      return;
    }
  *phase = 0.5f * (low + high);
  *joint = low + TS_JOINT_SHARE * (high - low);
}
