/* Iterative radix-2 complex FFT (definitions in fft.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "fft.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#define TWO_PI 6.28318530717958647692

static bool
is_power_of_two (size_t n)
{
  return n > 0 && (n & (n - 1)) == 0;
}

size_t
ts_fft_size (size_t n)
{
  size_t size = 1;
  while (size < n)
    {
      if (size > SIZE_MAX / 2)
        return 0;
      size *= 2;
    }
  return size;
}

/* exp(-2 pi i k / n) for k < n / 2, each from cos and sin directly so
 * errors do not build up along the table. */
static double complex *
new_twiddles (size_t n)
{
  size_t half = n / 2 ? n / 2 : 1;
  double complex *twiddle = malloc (half * sizeof *twiddle);
  if (!twiddle)
    return NULL;
  for (size_t k = 0; k < half; k++)
    {
      double angle = -TWO_PI * (double) k / (double) n;
      twiddle[k] = cos (angle) + I * sin (angle);
    }
  return twiddle;
}

/* Unscaled transform of n values (n a power of two): bit-reversed order,
 * then log2(n) stages of butterflies. */
static void
transform (double complex *data, size_t n, const double complex *twiddle, bool inverse)
{
  for (size_t i = 1, j = 0; i < n; i++)
    {
      size_t bit = n >> 1;
      for (; j & bit; bit >>= 1)
        j ^= bit;
      j |= bit;
      if (i < j)
        {
          double complex swap = data[i];
          data[i] = data[j];
          data[j] = swap;
        }
    }
  for (size_t length = 2; length <= n; length *= 2)
    {
      size_t half = length / 2, step = n / length;
      for (size_t start = 0; start < n; start += length)
        for (size_t k = 0; k < half; k++)
          {
            double complex w = inverse ? conj (twiddle[k * step]) : twiddle[k * step];
            double complex even = data[start + k], odd = data[start + k + half] * w;
            data[start + k] = even + odd;
            data[start + k + half] = even - odd;
          }
    }
}

bool
ts_fft_1d (double complex *data, size_t n, bool inverse)
{
  double complex *twiddle;

  if (!is_power_of_two (n))
    return false;
  twiddle = new_twiddles (n);
  if (!twiddle)
    return false;
  transform (data, n, twiddle, inverse);
  if (inverse)
    for (size_t i = 0; i < n; i++)
      data[i] /= (double) n;
  free (twiddle);
  return true;
}

/* Every row, then every column (through a contiguous copy: strided
 * butterflies would touch a new cache line at every access). Each line
 * is one thread's transform, so any number of threads gives the same
 * values. */
static bool
transform_lines (double complex *data, size_t width, size_t height,
                 const double complex *row_twiddle, const double complex *column_twiddle,
                 bool inverse)
{
  int failed = 0;
  /* Threads pay off from about 128 x 128 values. */
  bool threads = width * height >= 16384;

#pragma omp parallel if (threads)
  {
    double complex *column = malloc (height * sizeof *column);
    if (!column)
      {
#pragma omp atomic write
        failed = 1;
      }
#pragma omp for schedule(static)
    for (ptrdiff_t y = 0; y < (ptrdiff_t) height; y++)
      transform (data + (size_t) y * width, width, row_twiddle, inverse);
#pragma omp for schedule(static)
    for (ptrdiff_t x = 0; x < (ptrdiff_t) width; x++)
      {
        if (!column)
          continue;
        for (size_t y = 0; y < height; y++)
          column[y] = data[y * width + (size_t) x];
        transform (column, height, column_twiddle, inverse);
        for (size_t y = 0; y < height; y++)
          data[y * width + (size_t) x] = column[y];
      }
    free (column);
  }
  return !failed;
}

bool
ts_fft_2d (double complex *data, size_t width, size_t height, bool inverse)
{
  double complex *row_twiddle, *column_twiddle;
  bool ok;

  if (!is_power_of_two (width) || !is_power_of_two (height))
    return false;
  row_twiddle = new_twiddles (width);
  column_twiddle = new_twiddles (height);
  ok = row_twiddle && column_twiddle
       && transform_lines (data, width, height, row_twiddle, column_twiddle, inverse);
  if (ok && inverse)
    {
      double scale = 1.0 / ((double) width * (double) height);
      for (size_t i = 0; i < width * height; i++)
        data[i] *= scale;
    }
  free (row_twiddle);
  free (column_twiddle);
  return ok;
}
