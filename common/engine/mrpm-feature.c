/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "mrpm-feature.h"
#include "clones.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PCA_SAMPLES 256    /* covariance estimate: enough for <= 32 axes */
#define PCA_OVERSAMPLE 4   /* extra block columns speed up convergence   */
/* Simultaneous-iteration steps: with the oversampled block a few
 * suffice for the leading axes a feature keeps. */
#define PCA_ITERATIONS 4


void
ts_mrpm_feature_setup (const TsPyramid *pyramid, size_t level, size_t patch_size,
                       size_t levels_compared, TsMrpmFeature *f)
{
  const TsImage *im = &pyramid->level[level];
  size_t side = im->width < im->height ? im->width : im->height;
  size_t r = patch_size / 2;

  if (side <= 2 * r)
    r = (side - 1) / 2; /* tiny level: shrink rather than fail */
  f->r = r;
  f->rc = (r + 1) / 2;
  f->nlev = levels_compared < 1 ? 1 : levels_compared > 3 ? 3 : levels_compared;
  if (f->nlev > pyramid->levels - level)
    f->nlev = pyramid->levels - level;
  for (size_t j = 0; j < 3; j++)
    f->img[j] = j < f->nlev ? &pyramid->level[level + j] : NULL;
  f->dims = (2 * r + 1) * (2 * r + 1) * TS_CHANNELS
            + (f->nlev - 1) * (2 * f->rc + 1) * (2 * f->rc + 1) * TS_CHANNELS;
}

static inline size_t
clamp_index (ptrdiff_t i, size_t n)
{
  return i < 0 ? 0 : i >= (ptrdiff_t) n ? n - 1 : (size_t) i;
}

void
ts_mrpm_feature_extract (const TsMrpmFeature *f, size_t x, size_t y, float *out)
{
  const TsImage *im = f->img[0];
  size_t side = 2 * f->r + 1;

  for (size_t dy = 0; dy < side; dy++, out += side * TS_CHANNELS)
    memcpy (out, ts_image_pixel (im, x - f->r, y - f->r + dy), side * TS_CHANNELS * sizeof (float));
  for (size_t j = 1; j < f->nlev; j++)
    {
      const TsImage *c = f->img[j];
      ptrdiff_t cx = (ptrdiff_t) (x >> j), cy = (ptrdiff_t) (y >> j), rc = (ptrdiff_t) f->rc;
      for (ptrdiff_t dy = -rc; dy <= rc; dy++)
        for (ptrdiff_t dx = -rc; dx <= rc; dx++, out += TS_CHANNELS)
          memcpy (out, ts_image_pixel (c, clamp_index (cx + dx, c->width), clamp_index (cy + dy, c->height)),
                  TS_CHANNELS * sizeof (float));
    }
}

/* Exact squared feature distance; may stop early with a value > bound.
 * Coarse windows away from the border are read row by row; the clamped
 * path adds the same terms in the same order, so results are identical. */
TS_VECTOR_CLONES float
ts_mrpm_feature_distance (const TsMrpmFeature *f, size_t ax, size_t ay, size_t bx, size_t by, float bound)
{
  const TsImage *im = f->img[0];
  size_t side = 2 * f->r + 1, stride = im->width * TS_CHANNELS;
  const float *pa = ts_image_pixel (im, ax - f->r, ay - f->r);
  const float *pb = ts_image_pixel (im, bx - f->r, by - f->r);
  float acc[4] = { 0, 0, 0, 0 };

  for (size_t dy = 0; dy < side; dy++, pa += stride, pb += stride)
    {
      ts_lanes_add (acc, pa, pb, side * TS_CHANNELS);
      if (TS_LANES_TOTAL (acc) > bound)
        return TS_LANES_TOTAL (acc);
    }
  for (size_t j = 1; j < f->nlev; j++)
    {
      const TsImage *c = f->img[j];
      size_t rc = f->rc, cside = 2 * rc + 1;
      size_t cax = ax >> j, cay = ay >> j, cbx = bx >> j, cby = by >> j;
      size_t lo = cax < cbx ? cax : cbx, hi = cax > cbx ? cax : cbx;
      size_t loy = cay < cby ? cay : cby, hiy = cay > cby ? cay : cby;
      if (lo >= rc && loy >= rc && hi + rc < c->width && hiy + rc < c->height)
        {
          const float *qa = ts_image_pixel (c, cax - rc, cay - rc);
          const float *qb = ts_image_pixel (c, cbx - rc, cby - rc);
          for (size_t dy = 0; dy < cside; dy++, qa += c->width * TS_CHANNELS, qb += c->width * TS_CHANNELS)
            ts_lanes_add (acc, qa, qb, cside * TS_CHANNELS);
        }
      else
        for (ptrdiff_t dy = -(ptrdiff_t) rc; dy <= (ptrdiff_t) rc; dy++)
          {
            size_t ya = clamp_index ((ptrdiff_t) cay + dy, c->height);
            size_t yb = clamp_index ((ptrdiff_t) cby + dy, c->height);
            for (ptrdiff_t dx = -(ptrdiff_t) rc; dx <= (ptrdiff_t) rc; dx++)
              ts_lanes_add (acc, ts_image_pixel (c, clamp_index ((ptrdiff_t) cax + dx, c->width), ya),
                         ts_image_pixel (c, clamp_index ((ptrdiff_t) cbx + dx, c->width), yb), TS_CHANNELS);
          }
      if (TS_LANES_TOTAL (acc) > bound)
        break;
    }
  return TS_LANES_TOTAL (acc);
}

/* Per-level PCA basis (dims x m, dimension-major) by block
 * power iteration on a deterministic subsample of the candidate centres;
 * no D x D covariance, so large patches stay affordable. */
TsStatus
ts_mrpm_pca_basis (const TsMrpmFeature *f, const int32_t *list, size_t n, size_t width,
           size_t m, float *basis)
{
  size_t D = f->dims, S = n < PCA_SAMPLES ? n : PCA_SAMPLES;
  size_t b = m + PCA_OVERSAMPLE < D ? m + PCA_OVERSAMPLE : D;
  float *X = malloc (S * D * sizeof (float));
  double *Q = malloc (D * b * sizeof (double));
  double *Y = malloc (S * b * sizeof (double));
  double *mean = calloc (D, sizeof (double));

  if (!X || !Q || !Y || !mean)
    {
      free (X), free (Q), free (Y), free (mean);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t s = 0; s < S; s++)
    {
      size_t p = (size_t) list[s * n / S];
      ts_mrpm_feature_extract (f, p % width, p / width, X + s * D);
      for (size_t d = 0; d < D; d++)
        mean[d] += X[s * D + d];
    }
  for (size_t s = 0; s < S; s++)
    for (size_t d = 0; d < D; d++)
      X[s * D + d] -= (float) (mean[d] / (double) S);
  for (size_t i = 0; i < D * b; i++)
    Q[i] = (double) (ts_mix64 (i + 1) >> 11) / 9007199254740992.0 - 0.5;

  for (int it = 0; it < PCA_ITERATIONS; it++)
    {
      /* Q <- X^T X Q, then orthonormalise (simultaneous iteration keeps
       * the columns ordered by decreasing variance). Each entry is one
       * thread's fixed-order sum: the same on any number of threads. */
#pragma omp parallel for schedule(static)
      for (ptrdiff_t s = 0; s < (ptrdiff_t) S; s++)
        {
          double acc[MAX_PCA + PCA_OVERSAMPLE] = { 0 };
          for (size_t d = 0; d < D; d++)
            for (size_t j = 0; j < b; j++)
              acc[j] += X[(size_t) s * D + d] * Q[d * b + j];
          memcpy (Y + (size_t) s * b, acc, b * sizeof (double));
        }
#pragma omp parallel for schedule(static)
      for (ptrdiff_t d = 0; d < (ptrdiff_t) D; d++)
        {
          double acc[MAX_PCA + PCA_OVERSAMPLE] = { 0 };
          for (size_t s = 0; s < S; s++)
            for (size_t j = 0; j < b; j++)
              acc[j] += X[s * D + (size_t) d] * Y[s * b + j];
          memcpy (Q + (size_t) d * b, acc, b * sizeof (double));
        }
      for (size_t j = 0; j < b; j++)
        {
          for (size_t i = 0; i < j; i++)
            {
              double dot = 0;
              for (size_t d = 0; d < D; d++)
                dot += Q[d * b + i] * Q[d * b + j];
              for (size_t d = 0; d < D; d++)
                Q[d * b + j] -= dot * Q[d * b + i];
            }
          double norm = 0;
          for (size_t d = 0; d < D; d++)
            norm += Q[d * b + j] * Q[d * b + j];
          /* A degenerate (e.g. flat) exemplar has no variance left: zero
           * axes just contribute nothing to the projected distance. */
          double scale = norm > 1e-20 ? 1.0 / sqrt (norm) : 0.0;
          for (size_t d = 0; d < D; d++)
            Q[d * b + j] *= scale;
        }
    }
  for (size_t d = 0; d < D; d++)
    for (size_t j = 0; j < m; j++)
      basis[d * m + j] = (float) Q[d * b + j];
  free (X), free (Q), free (Y), free (mean);
  return TS_OK;
}

