/* Sums of squared differences of Lab+alpha values (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SSD_H
#define TS_SSD_H

#include <stddef.h>

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

#endif
