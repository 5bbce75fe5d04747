/* Wrap/mirror indexing, the E-step's virtual-coordinate tables and the
 * active region of a partly needed output. */
#include "test-util.h"
#include "engine/active-region.h"
#include "engine/indexing.h"
#include "engine/level.h"
#include "engine/pyramid.h"
#include "engine/rng.h"

#include <stdlib.h>

static void
test_wrap_mirror (void)
{
  CHECK (ts_wrap (-1, 5) == 4, "wrap -1");
  CHECK (ts_wrap (5, 5) == 0, "wrap 5");
  CHECK (ts_wrap (-11, 5) == 4, "wrap -11");
  CHECK (ts_mirror (-1, 5) == 1, "mirror -1 -> %zu", ts_mirror (-1, 5));
  CHECK (ts_mirror (5, 5) == 3, "mirror 5 -> %zu", ts_mirror (5, 5));
  CHECK (ts_mirror (-9, 5) == 1, "mirror far -> %zu", ts_mirror (-9, 5));
  CHECK (ts_mirror (7, 1) == 0, "mirror n=1");
  /* Mirrored index is always in range and continuous (steps of 0 or 1). */
  for (size_t n = 1; n < 9; n++)
    for (ptrdiff_t i = -40; i < 40; i++)
      {
        size_t a = ts_mirror (i, n), b = ts_mirror (i + 1, n);
        CHECK (a < n, "mirror in range");
        CHECK (n == 1 || (a > b ? a - b : b - a) == 1, "mirror continuous n=%zu i=%td", n, i);
        CHECK (ts_wrap (i, n) < n && (ts_wrap (i, n) + n - (size_t) ((i % (ptrdiff_t) n + (ptrdiff_t) n) % (ptrdiff_t) n)) % n == 0,
               "wrap matches modulo");
      }
  CHECK (ts_clamp_centre (0, 10, 2) == 2 && ts_clamp_centre (9, 10, 2) == 7 &&
         ts_clamp_centre (5, 10, 2) == 5, "clamp centre");
}

static void
test_virtual_coordinates (void)
{
  for (int wrap = 0; wrap < 2; wrap++)
    for (size_t n = 1; n < 12; n++)
      for (size_t r = 0; r < 6; r++)
        {
          TsAxisGrid g;
          CHECK (ts_axis_grid_init (&g, n, r, 2, 1, wrap) == TS_OK, "grid init");
          CHECK (g.virtual_start[n] == n + 2 * r, "every virtual coordinate listed once");
          for (size_t p = 0; p < n; p++)
            for (size_t v = g.virtual_start[p]; v < g.virtual_start[p + 1]; v++)
              CHECK (ts_border_index (g.virtual_coord[v], n, wrap) == p,
                     "virtual %td maps to %zu", g.virtual_coord[v], p);
          /* Centres cover every real coordinate when spacing <= 2r+1. */
          if (2 * r + 1 >= 2)
            for (size_t p = 0; p < n; p++)
              {
                bool covered = false;
                for (size_t j = 0; j < g.centres; j++)
                  {
                    ptrdiff_t c = ts_axis_grid_centre (&g, j);
                    covered |= (ptrdiff_t) p >= c - (ptrdiff_t) r && (ptrdiff_t) p <= c + (ptrdiff_t) r;
                  }
                CHECK (covered, "coordinate %zu of %zu covered (r=%zu)", p, n, r);
              }
          ts_axis_grid_free (&g);
        }
}

/* Distance along one axis between level coordinates a and b of n,
 * across the wrapped side if wrapping. */
static size_t
axis_distance (size_t a, size_t b, size_t n, bool wrap)
{
  size_t d = a > b ? a - b : b - a;
  return wrap && n - d < d ? n - d : d;
}

/* Both masks against their definition, by brute force: a level pixel is
 * active if a needed output pixel's block lies within 4 radii of it
 * (Chebyshev distance, wrapped where the output wraps), a centre if an
 * active pixel lies within one radius. */
static void
test_active_region (void)
{
  const size_t out_w = 37, out_h = 23;
  uint8_t *needed = malloc (out_w * out_h);
  CHECK (needed != NULL, "allocation");
  if (!needed)
    return;
  for (int trial = 0; trial < 12; trial++)
    {
      size_t level = (size_t) trial % 3, radius = 1 + (size_t) trial % 2;
      bool wrap_x = trial % 4 >= 2, wrap_y = trial % 5 == 0;
      size_t w = ts_level_side (out_w, level), h = ts_level_side (out_h, level);
      TsActiveRegion region;
      uint8_t *down = calloc (w * h, 1);

      /* A few needed pixels, one of them next to a corner. */
      for (size_t p = 0; p < out_w * out_h; p++)
        needed[p] = ts_random_below (ts_random (7, (uint32_t) trial, 0, p, 0), 97) == 0;
      needed[(out_h - 1) * out_w + 1] = 1;
      for (size_t p = 0; down && p < out_w * out_h; p++)
        if (needed[p])
          down[((p / out_w) >> level) * w + ((p % out_w) >> level)] = 1;
      CHECK (ts_active_region_init (&region, needed, out_w, out_h, level, w, h, radius, wrap_x,
                                    wrap_y) == TS_OK && down, "active region %d", trial);
      if (!region.pixels || !down)
        {
          free (down);
          continue;
        }
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          {
            bool active = false, centre = false;
            for (size_t v = 0; v < h; v++)
              for (size_t u = 0; u < w; u++)
                {
                  size_t d = axis_distance (x, u, w, wrap_x), e = axis_distance (y, v, h, wrap_y);
                  size_t cheb = d > e ? d : e;
                  active |= down[v * w + u] && cheb <= 4 * radius;
                  centre |= cheb <= 5 * radius && down[v * w + u];
                }
            CHECK (region.pixels[y * w + x] == active, "trial %d pixel (%zu, %zu) active %d", trial,
                   x, y, active);
            CHECK (region.centres[y * w + x] == centre, "trial %d centre (%zu, %zu) %d", trial, x,
                   y, centre);
          }
      CHECK (ts_active_any (region.pixels, w, h, 0, 0, w, h), "some pixel active");
      ts_active_region_free (&region);
      free (down);
    }
  free (needed);
}

int
main (void)
{
  test_wrap_mirror ();
  test_virtual_coordinates ();
  test_active_region ();
  return test_finish ("test-indexing");
}
