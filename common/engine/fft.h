/* A small complex FFT on power-of-two sizes (iterative radix-2), in one
 * and two dimensions, for correlations over many offsets: the engine's
 * lattice estimate (lattice.c) and the lattice measure
 * (tools/lattice-metrics.c). Pure C11, no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Forward: X[k] = sum_n x[n] exp(-2 pi i n k / N). Inverse: the same with
 * exp(+2 pi i n k / N), divided by N (by width * height in 2D), so an
 * inverse after a forward gives the input back. */
#ifndef TS_FFT_H
#define TS_FFT_H

#include <complex.h>
#include <stdbool.h>
#include <stddef.h>

/* The smallest power of two >= n (n >= 1), or 0 if it does not fit. */
size_t ts_fft_size (size_t n);

/* In place on `data` (width x height values, row by row); width and
 * height must be powers of two. Returns false only when out of memory
 * (the data are then unchanged) or when a size is not a power of two. */
bool ts_fft_2d (double complex *data, size_t width, size_t height, bool inverse);

/* In place on n contiguous values, n a power of two. */
bool ts_fft_1d (double complex *data, size_t n, bool inverse);

#endif
