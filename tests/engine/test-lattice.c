/* The lattice estimate and the lattice guide: periods of synthetic
 * lattices (running bond, a turned grid of dots with a fractional
 * period, stripes) found to a fraction of a pixel; none in noise, a flat
 * image, streaks, noise with one strong line or one feature seen twice;
 * a tileable output's phases run whole periods. */
#include "test-util.h"
#include "engine/lattice.h"

#include <math.h>
#include <stdlib.h>

static const double two_pi = 6.283185307179586;

/* Lightness of a running bond: bricks w x h, each row shifted by half a
 * brick, mortar lines 2 px wide, plus some smooth noise. */
static void
bricks (TsImage *image, size_t side, double w, double h)
{
  test_noise_image (image, side, side, 7);
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        float *p = image->pixels + (y * side + x) * TS_CHANNELS;
        double row = floor (y / h), fx = fmod (x + (fmod (row, 2.0) ? w / 2 : 0.0), w);
        double fy = fmod ((double) y, h);
        bool mortar = fx < 2.0 || fy < 2.0;
        p[0] = (float) ((mortar ? 80.0 : 40.0) + 0.2 * (p[0] - 50.0));
      }
}

/* Dots on a grid of period `period` turned by `angle` radians. */
static void
turned_dots (TsImage *image, size_t side, double period, double angle)
{
  test_noise_image (image, side, side, 11);
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        double u = (cos (angle) * x + sin (angle) * y) / period;
        double v = (-sin (angle) * x + cos (angle) * y) / period;
        double du = u - round (u), dv = v - round (v);
        float *p = image->pixels + (y * side + x) * TS_CHANNELS;
        p[0] = (float) (30.0 + 50.0 * exp (-(du * du + dv * dv) * 20.0) + 0.1 * (p[0] - 50.0));
      }
}

static void
stripes (TsImage *image, size_t side, double nx, double ny, double period)
{
  test_noise_image (image, side, side, 13);
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        float *p = image->pixels + (y * side + x) * TS_CHANNELS;
        /* white noise of +-2: nothing repeats along the stripes */
        unsigned h = (unsigned) (x * 73856093u ^ y * 19349663u) * 2654435761u;
        p[0] = (float) (50.0 + 30.0 * sin (two_pi * (nx * x + ny * y) / period) +
                        4.0 * ((double) (h >> 8) / 16777216.0 - 0.5));
      }
}

/* Rain-like streaks: white noise averaged along segments of `length`
 * px in the direction (nx, ny); nothing repeats across them. */
static void
streaks (TsImage *image, size_t side, double nx, double ny, int length)
{
  test_noise_image (image, side, side, 17);
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        double sum = 0.0;
        for (int t = 0; t < length; t++)
          {
            long sx = (long) lround (x + nx * t), sy = (long) lround (y + ny * t);
            unsigned h = (unsigned) (sx * 73856093L ^ sy * 19349663L) * 2654435761u;
            sum += (double) (h >> 8) / 16777216.0;
          }
        image->pixels[(y * side + x) * TS_CHANNELS] = (float) (20.0 + 60.0 * sum / length);
      }
}

/* Smooth noise crossed by one bright line `width` px wide, at `slope`
 * px across per px down. */
static void
noise_with_line (TsImage *image, size_t side, double slope, double width)
{
  test_noise_image (image, side, side, 19);
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      if (fabs ((double) x - (side / 2.0 + slope * ((double) y - side / 2.0))) < width / 2.0)
        image->pixels[(y * side + x) * TS_CHANNELS] = 95.0f;
}

/* Smooth noise holding one feature (a ring and a bar) twice, `dx`, `dy`
 * apart: a one-off match, not a repeat. */
static void
feature_twice (TsImage *image, size_t side, int dx, int dy)
{
  test_noise_image (image, side, side, 23);
  for (int copy = 0; copy < 2; copy++)
    {
      double cx = side / 2.0 - dx / 2.0 + copy * dx, cy = side / 2.0 - dy / 2.0 + copy * dy;
      for (size_t y = 0; y < side; y++)
        for (size_t x = 0; x < side; x++)
          {
            double u = x - cx, v = y - cy, r = hypot (u, v);
            if (fabs (r - 9.0) < 2.5 || (fabs (v) < 2.0 && fabs (u) < 16.0))
              image->pixels[(y * side + x) * TS_CHANNELS] = 95.0f;
          }
    }
}

static TsLatticeEstimate
estimate (const TsImage *image)
{
  TsImage working;
  TsPyramid pyramid;
  TsLatticeEstimate lattice = { 0 };

  CHECK (ts_image_to_working (image, &working) == TS_OK, "working copy");
  CHECK (ts_pyramid_build (&working, ts_pyramid_depth_for (image->width, image->height, 32),
                           &pyramid) == TS_OK, "pyramid");
  CHECK (ts_lattice_estimate (&pyramid, &lattice) == TS_OK, "estimate");
  ts_pyramid_free (&pyramid);
  ts_image_free (&working);
  return lattice;
}

/* Whether the estimate spans the lattice of `a`, `b`: each true period is
 * an integer combination of the estimated ones within `tolerance` px,
 * and the cells have the same area within 2 %. */
static bool
same_lattice (const TsLatticeEstimate *e, const double a[2], const double b[2], double tolerance)
{
  const double *p = e->vector[0], *q = e->vector[1];
  double det = p[0] * q[1] - p[1] * q[0], true_det = a[0] * b[1] - a[1] * b[0];
  const double *truth[2] = { a, b };

  if (e->vectors != 2 || fabs (fabs (det) / fabs (true_det) - 1.0) > 0.02)
    return false;
  for (int i = 0; i < 2; i++)
    {
      const double *t = truth[i];
      double n = round ((q[1] * t[0] - q[0] * t[1]) / det);
      double m = round ((p[0] * t[1] - p[1] * t[0]) / det);
      if (hypot (t[0] - n * p[0] - m * q[0], t[1] - n * p[1] - m * q[1]) > tolerance)
        return false;
    }
  return true;
}

static void
test_bricks (void)
{
  TsImage image;
  const double a[2] = { 24, 0 }, b[2] = { 12, 12 };
  bricks (&image, 128, 24, 12);
  TsLatticeEstimate e = estimate (&image);
  CHECK (same_lattice (&e, a, b, 0.25), "running bond 24x12: %zu vectors (%.2f, %.2f) (%.2f, %.2f)",
         e.vectors, e.vector[0][0], e.vector[0][1], e.vector[1][0], e.vector[1][1]);
  CHECK (e.strength >= TS_LATTICE_LEAST_PEAK, "strength %.3f", e.strength);
  free (image.pixels);
}

static void
test_turned_dots (void)
{
  TsImage image;
  double period = 14.3, angle = 0.35;
  const double a[2] = { period * cos (angle), period * sin (angle) };
  const double b[2] = { -period * sin (angle), period * cos (angle) };
  turned_dots (&image, 160, period, angle);
  TsLatticeEstimate e = estimate (&image);
  /* A fractional period: the fit on the far peaks finds it to a few
   * hundredths of a pixel per period. */
  CHECK (same_lattice (&e, a, b, 0.15), "turned dots: %zu vectors (%.3f, %.3f) (%.3f, %.3f)",
         e.vectors, e.vector[0][0], e.vector[0][1], e.vector[1][0], e.vector[1][1]);
  free (image.pixels);
}

static void
test_stripes (void)
{
  TsImage image;
  double norm = hypot (1.0, 0.3), nx = 1.0 / norm, ny = 0.3 / norm, period = 10.0;
  stripes (&image, 128, nx, ny, period);
  TsLatticeEstimate e = estimate (&image);
  /* The period across the stripes is found; a second period, if any,
   * lies along them (a far peak of the sampled ridge) and keeps the
   * spacing across them: every period crosses a whole number of them. */
  CHECK (e.vectors >= 1, "stripes: no period");
  for (size_t k = 0; k < e.vectors; k++)
    {
      double across = fabs (e.vector[k][0] * nx + e.vector[k][1] * ny) / period;
      CHECK (fabs (across - round (across)) < 0.03, "stripes: period %zu (%.2f, %.2f) crosses %.3f stripes",
             k, e.vector[k][0], e.vector[k][1], across);
    }
  if (e.vectors >= 1)
    {
      double across = fabs (e.vector[0][0] * nx + e.vector[0][1] * ny);
      CHECK (fabs (across - period) < 0.2, "stripes: first period across %.3f, want 10", across);
    }
  free (image.pixels);
}

static void
test_none (void)
{
  TsImage image;
  test_noise_image (&image, 128, 128, 3);
  TsLatticeEstimate e = estimate (&image);
  CHECK (e.vectors == 0, "smooth noise: %zu vectors, strength %.3f", e.vectors, e.strength);
  for (size_t i = 0; i < 128 * 128; i++)
    image.pixels[i * TS_CHANNELS] = 40.0f;
  e = estimate (&image);
  CHECK (e.vectors == 0, "flat: %zu vectors", e.vectors);
  free (image.pixels);
  /* Too small to hold two periods: no lattice, no failure. */
  test_noise_image (&image, 5, 40, 3);
  e = estimate (&image);
  CHECK (e.vectors == 0, "5x40: %zu vectors", e.vectors);
  free (image.pixels);
}

/* No texture that does not repeat has a lattice, however strong a peak
 * or ridge of its autocorrelation. */
static void
test_no_repeat (void)
{
  TsImage image;
  double norm = hypot (1.0, 2.0);
  streaks (&image, 128, 1.0 / norm, 2.0 / norm, 40);
  TsLatticeEstimate e = estimate (&image);
  CHECK (e.vectors == 0, "streaks: %zu vectors (%.2f, %.2f), strength %.3f", e.vectors,
         e.vector[0][0], e.vector[0][1], e.strength);
  free (image.pixels);
  noise_with_line (&image, 128, 0.3, 3.0);
  e = estimate (&image);
  CHECK (e.vectors == 0, "noise with one line: %zu vectors (%.2f, %.2f), strength %.3f", e.vectors,
         e.vector[0][0], e.vector[0][1], e.strength);
  free (image.pixels);
  feature_twice (&image, 128, 34, 22);
  e = estimate (&image);
  CHECK (e.vectors == 0, "one feature twice: %zu vectors (%.2f, %.2f), strength %.3f", e.vectors,
         e.vector[0][0], e.vector[0][1], e.strength);
  free (image.pixels);
}

/* A tileable output's phases run a whole number of periods across it:
 * the step from the last column to the first is the step between two
 * neighbouring columns. */
static void
test_guide_wraps (void)
{
  TsImage image, working;
  TsPyramid pyramid;
  TsGuidePyramid guides;
  bricks (&image, 128, 24, 12);
  TsLatticeEstimate e = estimate (&image);
  CHECK (ts_image_to_working (&image, &working) == TS_OK, "working copy");
  CHECK (ts_pyramid_build (&working, 3, &pyramid) == TS_OK, "pyramid");
  CHECK (ts_lattice_guide_build (&e, &pyramid, 250, 190, true, true, &guides) == TS_OK, "guide");
  CHECK (guides.lattice && guides.levels == 3 && guides.channels == 4, "a lattice guide");
  CHECK (!guides.exemplar[0].value.pixels, "the finest level is left free");
  for (size_t l = 1; l < guides.levels; l++)
    {
      const TsGuidePlane *t = &guides.target[l];
      CHECK (t->value.pixels != NULL, "level %zu is guided", l);
      if (!t->value.pixels)
        continue;
      for (size_t c = 0; c < 4; c += 2)
        {
          const float *first = ts_image_pixel (&t->value, 0, 0), *second = ts_image_pixel (&t->value, 1, 0);
          const float *last = ts_image_pixel (&t->value, t->width - 1, 0);
          const float *below = ts_image_pixel (&t->value, 0, 1);
          const float *bottom = ts_image_pixel (&t->value, 0, t->height - 1);
          double step = atan2 (second[c + 1], second[c]) - atan2 (first[c + 1], first[c]);
          double wrap = atan2 (first[c + 1], first[c]) - atan2 (last[c + 1], last[c]);
          double step_y = atan2 (below[c + 1], below[c]) - atan2 (first[c + 1], first[c]);
          double wrap_y = atan2 (first[c + 1], first[c]) - atan2 (bottom[c + 1], bottom[c]);
          CHECK (fabs (remainder (step - wrap, two_pi)) < 1e-3, "level %zu phase %zu: x step %.4f, wrap %.4f", l, c / 2, step, wrap);
          CHECK (fabs (remainder (step_y - wrap_y, two_pi)) < 1e-3, "level %zu phase %zu: y step %.4f, wrap %.4f", l, c / 2, step_y, wrap_y);
        }
    }
  ts_guide_pyramid_free (&guides);
  ts_pyramid_free (&pyramid);
  ts_image_free (&working);
  free (image.pixels);
}

int
main (void)
{
  test_bricks ();
  test_turned_dots ();
  test_stripes ();
  test_none ();
  test_no_repeat ();
  test_guide_wraps ();
  return test_finish ("test-lattice");
}
