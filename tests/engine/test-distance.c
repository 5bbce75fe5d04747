/* Exact Euclidean distance transforms: brute force agrees on random
 * grids of one, two and three dimensions, with and without wrapping. */
#include "test-util.h"
#include "engine/distance.h"
#include "engine/rng.h"

#include <math.h>
#include <stdlib.h>

/* The nearest feature's distance by trying every one. */
static float
brute_force (const unsigned char *feature, const size_t dims[3], const bool wrap[3], size_t at)
{
  size_t count = dims[0] * dims[1] * dims[2];
  double best = INFINITY;

  for (size_t q = 0; q < count; q++)
    {
      if (!feature[q])
        continue;
      double d2 = 0.0;
      size_t a_at = at, a_q = q;
      for (int a = 0; a < 3; a++)
        {
          double d = fabs ((double) (a_at % dims[a]) - (double) (a_q % dims[a]));
          if (wrap[a])
            d = fmin (d, (double) dims[a] - d);
          d2 += d * d;
          a_at /= dims[a];
          a_q /= dims[a];
        }
      best = fmin (best, d2);
    }
  return isinf (best) ? TS_DISTANCE_FAR : (float) sqrt (best);
}

static void
check_grid (const size_t dims[3], const bool wrap[3], unsigned share_per_1000, uint32_t seed)
{
  size_t count = dims[0] * dims[1] * dims[2], wrong = 0;
  unsigned char *feature = malloc (count);
  float *grid = malloc (count * sizeof (float));

  CHECK (feature && grid, "memory");
  if (!feature || !grid)
    {
      free (feature);
      free (grid);
      return;
    }
  for (size_t i = 0; i < count; i++)
    {
      feature[i] = ts_random_below (ts_random (seed, 0, 0, i, 1), 1000) < share_per_1000;
      grid[i] = feature[i] ? 0.0f : TS_DISTANCE_FAR;
    }
  CHECK (ts_distance_transform (grid, dims, wrap) == TS_OK, "transform");
  for (size_t i = 0; i < count; i++)
    {
      float expected = brute_force (feature, dims, wrap, i);
      if (!(fabsf (grid[i] - expected) <= 1e-4f * fmaxf (1.0f, expected)))
        wrong++;
    }
  CHECK (wrong == 0, "%zux%zux%zu (wrap %d%d%d, %u per 1000 features): %zu of %zu distances wrong",
         dims[0], dims[1], dims[2], wrap[0], wrap[1], wrap[2], share_per_1000, wrong, count);
  free (feature);
  free (grid);
}

int
main (void)
{
  static const size_t shapes[][3] = { { 37, 1, 1 }, { 23, 17, 1 }, { 11, 9, 13 }, { 16, 16, 16 } };
  static const bool wraps[][3] = { { false, false, false }, { true, true, true }, { true, false, true } };

  for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; s++)
    for (size_t w = 0; w < sizeof wraps / sizeof wraps[0]; w++)
      {
        check_grid (shapes[s], wraps[w], 20, (uint32_t) (s * 10 + w));
        check_grid (shapes[s], wraps[w], 300, (uint32_t) (s * 10 + w + 100));
      }
  /* No feature at all: every sample stays far. */
  size_t dims[3] = { 5, 4, 3 };
  bool wrap[3] = { true, true, true };
  float grid[60];
  for (size_t i = 0; i < 60; i++)
    grid[i] = TS_DISTANCE_FAR;
  CHECK (ts_distance_transform (grid, dims, wrap) == TS_OK, "transform without features");
  bool far = true;
  for (size_t i = 0; i < 60; i++)
    far = far && grid[i] == TS_DISTANCE_FAR;
  CHECK (far, "without features every sample stays TS_DISTANCE_FAR");
  return test_finish ("test-distance");
}
