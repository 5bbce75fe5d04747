/* Unit tests of tools/lattice-metrics.c and common/engine/fft.c on synthetic
 * lattices whose answers are known: a checkerboard kept (itself, a larger
 * and a shifted copy), the same board scrambled, a grid rotated by 30
 * degrees, noise (not near-regular), and the autocorrelation through the
 * FFT against the sum it stands for.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "engine/fft.h"
#include "lattice-metrics.h"
#include "engine/rng.h"
#include "test-util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define BOARD_PERIOD 16 /* squares of 8 px */
#define GRID_PERIOD 20.0
#define GRID_DEGREES 30.0

static void
new_image (TsImage *image, size_t width, size_t height)
{
  image->width = width;
  image->height = height;
  image->pixels = calloc (width * height * TS_CHANNELS, sizeof (float));
  if (!image->pixels)
    {
      fputs ("out of memory\n", stderr);
      exit (99);
    }
  for (size_t i = 0; i < width * height; i++)
    image->pixels[i * TS_CHANNELS + 3] = 1;
}

static void
set_lightness (TsImage *image, size_t x, size_t y, double lightness)
{
  image->pixels[(y * image->width + x) * TS_CHANNELS] = (float) lightness;
}

/* Light and dark squares of BOARD_PERIOD / 2 px, the board moved by
 * (shift_x, shift_y). */
static void
checkerboard (TsImage *image, size_t width, size_t height, size_t shift_x, size_t shift_y)
{
  const size_t half = BOARD_PERIOD / 2;
  new_image (image, width, height);
  for (size_t y = 0; y < height; y++)
    for (size_t x = 0; x < width; x++)
      set_lightness (image, x, y, ((x + shift_x) / half + (y + shift_y) / half) % 2 ? 80 : 20);
}

/* Two families of lines (cosines) GRID_PERIOD px apart, turned by
 * `degrees`: its lattice vectors are GRID_PERIOD * (cos, sin) and
 * GRID_PERIOD * (-sin, cos). */
static void
rotated_grid (TsImage *image, size_t width, size_t height, double degrees)
{
  double c = cos (degrees * PI / 180), s = sin (degrees * PI / 180);
  new_image (image, width, height);
  for (size_t y = 0; y < height; y++)
    for (size_t x = 0; x < width; x++)
      {
        double u = c * (double) x + s * (double) y, v = -s * (double) x + c * (double) y;
        set_lightness (image, x, y, 50 + 15 * cos (2 * PI * u / GRID_PERIOD) + 15 * cos (2 * PI * v / GRID_PERIOD));
      }
}

/* Independent lightness per pixel. */
static void
white_noise (TsImage *image, size_t width, size_t height, uint32_t seed)
{
  new_image (image, width, height);
  for (size_t y = 0; y < height; y++)
    for (size_t x = 0; x < width; x++)
      set_lightness (image, x, y, 100.0 * ts_lcg_next24 (&seed) / 16777216.0);
}

/* `source` cut into blocks of `block` px, which are put back in a random
 * order; `block` is no multiple of the board's squares, so neighbouring
 * blocks meet out of phase. Sides must be multiples of `block`. */
static void
scramble_blocks (const TsImage *source, size_t block, uint32_t seed, TsImage *out)
{
  size_t columns = source->width / block, rows = source->height / block, n = columns * rows;
  size_t *order = malloc (n * sizeof *order);
  if (!order)
    {
      fputs ("out of memory\n", stderr);
      exit (99);
    }
  for (size_t i = 0; i < n; i++)
    order[i] = i;
  for (size_t i = n - 1; i > 0; i--)
    {
      size_t j = ts_lcg_next24 (&seed) % (i + 1), swap = order[i];
      order[i] = order[j];
      order[j] = swap;
    }
  new_image (out, source->width, source->height);
  for (size_t b = 0; b < n; b++)
    {
      size_t to_x = b % columns * block, to_y = b / columns * block;
      size_t from_x = order[b] % columns * block, from_y = order[b] / columns * block;
      for (size_t y = 0; y < block; y++)
        memcpy (out->pixels + ((to_y + y) * out->width + to_x) * TS_CHANNELS,
                source->pixels + ((from_y + y) * source->width + from_x) * TS_CHANNELS,
                block * TS_CHANNELS * sizeof (float));
    }
  free (order);
}

static TsLattice
exemplar_lattice (const TsImage *exemplar, const char *what)
{
  TsLattice lattice;
  TsMeasureStatus status = ts_lattice_exemplar (exemplar, &lattice);
  CHECK (status == TS_MEASURE_OK, "%s: ts_lattice_exemplar failed (%d)", what, (int) status);
  return lattice;
}

/* The lattice figure of `result` against the exemplar's peaks. */
static double
lattice_figure (const TsLattice *exemplar, const TsImage *result, const char *what)
{
  TsLattice measured = *exemplar;
  TsMeasureStatus status = ts_lattice_result (result, &measured);
  CHECK (status == TS_MEASURE_OK, "%s: ts_lattice_result failed (%d)", what, (int) status);
  printf ("%-34s lattice %.4f\n", what, measured.lattice);
  return measured.lattice;
}

/* The FFT against the DFT's sum, forward and back. */
static void
test_fft (void)
{
  enum { N = 16 };
  double complex data[N], input[N];
  uint32_t seed = 5;
  double worst = 0;

  for (int n = 0; n < N; n++)
    input[n] = data[n] = ts_lcg_next24 (&seed) / 16777216.0 - 0.5 + I * (ts_lcg_next24 (&seed) / 16777216.0 - 0.5);
  CHECK (ts_fft_1d (data, N, false), "ts_fft_1d failed");
  for (int k = 0; k < N; k++)
    {
      double complex sum = 0;
      for (int n = 0; n < N; n++)
        sum += input[n] * cexp (-2 * PI * I * n * k / N);
      worst = fmax (worst, cabs (sum - data[k]));
    }
  CHECK (worst < 1e-12, "FFT differs from the DFT by %g", worst);
  CHECK (ts_fft_1d (data, N, true), "inverse ts_fft_1d failed");
  worst = 0;
  for (int n = 0; n < N; n++)
    worst = fmax (worst, cabs (input[n] - data[n]));
  CHECK (worst < 1e-14, "inverse FFT does not give the input back (%g)", worst);
  CHECK (!ts_fft_1d (data, 12, false), "a size that is no power of two was taken");
  CHECK (ts_fft_size (1) == 1 && ts_fft_size (317) == 512 && ts_fft_size (512) == 512, "ts_fft_size");
}

/* The map through the FFT against the direct sum at every offset, on
 * sides that are no powers of two and up to the largest radius. */
static void
test_map_matches_sum (void)
{
  TsImage image;
  const int radius_x = 44, radius_y = 20;
  double *map = malloc ((2 * radius_x + 1) * (2 * radius_y + 1) * sizeof *map), worst = 0;

  if (!map)
    exit (99);
  test_noise_image (&image, 45, 37, 3);
  CHECK (ts_lattice_autocorrelation_map (&image, radius_x, radius_y, map) == TS_MEASURE_OK, "map failed");
  for (int dy = -radius_y; dy <= radius_y; dy++)
    for (int dx = -radius_x; dx <= radius_x; dx++)
      {
        double direct = ts_lattice_autocorrelation (&image, dx, dy);
        double fft = map[(dy + radius_y) * (2 * radius_x + 1) + dx + radius_x];
        worst = fmax (worst, fabs (direct - fft));
      }
  CHECK (worst < 1e-9, "FFT autocorrelation differs from the sum by %g", worst);
  CHECK (map[radius_y * (2 * radius_x + 1) + radius_x] == 1, "R(0) is not 1");
  CHECK (isnan (ts_lattice_autocorrelation (&image, 45, 0)), "an offset with no overlap has a value");
  CHECK (ts_lattice_autocorrelation_map (&image, 45, 0, map) == TS_MEASURE_TOO_SMALL,
         "a radius beyond the image was taken");
  free (image.pixels);
  free (map);
}

static void
test_checkerboard (void)
{
  TsImage board, larger, shifted, scrambled, noise;
  TsLattice lattice;
  double figure;

  checkerboard (&board, 128, 128, 0, 0);
  lattice = exemplar_lattice (&board, "checkerboard");
  CHECK (ts_lattice_near_regular (&lattice) && lattice.strength > 0.95 && lattice.n_peaks == TS_LATTICE_PEAKS,
         "checkerboard: strength %.3f, %zu peaks", lattice.strength, lattice.n_peaks);
  /* Its lattice: offsets of whole squares with an even sum, the shortest
   * first, (8, 8) and (-8, 8) of length 11.3, then (16, 0) and (0, 16). */
  for (size_t i = 0; i < lattice.n_peaks; i++)
    {
      const TsLatticePeak *p = &lattice.peak[i];
      long squares = labs ((long) p->dx) / 8 + labs ((long) p->dy) / 8;
      CHECK (p->dx % 8 == 0 && p->dy % 8 == 0 && squares % 2 == 0 && p->exemplar > 0.95,
             "checkerboard peak %zu at (%d, %d), R %.3f is not a lattice vector", i, p->dx, p->dy, p->exemplar);
      CHECK (p->dx * p->dx + p->dy * p->dy <= 256, "checkerboard peak %zu at (%d, %d) is not among the shortest",
             i, p->dx, p->dy);
    }

  figure = lattice_figure (&lattice, &board, "checkerboard against itself");
  CHECK (fabs (figure - 1) < 1e-12, "checkerboard against itself: %.6f", figure);
  checkerboard (&larger, 256, 256, 0, 0);
  figure = lattice_figure (&lattice, &larger, "checkerboard, 256x256");
  CHECK (fabs (figure - 1) < 0.05, "the same board, larger: %.4f", figure);
  checkerboard (&shifted, 256, 256, 3, 5);
  figure = lattice_figure (&lattice, &shifted, "checkerboard, 256x256, shifted");
  CHECK (fabs (figure - 1) < 0.05, "the same board, larger and shifted: %.4f", figure);

  /* The larger board in blocks of 12 px (no multiple of the 8 px
   * squares), shuffled: the lattice is lost. */
  {
    TsImage region;
    new_image (&region, 240, 240);
    for (size_t y = 0; y < 240; y++)
      memcpy (region.pixels + y * 240 * TS_CHANNELS, larger.pixels + y * 256 * TS_CHANNELS,
              240 * TS_CHANNELS * sizeof (float));
    for (uint32_t seed = 1; seed <= 3; seed++)
      {
        char what[64];
        snprintf (what, sizeof what, "checkerboard scrambled, seed %u", (unsigned) seed);
        scramble_blocks (&region, 12, seed, &scrambled);
        figure = lattice_figure (&lattice, &scrambled, what);
        CHECK (fabs (figure) < 0.25, "%s: %.4f, not near 0", what, figure);
        free (scrambled.pixels);
      }
    free (region.pixels);
  }
  white_noise (&noise, 256, 256, 7);
  figure = lattice_figure (&lattice, &noise, "checkerboard against noise");
  CHECK (fabs (figure) < 0.1, "white noise keeps the board's lattice: %.4f", figure);

  free (board.pixels);
  free (larger.pixels);
  free (shifted.pixels);
  free (noise.pixels);
}

static void
test_rotated_grid (void)
{
  TsImage grid, larger, upright;
  TsLattice lattice;
  double c = cos (GRID_DEGREES * PI / 180), s = sin (GRID_DEGREES * PI / 180), figure;

  rotated_grid (&grid, 128, 128, GRID_DEGREES);
  lattice = exemplar_lattice (&grid, "rotated grid");
  printf ("rotated grid: strength %.4f\n", lattice.strength);
  CHECK (ts_lattice_near_regular (&lattice) && lattice.strength > 0.9 && lattice.n_peaks == TS_LATTICE_PEAKS,
         "rotated grid: strength %.3f, %zu peaks", lattice.strength, lattice.n_peaks);
  /* Every peak is a whole offset next to a lattice vector
   * i * GRID_PERIOD * (c, s) + j * GRID_PERIOD * (-s, c), within 0.75 px
   * (the nearest whole offset is at most 0.71 px away). */
  for (size_t i = 0; i < lattice.n_peaks; i++)
    {
      const TsLatticePeak *p = &lattice.peak[i];
      double along_u = round ((c * p->dx + s * p->dy) / GRID_PERIOD);
      double along_v = round ((-s * p->dx + c * p->dy) / GRID_PERIOD);
      double x = GRID_PERIOD * (c * along_u - s * along_v), y = GRID_PERIOD * (s * along_u + c * along_v);
      printf ("rotated grid peak (%d, %d) R %.4f: lattice vector (%.2f, %.2f)\n", p->dx, p->dy, p->exemplar, x, y);
      CHECK ((along_u != 0 || along_v != 0) && hypot (p->dx - x, p->dy - y) < 0.75,
             "rotated grid: peak %zu at (%d, %d) is not at a rotated lattice vector (nearest (%.2f, %.2f))", i,
             p->dx, p->dy, x, y);
    }

  figure = lattice_figure (&lattice, &grid, "rotated grid against itself");
  CHECK (fabs (figure - 1) < 1e-12, "rotated grid against itself: %.6f", figure);
  rotated_grid (&larger, 256, 256, GRID_DEGREES);
  figure = lattice_figure (&lattice, &larger, "rotated grid, 256x256");
  CHECK (fabs (figure - 1) < 0.1, "the same grid, larger: %.4f", figure);
  /* The grid not turned has other lattice vectors. */
  rotated_grid (&upright, 256, 256, 0);
  figure = lattice_figure (&lattice, &upright, "the grid upright");
  CHECK (figure < 0.5, "the upright grid keeps the rotated one's lattice: %.4f", figure);

  free (grid.pixels);
  free (larger.pixels);
  free (upright.pixels);
}

static void
test_not_near_regular (void)
{
  TsImage smooth, white, flat, small, result;
  TsLattice lattice, before;

  test_noise_image (&smooth, 128, 128, 11);
  lattice = exemplar_lattice (&smooth, "smooth noise");
  printf ("smooth noise: strength %.4f\n", lattice.strength);
  CHECK (!ts_lattice_near_regular (&lattice) && lattice.strength < TS_LATTICE_NEAR_REGULAR,
         "smooth noise is near-regular: strength %.3f", lattice.strength);
  CHECK (isnan (lattice_figure (&lattice, &smooth, "smooth noise against itself")),
         "a figure for an exemplar that is not near-regular");

  white_noise (&white, 128, 128, 2);
  lattice = exemplar_lattice (&white, "white noise");
  printf ("white noise: strength %.4f\n", lattice.strength);
  CHECK (!ts_lattice_near_regular (&lattice) && lattice.strength < 0.1, "white noise: strength %.3f",
         lattice.strength);

  new_image (&flat, 64, 64);
  lattice = exemplar_lattice (&flat, "one lightness");
  CHECK (lattice.n_peaks == 0 && lattice.strength == 0 && !ts_lattice_near_regular (&lattice),
         "a flat image has %zu peaks, strength %.3f", lattice.n_peaks, lattice.strength);

  /* Too small: an exemplar with no room for the shortest offsets, and a
   * result with no room for the exemplar's peaks. */
  new_image (&small, TS_LATTICE_MIN_SIDE - 1, 40);
  CHECK (ts_lattice_exemplar (&small, &lattice) == TS_MEASURE_TOO_SMALL, "an 11x40 exemplar was taken");
  checkerboard (&result, 128, 128, 0, 0);
  lattice = exemplar_lattice (&result, "checkerboard");
  free (result.pixels);
  checkerboard (&result, 20, 200, 0, 0);
  before = lattice;
  CHECK (ts_lattice_result (&result, &lattice) == TS_MEASURE_TOO_SMALL
           && memcmp (&before, &lattice, sizeof lattice) == 0,
         "a 20x200 result was measured at offsets up to 16 px across");

  free (smooth.pixels);
  free (white.pixels);
  free (flat.pixels);
  free (small.pixels);
  free (result.pixels);
}

int
main (void)
{
  test_fft ();
  test_map_matches_sum ();
  test_checkerboard ();
  test_rotated_grid ();
  test_not_near_regular ();
  return test_finish ("test-lattice-metrics");
}
