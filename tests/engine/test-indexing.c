/* Wrap/mirror indexing and the E-step's virtual-coordinate tables. */
#include "test-util.h"
#include "engine/indexing.h"
#include "engine/level.h"

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

int
main (void)
{
  test_wrap_mirror ();
  test_virtual_coordinates ();
  return test_finish ("test-indexing");
}
