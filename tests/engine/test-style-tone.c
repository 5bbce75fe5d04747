/* Style transfer's tone step on a result of pure grain (white noise
 * around one lightness), an exemplar of grain over a ramp and a picture
 * of gradients: the result's
 * blurred lightness must come to follow the picture's, its grain (what
 * the blur leaves out) and its colour must stay, transparent pixels and
 * a guide weight of 0 must leave it as it was, and a tileable result's
 * shift must continue across its edges. */
#include "test-util.h"
#include "engine/guide-style.h"
#include "engine/style-tone.h"
#include "guided-metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { SIDE = 96, EX_SIDE = 48 };

/* Uniform in [-1, 1), from a fixed sequence. */
static double
noise (uint32_t *state)
{
  *state = *state * 1664525u + 1013904223u;
  return (double) (*state >> 8) / (double) (1u << 23) - 1.0;
}

/* A grain image: L 50 plus noise of amplitude `grain`, a and b fixed. */
static bool
grain_image (TsImage *image, size_t side, double grain, uint32_t seed)
{
  image->width = image->height = side;
  image->pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  if (!image->pixels)
    return false;
  for (size_t i = 0; i < side * side; i++)
    {
      float *p = image->pixels + i * TS_CHANNELS;
      p[0] = (float) (50.0 + grain * noise (&seed));
      p[1] = 10.0f;
      p[2] = -20.0f;
      p[3] = 1.0f;
    }
  return true;
}

/* Channel 0 of `image` as lightness / 100, blurred as the step blurs. */
static bool
tone (const TsImage *image, bool wrap, float *out)
{
  size_t n = image->width * image->height;

  for (size_t i = 0; i < n; i++)
    out[i] = image->pixels[i * TS_CHANNELS] / 100.0f;
  return ts_blur_values (out, 1, image->width, image->height, TS_STYLE_GUIDE_BLUR, wrap,
                         wrap) == TS_OK;
}

static void
test_follows_picture (const TsImage *ex, const float *picture)
{
  size_t n = SIDE * SIDE;
  TsImage before, after;
  TsGuides guides;
  float *tone_before = malloc (n * sizeof (float)), *tone_after = malloc (n * sizeof (float));
  bool ok = tone_before && tone_after && grain_image (&before, SIDE, 12.0, 7) &&
            grain_image (&after, SIDE, 12.0, 7);

  CHECK (ok, "memory for the tone test");
  if (!ok)
    return;
  ts_guides_init (&guides);
  guides.target_guide = picture;
  CHECK (ts_style_tone (&guides, ex, false, false, &after) == TS_OK, "the tone step runs");

  ok = tone (&before, false, tone_before) &&
       tone (&after, false, tone_after);
  CHECK (ok, "tones computed");
  if (ok)
    {
      /* The measure: correlation of lightness blurred by 4 px. */
      double r_before = NAN, r_after = NAN;
      TsImage picture_lab = { SIDE, SIDE, calloc (n * TS_CHANNELS, sizeof (float)) };
      if (picture_lab.pixels)
        for (size_t i = 0; i < n; i++)
          picture_lab.pixels[i * TS_CHANNELS] = picture[i] * 100.0f;
      CHECK (picture_lab.pixels &&
               ts_measure_style_correlation (&picture_lab, &before, &r_before) == TS_MEASURE_OK &&
               ts_measure_style_correlation (&picture_lab, &after, &r_after) == TS_MEASURE_OK,
             "the correlations measured");
      free (picture_lab.pixels);
      printf ("tone: blurred L correlation with the picture %.3f -> %.3f\n", r_before, r_after);
      CHECK (r_after >= 0.9, "the result's tone follows the picture's (%.3f >= 0.9)", r_after);

      /* The grain: each pixel's difference from its tone, before and
       * after, apart by a small share of the grain's own spread. */
      double grain = 0.0, moved = 0.0, colour = 0.0;
      for (size_t i = 0; i < n; i++)
        {
          double g0 = before.pixels[i * TS_CHANNELS] / 100.0 - tone_before[i];
          double g1 = after.pixels[i * TS_CHANNELS] / 100.0 - tone_after[i];
          grain += g0 * g0;
          moved += (g1 - g0) * (g1 - g0);
          colour = fmax (colour, fabs (after.pixels[i * TS_CHANNELS + 1] - 10.0f) +
                                     fabs (after.pixels[i * TS_CHANNELS + 2] + 20.0f));
        }
      double ratio = sqrt (moved / grain);
      printf ("tone: grain changed by %.3f of its spread\n", ratio);
      CHECK (ratio <= 0.1, "the grain stays (changed by %.3f of its spread, <= 0.1)", ratio);
      CHECK (colour == 0.0, "a and b stay (largest change %g)", colour);
    }
  free (before.pixels);
  free (after.pixels);
  free (tone_before);
  free (tone_after);
}

/* Transparent pixels and a guide weight of 0 stay as they were. */
static void
test_left_alone (const TsImage *ex, const float *picture)
{
  size_t n = SIDE * SIDE;
  TsImage before, after;
  TsGuides guides;

  if (!grain_image (&before, SIDE, 12.0, 3) || !grain_image (&after, SIDE, 12.0, 3))
    {
      CHECK (false, "memory for the tone test");
      return;
    }
  for (size_t i = 0; i < n; i += 5)
    before.pixels[i * TS_CHANNELS + 3] = after.pixels[i * TS_CHANNELS + 3] = 0.0f;
  ts_guides_init (&guides);
  guides.target_guide = picture;
  ts_style_tone (&guides, ex, false, false, &after);
  size_t changed = 0, transparent_changed = 0;
  for (size_t i = 0; i < n; i++)
    if (after.pixels[i * TS_CHANNELS] != before.pixels[i * TS_CHANNELS])
      {
        changed++;
        transparent_changed += i % 5 == 0;
      }
  CHECK (changed > n / 2, "visible pixels move (%zu of %zu)", changed, n);
  CHECK (transparent_changed == 0, "transparent pixels stay (%zu moved)", transparent_changed);

  memcpy (after.pixels, before.pixels, n * TS_CHANNELS * sizeof (float));
  guides.weight = 0.0;
  ts_style_tone (&guides, ex, false, false, &after);
  CHECK (memcmp (after.pixels, before.pixels, n * TS_CHANNELS * sizeof (float)) == 0,
         "a guide weight of 0 leaves the result as synthesised");
  free (before.pixels);
  free (after.pixels);
}

/* Tileable: the shift across the wrapped edge is no larger than the
 * largest between two neighbours inside. */
static void
test_tileable (const TsImage *ex, const float *picture)
{
  TsImage before, after;
  TsGuides guides;

  if (!grain_image (&before, SIDE, 12.0, 11) || !grain_image (&after, SIDE, 12.0, 11))
    {
      CHECK (false, "memory for the tone test");
      return;
    }
  ts_guides_init (&guides);
  guides.target_guide = picture;
  ts_style_tone (&guides, ex, true, true, &after);
  double inside = 0.0, across = 0.0;
  for (size_t y = 0; y < SIDE; y++)
    for (size_t x = 0; x < SIDE; x++)
      {
        size_t i = y * SIDE + x, right = y * SIDE + (x + 1) % SIDE;
        double step = fabs ((after.pixels[right * TS_CHANNELS] - before.pixels[right * TS_CHANNELS]) -
                            (after.pixels[i * TS_CHANNELS] - before.pixels[i * TS_CHANNELS]));
        if (x + 1 < SIDE)
          inside = fmax (inside, step);
        else
          across = fmax (across, step);
      }
  printf ("tone, tileable: largest shift step %.3f inside, %.3f across the edge\n", inside, across);
  CHECK (across <= inside, "a tileable result's shift continues across its edge (%.3f <= %.3f)",
         across, inside);
  free (before.pixels);
  free (after.pixels);
}

int
main (void)
{
  TsImage ex;
  float *picture = malloc (SIDE * SIDE * sizeof (float));

  if (!picture || !grain_image (&ex, EX_SIDE, 20.0, 1))
    {
      fprintf (stderr, "out of memory\n");
      return 1;
    }
  /* The exemplar's tones span a range, as a picture's do: a ramp
   * under its grain. */
  for (size_t y = 0; y < EX_SIDE; y++)
    for (size_t x = 0; x < EX_SIDE; x++)
      ex.pixels[(y * EX_SIDE + x) * TS_CHANNELS] += (float) (30.0 * (double) x / EX_SIDE - 15.0);
  /* A picture tileable across, dark to light to dark, and a gradient
   * down. */
  for (size_t y = 0; y < SIDE; y++)
    for (size_t x = 0; x < SIDE; x++)
      picture[y * SIDE + x] = (float) (0.3 + 0.2 * sin (2.0 * 3.14159265358979 * (double) x / SIDE) +
                                       0.2 * (double) y / SIDE);
  test_follows_picture (&ex, picture);
  test_left_alone (&ex, picture);
  test_tileable (&ex, picture);
  free (ex.pixels);
  free (picture);
  return test_finish ("test-style-tone");
}
