/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide-blur.h"
#include "indexing.h"

#include <math.h>
#include <stdlib.h>

/* One pass along rows (`across`) or columns of channel 0. */
static void
blur_pass (const float *in, float *out, size_t w, size_t h, const double *kernel, int radius,
           bool across)
{
#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double s = 0.0;
        for (int k = -radius; k <= radius; k++)
          {
            size_t sx = across ? ts_mirror ((ptrdiff_t) x + k, w) : x;
            size_t sy = across ? (size_t) y : ts_mirror (y + k, h);
            s += kernel[k + radius] * in[(sy * w + sx) * TS_CHANNELS];
          }
        out[((size_t) y * w + x) * TS_CHANNELS] = (float) s;
      }
}

TsStatus
ts_guide_blur (TsImage *image, double sigma)
{
  size_t w = image->width, h = image->height;
  int radius = (int) ceil (3.0 * sigma);
  double *kernel = malloc ((size_t) (2 * radius + 1) * sizeof (double)), total = 0.0;
  float *tmp = malloc (w * h * TS_CHANNELS * sizeof (float));

  if (!kernel || !tmp)
    {
      free (kernel);
      free (tmp);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (int k = -radius; k <= radius; k++)
    total += kernel[k + radius] = exp (-0.5 * k * k / (sigma * sigma));
  for (int k = 0; k <= 2 * radius; k++)
    kernel[k] /= total;
  blur_pass (image->pixels, tmp, w, h, kernel, radius, true);
  blur_pass (tmp, image->pixels, w, h, kernel, radius, false);
  free (kernel);
  free (tmp);
  return TS_OK;
}
