/* ts_heal in C: pixels outside the hole unchanged, every hole pixel from a
 * known source pixel, the same result at 1 and 2 threads, memory that
 * grows with the context and not the image, progress reports and
 * cancellation, and the errors of bad input.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static uint8_t *
square_hole (size_t w, size_t h, size_t x0, size_t y0, size_t side)
{
  uint8_t *hole = calloc (w * h, 1);
  for (size_t y = y0; hole && y < y0 + side && y < h; y++)
    memset (hole + y * w + x0, 1, side);
  return hole;
}

static TsStatus
heal (const TsHealParams *p, const TsImage *image, const uint8_t *hole, TsImage *out,
      int32_t *map, TsError *error)
{
  out->width = image->width;
  out->height = image->height;
  out->pixels = malloc (image->width * image->height * TS_CHANNELS * sizeof (float));
  if (!out->pixels)
    abort ();
  return ts_heal (p, image, hole, NULL, out, map, NULL, NULL, error);
}

static void
test_fill (const TsImage *image)
{
  size_t w = image->width, h = image->height, n = w * h;
  uint8_t *hole = square_hole (w, h, w / 2 - 12, h / 2 - 12, 24);
  int32_t *map = malloc (n * sizeof (int32_t));
  TsHealParams p;
  TsImage one = { 0 }, two = { 0 };
  TsError error;
  size_t outside = 0, bad_source = 0;

  ts_heal_params_init (&p);
  p.seed = 5;
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  CHECK (heal (&p, image, hole, &one, map, &error) == TS_OK, "%s", error.message);
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  CHECK (heal (&p, image, hole, &two, NULL, &error) == TS_OK, "%s", error.message);
  CHECK (memcmp (one.pixels, two.pixels, n * TS_CHANNELS * sizeof (float)) == 0,
         "1 and 2 threads give bit-identical results");
  for (size_t i = 0; i < n; i++)
    {
      if (!hole[i])
        outside += memcmp (one.pixels + i * TS_CHANNELS, image->pixels + i * TS_CHANNELS,
                           TS_CHANNELS * sizeof (float)) != 0 || map[i] != -1;
      else
        bad_source += map[i] < 0 || (size_t) map[i] >= n || hole[map[i]];
    }
  CHECK (outside == 0, "%zu pixels outside the hole changed", outside);
  CHECK (bad_source == 0, "%zu hole pixels do not come from a known pixel", bad_source);
  free (one.pixels);
  free (two.pixels);
  free (map);
  free (hole);
}

/* Every hole pixel comes from where the options allow: left or right of
 * the hole's columns with sample-from sides, above or below its rows
 * with above-below, and within the context of the hole's bounds. */
static void
test_sources_allowed (const TsImage *image)
{
  size_t w = image->width, h = image->height, n = w * h, x0 = w / 2 - 16, y0 = h / 2 - 16;
  uint8_t *hole = square_hole (w, h, x0, y0, 32);
  int32_t *map = malloc (n * sizeof (int32_t));
  static const TsHealSampleFrom from[3] = { TS_HEAL_SIDES, TS_HEAL_ABOVE_BELOW, TS_HEAL_ALL_AROUND };
  TsHealParams p;
  TsImage out = { 0 };
  TsError error;

  if (!hole || !map)
    abort ();
  for (int k = 0; k < 3; k++)
    {
      size_t wrong = 0, context = k == 2 ? 20 : 0;
      ts_heal_params_init (&p);
      p.seed = 3;
      p.sample_from = from[k];
      p.context = context;
      CHECK (heal (&p, image, hole, &out, map, &error) == TS_OK, "%s", error.message);
      for (size_t i = 0; i < n; i++)
        if (hole[i])
          {
            size_t sx = (size_t) map[i] % w, sy = (size_t) map[i] / w;
            bool beside = sx < x0 || sx >= x0 + 32, over = sy < y0 || sy >= y0 + 32;
            wrong += k == 0 ? !beside : k == 1 ? !over
                     : sx + context + 3 < x0 || sx >= x0 + 32 + context + 3 ||
                       sy + context + 3 < y0 || sy >= y0 + 32 + context + 3;
          }
      CHECK (wrong == 0, "sample-from %d, context %zu: %zu hole pixels copied from outside "
             "the allowed source", (int) from[k], context, wrong);
      free (out.pixels);
    }
  free (map);
  free (hole);
}

static void
test_memory_follows_context (void)
{
  TsHealParams p;
  TsImage small = { 256, 256, NULL }, large = { 2048, 2048, NULL };
  uint8_t *hole_small = square_hole (256, 256, 100, 100, 40);
  uint8_t *hole_large = square_hole (2048, 2048, 1000, 1000, 40);
  size_t a, b, whole;
  TsError error;

  small.pixels = calloc (256 * 256 * TS_CHANNELS, sizeof (float));
  large.pixels = calloc ((size_t) 2048 * 2048 * TS_CHANNELS, sizeof (float));
  ts_heal_params_init (&p);
  p.context = 50;
  CHECK (ts_heal_estimate_memory (&p, &small, hole_small, NULL, &a, &error) == TS_OK, "%s",
         error.message);
  CHECK (ts_heal_estimate_memory (&p, &large, hole_large, NULL, &b, &error) == TS_OK, "%s",
         error.message);
  CHECK (a == b, "context 50: the same memory for a 256^2 and a 2048^2 image (%zu, %zu)", a, b);
  p.context = 0;
  CHECK (ts_heal_estimate_memory (&p, &large, hole_large, NULL, &whole, &error) == TS_OK, "%s",
         error.message);
  CHECK (whole > 50 * b, "context 0 works on the whole 2048^2 image (%zu vs %zu)", whole, b);
  free (small.pixels);
  free (large.pixels);
  free (hole_small);
  free (hole_large);
}

static void
test_errors (const TsImage *image)
{
  size_t w = image->width, h = image->height, n = w * h;
  uint8_t *none = calloc (n, 1), *all = malloc (n), *hole = square_hole (w, h, 20, 20, 20);
  TsHealParams p;
  TsImage out = { 0 };
  TsError error;

  memset (all, 1, n);
  ts_heal_params_init (&p);
  CHECK (heal (&p, image, none, &out, NULL, &error) == TS_OK &&
         memcmp (out.pixels, image->pixels, n * TS_CHANNELS * sizeof (float)) == 0,
         "an empty hole gives the image back");
  free (out.pixels);
  CHECK (ts_heal_params_validate (&p, image, all, NULL, &error) == TS_ERROR_NOTHING_TO_SAMPLE &&
         strstr (error.message, "nothing to fill"), "a hole covering everything: %s",
         error.message);
  p.context = 3;
  CHECK (ts_heal_params_validate (&p, image, hole, NULL, &error) == TS_ERROR_NOTHING_TO_SAMPLE &&
         strstr (error.message, "too small"), "context 3: %s", error.message);
  p.context = TS_HEAL_MAX_CONTEXT + 1;
  CHECK (ts_heal_params_validate (&p, image, hole, NULL, &error) == TS_ERROR_BAD_PARAMETER,
         "context above the maximum is refused");
  ts_heal_params_init (&p);
  p.quality = 0;
  CHECK (ts_heal_params_validate (&p, image, hole, NULL, &error) == TS_ERROR_BAD_PARAMETER,
         "quality 0 is refused");
  ts_heal_params_init (&p);
  p.fine_patch_size = 4;
  CHECK (ts_heal_params_validate (&p, image, hole, NULL, &error) == TS_ERROR_BAD_PARAMETER,
         "an even patch size is refused");
  ts_heal_params_init (&p);
  p.sample_from = (TsHealSampleFrom) 7;
  CHECK (ts_heal_params_validate (&p, image, hole, NULL, &error) == TS_ERROR_BAD_PARAMETER,
         "an unknown sample-from is refused");
  CHECK (ts_heal_params_validate (&p, image, NULL, NULL, &error) == TS_ERROR_INVALID_ARGUMENT,
         "no hole is refused");
  free (none);
  free (all);
  free (hole);
}

typedef struct
{
  size_t calls, stop_after, backwards, out_of_range, done_calls;
  double last;
} Progress;

static bool
record_progress (double fraction, const char *stage, void *user_data)
{
  Progress *p = user_data;
  p->calls++;
  p->backwards += fraction < p->last;
  p->out_of_range += !(fraction >= 0.0 && fraction <= 1.0);
  p->done_calls += stage && strcmp (stage, "done") == 0;
  p->last = fraction;
  return p->stop_after == 0 || p->calls < p->stop_after;
}

/* Progress rises from 0 to 1 and ends with "done"; a callback that says
 * stop cancels the heal soon, with TS_ERROR_CANCELLED and the output
 * untouched. */
static void
test_progress_and_cancel (const TsImage *image)
{
  size_t w = image->width, h = image->height, n = w * h;
  uint8_t *hole = square_hole (w, h, w / 2 - 12, h / 2 - 12, 24);
  float *out = malloc (n * TS_CHANNELS * sizeof (float));
  TsImage output = { w, h, out };
  Progress progress = { 0 };
  TsHealParams p;
  TsError error;
  size_t touched = 0, full_run;

  if (!hole || !out)
    abort ();
  ts_heal_params_init (&p);
  p.seed = 3;
  CHECK (ts_heal (&p, image, hole, NULL, &output, NULL, record_progress, &progress, &error) == TS_OK,
         "%s", error.message);
  CHECK (progress.calls >= 5, "progress reported %zu times (at least 5)", progress.calls);
  CHECK (progress.backwards == 0, "progress went backwards %zu times", progress.backwards);
  CHECK (progress.out_of_range == 0, "%zu progress fractions outside 0..1", progress.out_of_range);
  CHECK (progress.last == 1.0 && progress.done_calls == 1,
         "progress ends at 1 with one \"done\" (last %g, %zu done)", progress.last,
         progress.done_calls);
  full_run = progress.calls;

  for (size_t i = 0; i < n * TS_CHANNELS; i++)
    out[i] = -7.0f;
  memset (&progress, 0, sizeof progress);
  progress.stop_after = 2;
  CHECK (ts_heal (&p, image, hole, NULL, &output, NULL, record_progress, &progress, &error) ==
           TS_ERROR_CANCELLED,
         "a callback returning false cancels the heal");
  CHECK (strstr (error.message, "cancel") != NULL, "the error says so: %s", error.message);
  CHECK (progress.calls < full_run, "cancelled after %zu reports (a full run makes %zu)",
         progress.calls, full_run);
  for (size_t i = 0; i < n * TS_CHANNELS; i++)
    touched += out[i] != -7.0f;
  CHECK (touched == 0, "a cancelled heal leaves the output untouched (%zu values written)", touched);
  free (out);
  free (hole);
}

int
main (void)
{
  TsImage stone;

  test_load_exemplar ("stone33.png", &stone);
  test_fill (&stone);
  test_sources_allowed (&stone);
  test_errors (&stone);
  test_progress_and_cancel (&stone);
  test_memory_follows_context ();
  free (stone.pixels);
  return test_finish ("test-heal-engine");
}
