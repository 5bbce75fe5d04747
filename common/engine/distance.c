/* Exact Euclidean distance transforms: one pass of the 1D squared
 * transform per axis (the lower envelope of parabolas), then the root.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "engine/distance.h"

#include <math.h>
#include <stdlib.h>

typedef struct
{
  double *f, *d, *z;
  size_t *v;
} Scratch;

/* Where the parabolas of samples q and p of f meet. */
static double
intersection (const double *f, size_t q, size_t p)
{
  double a = (double) q, b = (double) p;
  return ((f[q] + a * a) - (f[p] + b * b)) / (2.0 * a - 2.0 * b);
}

/* The 1D squared distance transform of s->f into s->d (n samples). */
static void
distance_1d (Scratch *s, size_t n)
{
  size_t k = 0;

  s->v[0] = 0;
  s->z[0] = -INFINITY;
  s->z[1] = INFINITY;
  for (size_t q = 1; q < n; q++)
    {
      double x = intersection (s->f, q, s->v[k]);
      /* z[0] is -infinity, so k never goes below 0. */
      while (x <= s->z[k])
        x = intersection (s->f, q, s->v[--k]);
      k++;
      s->v[k] = q;
      s->z[k] = x;
      s->z[k + 1] = INFINITY;
    }
  k = 0;
  for (size_t q = 0; q < n; q++)
    {
      while (s->z[k + 1] < (double) q)
        k++;
      double t = (double) q - (double) s->v[k];
      s->d[q] = t * t + s->f[s->v[k]];
    }
}

/* Squared transform along one line of n samples `stride` apart; a
 * wrapping line runs over three periods and keeps the middle one. */
static void
distance_line (float *line, size_t n, size_t stride, bool wrap, Scratch *s)
{
  size_t copies = wrap ? 3 : 1, m = n * copies;

  for (size_t i = 0; i < m; i++)
    s->f[i] = line[(i % n) * stride];
  distance_1d (s, m);
  for (size_t i = 0; i < n; i++)
    {
      double d = s->d[(copies / 2) * n + i];
      line[i * stride] = d < TS_DISTANCE_FAR ? (float) d : TS_DISTANCE_FAR;
    }
}

TsStatus
ts_distance_transform (float *grid, const size_t dims[3], const bool wrap[3])
{
  size_t count = dims[0] * dims[1] * dims[2], longest = 0;
  Scratch s;

  for (int a = 0; a < 3; a++)
    longest = 3 * dims[a] > longest ? 3 * dims[a] : longest;
  s.f = malloc (longest * sizeof (double));
  s.d = malloc (longest * sizeof (double));
  s.z = malloc ((longest + 1) * sizeof (double));
  s.v = malloc (longest * sizeof (size_t));
  if (!s.f || !s.d || !s.z || !s.v)
    {
      free (s.f), free (s.d), free (s.z), free (s.v);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (int a = 0; a < 3; a++)
    {
      size_t n = dims[a], stride = a == 0 ? 1 : a == 1 ? dims[0] : dims[0] * dims[1];
      if (n < 2)
        continue;
      /* Lines start at every sample whose coordinate along `a` is 0. */
      for (size_t start = 0; start < count; start++)
        if (start / stride % n == 0)
          distance_line (grid + start, n, stride, wrap[a], &s);
    }
  for (size_t i = 0; i < count; i++)
    if (grid[i] < TS_DISTANCE_FAR)
      grid[i] = sqrtf (grid[i]);
  free (s.f), free (s.d), free (s.z), free (s.v);
  return TS_OK;
}
