/* The part of an output level worth optimizing when the caller needs
 * only some of the output's pixels.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "active-region.h"

#include <stdlib.h>
#include <string.h>

/* How far from a needed pixel the E-step updates, in window radii: the
 * windows voting for a needed pixel (1) read pixels within 2; theirs
 * are voted for by windows that read within 4. Two radii left the
 * needed regions' coherence up to 1.3x that of the whole box on thin
 * regions; four matched it (docs/guided.md, "Only the needed pixels"). */
#define TS_ACTIVE_RADII 4

/* One axis of a square dilation: out[i] = any of in[i - r .. i + r]
 * (wrapping or clipped), over `count` lines of n values `stride` apart,
 * lines `line` apart. Prefix counts make it O(n) per line whatever r. */
static TsStatus
dilate_axis (const uint8_t *in, uint8_t *out, size_t n, size_t stride, size_t count,
             size_t line, size_t r, bool wrap)
{
  TsStatus status = TS_OK;

#pragma omp parallel
  {
    size_t *prefix = malloc ((n + 1) * sizeof (size_t));
    if (!prefix)
      {
#pragma omp atomic write
        status = TS_ERROR_OUT_OF_MEMORY;
      }
#pragma omp for schedule(static)
    for (ptrdiff_t l = 0; l < (ptrdiff_t) count; l++)
      {
        const uint8_t *a = in + (size_t) l * line;
        uint8_t *b = out + (size_t) l * line;
        if (!prefix)
          continue;
        prefix[0] = 0;
        for (size_t i = 0; i < n; i++)
          prefix[i + 1] = prefix[i] + (a[i * stride] != 0);
        for (size_t i = 0; i < n; i++)
          {
            size_t hits;
            if (wrap && 2 * r + 1 >= n)
              hits = prefix[n];
            else if (wrap)
              {
                /* [i - r, i + r] modulo n: at most two pieces. */
                ptrdiff_t lo = (ptrdiff_t) i - (ptrdiff_t) r, hi = (ptrdiff_t) (i + r);
                hits = prefix[hi < (ptrdiff_t) n ? (size_t) hi + 1 : n] - prefix[lo > 0 ? (size_t) lo : 0];
                if (lo < 0)
                  hits += prefix[n] - prefix[(size_t) ((ptrdiff_t) n + lo)];
                if (hi >= (ptrdiff_t) n)
                  hits += prefix[(size_t) hi - n + 1];
              }
            else
              hits = prefix[i + r + 1 < n ? i + r + 1 : n] - prefix[i > r ? i - r : 0];
            b[i * stride] = hits > 0;
          }
      }
    free (prefix);
  }
  return status;
}

/* Square dilation of `in` (w x h) by r into `out`, via `tmp`. */
static TsStatus
dilate (const uint8_t *in, uint8_t *tmp, uint8_t *out, size_t w, size_t h, size_t r,
        bool wrap_x, bool wrap_y)
{
  TsStatus status = dilate_axis (in, tmp, w, 1, h, w, r, wrap_x);
  if (status == TS_OK)
    status = dilate_axis (tmp, out, h, w, w, 1, r, wrap_y);
  return status;
}

TsStatus
ts_active_region_init (TsActiveRegion *region, const uint8_t *needed, size_t out_w,
                       size_t out_h, size_t level, size_t w, size_t h, size_t radius,
                       bool wrap_x, bool wrap_y)
{
  uint8_t *down = calloc (w * h, 1), *tmp = malloc (w * h);
  TsStatus status = TS_OK;

  region->pixels = malloc (w * h);
  region->centres = malloc (w * h);
  if (!down || !tmp || !region->pixels || !region->centres)
    status = TS_ERROR_OUT_OF_MEMORY;
  /* A level pixel is needed if any output pixel of its block is. */
  for (size_t y = 0; status == TS_OK && y < out_h; y++)
    for (size_t x = 0; x < out_w; x++)
      if (needed[y * out_w + x])
        down[(y >> level) * w + (x >> level)] = 1;
  if (status == TS_OK)
    status = dilate (down, tmp, region->pixels, w, h, TS_ACTIVE_RADII * radius, wrap_x, wrap_y);
  if (status == TS_OK)
    status = dilate (region->pixels, tmp, region->centres, w, h, radius, wrap_x, wrap_y);
  free (down);
  free (tmp);
  if (status != TS_OK)
    ts_active_region_free (region);
  return status;
}

void
ts_active_region_free (TsActiveRegion *region)
{
  free (region->pixels);
  free (region->centres);
  region->pixels = NULL;
  region->centres = NULL;
}

bool
ts_active_any (const uint8_t *mask, size_t w, size_t h, size_t x0, size_t y0, size_t x1,
               size_t y1)
{
  x1 = x1 < w ? x1 : w;
  y1 = y1 < h ? y1 : h;
  for (size_t y = y0; y < y1; y++)
    if (x0 < x1 && memchr (mask + y * w + x0, 1, x1 - x0))
      return true;
  return false;
}
