/* The lattice measure: autocorrelation of lightness, its peaks in the
 * exemplar, and the result's autocorrelation there (definitions in
 * lattice-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "lattice-metrics.h"
#include "engine/fft.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* Below this variance (Lab L units squared) an image is one lightness:
 * float rounding of the mean leaves a flat image a little above 0. */
#define FLAT_VARIANCE 1e-12
/* Peak values closer than this are a tie (see ranks_before). */
#define PEAK_TIE 1e-9

typedef struct
{
  double mean, variance;
} LightnessStats;

static double
lightness (const TsImage *image, size_t x, size_t y)
{
  return image->pixels[(y * image->width + x) * TS_CHANNELS];
}

static LightnessStats
lightness_stats (const TsImage *image)
{
  size_t n = image->width * image->height;
  double sum = 0, squares = 0;
  LightnessStats stats;

  for (size_t y = 0; y < image->height; y++)
    for (size_t x = 0; x < image->width; x++)
      sum += lightness (image, x, y);
  stats.mean = sum / (double) n;
  for (size_t y = 0; y < image->height; y++)
    for (size_t x = 0; x < image->width; x++)
      {
        double f = lightness (image, x, y) - stats.mean;
        squares += f * f;
      }
  stats.variance = squares / (double) n;
  return stats;
}

static size_t
overlap (const TsImage *image, int dx, int dy)
{
  size_t adx = (size_t) abs (dx), ady = (size_t) abs (dy);
  if (adx >= image->width || ady >= image->height)
    return 0;
  return (image->width - adx) * (image->height - ady);
}

static double
autocorrelation (const TsImage *image, const LightnessStats *stats, int dx, int dy)
{
  size_t n = overlap (image, dx, dy);
  size_t x0 = dx < 0 ? (size_t) -dx : 0, y0 = dy < 0 ? (size_t) -dy : 0;
  size_t x1 = image->width - (dx > 0 ? (size_t) dx : 0), y1 = image->height - (dy > 0 ? (size_t) dy : 0);
  double sum = 0;

  if (n == 0)
    return NAN;
  if (dx == 0 && dy == 0)
    return 1;
  if (stats->variance < FLAT_VARIANCE)
    return 0;
  for (size_t y = y0; y < y1; y++)
    for (size_t x = x0; x < x1; x++)
      sum += (lightness (image, x, y) - stats->mean)
             * (lightness (image, (size_t) ((long) x + dx), (size_t) ((long) y + dy)) - stats->mean);
  return sum / ((double) n * stats->variance);
}

double
ts_lattice_autocorrelation (const TsImage *image, int dx, int dy)
{
  LightnessStats stats;
  if (overlap (image, dx, dy) == 0)
    return NAN;
  stats = lightness_stats (image);
  return autocorrelation (image, &stats, dx, dy);
}

TsMeasureStatus
ts_lattice_autocorrelation_map (const TsImage *image, int radius_x, int radius_y, double *map)
{
  size_t w = image->width, h = image->height, map_w = 2 * (size_t) radius_x + 1;
  size_t fft_w, fft_h;
  double complex *data;
  LightnessStats stats;

  if (radius_x < 0 || radius_y < 0 || (size_t) radius_x >= w || (size_t) radius_y >= h)
    return TS_MEASURE_TOO_SMALL;
  /* Padding of at least the radius keeps the circular correlation of
   * the padded image equal to the sum over the overlap. */
  fft_w = ts_fft_size (w + (size_t) radius_x);
  fft_h = ts_fft_size (h + (size_t) radius_y);
  if (fft_w == 0 || fft_h == 0 || fft_h > SIZE_MAX / sizeof *data / fft_w)
    return TS_MEASURE_OUT_OF_MEMORY;
  data = calloc (fft_w * fft_h, sizeof *data);
  if (!data)
    return TS_MEASURE_OUT_OF_MEMORY;
  stats = lightness_stats (image);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      data[y * fft_w + x] = lightness (image, x, y) - stats.mean;
  if (!ts_fft_2d (data, fft_w, fft_h, false))
    {
      free (data);
      return TS_MEASURE_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < fft_w * fft_h; i++)
    data[i] = creal (data[i]) * creal (data[i]) + cimag (data[i]) * cimag (data[i]);
  if (!ts_fft_2d (data, fft_w, fft_h, true))
    {
      free (data);
      return TS_MEASURE_OUT_OF_MEMORY;
    }
  for (int dy = -radius_y; dy <= radius_y; dy++)
    for (int dx = -radius_x; dx <= radius_x; dx++)
      {
        size_t fx = dx < 0 ? fft_w - (size_t) -dx : (size_t) dx;
        size_t fy = dy < 0 ? fft_h - (size_t) -dy : (size_t) dy;
        double *r = &map[(size_t) (dy + radius_y) * map_w + (size_t) (dx + radius_x)];
        if (dx == 0 && dy == 0)
          *r = 1;
        else if (stats.variance < FLAT_VARIANCE)
          *r = 0;
        else
          *r = creal (data[fy * fft_w + fx]) / ((double) overlap (image, dx, dy) * stats.variance);
      }
  free (data);
  return TS_MEASURE_OK;
}

/* The largest |dx| (or |dy|) looked at on a side of `side` pixels. */
static int
offset_limit (size_t side)
{
  return side / 2 < TS_LATTICE_MAX_LAG ? (int) (side / 2) : TS_LATTICE_MAX_LAG;
}

/* Whether `a` (value, offset) ranks before `b` among the peaks. Values
 * within PEAK_TIE are equal: an exact lattice has many peaks of 1, which
 * the FFT's rounding would otherwise order at random. */
static bool
ranks_before (const TsLatticePeak *a, const TsLatticePeak *b)
{
  long a_length = (long) a->dx * a->dx + (long) a->dy * a->dy;
  long b_length = (long) b->dx * b->dx + (long) b->dy * b->dy;
  if (fabs (a->exemplar - b->exemplar) > PEAK_TIE)
    return a->exemplar > b->exemplar;
  if (a_length != b_length)
    return a_length < b_length;
  return a->dy != b->dy ? a->dy < b->dy : a->dx < b->dx;
}

/* Keeps the TS_LATTICE_PEAKS best of the candidates offered, in order. */
static void
offer_peak (TsLattice *lattice, TsLatticePeak candidate)
{
  size_t at = lattice->n_peaks;
  while (at > 0 && ranks_before (&candidate, &lattice->peak[at - 1]))
    at--;
  if (at >= TS_LATTICE_PEAKS)
    return;
  for (size_t i = lattice->n_peaks < TS_LATTICE_PEAKS ? lattice->n_peaks : TS_LATTICE_PEAKS - 1; i > at; i--)
    lattice->peak[i] = lattice->peak[i - 1];
  lattice->peak[at] = candidate;
  if (lattice->n_peaks < TS_LATTICE_PEAKS)
    lattice->n_peaks++;
}

/* Whether the map's value at (dx, dy) is a peak: above the neighbours
 * before it in row order, at least those after. */
static bool
is_local_maximum (const double *map, int radius_x, int radius_y, int dx, int dy)
{
  size_t map_w = 2 * (size_t) radius_x + 1;
  double centre = map[(size_t) (dy + radius_y) * map_w + (size_t) (dx + radius_x)];
  for (int ny = -1; ny <= 1; ny++)
    for (int nx = -1; nx <= 1; nx++)
      {
        double neighbour;
        if (nx == 0 && ny == 0)
          continue;
        neighbour = map[(size_t) (dy + ny + radius_y) * map_w + (size_t) (dx + nx + radius_x)];
        if (ny < 0 || (ny == 0 && nx < 0) ? neighbour >= centre : neighbour > centre)
          return false;
      }
  return true;
}

TsMeasureStatus
ts_lattice_exemplar (const TsImage *exemplar, TsLattice *out)
{
  int limit_x, limit_y, radius_x, radius_y;
  size_t map_w;
  double *map;
  TsMeasureStatus status;
  LightnessStats stats;

  *out = (TsLattice) { .n_peaks = 0, .strength = 0, .lattice = NAN };
  if (exemplar->width < TS_LATTICE_MIN_SIDE || exemplar->height < TS_LATTICE_MIN_SIDE)
    return TS_MEASURE_TOO_SMALL;
  limit_x = offset_limit (exemplar->width);
  limit_y = offset_limit (exemplar->height);
  /* one more each way for the neighbours of the outermost offsets */
  radius_x = limit_x + 1;
  radius_y = limit_y + 1;
  map_w = 2 * (size_t) radius_x + 1;
  map = malloc (map_w * (2 * (size_t) radius_y + 1) * sizeof *map);
  if (!map)
    return TS_MEASURE_OUT_OF_MEMORY;
  status = ts_lattice_autocorrelation_map (exemplar, radius_x, radius_y, map);
  if (status != TS_MEASURE_OK)
    {
      free (map);
      return status;
    }
  for (int dy = 0; dy <= limit_y; dy++)
    for (int dx = -limit_x; dx <= limit_x; dx++)
      {
        long length2 = (long) dx * dx + (long) dy * dy;
        double r = map[(size_t) (dy + radius_y) * map_w + (size_t) (dx + radius_x)];
        if ((dy == 0 && dx <= 0) || length2 < (long) TS_LATTICE_MIN_LAG * TS_LATTICE_MIN_LAG
            || length2 > (long) TS_LATTICE_MAX_LAG * TS_LATTICE_MAX_LAG || !(r > 0)
            || !is_local_maximum (map, radius_x, radius_y, dx, dy))
          continue;
        offer_peak (out, (TsLatticePeak) { dx, dy, r, NAN });
      }
  free (map);
  /* The peaks' values summed directly, as the result's will be. */
  stats = lightness_stats (exemplar);
  for (size_t i = 0; i < out->n_peaks; i++)
    out->peak[i].exemplar = autocorrelation (exemplar, &stats, out->peak[i].dx, out->peak[i].dy);
  if (out->n_peaks > 0)
    out->strength = out->peak[0].exemplar;
  return TS_MEASURE_OK;
}

bool
ts_lattice_near_regular (const TsLattice *lattice)
{
  return lattice->n_peaks > 0 && lattice->strength >= TS_LATTICE_NEAR_REGULAR;
}

void
ts_lattice_min_result_size (const TsLattice *lattice, size_t *width, size_t *height)
{
  *width = *height = 1;
  for (size_t i = 0; i < lattice->n_peaks; i++)
    {
      size_t need_w = 2 * (size_t) abs (lattice->peak[i].dx), need_h = 2 * (size_t) abs (lattice->peak[i].dy);
      *width = need_w > *width ? need_w : *width;
      *height = need_h > *height ? need_h : *height;
    }
}

TsMeasureStatus
ts_lattice_result (const TsImage *result, TsLattice *lattice)
{
  size_t need_w, need_h;
  double ratios = 0;
  LightnessStats stats;

  ts_lattice_min_result_size (lattice, &need_w, &need_h);
  if (result->width < need_w || result->height < need_h)
    return TS_MEASURE_TOO_SMALL;
  stats = lightness_stats (result);
  for (size_t i = 0; i < lattice->n_peaks; i++)
    {
      TsLatticePeak *p = &lattice->peak[i];
      p->result = autocorrelation (result, &stats, p->dx, p->dy);
      ratios += p->result / p->exemplar;
    }
  lattice->lattice = ts_lattice_near_regular (lattice) ? ratios / (double) lattice->n_peaks : NAN;
  return TS_MEASURE_OK;
}
