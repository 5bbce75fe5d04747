/* Matching on colour and aligned feature maps: the exemplar in
 * "appearance space" (Lefebvre and Hoppe 2006), reduced to the engine's
 * three colour channels by PCA, so every step of the synthesis works on it
 * unchanged and the colours are copied afterwards by the source map.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "error.h"
#include "image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lab and the features: at most 3 + TS_MAX_FEATURE_CHANNELS dimensions. */
#define MAX_DIMS (3 + TS_MAX_FEATURE_CHANNELS)
/* A feature's 0..1 at weight 1 spans as much as L's 0..100. */
#define FEATURE_SCALE 100.0
/* Cyclic Jacobi converges quadratically, in about ten sweeps or fewer
 * for these small matrices; the cap only bounds a pathological input. */
#define JACOBI_SWEEPS 64

/* Eigen-decomposition of the symmetric n x n `a` (destroyed) by cyclic
 * Jacobi rotations: a fixed order of exact operations, so the same bits on
 * every machine and thread count. Columns of `v` are the eigenvectors,
 * `values` their eigenvalues. */
static void
jacobi (double a[MAX_DIMS][MAX_DIMS], size_t n, double v[MAX_DIMS][MAX_DIMS], double *values)
{
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < JACOBI_SWEEPS; sweep++)
    {
      double off = 0.0;
      for (size_t p = 0; p < n; p++)
        for (size_t q = p + 1; q < n; q++)
          off += a[p][q] * a[p][q];
      if (off < 1e-30)
        break;
      for (size_t p = 0; p < n; p++)
        for (size_t q = p + 1; q < n; q++)
          {
            if (fabs (a[p][q]) < 1e-300)
              continue;
            double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            double t = (theta >= 0 ? 1.0 : -1.0) / (fabs (theta) + sqrt (theta * theta + 1.0));
            double c = 1.0 / sqrt (t * t + 1.0), s = t * c;
            for (size_t k = 0; k < n; k++)
              {
                double akp = a[k][p], akq = a[k][q];
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
              }
            for (size_t k = 0; k < n; k++)
              {
                double apk = a[p][k], aqk = a[q][k];
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
              }
            for (size_t k = 0; k < n; k++)
              {
                double vkp = v[k][p], vkq = v[k][q];
                v[k][p] = c * vkp - s * vkq;
                v[k][q] = s * vkp + c * vkq;
              }
          }
    }
  for (size_t i = 0; i < n; i++)
    values[i] = a[i][i];
}

static void
appearance (const TsImage *exemplar, const TsFeatureMap *features, double weight, size_t i,
            double *out)
{
  const float *lab = exemplar->pixels + i * TS_CHANNELS;
  for (size_t c = 0; c < 3; c++)
    out[c] = lab[c];
  for (size_t c = 0; c < features->channels; c++)
    out[3 + c] = weight * FEATURE_SCALE * features->values[i * features->channels + c];
}

TsStatus
ts_feature_matching_image (const TsImage *exemplar, const TsFeatureMap *features, double weight,
                           TsImage *matching, TsError *error)
{
  double mean[MAX_DIMS] = { 0 }, cov[MAX_DIMS][MAX_DIMS] = { { 0 } };
  double vectors[MAX_DIMS][MAX_DIMS], values[MAX_DIMS], x[MAX_DIMS];
  size_t order[MAX_DIMS], n, dims, opaque = 0;

  if (matching)
    memset (matching, 0, sizeof *matching);
  if (!exemplar || !exemplar->pixels || !features || !features->values || !matching)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no exemplar, feature map or result given");
  if (features->width != exemplar->width || features->height != exemplar->height)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the feature map is %zux%zu but the exemplar %zux%zu: they must be aligned, "
                    "of the same size", features->width, features->height,
                    exemplar->width, exemplar->height);
  if (features->channels < 1 || features->channels > TS_MAX_FEATURE_CHANNELS)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "a feature map has 1 to %d channels, got %zu", TS_MAX_FEATURE_CHANNELS,
                    features->channels);
  if (!(weight >= 0.0 && weight <= TS_MAX_FEATURE_WEIGHT))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "the feature weight must be 0 to %g, got %g",
                    TS_MAX_FEATURE_WEIGHT, weight);
  n = exemplar->width * exemplar->height;
  dims = 3 + features->channels;
  for (size_t i = 0; i < n * features->channels; i++)
    if (!isfinite (features->values[i]))
      return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                      "the feature map holds a value that is not a number");

  /* Statistics of the opaque pixels, in a fixed order (serial: a few
   * thousand pixels, and sums must not depend on the thread count). */
  for (size_t i = 0; i < n; i++)
    if (exemplar->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        appearance (exemplar, features, weight, i, x);
        for (size_t c = 0; c < dims; c++)
          mean[c] += x[c];
        opaque++;
      }
  if (opaque == 0)
    return ts_fail (error, TS_ERROR_TRANSPARENT_EXEMPLAR, "the exemplar is fully transparent");
  for (size_t c = 0; c < dims; c++)
    mean[c] /= (double) opaque;
  for (size_t i = 0; i < n; i++)
    if (exemplar->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        appearance (exemplar, features, weight, i, x);
        for (size_t r = 0; r < dims; r++)
          for (size_t c = 0; c < dims; c++)
            cov[r][c] += (x[r] - mean[r]) * (x[c] - mean[c]);
      }
  jacobi (cov, dims, vectors, values);

  /* The three directions of largest variance, largest first (ties by
   * index, so the order is fixed). */
  for (size_t i = 0; i < dims; i++)
    order[i] = i;
  for (size_t i = 0; i < dims; i++)
    for (size_t j = i + 1; j < dims; j++)
      if (values[order[j]] > values[order[i]])
        {
          size_t t = order[i];
          order[i] = order[j];
          order[j] = t;
        }

  matching->pixels = malloc (n * TS_CHANNELS * sizeof (float));
  if (!matching->pixels)
    return ts_fail (error, TS_ERROR_OUT_OF_MEMORY, "out of memory for the %zux%zu matching image",
                    exemplar->width, exemplar->height);
  matching->width = exemplar->width;
  matching->height = exemplar->height;
  for (size_t i = 0; i < n; i++)
    {
      float *out = matching->pixels + i * TS_CHANNELS;
      appearance (exemplar, features, weight, i, x);
      for (size_t k = 0; k < 3; k++)
        {
          double sum = 0.0;
          for (size_t c = 0; c < dims; c++)
            sum += (x[c] - mean[c]) * vectors[c][order[k]];
          out[k] = (float) sum;
        }
      out[3] = exemplar->pixels[i * TS_CHANNELS + 3];
    }
  return TS_OK;
}

void
ts_copy_by_source_map (const TsImage *exemplar, const int32_t *source_map, TsImage *output)
{
  size_t n = output->width * output->height;

  for (size_t i = 0; i < n; i++)
    {
      size_t x = (size_t) source_map[2 * i], y = (size_t) source_map[2 * i + 1];
      memcpy (output->pixels + i * TS_CHANNELS,
              exemplar->pixels + (y * exemplar->width + x) * TS_CHANNELS,
              TS_CHANNELS * sizeof (float));
      ts_pixel_readable (output->pixels + i * TS_CHANNELS);
    }
}
