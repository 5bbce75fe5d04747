/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "pyramid.h"
#include "indexing.h"

#include <stdlib.h>
#include <string.h>

static const float binomial5[5] = { 1.0f / 16, 4.0f / 16, 6.0f / 16, 4.0f / 16, 1.0f / 16 };

size_t
ts_pyramid_depth_for (size_t width, size_t height, size_t coarsest_side)
{
  size_t side = width < height ? width : height;
  size_t levels = 1;

  /* Halve while the result stays closer to the target than the current. */
  while (side / 2 >= coarsest_side - coarsest_side / 4 && side > coarsest_side)
    {
      side = (side + 1) / 2;
      levels++;
    }
  return levels;
}

/* Alpha-weighted separable filter of one channel set at (x, y) of `in`,
 * sampled horizontally (pass 1) into a temporary of full height. */
TsStatus
ts_pyramid_reduce (const TsImage *in, TsImage *out)
{
  size_t ow = (in->width + 1) / 2, oh = (in->height + 1) / 2;
  TsImage tmp; /* horizontally filtered, premultiplied, ow x in->height */
  TsStatus status;

  status = ts_image_alloc (&tmp, ow, in->height);
  if (status != TS_OK)
    return status;
  status = ts_image_alloc (out, ow, oh);
  if (status != TS_OK)
    {
      ts_image_free (&tmp);
      return status;
    }

#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) in->height; y++)
    for (size_t x = 0; x < ow; x++)
      {
        float acc[4] = { 0, 0, 0, 0 };
        for (int t = 0; t < 5; t++)
          {
            size_t sx = ts_mirror ((ptrdiff_t) (2 * x) + t - 2, in->width);
            const float *p = ts_image_pixel (in, sx, (size_t) y);
            float wa = binomial5[t] * p[3];
            acc[0] += wa * p[0];
            acc[1] += wa * p[1];
            acc[2] += wa * p[2];
            acc[3] += wa;
          }
        memcpy (ts_image_pixel (&tmp, x, (size_t) y), acc, sizeof acc);
      }

#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) oh; y++)
    for (size_t x = 0; x < ow; x++)
      {
        float acc[4] = { 0, 0, 0, 0 };
        for (int t = 0; t < 5; t++)
          {
            size_t sy = ts_mirror (2 * y + t - 2, in->height);
            const float *p = ts_image_pixel (&tmp, x, sy);
            for (int c = 0; c < 4; c++)
              acc[c] += binomial5[t] * p[c];
          }
        float *o = ts_image_pixel (out, x, (size_t) y);
        if (acc[3] > 1e-6f)
          {
            o[0] = acc[0] / acc[3];
            o[1] = acc[1] / acc[3];
            o[2] = acc[2] / acc[3];
          }
        else
          {
            /* Fully transparent: keep the unweighted colour of the source
             * pixel so the value stays defined. */
            const float *p = ts_image_pixel (in, 2 * x, 2 * (size_t) y);
            o[0] = p[0];
            o[1] = p[1];
            o[2] = p[2];
          }
        o[3] = acc[3];
      }

  ts_image_free (&tmp);
  return TS_OK;
}

TsStatus
ts_pyramid_build (const TsImage *base, size_t levels, TsPyramid *pyramid)
{
  TsStatus status;

  pyramid->levels = 0;
  pyramid->level = calloc (levels ? levels : 1, sizeof (TsImage));
  if (!pyramid->level)
    return TS_ERROR_OUT_OF_MEMORY;

  status = ts_image_alloc (&pyramid->level[0], base->width, base->height);
  if (status != TS_OK)
    {
      ts_pyramid_free (pyramid);
      return status;
    }
  memcpy (pyramid->level[0].pixels, base->pixels,
          ts_image_pixel_count (base) * TS_CHANNELS * sizeof (float));
  pyramid->levels = 1;

  for (size_t l = 1; l < levels; l++)
    {
      status = ts_pyramid_reduce (&pyramid->level[l - 1], &pyramid->level[l]);
      if (status != TS_OK)
        {
          ts_pyramid_free (pyramid);
          return status;
        }
      pyramid->levels = l + 1;
    }
  return TS_OK;
}

void
ts_pyramid_free (TsPyramid *pyramid)
{
  if (!pyramid)
    return;
  for (size_t l = 0; l < pyramid->levels; l++)
    ts_image_free (&pyramid->level[l]);
  free (pyramid->level);
  pyramid->level = NULL;
  pyramid->levels = 0;
}
