/* Border handling for neighbourhood indexing (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_INDEXING_H
#define TS_INDEXING_H

#include <stddef.h>

/* Wrap-around index in [0, n): tileable outputs. */
static inline size_t
ts_wrap (ptrdiff_t i, size_t n)
{
  ptrdiff_t m = i % (ptrdiff_t) n;
  return (size_t) (m < 0 ? m + (ptrdiff_t) n : m);
}

/* Mirror index without repeating the edge pixel (…2 1 0 1 2…), for any
 * i, also far outside [0, n). */
static inline size_t
ts_mirror (ptrdiff_t i, size_t n)
{
  if (n == 1)
    return 0;
  ptrdiff_t period = 2 * ((ptrdiff_t) n - 1);
  ptrdiff_t m = i % period;
  if (m < 0)
    m += period;
  return (size_t) (m < (ptrdiff_t) n ? m : period - m);
}

static inline size_t
ts_border_index (ptrdiff_t i, size_t n, int wrap)
{
  return wrap ? ts_wrap (i, n) : ts_mirror (i, n);
}

/* Clamps a neighbourhood centre so a window of radius r lies inside
 * [0, n); n must be > 2r. */
static inline size_t
ts_clamp_centre (ptrdiff_t c, size_t n, size_t r)
{
  if (c < (ptrdiff_t) r)
    return r;
  if (c > (ptrdiff_t) (n - 1 - r))
    return n - 1 - r;
  return (size_t) c;
}

#endif
