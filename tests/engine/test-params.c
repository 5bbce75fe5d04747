/* Parameter validation: every bad value gets its status and a message
 * that names the problem. */
#include "test-util.h"

#include <stdlib.h>
#include <string.h>

static TsImage exemplar;

static void
expect (const TsParams *p, const TsImage *ex, TsStatus status, const char *words)
{
  TsError error = { TS_OK, "" };
  TsStatus got = ts_params_validate (p, ex, &error);
  CHECK (got == status, "status %d, expected %d (%s)", got, status, error.message);
  if (status != TS_OK)
    {
      CHECK (error.status == status, "error.status %d", error.status);
      CHECK (strstr (error.message, words) != NULL, "message '%s' should mention '%s'",
             error.message, words);
    }
}

int
main (void)
{
  TsParams p;
  TsImage empty = { 0, 0, NULL }, tiny;

  test_noise_image (&exemplar, 40, 30, 1);
  ts_params_init (&p);
  CHECK (p.output_width == 512 && p.output_height == 512, "default size");
  CHECK (p.quality >= TS_MIN_QUALITY && p.quality <= TS_MAX_QUALITY, "default quality");
  expect (&p, &exemplar, TS_OK, "");

  expect (NULL, &exemplar, TS_ERROR_INVALID_ARGUMENT, "no parameters");
  expect (&p, &empty, TS_ERROR_EMPTY_EXEMPLAR, "no pixels");

  p.output_width = 0;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "1 to 16384");
  p.output_width = 16385;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "16385x512");
  ts_params_init (&p);
  p.quality = 11;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "quality");
  ts_params_init (&p);
  p.patch_size = 8;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "odd");
  ts_params_init (&p);
  p.patch_size = 7;
  p.fine_patch_size = 9;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "must not exceed");
  ts_params_init (&p);
  p.max_iterations = -1;
  expect (&p, &exemplar, TS_ERROR_BAD_PARAMETER, "iterations");

  ts_params_init (&p);
  test_noise_image (&tiny, 2, 5, 1);
  expect (&p, &tiny, TS_ERROR_EXEMPLAR_TOO_SMALL, "2x5");
  for (size_t i = 0; i < 40 * 30; i++)
    exemplar.pixels[i * TS_CHANNELS + 3] = 0.0f;
  expect (&p, &exemplar, TS_ERROR_TRANSPARENT_EXEMPLAR, "fully transparent");
  exemplar.pixels[3] = 0.5f;
  expect (&p, &exemplar, TS_OK, "");

  /* Memory: the estimate grows with the output; a limit refuses with the
   * amount needed. */
  size_t small = 0, large = 0;
  CHECK (ts_estimate_memory (&p, &exemplar, &small, NULL) == TS_OK, "estimate");
  p.output_width = p.output_height = 4096;
  CHECK (ts_estimate_memory (&p, &exemplar, &large, NULL) == TS_OK, "estimate");
  CHECK (large > small * 12 && large > (size_t) 4096 * 4096 * 32, "estimate grows: %zu %zu", small, large);
  p.memory_limit = (size_t) 64 << 20;
  expect (&p, &exemplar, TS_ERROR_TOO_LARGE, "MiB");

  /* Preserve weights need a source map, and sources must be inside. */
  ts_params_init (&p);
  float preserve[4] = { 0, 0, 0, 0 };
  int32_t sources[8] = { 0, 0, 1, 1, 2, 2, 40, 0 };
  p.output_width = p.output_height = 2;
  p.preserve = preserve;
  expect (&p, &exemplar, TS_ERROR_INVALID_ARGUMENT, "initial source map");
  p.initial_source = sources;
  expect (&p, &exemplar, TS_ERROR_INVALID_ARGUMENT, "outside the exemplar");
  sources[6] = 39;
  expect (&p, &exemplar, TS_OK, "");
  preserve[2] = 1.5f;
  expect (&p, &exemplar, TS_ERROR_INVALID_ARGUMENT, "[0, 1]");

  CHECK (strcmp (ts_status_string (TS_ERROR_CANCELLED), "cancelled") == 0, "status string");
  free (exemplar.pixels);
  free (tiny.pixels);
  return test_finish ("test-params");
}
