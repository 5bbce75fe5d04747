/* Unit tests of tools/shape-metrics.c on shapes whose answers are known:
 * squares, a digital disc, stripes, a checkerboard and an L, and the
 * k-means split of coloured images into those shapes' phases.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "shape-metrics.h"
#include "test-util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


#define EXACT 1e-12
#define PI 3.14159265358979323846

static bool
near (double a, double b, double tolerance)
{
  return fabs (a - b) <= tolerance;
}

static uint8_t *
new_labels (size_t w, size_t h)
{
  uint8_t *labels = calloc (w * h, 1);
  if (!labels)
    {
      fputs ("out of memory\n", stderr);
      exit (99);
    }
  return labels;
}

static void
fill_rect (uint8_t *labels, size_t w, size_t x0, size_t y0, size_t x1, size_t y1, uint8_t phase)
{
  for (size_t y = y0; y < y1; y++)
    for (size_t x = x0; x < x1; x++)
      labels[y * w + x] = phase;
}

static void
measure (const uint8_t *labels, size_t w, size_t h, int phases, TsPhaseShape *out)
{
  TsMeasureStatus status = ts_shape_measure_labels (labels, w, h, phases, out);
  if (status != TS_MEASURE_OK)
    {
      fprintf (stderr, "ts_shape_measure_labels failed (%d)\n", (int) status);
      exit (99);
    }
}

/* The two-point correlation counted pair by pair, as defined. */
static double
brute_s2 (const uint8_t *labels, size_t w, size_t h, uint8_t phase, size_t r)
{
  size_t rows = 0, row_pairs = 0, columns = 0, column_pairs = 0;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        if (x + r < w)
          row_pairs++, rows += labels[y * w + x] == phase && labels[y * w + x + r] == phase;
        if (y + r < h)
          column_pairs++, columns += labels[y * w + x] == phase && labels[(y + r) * w + x] == phase;
      }
  if (!row_pairs && !column_pairs)
    return NAN;
  if (!row_pairs || !column_pairs)
    return row_pairs ? (double) rows / (double) row_pairs : (double) columns / (double) column_pairs;
  return 0.5 * ((double) rows / (double) row_pairs + (double) columns / (double) column_pairs);
}

static void
check_s2_brute (const uint8_t *labels, size_t w, size_t h, int phases, const TsPhaseShape *shape,
                const char *what)
{
  for (int k = 0; k < phases; k++)
    for (size_t r = 1; r <= TS_SHAPE_MAX_LAG; r++)
      {
        double want = brute_s2 (labels, w, h, (uint8_t) k, r);
        CHECK (isnan (want) ? isnan (shape[k].s2[r]) : near (shape[k].s2[r], want, EXACT),
               "%s phase %d s2(%zu) %.15g, counted %.15g", what, k, r, shape[k].s2[r], want);
      }
}

/* A 10 x 10 square in a 64 x 48 frame, with a 3 x 3 speck (too small to
 * count) and a 3 x 4 rectangle (just large enough). */
static void
test_square (void)
{
  const size_t w = 64, h = 48;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[2];

  fill_rect (labels, w, 20, 15, 30, 25, 1);
  measure (labels, w, h, 2, shape);
  CHECK (near (shape[1].fraction, 100.0 / 3072.0, EXACT), "square fraction %g", shape[1].fraction);
  CHECK (near (shape[1].chord_rows, 10.0, EXACT), "square chord along rows %g", shape[1].chord_rows);
  CHECK (near (shape[1].chord_columns, 10.0, EXACT), "square chord along columns %g", shape[1].chord_columns);
  CHECK (near (shape[1].solidity, 1.0, EXACT), "square solidity %.15g", shape[1].solidity);
  CHECK (shape[1].components == 1, "square components %zu", shape[1].components);
  /* the frame: one component whose hull is the whole image */
  CHECK (near (shape[0].solidity, 2972.0 / 3072.0, EXACT), "frame solidity %.15g", shape[0].solidity);
  CHECK (near (shape[0].chord_rows, 2972.0 / 58.0, EXACT), "frame chord %.15g", shape[0].chord_rows);
  for (size_t r = 1; r <= TS_SHAPE_MAX_LAG; r++)
    {
      double overlap = r < 10 ? 10.0 * (10.0 - (double) r) : 0.0;
      double want = 0.5 * (overlap / (48.0 * (64.0 - (double) r)) + overlap / ((48.0 - (double) r) * 64.0));
      CHECK (near (shape[1].s2[r], want, EXACT), "square s2(%zu) %.15g, want %.15g", r, shape[1].s2[r], want);
    }
  check_s2_brute (labels, w, h, 2, shape, "square");

  fill_rect (labels, w, 2, 2, 5, 5, 1);
  measure (labels, w, h, 2, shape);
  CHECK (shape[1].components == 1 && near (shape[1].solidity, 1.0, EXACT),
         "a 9-pixel speck must not count: %zu components, solidity %g", shape[1].components, shape[1].solidity);
  fill_rect (labels, w, 40, 35, 43, 39, 1);
  measure (labels, w, h, 2, shape);
  CHECK (shape[1].components == 2, "a 12-pixel rectangle counts: %zu components", shape[1].components);
  CHECK (near (shape[1].fraction, 121.0 / 3072.0, EXACT), "fraction counts every pixel: %g", shape[1].fraction);
  free (labels);
}

/* Twice the area of the convex hull of every corner of every pixel of
 * `phase`, by gift wrapping: independent of the library's hull. */
static double
brute_hull_area (const uint8_t *labels, size_t w, size_t h, uint8_t phase)
{
  size_t count = 0, start = 0, current;
  long (*points)[2] = malloc (4 * w * h * sizeof *points);
  double area2 = 0.0;
  if (!points)
    exit (99);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      if (labels[y * w + x] == phase)
        for (int c = 0; c < 4; c++)
          {
            points[count][0] = (long) x + (c & 1);
            points[count][1] = (long) y + (c >> 1);
            count++;
          }
  for (size_t i = 1; i < count; i++)
    if (points[i][0] < points[start][0] || (points[i][0] == points[start][0] && points[i][1] < points[start][1]))
      start = i;
  current = start;
  do
    {
      size_t next = current == 0 ? 1 : 0;
      for (size_t i = 0; i < count; i++)
        {
          long cross = (points[next][0] - points[current][0]) * (points[i][1] - points[current][1])
                       - (points[next][1] - points[current][1]) * (points[i][0] - points[current][0]);
          long far_i = labs (points[i][0] - points[current][0]) + labs (points[i][1] - points[current][1]);
          long far_next = labs (points[next][0] - points[current][0]) + labs (points[next][1] - points[current][1]);
          if (cross < 0 || (cross == 0 && far_i > far_next))
            next = i;
        }
      area2 += (double) (points[current][0] * points[next][1] - points[next][0] * points[current][1]);
      current = next;
    }
  while (current != start);
  free (points);
  return fabs (area2) / 2.0;
}

/* A digital disc of diameter 21 (pixel centres within 10.5 of the centre). */
static void
test_disc (void)
{
  const size_t w = 80, h = 80;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[2];
  size_t area = 0, rows = 0;

  for (size_t y = 0; y < h; y++)
    {
      bool row = false;
      for (size_t x = 0; x < w; x++)
        {
          double dx = (double) x + 0.5 - 40.0, dy = (double) y + 0.5 - 40.0;
          if (dx * dx + dy * dy <= 10.5 * 10.5)
            labels[y * w + x] = 1, area++, row = true;
        }
      rows += row;
    }
  measure (labels, w, h, 2, shape);
  CHECK (near (shape[1].fraction, (double) area / 6400.0, EXACT), "disc fraction %g", shape[1].fraction);
  CHECK (fabs ((double) area / (PI * 10.5 * 10.5) - 1.0) < 0.05, "digital disc area %zu", area);
  /* one run per row: the mean chord is the area over the rows it spans */
  CHECK (near (shape[1].chord_rows, (double) area / (double) rows, EXACT), "disc chord %.15g", shape[1].chord_rows);
  CHECK (near (shape[1].chord_columns, shape[1].chord_rows, EXACT), "disc chords differ by direction");
  CHECK (fabs (shape[1].chord_rows / (PI / 4.0 * 21.0) - 1.0) < 0.05, "disc chord %g, (pi/4) d %g",
         shape[1].chord_rows, PI / 4.0 * 21.0);
  {
    double hull = brute_hull_area (labels, w, h, 1);
    CHECK (near (shape[1].solidity, (double) area / hull, EXACT), "disc solidity %.15g, gift wrapping %.15g",
           shape[1].solidity, (double) area / hull);
    CHECK (shape[1].solidity > 0.95 && shape[1].solidity < 1.0, "disc solidity %g", shape[1].solidity);
  }
  check_s2_brute (labels, w, h, 2, shape, "disc");
  free (labels);
}

/* Vertical stripes 6 pixels wide across 96 x 40 (8 periods). */
static void
test_stripes (void)
{
  const size_t w = 96, h = 40, width = 6;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[2];

  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      labels[y * w + x] = (uint8_t) ((x / width) % 2);
  measure (labels, w, h, 2, shape);
  for (int k = 0; k < 2; k++)
    {
      CHECK (near (shape[k].fraction, 0.5, EXACT), "stripes fraction %g", shape[k].fraction);
      CHECK (near (shape[k].chord_rows, 6.0, EXACT), "stripes chord across %g", shape[k].chord_rows);
      CHECK (near (shape[k].chord_columns, 40.0, EXACT), "stripes chord along %g", shape[k].chord_columns);
      CHECK (near (shape[k].solidity, 1.0, EXACT) && shape[k].components == 8,
             "stripes solidity %g, %zu components", shape[k].solidity, shape[k].components);
      for (size_t r = 1; r <= TS_SHAPE_MAX_LAG; r++)
        {
          /* along rows a triangle wave, 1/2 at multiples of the period and
           * 0 half a period further; along columns the fraction, 1/2 */
          double off = fmod ((double) r, 12.0), d = fmin (off, 12.0 - off);
          double triangle = fmax (0.0, 6.0 - d) / 12.0, edge = 6.0 / (double) (w - r);
          CHECK (fabs (shape[k].s2[r] - 0.5 * (triangle + 0.5)) <= 0.5 * edge + EXACT,
                 "stripes s2(%zu) %g, triangle wave %g", r, shape[k].s2[r], 0.5 * (triangle + 0.5));
        }
      CHECK (near (shape[k].s2[6], 0.25, EXACT) && near (shape[k].s2[18], 0.25, EXACT),
             "stripes half a period apart never both in phase: %g %g", shape[k].s2[6], shape[k].s2[18]);
      CHECK (near (shape[k].s2[12], 0.5, EXACT) && near (shape[k].s2[24], 0.5, EXACT),
             "stripes a period apart always alike: %g %g", shape[k].s2[12], shape[k].s2[24]);
    }
  check_s2_brute (labels, w, h, 2, shape, "stripes");
  free (labels);
}

/* 5 x 5 tiles over 40 x 40: tiles of one colour touch only at corners,
 * so each is a component of its own. */
static void
test_checkerboard (void)
{
  const size_t w = 40, h = 40;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[2];

  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      labels[y * w + x] = (uint8_t) ((x / 5 + y / 5) % 2);
  measure (labels, w, h, 2, shape);
  for (int k = 0; k < 2; k++)
    {
      CHECK (near (shape[k].fraction, 0.5, EXACT), "checkerboard fraction %g", shape[k].fraction);
      CHECK (near (shape[k].chord_rows, 5.0, EXACT) && near (shape[k].chord_columns, 5.0, EXACT),
             "checkerboard chords %g %g", shape[k].chord_rows, shape[k].chord_columns);
      CHECK (shape[k].components == 32 && near (shape[k].solidity, 1.0, EXACT),
             "checkerboard: %zu components, solidity %g", shape[k].components, shape[k].solidity);
      CHECK (near (shape[k].s2[5], 0.0, EXACT) && near (shape[k].s2[10], 0.5, EXACT),
             "checkerboard s2(5) %g s2(10) %g", shape[k].s2[5], shape[k].s2[10]);
    }
  check_s2_brute (labels, w, h, 2, shape, "checkerboard");
  free (labels);
}

/* A 20 x 20 square missing its 10 x 10 top right quarter: area 300, hull
 * the square less the triangle cut across that corner, 350. */
static void
test_l_shape (void)
{
  const size_t w = 40, h = 40;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[2];

  fill_rect (labels, w, 5, 5, 15, 15, 1);
  fill_rect (labels, w, 5, 15, 25, 25, 1);
  measure (labels, w, h, 2, shape);
  CHECK (near (shape[1].solidity, 6.0 / 7.0, EXACT), "L solidity %.15g, want 6/7", shape[1].solidity);
  CHECK (near (shape[1].solidity, 300.0 / brute_hull_area (labels, w, h, 1), EXACT), "L hull");
  CHECK (near (shape[1].chord_rows, 15.0, EXACT) && near (shape[1].chord_columns, 15.0, EXACT),
         "L chords %g %g", shape[1].chord_rows, shape[1].chord_columns);
  free (labels);
}

/* Sides below the lags: s2 from the direction that has pairs, NAN where
 * neither has; an absent phase has no chords and no solidity. */
static void
test_edges (void)
{
  const size_t w = 20, h = 10;
  uint8_t *labels = new_labels (w, h);
  TsPhaseShape shape[3];

  fill_rect (labels, w, 0, 0, 12, 10, 1);
  measure (labels, w, h, 3, shape);
  CHECK (near (shape[1].s2[15], 0.0, EXACT) && near (shape[0].s2[15], 0.0, EXACT),
         "rows only at r = 15: %g %g", shape[1].s2[15], shape[0].s2[15]);
  CHECK (near (shape[1].s2[5], 0.5 * (7.0 / 15.0 + 12.0 / 20.0), EXACT), "s2(5) %g", shape[1].s2[5]);
  CHECK (isnan (shape[1].s2[20]) && isnan (shape[1].s2[32]), "no pairs at r = 20: %g", shape[1].s2[20]);
  CHECK (shape[2].fraction == 0.0 && isnan (shape[2].chord_rows) && isnan (shape[2].solidity)
           && shape[2].components == 0 && shape[2].s2[3] == 0.0,
         "absent phase: fraction %g chord %g solidity %g", shape[2].fraction, shape[2].chord_rows,
         shape[2].solidity);
  free (labels);
}

static TsImage
paint (const uint8_t *labels, size_t w, size_t h, const float colours[][3])
{
  TsImage image = { w, h, malloc (w * h * TS_CHANNELS * sizeof (float)) };
  if (!image.pixels)
    exit (99);
  for (size_t p = 0; p < w * h; p++)
    {
      /* a fixed, uneven jitter of up to 3 Lab units */
      float jitter = (float) ((p * 7919u) % 13u) / 2.0f - 3.0f;
      for (int c = 0; c < 3; c++)
        image.pixels[p * TS_CHANNELS + (size_t) c] = colours[labels[p]][c] + (c == 0 ? jitter : -0.5f * jitter);
      image.pixels[p * TS_CHANNELS + 3] = 1.0f;
    }
  return image;
}

/* Colour images of a disc and of three bands: k-means finds the colours
 * (darkest first whatever the labels), and the measures of the coloured
 * image are those of its labels. */
static void
test_kmeans (void)
{
  const size_t w = 60, h = 50;
  static const float two[2][3] = { { 80, -5, 20 }, { 30, 10, 5 } };
  static const float three[3][3] = { { 55, 40, 30 }, { 20, 0, -10 }, { 90, 0, 5 } };
  uint8_t *labels = new_labels (w, h), *found = new_labels (w, h);
  TsPhaseCentres centres, again;
  TsPhaseShape from_image[3], from_labels[3];
  TsImage image;

  /* both zeroed whole, padding included, to compare them byte for byte */
  memset (&centres, 0, sizeof centres);
  memset (&again, 0, sizeof again);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      labels[y * w + x] = (x - 30.0) * (x - 30.0) + (y - 25.0) * (y - 25.0) <= 144.0;
  image = paint (labels, w, h, two);
  CHECK (ts_shape_centres (&image, 2, &centres) == TS_MEASURE_OK, "k-means failed");
  CHECK (ts_shape_centres (&image, 2, &again) == TS_MEASURE_OK && !memcmp (&centres, &again, sizeof centres),
         "k-means must give the same centres every time");
  for (int c = 0; c < 3; c++)
    CHECK (near (centres.centre[0][c], two[1][c], 0.5) && near (centres.centre[1][c], two[0][c], 0.5),
           "centres (%g %g %g) (%g %g %g)", centres.centre[0][0], centres.centre[0][1], centres.centre[0][2],
           centres.centre[1][0], centres.centre[1][1], centres.centre[1][2]);
  ts_shape_label (&image, &centres, found);
  for (size_t p = 0; p < w * h; p++)
    CHECK (found[p] == 1 - labels[p], "pixel %zu in phase %d", p, found[p]);
  CHECK (ts_shape_measure (&image, &centres, from_image) == TS_MEASURE_OK, "measure failed");
  measure (found, w, h, 2, from_labels);
  CHECK (!memcmp (from_image, from_labels, 2 * sizeof from_image[0]), "image and labels measure apart");
  free (image.pixels);

  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      labels[y * w + x] = (uint8_t) (x < 15 ? 0 : x < 40 ? 1 : 2);
  image = paint (labels, w, h, three);
  CHECK (ts_shape_centres (&image, 3, &centres) == TS_MEASURE_OK && centres.phases == 3, "3 phases");
  for (int c = 0; c < 3; c++)
    CHECK (near (centres.centre[0][c], three[1][c], 0.5) && near (centres.centre[1][c], three[0][c], 0.5)
             && near (centres.centre[2][c], three[2][c], 0.5),
           "three centres, channel %d: %g %g %g", c, centres.centre[0][c], centres.centre[1][c], centres.centre[2][c]);
  CHECK (ts_shape_measure (&image, &centres, from_image) == TS_MEASURE_OK
           && near (from_image[0].fraction, 25.0 / 60.0, EXACT) && near (from_image[1].fraction, 15.0 / 60.0, EXACT)
           && near (from_image[2].fraction, 20.0 / 60.0, EXACT),
         "band fractions %g %g %g", from_image[0].fraction, from_image[1].fraction, from_image[2].fraction);
  CHECK (ts_shape_centres (&image, 4, &centres) == TS_MEASURE_TOO_SMALL, "4 phases must be refused");
  CHECK (ts_shape_centres (&image, 1, &centres) == TS_MEASURE_TOO_SMALL, "1 phase must be refused");
  free (image.pixels);
  free (labels);
  free (found);
}

int
main (void)
{
  test_square ();
  test_disc ();
  test_stripes ();
  test_checkerboard ();
  test_l_shape ();
  test_edges ();
  test_kmeans ();
  return test_finish ("test-shape-metrics");
}
