/* Matching on colour and a feature map (ts_feature_matching_image): bad
 * maps get their status and a message; without weight the matching image
 * is Lab turned rigidly (distances kept); with weight the features count;
 * the same bits every time; copying by a source map is exact. */
#include "test-util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 24
#define H 20

static void
expect_error (const TsImage *ex, const TsFeatureMap *f, double weight, TsStatus status,
              const char *words)
{
  TsError error = { TS_OK, "" };
  TsImage m;
  TsStatus got = ts_feature_matching_image (ex, f, weight, &m, &error);
  CHECK (got == status && error.status == status, "status %d, expected %d (%s)", got, status,
         error.message);
  CHECK (strstr (error.message, words) != NULL, "message '%s' should mention '%s'",
         error.message, words);
  CHECK (m.pixels == NULL && m.width == 0, "no matching image after a failure");
}

static double
distance (const TsImage *im, size_t a, size_t b, size_t channels)
{
  double sum = 0.0;
  for (size_t c = 0; c < channels; c++)
    {
      double d = im->pixels[a * TS_CHANNELS + c] - im->pixels[b * TS_CHANNELS + c];
      sum += d * d;
    }
  return sqrt (sum);
}

int
main (void)
{
  TsImage ex, m, m2;
  TsError error;
  float *height = malloc (W * H * sizeof (float)), *normal = malloc (W * H * 3 * sizeof (float));
  TsFeatureMap f = { W, H, 1, height }, f3 = { W, H, 3, normal }, wrong = { W - 1, H, 1, height };

  test_noise_image (&ex, W, H, 5);
  for (size_t i = 0; i < W * H; i++)
    {
      height[i] = (float) ((i % W) / 4 % 2);           /* stripes colour knows nothing of */
      for (size_t c = 0; c < 3; c++)
        normal[3 * i + c] = (float) ((i * 7 + c * 3) % 11) / 10.0f;
    }

  expect_error (&ex, &wrong, 1.0, TS_ERROR_BAD_PARAMETER, "23x20 but the exemplar 24x20");
  f.channels = 0;
  expect_error (&ex, &f, 1.0, TS_ERROR_BAD_PARAMETER, "1 to 4 channels");
  f.channels = 5;
  expect_error (&ex, &f, 1.0, TS_ERROR_BAD_PARAMETER, "1 to 4 channels");
  f.channels = 1;
  expect_error (&ex, &f, -1.0, TS_ERROR_BAD_PARAMETER, "weight must be 0 to 10");
  expect_error (&ex, &f, NAN, TS_ERROR_BAD_PARAMETER, "weight must be 0 to 10");
  height[3] = NAN;
  expect_error (&ex, &f, 1.0, TS_ERROR_BAD_PARAMETER, "not a number");
  height[3] = 0.0f;
  expect_error (&ex, NULL, 1.0, TS_ERROR_INVALID_ARGUMENT, "no exemplar");

  /* Weight 0: a rotation of Lab, so every distance stays. */
  CHECK (ts_feature_matching_image (&ex, &f, 0.0, &m, &error) == TS_OK, "weight 0: %s", error.message);
  double worst = 0.0;
  for (size_t a = 0; a < W * H; a += 7)
    for (size_t b = a + 1; b < W * H; b += 13)
      worst = fmax (worst, fabs (distance (&m, a, b, 3) - distance (&ex, a, b, 3)));
  CHECK (worst < 1e-3, "weight 0 keeps Lab distances (worst change %g)", worst);
  CHECK (memcmp (&m.pixels[3], &ex.pixels[3], sizeof (float)) == 0, "alpha kept");
  free (m.pixels);

  /* Weight 1: two pixels of the same colour but different height are
   * told apart; the same call gives the same bits. */
  memcpy (&ex.pixels[1 * TS_CHANNELS], &ex.pixels[5 * TS_CHANNELS], 3 * sizeof (float));
  CHECK (height[1] != height[5], "the test pixels differ in height");
  CHECK (ts_feature_matching_image (&ex, &f, 1.0, &m, &error) == TS_OK, "weight 1: %s", error.message);
  CHECK (distance (&m, 1, 5, 3) > 50.0, "same colour, other height: distance %.1f > 50",
         distance (&m, 1, 5, 3));
  CHECK (ts_feature_matching_image (&ex, &f, 1.0, &m2, &error) == TS_OK, "again");
  CHECK (memcmp (m.pixels, m2.pixels, W * H * TS_CHANNELS * sizeof (float)) == 0, "same bits");
  free (m.pixels);
  free (m2.pixels);
  CHECK (ts_feature_matching_image (&ex, &f3, 2.0, &m, &error) == TS_OK, "3 channels: %s",
         error.message);
  free (m.pixels);

  /* Copy by a source map. */
  int32_t map[4] = { 3, 2, 0, 19 };
  TsImage out = { 2, 1, malloc (2 * TS_CHANNELS * sizeof (float)) };
  ts_copy_by_source_map (&ex, map, &out);
  CHECK (memcmp (out.pixels, &ex.pixels[(2 * W + 3) * TS_CHANNELS], 16) == 0 &&
         memcmp (out.pixels + 4, &ex.pixels[(19 * W + 0) * TS_CHANNELS], 16) == 0,
         "copied by the map");
  free (out.pixels);
  free (height);
  free (normal);
  free (ex.pixels);
  return test_finish ("test-features");
}
