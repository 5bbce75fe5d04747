/* Sums of squared differences of Lab+alpha values (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SSD_H
#define TS_SSD_H

#include <stddef.h>
#include <string.h>

/* Four independent lanes (one per channel) vectorise without reassociation;
 * every partial total uses the same combination as the final one, so a
 * partial total never exceeds the full distance (rounding is monotone). */
#define TS_LANES_TOTAL(acc) (((acc)[0] + (acc)[1]) + ((acc)[2] + (acc)[3]))

static inline void
ts_lanes_add (float *acc, const float *a, const float *b, size_t count)
{
  for (size_t i = 0; i < count; i += 4)
    for (size_t c = 0; c < 4; c++)
      {
        float d = a[i + c] - b[i + c];
        acc[c] += d * d;
      }
}

/* Sum of squared differences of `pixels` four-channel pixels, for the
 * M-steps' patch rows. Even and odd pixels add into two sets of lanes:
 * two independent chains of additions, where one would be bound by the
 * adds' latency. Any row gives the same total wherever it is used. */
#if defined(__GNUC__)
/* A pair of pixels, and one pixel, as vectors (GCC and clang): lane-wise
 * arithmetic, the same values as with single floats, whether the target
 * has 8- or 4-float registers. */
typedef float TsPixelPairLanes __attribute__ ((vector_size (8 * sizeof (float))));
typedef float TsPixelLanes __attribute__ ((vector_size (4 * sizeof (float))));

static inline float
ts_pixels_ssd (const float *a, const float *b, size_t pixels)
{
  TsPixelPairLanes pair = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f };
  TsPixelLanes even, odd, last;
  size_t i = 0;

  for (; i + 1 < pixels; i += 2)
    {
      TsPixelPairLanes pa, pb, d;
      memcpy (&pa, a + 4 * i, sizeof pa);
      memcpy (&pb, b + 4 * i, sizeof pb);
      d = pa - pb;
      pair += d * d;
    }
  even = (TsPixelLanes) { pair[0], pair[1], pair[2], pair[3] };
  odd = (TsPixelLanes) { pair[4], pair[5], pair[6], pair[7] };
  if (i < pixels)
    {
      TsPixelLanes la, lb;
      memcpy (&la, a + 4 * i, sizeof la);
      memcpy (&lb, b + 4 * i, sizeof lb);
      last = la - lb;
      even += last * last;
    }
  even += odd;
  return (even[0] + even[1]) + (even[2] + even[3]);
}
#else
static inline float
ts_pixels_ssd (const float *a, const float *b, size_t pixels)
{
  float even[4] = { 0.0f, 0.0f, 0.0f, 0.0f }, odd[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  size_t i = 0;

  for (; i + 1 < pixels; i += 2)
    {
      ts_lanes_add (even, a + 4 * i, b + 4 * i, 4);
      ts_lanes_add (odd, a + 4 * i + 4, b + 4 * i + 4, 4);
    }
  if (i < pixels)
    ts_lanes_add (even, a + 4 * i, b + 4 * i, 4);
  for (size_t c = 0; c < 4; c++)
    even[c] += odd[c];
  return TS_LANES_TOTAL (even);
}
#endif

#endif
