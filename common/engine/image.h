/* Allocation and copying of engine images (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_IMAGE_H
#define TS_IMAGE_H

#include "texsynth.h"

#include <math.h>

/* Weight of alpha against Lab in every distance: the engine's working
 * images store alpha * TS_ALPHA_SCALE in channel 3, so a fully transparent
 * vs. opaque difference costs as much as black vs. white. */
#define TS_ALPHA_SCALE 100.0f

/* Allocates width*height pixels (zeroed); overflow-checked. */
TsStatus ts_image_alloc (TsImage *image, size_t width, size_t height);
void     ts_image_free (TsImage *image);
size_t   ts_image_pixel_count (const TsImage *image);

static inline float *
ts_image_pixel (const TsImage *image, size_t x, size_t y)
{
  return image->pixels + (y * image->width + x) * TS_CHANNELS;
}

/* One pixel as the engine reads an exemplar: non-finite values (from
 * float files) 0, alpha clamped to [0, 1]. */
static inline void
ts_pixel_readable (float *pixel)
{
  for (int c = 0; c < TS_CHANNELS; c++)
    if (!isfinite (pixel[c]))
      pixel[c] = 0.0f;
  pixel[3] = pixel[3] < 0.0f ? 0.0f : pixel[3] > 1.0f ? 1.0f : pixel[3];
}

/* Working copy: each pixel as ts_pixel_readable makes it, channel 3
 * scaled by TS_ALPHA_SCALE. */
TsStatus ts_image_to_working (const TsImage *in, TsImage *out);
/* Inverse of ts_image_to_working, in place into an allocated `out`. */
void     ts_image_from_working (const TsImage *in, TsImage *out);

/* Multiplication of sizes with overflow detection (false on overflow). */
static inline int
ts_size_mul (size_t a, size_t b, size_t *out)
{
  if (a != 0 && b > (size_t) -1 / a)
    return 0;
  *out = a * b;
  return 1;
}

#endif
