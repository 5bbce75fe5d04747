/* Bad input through the engine: every case gets its expected status, a
 * message, and leaves the caller's output untouched; every accepted case
 * gives finite pixels. Prints how many distinct bad inputs were tried.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SENTINEL -12345.0f

static int cases_tried, cases_refused, cases_accepted;

static float *
alloc_floats (size_t count)
{
  float *p = malloc ((count ? count : 1) * sizeof (float));
  if (!p)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  return p;
}

static void
fill_sentinel (TsImage *image)
{
  for (size_t i = 0; i < image->width * image->height * TS_CHANNELS; i++)
    image->pixels[i] = SENTINEL;
}

static bool
all_sentinel (const TsImage *image)
{
  for (size_t i = 0; i < image->width * image->height * TS_CHANNELS; i++)
    if (image->pixels[i] != SENTINEL)
      return false;
  return true;
}

static bool
all_finite_and_alpha_in_range (const TsImage *image)
{
  for (size_t i = 0; i < image->width * image->height; i++)
    {
      const float *p = image->pixels + i * TS_CHANNELS;
      if (!isfinite (p[0]) || !isfinite (p[1]) || !isfinite (p[2]) || !(p[3] >= 0.0f && p[3] <= 1.0f))
        return false;
    }
  return true;
}

/* Runs ts_synthesize on a sentinel-filled output of the params' size (or a
 * 1x1 one when that size is itself the bad input) and checks the outcome. */
static void
expect_synthesis (const char *what, const TsParams *params, const TsImage *exemplar,
                  TsStatus expected, const char *message_part)
{
  bool sized = params && params->output_width >= 1 && params->output_width <= 64 &&
               params->output_height >= 1 && params->output_height <= 64;
  TsImage out = { sized ? params->output_width : 1, sized ? params->output_height : 1, NULL };
  TsError error = { TS_OK, "" };
  TsStatus status;

  out.pixels = alloc_floats (out.width * out.height * TS_CHANNELS);
  fill_sentinel (&out);
  status = ts_synthesize (params, exemplar, &out, NULL, NULL, &error);
  cases_tried++;
  CHECK (status == expected, "%s: status %d (%s), expected %d; message: %s", what, (int) status,
         ts_status_string (status), (int) expected, error.message);
  if (status == TS_OK)
    {
      cases_accepted++;
      CHECK (all_finite_and_alpha_in_range (&out), "%s: the result has non-finite pixels", what);
    }
  else
    {
      cases_refused++;
      CHECK (error.message[0] != '\0', "%s: no message", what);
      CHECK (all_sentinel (&out), "%s: a failed synthesis changed the output", what);
      if (message_part)
        CHECK (strstr (error.message, message_part) != NULL, "%s: message \"%s\" lacks \"%s\"",
               what, error.message, message_part);
    }
  printf ("%-52s -> %s%s%s\n", what, ts_status_string (status), status ? ": " : "",
          status ? error.message : "");
  free (out.pixels);
}

static void
make_image (TsImage *image, size_t w, size_t h, float l, float a, float b, float alpha)
{
  image->width = w;
  image->height = h;
  image->pixels = alloc_floats (w * h * TS_CHANNELS);
  for (size_t i = 0; i < w * h; i++)
    {
      image->pixels[i * TS_CHANNELS + 0] = l;
      image->pixels[i * TS_CHANNELS + 1] = a;
      image->pixels[i * TS_CHANNELS + 2] = b;
      image->pixels[i * TS_CHANNELS + 3] = alpha;
    }
}

static TsParams
small_params (void)
{
  TsParams p;
  ts_params_init (&p);
  p.output_width = 24;
  p.output_height = 20;
  p.seed = 5;
  return p;
}

static void
test_degenerate_exemplars (void)
{
  TsParams p = small_params ();
  TsImage ex = { 0, 0, NULL }, tiny, flat, clear;
  float one_pixel[4] = { 50, 0, 0, 1 };

  expect_synthesis ("no parameters", NULL, &ex, TS_ERROR_INVALID_ARGUMENT, NULL);
  expect_synthesis ("no exemplar", &p, NULL, TS_ERROR_INVALID_ARGUMENT, NULL);
  expect_synthesis ("0x0 exemplar", &p, &ex, TS_ERROR_EMPTY_EXEMPLAR, "no pixels");
  ex.width = 7;
  expect_synthesis ("7x0 exemplar", &p, &ex, TS_ERROR_EMPTY_EXEMPLAR, "no pixels");
  ex.height = 7;
  expect_synthesis ("7x7 exemplar with no pixel data", &p, &ex, TS_ERROR_EMPTY_EXEMPLAR, NULL);

  ex = (TsImage) { 1, 1, one_pixel };
  expect_synthesis ("1x1 exemplar", &p, &ex, TS_ERROR_EXEMPLAR_TOO_SMALL, "at least");
  make_image (&tiny, 2, 40, 50, 0, 0, 1);
  expect_synthesis ("2x40 exemplar", &p, &tiny, TS_ERROR_EXEMPLAR_TOO_SMALL, "at least");
  free (tiny.pixels);

  /* Larger neighbourhoods than the exemplar: the engine shrinks them. */
  make_image (&tiny, 4, 4, 50, 10, -10, 1);
  tiny.pixels[0] = 90;
  p.patch_size = TS_MAX_PATCH_SIZE;
  p.fine_patch_size = TS_MAX_PATCH_SIZE;
  expect_synthesis ("4x4 exemplar, 31x31 neighbourhoods", &p, &tiny, TS_OK, NULL);
  free (tiny.pixels);
  p = small_params ();

  make_image (&flat, 16, 16, 42, 7, -3, 1);
  expect_synthesis ("one-colour exemplar", &p, &flat, TS_OK, NULL);
  make_image (&clear, 16, 16, 42, 7, -3, 0);
  expect_synthesis ("fully transparent exemplar", &p, &clear, TS_ERROR_TRANSPARENT_EXEMPLAR,
                    "transparent");
  /* Negative alpha is no more opaque than 0. */
  for (size_t i = 0; i < 16 * 16; i++)
    clear.pixels[i * TS_CHANNELS + 3] = -1.0f;
  expect_synthesis ("exemplar with negative alpha everywhere", &p, &clear,
                    TS_ERROR_TRANSPARENT_EXEMPLAR, "transparent");
  /* One opaque pixel: everything is copied from it. */
  clear.pixels[5 * 16 * TS_CHANNELS + 5 * TS_CHANNELS + 3] = 1.0f;
  expect_synthesis ("exemplar with a single opaque pixel", &p, &clear, TS_OK, NULL);
  free (flat.pixels);
  free (clear.pixels);
}

static void
test_non_finite_pixels (void)
{
  static const struct { const char *what; int channel; float value; bool every; TsStatus expect; } cases[] = {
    { "NaN L in some pixels", 0, NAN, false, TS_OK },
    { "+Inf a in some pixels", 1, INFINITY, false, TS_OK },
    { "-Inf b in some pixels", 2, -INFINITY, false, TS_OK },
    { "NaN alpha in some pixels", 3, NAN, false, TS_OK },
    { "+Inf alpha in some pixels", 3, INFINITY, false, TS_OK },
    { "huge finite L (1e30) in some pixels", 0, 1e30f, false, TS_OK },
    { "huge alpha (1e30) in some pixels", 3, 1e30f, false, TS_OK },
    { "NaN L in every pixel", 0, NAN, true, TS_OK },
    { "NaN alpha in every pixel", 3, NAN, true, TS_ERROR_TRANSPARENT_EXEMPLAR },
    { "+Inf alpha in every pixel", 3, INFINITY, true, TS_ERROR_TRANSPARENT_EXEMPLAR },
    { "FLT_MAX L in every pixel", 0, 3.4e38f, true, TS_OK },
  };
  TsParams p = small_params ();

  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
    {
      TsImage ex;
      test_noise_image (&ex, 20, 18, (unsigned) c);
      for (size_t i = 0; i < ex.width * ex.height; i++)
        if (cases[c].every || i % 7 == 3)
          ex.pixels[i * TS_CHANNELS + cases[c].channel] = cases[c].value;
      expect_synthesis (cases[c].what, &p, &ex, cases[c].expect, NULL);
      p.wrap_x = p.wrap_y = true;
      expect_synthesis (cases[c].what, &p, &ex, cases[c].expect, NULL);
      p.wrap_x = p.wrap_y = false;
      free (ex.pixels);
    }
}

static void
test_parameter_ranges (void)
{
  static const struct { const char *what; int field; long long value; TsStatus expect; } cases[] = {
    { "output width 0", 0, 0, TS_ERROR_BAD_PARAMETER },
    { "output width 16385", 0, TS_MAX_OUTPUT_SIDE + 1, TS_ERROR_BAD_PARAMETER },
    { "output height 0", 1, 0, TS_ERROR_BAD_PARAMETER },
    { "output height SIZE_MAX", 1, -1, TS_ERROR_BAD_PARAMETER },
    { "quality 0", 2, 0, TS_ERROR_BAD_PARAMETER },
    { "quality 11", 2, 11, TS_ERROR_BAD_PARAMETER },
    { "quality INT_MIN", 2, INT_MIN, TS_ERROR_BAD_PARAMETER },
    { "quality INT_MAX", 2, INT_MAX, TS_ERROR_BAD_PARAMETER },
    { "patch size 1", 3, 1, TS_ERROR_BAD_PARAMETER },
    { "patch size 4 (even)", 3, 4, TS_ERROR_BAD_PARAMETER },
    { "patch size 33", 3, 33, TS_ERROR_BAD_PARAMETER },
    { "patch size -1", 3, -1, TS_ERROR_BAD_PARAMETER },
    { "fine patch size 2", 4, 2, TS_ERROR_BAD_PARAMETER },
    { "fine patch size INT_MAX", 4, INT_MAX, TS_ERROR_BAD_PARAMETER },
    { "iterations -1", 5, -1, TS_ERROR_BAD_PARAMETER },
    { "iterations 101", 5, 101, TS_ERROR_BAD_PARAMETER },
    /* Every limit itself is accepted. */
    { "output width 1", 0, 1, TS_OK },
    { "output height 1", 1, 1, TS_OK },
    { "quality 1", 2, TS_MIN_QUALITY, TS_OK },
    { "quality 10", 2, TS_MAX_QUALITY, TS_OK },
    { "patch size 3", 3, TS_MIN_PATCH_SIZE, TS_OK },
    { "patch size 31", 3, TS_MAX_PATCH_SIZE, TS_OK },
    { "fine patch size 3", 4, TS_MIN_PATCH_SIZE, TS_OK },
    { "fine patch size 31", 4, TS_MAX_PATCH_SIZE, TS_OK },
    { "iterations 1", 5, 1, TS_OK },
    { "iterations 100", 5, TS_MAX_ITERATIONS, TS_OK },
    { "seed 0", 6, 0, TS_OK },
    { "seed UINT32_MAX", 6, UINT32_MAX, TS_OK },
  };
  TsImage ex;

  test_noise_image (&ex, 32, 32, 3);
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
    {
      TsParams p = small_params ();
      long long v = cases[c].value;
      switch (cases[c].field)
        {
        case 0: p.output_width = v < 0 ? SIZE_MAX : (size_t) v; break;
        case 1: p.output_height = v < 0 ? SIZE_MAX : (size_t) v; break;
        case 2: p.quality = (int) v; break;
        case 3: p.patch_size = (int) v; break;
        case 4: p.fine_patch_size = (int) v; break;
        case 5: p.max_iterations = (int) v; break;
        case 6: p.seed = (uint32_t) v; break;
        }
      expect_synthesis (cases[c].what, &p, &ex, cases[c].expect, NULL);
    }

  {
    TsParams p = small_params ();
    p.patch_size = 5;
    p.fine_patch_size = 7;
    expect_synthesis ("fine patch size above patch size", &p, &ex, TS_ERROR_BAD_PARAMETER, "exceed");
    p = small_params ();
    p.output_width = p.output_height = 1;
    p.wrap_x = p.wrap_y = true;
    expect_synthesis ("1x1 tileable output", &p, &ex, TS_OK, NULL);
    p = small_params ();
    p.quality = TS_MAX_QUALITY;
    p.patch_size = p.fine_patch_size = TS_MAX_PATCH_SIZE;
    p.max_iterations = TS_MAX_ITERATIONS;
    p.wrap_x = true;
    expect_synthesis ("every property at its maximum", &p, &ex, TS_OK, NULL);
  }
  free (ex.pixels);
}

static void
test_inconsistent_arguments (void)
{
  TsParams p = small_params ();
  TsImage ex, out;
  TsError error = { TS_OK, "" };
  int32_t *source;
  float *preserve;
  size_t n = p.output_width * p.output_height;

  test_noise_image (&ex, 16, 16, 9);
  p.preserve = (float[1]) { 0.5f };
  expect_synthesis ("preserve weights without a source map", &p, &ex,
                    TS_ERROR_INVALID_ARGUMENT, "initial source");

  source = calloc (2 * n, sizeof (int32_t));
  preserve = calloc (n, sizeof (float));
  if (!source || !preserve)
    exit (1);
  p = small_params ();
  p.initial_source = source;
  source[2 * (n - 1)] = 16;
  expect_synthesis ("initial source outside the exemplar", &p, &ex, TS_ERROR_INVALID_ARGUMENT,
                    "outside");
  source[2 * (n - 1)] = -1;
  expect_synthesis ("negative initial source", &p, &ex, TS_ERROR_INVALID_ARGUMENT, "outside");
  source[2 * (n - 1)] = 0;
  p.preserve = preserve;
  preserve[3] = NAN;
  expect_synthesis ("NaN preserve weight", &p, &ex, TS_ERROR_INVALID_ARGUMENT, "[0, 1]");
  preserve[3] = 1.5f;
  expect_synthesis ("preserve weight 1.5", &p, &ex, TS_ERROR_INVALID_ARGUMENT, "[0, 1]");
  free (source);
  free (preserve);

  /* Output of the wrong size, or none: refused, nothing written. */
  p = small_params ();
  out = (TsImage) { p.output_width + 1, p.output_height, alloc_floats ((p.output_width + 1) * p.output_height * TS_CHANNELS) };
  fill_sentinel (&out);
  cases_tried++;
  CHECK (ts_synthesize (&p, &ex, &out, NULL, NULL, &error) == TS_ERROR_INVALID_ARGUMENT &&
         all_sentinel (&out), "an output of the wrong size is refused untouched");
  CHECK (ts_synthesize (&p, &ex, NULL, NULL, NULL, NULL) == TS_ERROR_INVALID_ARGUMENT,
         "no output image is refused");
  cases_tried++;
  cases_refused += 2;
  printf ("%-52s -> %s\n", "output of the wrong size / no output", error.message);
  free (out.pixels);
  free (ex.pixels);
}

/* Huge outputs are refused from the estimate, before any allocation (the
 * 1x1 output shows the caller need not allocate either); a raised limit
 * lets a size through that the default refuses. */
static void
test_memory_refusal (void)
{
  TsParams p = small_params ();
  TsImage ex;
  TsError error = { TS_OK, "" };
  size_t bytes = 0;

  test_noise_image (&ex, 64, 64, 4);
  p.output_width = p.output_height = TS_MAX_OUTPUT_SIDE;
  CHECK (ts_estimate_memory (&p, &ex, &bytes, &error) == TS_OK && bytes > ((size_t) 8 << 30),
         "16384x16384 estimate is over 8 GiB: %zu", bytes);
  p.memory_limit = (size_t) 4 << 30;
  expect_synthesis ("16384x16384 output under a 4 GiB limit", &p, &ex, TS_ERROR_TOO_LARGE, "MiB");
  {
    char needed[64];
    TsError e2;
    ts_params_validate (&p, &ex, &e2);
    snprintf (needed, sizeof needed, "%.1f MiB", (double) bytes / 1048576.0);
    CHECK (strstr (e2.message, needed) != NULL, "message gives the need (%s): %s", needed, e2.message);
    CHECK (strstr (e2.message, "4096.0 MiB") != NULL, "message gives the limit: %s", e2.message);
  }

  p = small_params ();
  p.memory_limit = 1 << 20;
  expect_synthesis ("24x20 output under a 1 MiB limit", &p, &ex, TS_ERROR_TOO_LARGE, "limit");
  p.memory_limit = (size_t) 64 << 20;
  expect_synthesis ("24x20 output, limit raised to 64 MiB", &p, &ex, TS_OK, NULL);
  p.memory_limit = SIZE_MAX;
  expect_synthesis ("24x20 output, limit SIZE_MAX", &p, &ex, TS_OK, NULL);

  /* A huge exemplar is refused on its size before its pixels are read. */
  {
    TsImage huge = { (size_t) 1 << 40, 4, ex.pixels };
    expect_synthesis ("2^40 x 4 exemplar", &p, &huge, TS_ERROR_BAD_PARAMETER, "at most");
    huge = (TsImage) { SIZE_MAX, SIZE_MAX, ex.pixels };
    expect_synthesis ("SIZE_MAX x SIZE_MAX exemplar", &p, &huge, TS_ERROR_BAD_PARAMETER, "at most");
  }
  CHECK (ts_estimate_memory (&p, &ex, NULL, &error) == TS_ERROR_INVALID_ARGUMENT,
         "estimate without a place to store it is refused");
  free (ex.pixels);
}

static void
expect_tileable (const char *what, const TsTileableParams *params, const TsImage *input,
                 TsStatus expected)
{
  TsImage out = { input ? input->width : 1, input ? input->height : 1, NULL };
  TsError error = { TS_OK, "" };
  TsStatus status;

  if (out.width * out.height == 0 || out.width > 4096)
    out.width = out.height = 1;
  out.pixels = alloc_floats (out.width * out.height * TS_CHANNELS);
  fill_sentinel (&out);
  status = ts_make_tileable (params, input, &out, NULL, NULL, &error);
  cases_tried++;
  CHECK (status == expected, "tileable, %s: status %d (%s), expected %d; %s", what, (int) status,
         ts_status_string (status), (int) expected, error.message);
  if (status == TS_OK)
    {
      cases_accepted++;
      CHECK (all_finite_and_alpha_in_range (&out), "tileable, %s: non-finite result", what);
    }
  else
    {
      cases_refused++;
      CHECK (error.message[0] != '\0', "tileable, %s: no message", what);
      CHECK (all_sentinel (&out), "tileable, %s: output changed on failure", what);
    }
  printf ("tileable: %-42s -> %s%s%s\n", what, ts_status_string (status), status ? ": " : "",
          status ? error.message : "");
  free (out.pixels);
}

static void
test_tileable_inputs (void)
{
  TsTileableParams p;
  TsImage in, small, clear;

  ts_tileable_params_init (&p);
  p.seed = 2;
  test_noise_image (&in, 40, 36, 6);
  expect_tileable ("no parameters", NULL, &in, TS_ERROR_INVALID_ARGUMENT);
  expect_tileable ("no input", &p, NULL, TS_ERROR_INVALID_ARGUMENT);
  p.seam_width = NAN;
  expect_tileable ("NaN seam width", &p, &in, TS_ERROR_BAD_PARAMETER);
  p.seam_width = 0.0;
  expect_tileable ("seam width 0", &p, &in, TS_ERROR_BAD_PARAMETER);
  p.seam_width = INFINITY;
  expect_tileable ("infinite seam width", &p, &in, TS_ERROR_BAD_PARAMETER);
  p.seam_width = TS_TILEABLE_MAX_SEAM_WIDTH;
  expect_tileable ("largest seam width", &p, &in, TS_OK);
  p.seam_width = TS_TILEABLE_MIN_SEAM_WIDTH;
  expect_tileable ("smallest seam width", &p, &in, TS_OK);
  ts_tileable_params_init (&p);
  p.direction = (TsTileableDirection) 99;
  expect_tileable ("direction 99", &p, &in, TS_ERROR_BAD_PARAMETER);
  ts_tileable_params_init (&p);
  p.quality = 0;
  expect_tileable ("quality 0", &p, &in, TS_ERROR_BAD_PARAMETER);
  ts_tileable_params_init (&p);
  for (size_t i = 0; i < in.width * in.height; i += 5)
    in.pixels[i * TS_CHANNELS] = NAN;
  expect_tileable ("NaN pixels", &p, &in, TS_OK);

  make_image (&small, TS_TILEABLE_MIN_SIDE - 1, 40, 50, 0, 0, 1);
  expect_tileable ("input narrower than the minimum", &p, &small, TS_ERROR_EXEMPLAR_TOO_SMALL);
  p.direction = TS_TILEABLE_VERTICAL;
  expect_tileable ("narrow input, vertical only", &p, &small, TS_OK);
  ts_tileable_params_init (&p);
  make_image (&clear, 20, 20, 50, 0, 0, 0);
  expect_tileable ("fully transparent input", &p, &clear, TS_ERROR_TRANSPARENT_EXEMPLAR);
  free (in.pixels);
  free (small.pixels);
  free (clear.pixels);
}

int
main (void)
{
  test_degenerate_exemplars ();
  test_non_finite_pixels ();
  test_parameter_ranges ();
  test_inconsistent_arguments ();
  test_memory_refusal ();
  test_tileable_inputs ();
  printf ("\nbad-input figures: %d distinct inputs tried, %d refused with a message, "
          "%d accepted with a finite result, 0 crashes\n", cases_tried, cases_refused,
          cases_accepted);
  return test_finish ("test-bad-input");
}
