/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

TsStatus
ts_image_alloc (TsImage *image, size_t width, size_t height)
{
  size_t pixels, floats;

  image->width = 0;
  image->height = 0;
  image->pixels = NULL;
  if (!ts_size_mul (width, height, &pixels) ||
      !ts_size_mul (pixels, TS_CHANNELS, &floats) ||
      floats > (size_t) -1 / sizeof (float))
    return TS_ERROR_TOO_LARGE;
  image->pixels = calloc (floats > 0 ? floats : 1, sizeof (float));
  if (!image->pixels)
    return TS_ERROR_OUT_OF_MEMORY;
  image->width = width;
  image->height = height;
  return TS_OK;
}

void
ts_image_free (TsImage *image)
{
  if (!image)
    return;
  free (image->pixels);
  image->pixels = NULL;
  image->width = 0;
  image->height = 0;
}

size_t
ts_image_pixel_count (const TsImage *image)
{
  return image->width * image->height;
}

TsStatus
ts_image_to_working (const TsImage *in, TsImage *out)
{
  TsStatus status = ts_image_alloc (out, in->width, in->height);
  size_t n;

  if (status != TS_OK)
    return status;
  n = ts_image_pixel_count (in);
  memcpy (out->pixels, in->pixels, n * TS_CHANNELS * sizeof (float));
  /* NaN/Inf from float files would poison every distance; alpha out of
   * [0, 1] (float files allow it) would be copied into the result as it
   * is and weigh more than colour in every distance. */
  for (size_t i = 0; i < n; i++)
    {
      ts_pixel_readable (out->pixels + i * TS_CHANNELS);
      out->pixels[i * TS_CHANNELS + 3] *= TS_ALPHA_SCALE;
    }
  return TS_OK;
}

void
ts_image_from_working (const TsImage *in, TsImage *out)
{
  size_t n = ts_image_pixel_count (in);

  memcpy (out->pixels, in->pixels, n * TS_CHANNELS * sizeof (float));
  for (size_t i = 0; i < n; i++)
    out->pixels[i * TS_CHANNELS + 3] /= TS_ALPHA_SCALE;
}
