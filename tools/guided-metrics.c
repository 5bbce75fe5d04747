/* Measures of guided synthesis (see guided-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guided-metrics.h"
#include "patch-search.h"
#include "window-grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#define TS_OMP(x) _Pragma (#x)
#else
#define TS_OMP(x)
#endif

#define R TS_MEASURE_RADIUS

bool
ts_guide_label_maps (const TsImage *exemplar_guide, const TsImage *target_guide,
                     uint8_t *exemplar_labels, uint8_t *target_labels, size_t *labels)
{
  float table[TS_LABEL_MAX][3];
  size_t count = 0, n = exemplar_guide->width * exemplar_guide->height;

  for (size_t i = 0; i < n; i++)
    {
      const float *p = exemplar_guide->pixels + i * TS_CHANNELS;
      size_t j;
      for (j = 0; j < count && memcmp (table[j], p, sizeof table[j]) != 0; j++)
        ;
      if (j == count)
        {
          if (count == TS_LABEL_MAX)
            return false;
          memcpy (table[count++], p, sizeof table[0]);
        }
      exemplar_labels[i] = (uint8_t) j;
    }
  n = target_guide->width * target_guide->height;
  for (size_t i = 0; i < n; i++)
    {
      const float *p = target_guide->pixels + i * TS_CHANNELS;
      double best = INFINITY;
      for (size_t j = 0; j < count; j++)
        {
          double d = 0.0;
          for (int c = 0; c < 3; c++)
            d += (double) (p[c] - table[j][c]) * (double) (p[c] - table[j][c]);
          if (d < best)
            {
              best = d;
              target_labels[i] = (uint8_t) j;
            }
        }
    }
  *labels = count;
  return true;
}

static TsWindowGrid
inner_grid (const TsImage *image)
{
  TsWindowGrid g = { image, R, false, false, R, R, image->width - 2 * R,
                     image->height - 2 * R, 1 };
  return g;
}

/* Every inner result pixel's nearest exemplar window: its centre's index
 * in the exemplar (y * width + x) and the RMS distance; others get
 * SIZE_MAX. */
static TsMeasureStatus
nearest_centres (const TsImage *exemplar, const TsImage *result, size_t *centre, double *rms)
{
  TsWindowGrid db = inner_grid (exemplar), q = inner_grid (result);
  TsPatchIndex *index = ts_patch_index_new (&db, 16);
  size_t dims = ts_grid_dims (&q);
  bool ok = index != NULL;

  for (size_t i = 0; i < result->width * result->height; i++)
    centre[i] = SIZE_MAX;
  if (!ok)
    return TS_MEASURE_OUT_OF_MEMORY;
  TS_OMP (omp parallel reduction (&& : ok))
  {
    float *vec = malloc (dims * sizeof (float));
    ok = vec != NULL;
    TS_OMP (omp for schedule (dynamic, 1))
    for (size_t row = 0; row < q.ny; row++)
      {
        size_t match = TS_SEARCH_NONE;
        for (size_t col = 0; vec && col < q.nx; col++)
          {
            size_t i = row * q.nx + col, x, y, guess = TS_SEARCH_NONE;
            float ssd;
            /* The neighbour's match, one to the right, is a good guess. */
            if (match != TS_SEARCH_NONE && match % db.nx + 1 < db.nx)
              guess = match + 1;
            ts_grid_gather (&q, i, vec);
            match = ts_patch_index_nearest (index, vec, guess, &ssd);
            ts_grid_centre (&q, i, &x, &y);
            size_t ex_x, ex_y;
            ts_grid_centre (&db, match, &ex_x, &ex_y);
            centre[y * result->width + x] = ex_y * exemplar->width + ex_x;
            rms[y * result->width + x] = sqrt ((double) ssd / (double) dims);
          }
      }
    free (vec);
  }
  ts_patch_index_free (index);
  return ok ? TS_MEASURE_OK : TS_MEASURE_OUT_OF_MEMORY;
}

static bool
is_edge (const uint8_t *labels, size_t w, size_t h, size_t x, size_t y)
{
  uint8_t l = labels[y * w + x];
  if (l == TS_LABEL_NONE)
    return false;
  return (x + 1 < w && labels[y * w + x + 1] != l && labels[y * w + x + 1] != TS_LABEL_NONE)
         || (y + 1 < h && labels[(y + 1) * w + x] != l && labels[(y + 1) * w + x] != TS_LABEL_NONE);
}

/* Mean distance from the edge pixels of `from` to the nearest of `to`. */
static double
edge_distance (const uint8_t *from, const uint8_t *to, size_t w, size_t h)
{
  const int s = TS_LABEL_EDGE_SEARCH;
  double sum = 0.0;
  size_t n = 0;

  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double best = s;
        if (!is_edge (from, w, h, x, y))
          continue;
        for (int dy = -s; dy <= s; dy++)
          for (int dx = -s; dx <= s; dx++)
            {
              ptrdiff_t tx = (ptrdiff_t) x + dx, ty = (ptrdiff_t) y + dy;
              double d = sqrt ((double) (dx * dx + dy * dy));
              if (d < best && tx >= 0 && ty >= 0 && tx < (ptrdiff_t) w && ty < (ptrdiff_t) h &&
                  is_edge (to, w, h, (size_t) tx, (size_t) ty))
                best = d;
            }
        sum += best;
        n++;
      }
  return n ? sum / (double) n : NAN;
}

static bool
near_target_edge (const uint8_t *target, size_t w, size_t h, size_t x, size_t y)
{
  size_t m = TS_LABEL_EDGE_MARGIN;
  for (size_t yy = y >= m ? y - m : 0; yy <= y + m && yy < h; yy++)
    for (size_t xx = x >= m ? x - m : 0; xx <= x + m && xx < w; xx++)
      if (target[yy * w + xx] != target[y * w + x])
        return true;
  return false;
}

TsMeasureStatus
ts_measure_labels (const TsImage *exemplar, const uint8_t *exemplar_labels,
                   const TsImage *result, const uint8_t *target_labels, size_t labels,
                   TsLabelMeasures *out)
{
  size_t w = result->width, h = result->height, n = w * h;
  size_t judged = 0, right = 0, region_n[TS_LABEL_MAX] = { 0 };
  double region_sum[TS_LABEL_MAX] = { 0 };
  size_t *centre;
  double *rms;
  uint8_t *result_labels, *target_inner;
  TsMeasureStatus status;

  memset (out, 0, sizeof *out);
  out->fidelity = out->edge_offset = NAN;
  out->labels = labels;
  for (size_t l = 0; l < TS_LABEL_MAX; l++)
    out->region_coherence[l] = NAN;
  if (exemplar->width < TS_MEASURE_MIN_SIDE || exemplar->height < TS_MEASURE_MIN_SIDE ||
      w < TS_MEASURE_MIN_SIDE || h < TS_MEASURE_MIN_SIDE)
    return TS_MEASURE_TOO_SMALL;
  centre = malloc (n * sizeof *centre);
  rms = malloc (n * sizeof *rms);
  result_labels = malloc (n);
  target_inner = malloc (n);
  status = centre && rms && result_labels && target_inner ? TS_MEASURE_OK
                                                          : TS_MEASURE_OUT_OF_MEMORY;
  if (status == TS_MEASURE_OK)
    status = nearest_centres (exemplar, result, centre, rms);
  if (status == TS_MEASURE_OK)
    {
      for (size_t i = 0; i < n; i++)
        {
          result_labels[i] = centre[i] == SIZE_MAX ? TS_LABEL_NONE : exemplar_labels[centre[i]];
          /* Edges are compared where both maps are defined. */
          target_inner[i] = centre[i] == SIZE_MAX ? TS_LABEL_NONE : target_labels[i];
        }
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          {
            size_t i = y * w + x;
            if (centre[i] == SIZE_MAX || near_target_edge (target_labels, w, h, x, y))
              continue;
            judged++;
            right += result_labels[i] == target_labels[i];
            region_sum[target_labels[i]] += rms[i];
            region_n[target_labels[i]]++;
          }
      out->fidelity = judged ? (double) right / (double) judged : NAN;
      out->edge_offset = 0.5 * (edge_distance (target_inner, result_labels, w, h)
                                + edge_distance (result_labels, target_inner, w, h));
      for (size_t l = 0; l < labels && l < TS_LABEL_MAX; l++)
        if (region_n[l])
          out->region_coherence[l] = region_sum[l] / (double) region_n[l];
    }
  free (centre);
  free (rms);
  free (result_labels);
  free (target_inner);
  return status;
}

/* Lightness blurred by a Gaussian (mirrored borders), separably. */
static bool
blurred_lightness (const TsImage *image, double *out)
{
  size_t w = image->width, h = image->height;
  int radius = (int) ceil (3.0 * TS_STYLE_BLUR_SIGMA);
  double kernel[64], total = 0.0, *tmp = malloc (w * h * sizeof (double));

  if (!tmp)
    return false;
  for (int k = -radius; k <= radius; k++)
    total += kernel[k + radius] = exp (-0.5 * k * k / (TS_STYLE_BLUR_SIGMA * TS_STYLE_BLUR_SIGMA));
  for (int k = 0; k <= 2 * radius; k++)
    kernel[k] /= total;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double s = 0.0;
        for (int k = -radius; k <= radius; k++)
          {
            ptrdiff_t t = (ptrdiff_t) x + k;
            while (t < 0 || t >= (ptrdiff_t) w)
              t = t < 0 ? -t - 1 : 2 * (ptrdiff_t) w - t - 1;
            s += kernel[k + radius] * image->pixels[(y * w + (size_t) t) * TS_CHANNELS];
          }
        tmp[y * w + x] = s;
      }
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double s = 0.0;
        for (int k = -radius; k <= radius; k++)
          {
            ptrdiff_t t = (ptrdiff_t) y + k;
            while (t < 0 || t >= (ptrdiff_t) h)
              t = t < 0 ? -t - 1 : 2 * (ptrdiff_t) h - t - 1;
            s += kernel[k + radius] * tmp[(size_t) t * w + x];
          }
        out[y * w + x] = s;
      }
  free (tmp);
  return true;
}

TsMeasureStatus
ts_measure_style_correlation (const TsImage *target, const TsImage *result, double *correlation)
{
  size_t n = result->width * result->height;
  double *a = malloc (n * sizeof (double)), *b = malloc (n * sizeof (double));
  double ma = 0, mb = 0, saa = 0, sbb = 0, sab = 0;
  bool ok = a && b && blurred_lightness (target, a) && blurred_lightness (result, b);

  *correlation = NAN;
  if (ok)
    {
      for (size_t i = 0; i < n; i++)
        {
          ma += a[i];
          mb += b[i];
        }
      ma /= (double) n;
      mb /= (double) n;
      for (size_t i = 0; i < n; i++)
        {
          saa += (a[i] - ma) * (a[i] - ma);
          sbb += (b[i] - mb) * (b[i] - mb);
          sab += (a[i] - ma) * (b[i] - mb);
        }
      if (saa > 0.0 && sbb > 0.0)
        *correlation = sab / sqrt (saa * sbb);
    }
  free (a);
  free (b);
  return ok ? TS_MEASURE_OK : TS_MEASURE_OUT_OF_MEMORY;
}
