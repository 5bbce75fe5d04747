/* Which way round the slices read one shared exemplar
 * (common/solid/handedness.c). Lines that fall diagonally cannot be
 * sheets of a solid in all three orientations read the same way round;
 * the engine reads the exemplar mirrored across x, and then every slice
 * shows the lines. Rising lines and per-axis exemplars are read as
 * given, and the recorded sources always name the caller's pixels.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"
#include "solid/solid.h"
#include "slice-figures.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define EDGE 32
#define PERIOD 8.0

typedef enum
{
  FALLING, /* lines along (1, 1), image y down */
  RISING,  /* lines along (1, -1) */
  UPRIGHT  /* vertical lines */
} Lines;

static void
stripes (Lines lines, TsImage *image)
{
  CHECK (ts_image_alloc (image, EDGE, EDGE) == TS_OK, "out of memory");
  for (size_t y = 0; y < EDGE; y++)
    for (size_t x = 0; x < EDGE; x++)
      {
        double t = lines == FALLING ? (double) x - (double) y
                   : lines == RISING ? (double) x + (double) y : (double) x;
        float *p = image->pixels + (y * EDGE + x) * TS_CHANNELS;
        p[0] = (float) (50.0 + 30.0 * sin (2.0 * 3.14159265358979323846 * t / PERIOD));
        p[1] = p[2] = 0.0f;
        p[3] = 1.0f;
      }
}

static void
test_bias (void)
{
  TsImage falling, rising, upright, flat;

  stripes (FALLING, &falling);
  stripes (RISING, &rising);
  stripes (UPRIGHT, &upright);
  CHECK (ts_image_alloc (&flat, EDGE, EDGE) == TS_OK, "out of memory");
  for (size_t p = 0; p < EDGE * EDGE; p++)
    flat.pixels[p * TS_CHANNELS] = 40.0f, flat.pixels[p * TS_CHANNELS + 3] = 1.0f;
  CHECK (ts_solid_diagonal_bias (&falling) < -0.95, "falling lines: bias %.3f, expected near -1",
         ts_solid_diagonal_bias (&falling));
  CHECK (ts_solid_diagonal_bias (&rising) > 0.95, "rising lines: bias %.3f, expected near 1",
         ts_solid_diagonal_bias (&rising));
  CHECK (fabs (ts_solid_diagonal_bias (&upright)) < 0.01, "upright lines: bias %.3f, expected 0",
         ts_solid_diagonal_bias (&upright));
  CHECK (ts_solid_diagonal_bias (&flat) == 0.0, "flat image: bias %.3f, expected 0",
         ts_solid_diagonal_bias (&flat));
  /* Transparent pixels carry no edges. */
  for (size_t p = 0; p < EDGE * EDGE; p++)
    falling.pixels[p * TS_CHANNELS + 3] = 0.0f;
  CHECK (ts_solid_diagonal_bias (&falling) == 0.0, "transparent image: bias %.3f, expected 0",
         ts_solid_diagonal_bias (&falling));
  /* Mirrored, falling lines rise. */
  ts_solid_mirror_image (&rising);
  CHECK (ts_solid_diagonal_bias (&rising) < -0.95, "mirrored rising lines: bias %.3f",
         ts_solid_diagonal_bias (&rising));
  ts_image_free (&falling);
  ts_image_free (&rising);
  ts_image_free (&upright);
  ts_image_free (&flat);
}

/* Synthesises EDGE^3 from `ex` on every orientation; checks the sources'
 * round trip and returns the middle slices' biases. */
static void
slice_biases (const TsImage *const ex[3], double bias[3])
{
  size_t voxels = (size_t) EDGE * EDGE * EDGE, wrong = 0;
  float *volume = malloc (voxels * TS_CHANNELS * sizeof (float));
  float *laid = malloc (voxels * TS_CHANNELS * sizeof (float));
  TsSolidSource *sources = malloc (voxels * sizeof (TsSolidSource));
  const void *maps[3];
  size_t pixels[3];
  TsSolidParams p;
  TsError error;

  CHECK (volume && laid && sources, "out of memory");
  ts_solid_params_init (&p);
  p.size = EDGE;
  p.seed = 5;
  p.record_sources = true;
  CHECK (ts_synthesize_solid_with_sources (&p, ex, volume, sources, NULL, NULL, &error) == TS_OK,
         "synthesis: %s", error.message);
  for (int a = 0; a < 3; a++)
    {
      maps[a] = ex[a]->pixels;
      pixels[a] = ex[a]->width * ex[a]->height;
    }
  CHECK (ts_solid_apply_sources (sources, voxels, maps, pixels, TS_CHANNELS * sizeof (float), laid,
                                 &error) == TS_OK, "applying the sources: %s", error.message);
  for (size_t v = 0; v < voxels; v++)
    wrong += memcmp (laid + v * TS_CHANNELS, volume + v * TS_CHANNELS,
                     3 * sizeof (float)) != 0;
  CHECK (wrong == 0, "%zu of %zu voxels differ from the caller's pixels their sources name",
         wrong, voxels);
  for (int a = 0; a < 3; a++)
    {
      TsImage slice;
      CHECK (ts_image_alloc (&slice, EDGE, EDGE) == TS_OK, "out of memory");
      slice_cut (volume, EDGE, a, EDGE / 2, &slice);
      bias[a] = ts_solid_diagonal_bias (&slice);
      ts_image_free (&slice);
    }
  free (volume);
  free (laid);
  free (sources);
}

static void
test_solids (void)
{
  TsImage falling, rising, falling_y, falling_z;
  double bias[3];

  stripes (FALLING, &falling);
  stripes (RISING, &rising);
  stripes (FALLING, &falling_y);
  stripes (FALLING, &falling_z);

  /* Mirrored across x: the sheets x - y - z = c. */
  const TsImage *shared_falling[3] = { &falling, &falling, &falling };
  slice_biases (shared_falling, bias);
  printf ("falling lines, one exemplar: slice biases x %.3f y %.3f z %.3f\n", bias[0], bias[1],
          bias[2]);
  CHECK (bias[0] > 0.7 && bias[1] < -0.7 && bias[2] < -0.7,
         "falling lines: the slices across x should rise (> 0.7), across y and z fall (< -0.7)");

  /* As given: the sheets x + y + z = c. */
  const TsImage *shared_rising[3] = { &rising, &rising, &rising };
  slice_biases (shared_rising, bias);
  printf ("rising lines, one exemplar: slice biases x %.3f y %.3f z %.3f\n", bias[0], bias[1],
          bias[2]);
  CHECK (bias[0] > 0.7 && bias[1] > 0.7 && bias[2] > 0.7,
         "rising lines: every slice should rise (> 0.7)");

  /* Per-axis exemplars are read as given: a caller who mirrors the
   * exemplar across x gets the same sheets. */
  const TsImage *per_axis[3] = { &rising, &falling_y, &falling_z };
  slice_biases (per_axis, bias);
  printf ("rising lines across x, falling across y and z: slice biases x %.3f y %.3f z %.3f\n",
          bias[0], bias[1], bias[2]);
  CHECK (bias[0] > 0.7 && bias[1] < -0.7 && bias[2] < -0.7,
         "per-axis exemplars: the slices across x should rise (> 0.7), across y and z fall (< -0.7)");

  ts_image_free (&falling);
  ts_image_free (&rising);
  ts_image_free (&falling_y);
  ts_image_free (&falling_z);
}

int
main (void)
{
  test_bias ();
  test_solids ();
  return test_finish ("test-solid-handedness");
}
