/* Seam figures across the wrap and interior lines (seam-planes.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "seam-planes.h"
#include "metrics.h"
#include "slice-figures.h"

#include <stdlib.h>
#include <string.h>

/* `in` rolled by `shift` along both axes into `out`: the lines at
 * n - shift move to the wrap. */
static void
roll (const TsImage *in, size_t shift, TsImage *out)
{
  size_t n = in->width;

  for (size_t v = 0; v < n; v++)
    for (size_t u = 0; u < n; u++)
      memcpy (out->pixels + (((v + shift) % n) * n + (u + shift) % n) * TS_CHANNELS,
              in->pixels + (v * n + u) * TS_CHANNELS, TS_CHANNELS * sizeof (float));
}

bool
seam_planes (const TsImage *exemplar, const float *volume, size_t n, double planes[SEAM_PLANES])
{
  TsImage slice = { n, n, malloc (n * n * TS_CHANNELS * sizeof (float)) };
  TsImage rolled = { n, n, malloc (n * n * TS_CHANNELS * sizeof (float)) };
  bool ok = slice.pixels && rolled.pixels;

  for (int k = 0; k < SEAM_PLANES; k++)
    planes[k] = 0.0;
  /* The slices slice_figures takes its seam on. */
  for (int axis = 0; axis < 3 && ok; axis++)
    for (size_t s = 0; s < SLICE_SEAM_SLICES && ok; s++)
      {
        slice_cut (volume, n, axis, (2 * s + 1) * n / (2 * SLICE_SEAM_SLICES), &slice);
        for (size_t k = 0; k < SEAM_PLANES && ok; k++)
          {
            double coherence, seam;
            roll (&slice, k * n / SEAM_PLANES, &rolled);
            ok = ts_measure_coherence (exemplar, &rolled, true, true, &coherence, &seam)
                 == TS_MEASURE_OK;
            planes[k] += seam / (3.0 * SLICE_SEAM_SLICES);
          }
      }
  free (slice.pixels);
  free (rolled.pixels);
  return ok;
}
