/* Quality measures of a healed image (heal-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-metrics.h"
#include "patch-search.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#define TS_OMP(x) _Pragma (#x)
#else
#define TS_OMP(x)
#endif

#define R TS_MEASURE_RADIUS
#define SIDE (2 * R + 1)

/* Chebyshev distance of every pixel to the hole (two-pass chamfer). */
static uint32_t *
distance_to_hole (const uint8_t *hole, size_t w, size_t h)
{
  uint32_t *d = malloc (w * h * sizeof (uint32_t));
  if (!d)
    return NULL;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        uint32_t v = hole[y * w + x] ? 0 : UINT32_MAX - 1;
        if (x > 0 && d[y * w + x - 1] + 1 < v) v = d[y * w + x - 1] + 1;
        if (y > 0)
          for (size_t xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < w; xx++)
            if (d[(y - 1) * w + xx] + 1 < v) v = d[(y - 1) * w + xx] + 1;
        d[y * w + x] = v;
      }
  for (size_t y = h; y-- > 0;)
    for (size_t x = w; x-- > 0;)
      {
        uint32_t v = d[y * w + x];
        if (x + 1 < w && d[y * w + x + 1] + 1 < v) v = d[y * w + x + 1] + 1;
        if (y + 1 < h)
          for (size_t xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < w; xx++)
            if (d[(y + 1) * w + xx] + 1 < v) v = d[(y + 1) * w + xx] + 1;
        d[y * w + x] = v;
      }
  return d;
}

/* Windows packed side by side as 7x7 blocks, so that a grid of step 7
 * holds exactly them (patch-search indexes regular grids only). */
typedef struct
{
  TsImage      image;
  TsWindowGrid grid;
  size_t       count;
} Packed;

static bool
pack (const TsImage *from, const size_t *centres, size_t count, Packed *p)
{
  size_t cols = (size_t) ceil (sqrt ((double) count)), rows = (count + cols - 1) / cols;

  memset (p, 0, sizeof *p);
  p->count = count;
  p->image.width = cols * SIDE;
  p->image.height = rows * SIDE;
  p->image.pixels = malloc (p->image.width * p->image.height * TS_CHANNELS * sizeof (float));
  if (!p->image.pixels)
    return false;
  for (size_t b = 0; b < cols * rows; b++)
    {
      /* Blocks past the last window repeat it: harmless for a nearest search. */
      size_t c = centres[b < count ? b : count - 1];
      size_t cx = c % from->width, cy = c / from->width, bx = b % cols, by = b / cols;
      for (size_t dy = 0; dy < SIDE; dy++)
        memcpy (p->image.pixels + ((by * SIDE + dy) * p->image.width + bx * SIDE) * TS_CHANNELS,
                from->pixels + ((cy + dy - R) * from->width + cx - R) * TS_CHANNELS,
                SIDE * TS_CHANNELS * sizeof (float));
    }
  p->grid = (TsWindowGrid) { .image = &p->image, .radius = R, .x0 = R, .y0 = R,
                             .nx = cols, .ny = rows, .step = SIDE };
  return true;
}

/* Mean RMS distance from each window of `queries` to its nearest in `db`. */
static bool
mean_nearest (const Packed *queries, const Packed *db, double *mean)
{
  TsPatchIndex *index = ts_patch_index_new (&db->grid, 16);
  size_t dims = ts_grid_dims (&db->grid);
  float *ssd = malloc (queries->count * sizeof (float));
  bool ok = index && ssd;
  double sum = 0.0;

  if (ok)
    TS_OMP (omp parallel reduction (&& : ok))
    {
      float *vec = malloc (dims * sizeof (float));
      ok = vec != NULL;
      TS_OMP (omp for schedule (dynamic, 64))
      for (size_t i = 0; i < queries->count; i++)
        if (vec)
          {
            ts_grid_gather (&queries->grid, i, vec);
            ts_patch_index_nearest (index, vec, TS_SEARCH_NONE, &ssd[i]);
          }
      free (vec);
    }
  for (size_t i = 0; ok && i < queries->count; i++)   /* in order: same sum at any thread count */
    sum += sqrt ((double) ssd[i] / (double) dims);
  *mean = ok ? sum / (double) queries->count : NAN;
  ts_patch_index_free (index);
  free (ssd);
  return ok;
}

static double
lab_step (const TsImage *im, size_t p, size_t q)
{
  const float *a = im->pixels + p * TS_CHANNELS, *b = im->pixels + q * TS_CHANNELS;
  double s = 0.0;
  for (int c = 0; c < 3; c++)
    s += ((double) a[c] - b[c]) * ((double) a[c] - b[c]);
  return sqrt (s);
}

/* Outline steps over near known steps in `im`. */
static double
boundary_ratio (const TsImage *im, const uint8_t *hole, const uint32_t *dist)
{
  size_t w = im->width, h = im->height, n_out = 0, n_in = 0;
  double s_out = 0.0, s_in = 0.0;

  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      for (int dir = 0; dir < 2; dir++)
        {
          size_t p = y * w + x, q;
          if ((dir == 0 && x + 1 >= w) || (dir == 1 && y + 1 >= h))
            continue;
          q = dir == 0 ? p + 1 : p + w;
          if ((hole[p] != 0) != (hole[q] != 0))
            {
              s_out += lab_step (im, p, q);
              n_out++;
            }
          else if (!hole[p] && !hole[q] && dist[p] <= TS_HEAL_MEASURE_NEAR &&
                   dist[q] <= TS_HEAL_MEASURE_NEAR)
            {
              s_in += lab_step (im, p, q);
              n_in++;
            }
        }
  return n_out && n_in && s_in > 0.0 ? (s_out / (double) n_out) / (s_in / (double) n_in) : NAN;
}

static double
sharpness_ratio (const TsImage *im, const uint8_t *hole, const uint32_t *dist)
{
  size_t w = im->width, h = im->height, n_hole = 0, n_near = 0;
  double s_hole = 0.0, s_near = 0.0;

  for (size_t y = 1; y + 1 < h; y++)
    for (size_t x = 1; x + 1 < w; x++)
      {
        size_t p = y * w + x;
        double gx = 0.5 * ((double) im->pixels[(p + 1) * TS_CHANNELS] - im->pixels[(p - 1) * TS_CHANNELS]);
        double gy = 0.5 * ((double) im->pixels[(p + w) * TS_CHANNELS] - im->pixels[(p - w) * TS_CHANNELS]);
        double g = sqrt (gx * gx + gy * gy);
        if (hole[p])
          {
            s_hole += g;
            n_hole++;
          }
        else if (dist[p] <= TS_HEAL_MEASURE_NEAR)
          {
            s_near += g;
            n_near++;
          }
      }
  return n_hole && n_near && s_near > 0.0 ? (s_hole / (double) n_hole) / (s_near / (double) n_near) : NAN;
}

TsMeasureStatus
ts_measure_heal (const TsImage *original, const TsImage *result, const uint8_t *hole,
                 TsHealMeasures *out)
{
  size_t w = original->width, h = original->height, n = w * h, nf = 0, nr = 0;
  uint32_t *dist, *sum = NULL;
  size_t *fill = NULL, *ref = NULL;
  Packed pf = { 0 }, pr = { 0 };
  TsMeasureStatus status = TS_MEASURE_OUT_OF_MEMORY;

  memset (out, 0, sizeof *out);
  if (result->width != w || result->height != h || w < SIDE || h < SIDE)
    return TS_MEASURE_TOO_SMALL;
  dist = distance_to_hole (hole, w, h);
  sum = calloc ((w + 1) * (h + 1), sizeof (uint32_t));
  fill = malloc (n * sizeof (size_t));
  ref = malloc (n * sizeof (size_t));
  if (!dist || !sum || !fill || !ref)
    goto out;
  for (size_t p = 0; p < n; p++)
    {
      out->hole_pixels += hole[p] != 0;
      if (!hole[p])
        for (int c = 0; c < TS_CHANNELS; c++)
          if (fabsf (original->pixels[p * TS_CHANNELS + c] - result->pixels[p * TS_CHANNELS + c]) >
              (c == 3 ? TS_HEAL_MEASURE_SAME / 100.0f : TS_HEAL_MEASURE_SAME))
            {
              out->outside_changed++;
              break;
            }
    }
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      sum[(y + 1) * (w + 1) + x + 1] = (hole[y * w + x] != 0) + sum[y * (w + 1) + x + 1] +
                                       sum[(y + 1) * (w + 1) + x] - sum[y * (w + 1) + x];
  for (size_t y = R; y + R < h; y++)
    for (size_t x = R; x + R < w; x++)
      {
        size_t x0 = x - R, y0 = y - R, x1 = x + R + 1, y1 = y + R + 1;
        uint32_t in = sum[y1 * (w + 1) + x1] - sum[y0 * (w + 1) + x1] - sum[y1 * (w + 1) + x0] +
                      sum[y0 * (w + 1) + x0];
        if (2 * in >= SIDE * SIDE)
          fill[nf++] = y * w + x;
        else if (in == 0 && dist[y * w + x] <= TS_HEAL_MEASURE_NEAR)
          ref[nr++] = y * w + x;
      }
  if (nf == 0 || nr == 0)
    {
      status = TS_MEASURE_TOO_SMALL;
      goto out;
    }
  if (!pack (result, fill, nf, &pf) || !pack (original, ref, nr, &pr))
    goto out;
  if (!mean_nearest (&pf, &pr, &out->coherence) || !mean_nearest (&pr, &pf, &out->completeness))
    goto out;
  out->fill_bds = out->coherence + out->completeness;
  out->boundary = boundary_ratio (result, hole, dist);
  out->boundary_original = boundary_ratio (original, hole, dist);
  out->sharpness = sharpness_ratio (result, hole, dist);
  out->sharpness_original = sharpness_ratio (original, hole, dist);
  status = TS_MEASURE_OK;
out:
  free (dist);
  free (sum);
  free (fill);
  free (ref);
  free (pf.image.pixels);
  free (pr.image.pixels);
  return status;
}
