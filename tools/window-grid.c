/* Window grids (gather, SSD) and their PCA basis.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "window-grid.h"
#include "engine/rng.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PCA_SAMPLES 4096      /* windows used to estimate the covariance */
#define PCA_ITERATIONS 24     /* subspace iterations (speed, not exactness) */

size_t
ts_grid_dims (const TsWindowGrid *grid)
{
  size_t side = 2 * (size_t) grid->radius + 1;
  return 3 * side * side;
}

size_t
ts_grid_count (const TsWindowGrid *grid)
{
  return grid->nx * grid->ny;
}

void
ts_grid_centre (const TsWindowGrid *grid, size_t i, size_t *x, size_t *y)
{
  *x = grid->x0 + (i % grid->nx) * grid->step;
  *y = grid->y0 + (i / grid->nx) * grid->step;
}

/* Column (or row) of window offset d around centre c on an axis of n
 * pixels; |d| < n, so one correction is enough when wrapping. */
static size_t
axis_index (size_t c, int d, size_t n)
{
  ptrdiff_t i = (ptrdiff_t) c + d;
  if (i < 0)
    i += (ptrdiff_t) n;
  else if (i >= (ptrdiff_t) n)
    i -= (ptrdiff_t) n;
  return (size_t) i;
}

/* Pixel columns of a window; true if they are consecutive (no wrap). */
static bool
window_columns (const TsWindowGrid *grid, size_t cx, size_t *cols)
{
  int r = grid->radius;
  size_t w = grid->image->width;
  for (int d = -r; d <= r; d++)
    cols[d + r] = axis_index (cx, d, w);
  return cols[2 * r] > cols[0];
}

void
ts_grid_gather (const TsWindowGrid *grid, size_t i, float *vec)
{
  const TsImage *im = grid->image;
  size_t cx, cy, cols[2 * TS_SEARCH_MAX_RADIUS + 1];
  int r = grid->radius;

  ts_grid_centre (grid, i, &cx, &cy);
  window_columns (grid, cx, cols);
  for (int dy = -r; dy <= r; dy++)
    {
      const float *row = im->pixels + axis_index (cy, dy, im->height) * im->width * TS_CHANNELS;
      for (int dx = -r; dx <= r; dx++)
        {
          const float *p = row + cols[dx + r] * TS_CHANNELS;
          *vec++ = p[0];
          *vec++ = p[1];
          *vec++ = p[2];
        }
    }
}

float
ts_grid_ssd (const float *vec, const TsWindowGrid *grid, size_t i, float limit)
{
  const TsImage *im = grid->image;
  size_t cx, cy, cols[2 * TS_SEARCH_MAX_RADIUS + 1];
  int r = grid->radius, side = 2 * r + 1;
  float sum = 0.0f;
  bool contiguous;

  ts_grid_centre (grid, i, &cx, &cy);
  contiguous = window_columns (grid, cx, cols);
  for (int dy = -r; dy <= r; dy++)
    {
      const float *row = im->pixels + axis_index (cy, dy, im->height) * im->width * TS_CHANNELS;
      float rs = 0.0f;
      if (contiguous)
        {
          const float *p = row + cols[0] * TS_CHANNELS;
          for (int k = 0; k < side; k++, p += TS_CHANNELS, vec += 3)
            {
              float d0 = vec[0] - p[0], d1 = vec[1] - p[1], d2 = vec[2] - p[2];
              rs += d0 * d0 + d1 * d1 + d2 * d2;
            }
        }
      else
        for (int k = 0; k < side; k++, vec += 3)
          {
            const float *p = row + cols[k] * TS_CHANNELS;
            float d0 = vec[0] - p[0], d1 = vec[1] - p[1], d2 = vec[2] - p[2];
            rs += d0 * d0 + d1 * d1 + d2 * d2;
          }
      sum += rs;
      if (sum > limit)
        return sum;
    }
  return sum;
}

/* Orthonormalises the first `head` columns of q (dims x stride) by
 * modified Gram-Schmidt, twice for accuracy; a column that vanishes
 * (rank-deficient data, e.g. a flat image) is replaced by a unit vector.
 * Orthonormality is what the lower bound relies on. */
static void
orthonormalise (double *q, size_t dims, size_t head, size_t stride)
{
  size_t next_unit = 0;
  for (size_t k = 0; k < head; k++)
    for (size_t attempt = 0;; attempt++)
      {
        double norm = 0.0;
        for (int pass = 0; pass < 2; pass++)
          for (size_t j = 0; j < k; j++)
            {
              double dot = 0.0;
              for (size_t i = 0; i < dims; i++)
                dot += q[i * stride + j] * q[i * stride + k];
              for (size_t i = 0; i < dims; i++)
                q[i * stride + k] -= dot * q[i * stride + j];
            }
        for (size_t i = 0; i < dims; i++)
          norm += q[i * stride + k] * q[i * stride + k];
        norm = sqrt (norm);
        if (norm > 1e-9 || attempt > dims)
          {
            for (size_t i = 0; i < dims; i++)
              q[i * stride + k] /= norm;
            break;
          }
        for (size_t i = 0; i < dims; i++)
          q[i * stride + k] = i == next_unit % dims ? 1.0 : 0.0;
        next_unit++;
      }
}

bool
ts_grid_pca (const TsWindowGrid *grid, size_t head, size_t stride, double *mean,
             double *basis)
{
  size_t dims = ts_grid_dims (grid), n = ts_grid_count (grid);
  size_t step = n > PCA_SAMPLES ? n / PCA_SAMPLES : 1;
  size_t samples = 0;
  double *cov = calloc (dims * dims, sizeof (double));
  double *z = calloc (dims * stride, sizeof (double));
  float *vec = malloc (dims * sizeof (float));
  uint32_t state = 12345u;

  if (!cov || !z || !vec)
    {
      free (cov), free (z), free (vec);
      return false;
    }
  for (size_t s = 0; s < n; s += step, samples++)
    {
      ts_grid_gather (grid, s, vec);
      for (size_t i = 0; i < dims; i++)
        mean[i] += vec[i];
    }
  for (size_t i = 0; i < dims; i++)
    mean[i] /= (double) samples;
  for (size_t s = 0; s < n; s += step)
    {
      ts_grid_gather (grid, s, vec);
      for (size_t i = 0; i < dims; i++)
        {
          double ci = vec[i] - mean[i];
          for (size_t j = 0; j <= i; j++)
            cov[i * dims + j] += ci * (vec[j] - mean[j]);
        }
    }
  for (size_t i = 0; i < dims; i++)
    for (size_t j = 0; j < i; j++)
      cov[j * dims + i] = cov[i * dims + j];

  /* Fixed pseudo-random start: same basis on every run. */
  for (size_t i = 0; i < dims; i++)
    for (size_t k = 0; k < head; k++)
      {
        basis[i * stride + k] = (double) ts_lcg_next24 (&state) / 16777216.0 - 0.5;
      }
  orthonormalise (basis, dims, head, stride);
  for (int it = 0; it < PCA_ITERATIONS; it++)
    {
      memset (z, 0, dims * stride * sizeof (double));
      for (size_t i = 0; i < dims; i++)
        for (size_t j = 0; j < dims; j++)
          {
            double c = cov[i * dims + j];
            for (size_t k = 0; k < head; k++)
              z[i * stride + k] += c * basis[j * stride + k];
          }
      orthonormalise (z, dims, head, stride);
      memcpy (basis, z, dims * stride * sizeof (double));
    }
  free (cov), free (z), free (vec);
  return true;
}
