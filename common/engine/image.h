/* Allocation and copying of engine images (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_IMAGE_H
#define TS_IMAGE_H

#include "texsynth.h"

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

/* Working copy: channel 3 scaled by TS_ALPHA_SCALE. */
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
