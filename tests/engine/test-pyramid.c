/* Gaussian pyramid: depth, sizes, filtering, alpha handling. */
#include "test-util.h"
#include "engine/pyramid.h"

#include <math.h>
#include <stdlib.h>

static void
test_depth (void)
{
  CHECK (ts_pyramid_depth_for (128, 128, 32) == 3, "128 -> 3 levels, got %zu", ts_pyramid_depth_for (128, 128, 32));
  CHECK (ts_pyramid_depth_for (256, 200, 32) == 4, "256x200 -> 4 levels (200,100,50,25)");
  CHECK (ts_pyramid_depth_for (20, 300, 32) == 1, "short side 20 -> 1 level");
  CHECK (ts_pyramid_depth_for (64, 64, 32) == 2, "64 -> 2 levels");
  /* The coarsest shorter side stays within [24, 64) for sides >= 24. */
  for (size_t side = 24; side < 3000; side += 7)
    {
      size_t levels = ts_pyramid_depth_for (side, side + 5, 32), s = side;
      for (size_t l = 1; l < levels; l++)
        s = (s + 1) / 2;
      CHECK (s >= 24 && s < 64, "side %zu: coarsest %zu", side, s);
    }
}

static void
test_reduce (void)
{
  TsImage in, out;
  CHECK (ts_image_alloc (&in, 9, 6) == TS_OK, "alloc");
  for (size_t i = 0; i < 9 * 6; i++)
    {
      float *p = in.pixels + i * TS_CHANNELS;
      p[0] = 50.0f; p[1] = -10.0f; p[2] = 20.0f; p[3] = 100.0f;
    }
  CHECK (ts_pyramid_reduce (&in, &out) == TS_OK, "reduce");
  CHECK (out.width == 5 && out.height == 3, "ceil sizes: %zux%zu", out.width, out.height);
  for (size_t i = 0; i < 5 * 3; i++)
    {
      const float *p = out.pixels + i * TS_CHANNELS;
      CHECK (fabsf (p[0] - 50.0f) < 1e-3f && fabsf (p[1] + 10.0f) < 1e-3f &&
             fabsf (p[2] - 20.0f) < 1e-3f && fabsf (p[3] - 100.0f) < 1e-3f,
             "a constant image stays constant");
    }
  ts_image_free (&out);

  /* Transparent pixels don't bleed their colour into opaque ones. */
  for (size_t y = 0; y < 6; y++)
    for (size_t x = 0; x < 9; x++)
      {
        float *p = ts_image_pixel (&in, x, y);
        p[0] = x < 4 ? 90.0f : 10.0f;
        p[3] = x < 4 ? 0.0f : 100.0f;
      }
  CHECK (ts_pyramid_reduce (&in, &out) == TS_OK, "reduce");
  for (size_t y = 0; y < out.height; y++)
    for (size_t x = 0; x < out.width; x++)
      {
        const float *p = ts_image_pixel (&out, x, y);
        if (p[3] > 0.0f)
          CHECK (fabsf (p[0] - 10.0f) < 1e-3f, "no bleed at (%zu,%zu): L=%f", x, y, p[0]);
      }
  ts_image_free (&out);
  ts_image_free (&in);
}

static void
test_build (void)
{
  TsImage noise;
  TsPyramid pyr;
  test_noise_image (&noise, 100, 70, 3);
  CHECK (ts_pyramid_build (&noise, 3, &pyr) == TS_OK, "build");
  CHECK (pyr.levels == 3, "levels");
  CHECK (pyr.level[1].width == 50 && pyr.level[1].height == 35, "level 1 size");
  CHECK (pyr.level[2].width == 25 && pyr.level[2].height == 18, "level 2 size");
  /* Filtering lowers the variance of noise. */
  double var[2] = { 0, 0 };
  for (int l = 0; l < 2; l++)
    {
      const TsImage *im = &pyr.level[2 * l];
      size_t n = im->width * im->height;
      double mean = 0, sq = 0;
      for (size_t i = 0; i < n; i++)
        mean += im->pixels[i * TS_CHANNELS];
      mean /= (double) n;
      for (size_t i = 0; i < n; i++)
        sq += pow (im->pixels[i * TS_CHANNELS] - mean, 2);
      var[l] = sq / (double) n;
    }
  CHECK (var[1] < var[0] * 0.9, "variance drops: %f -> %f", var[0], var[1]);
  ts_pyramid_free (&pyr);
  free (noise.pixels);
}

int
main (void)
{
  test_depth ();
  test_reduce ();
  test_build ();
  return test_finish ("test-pyramid");
}
