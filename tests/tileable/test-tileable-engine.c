/* ts_make_tileable and its plan: preserve map shape, identity start,
 * kept pixels, transparency, determinism across thread counts, errors.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"
#include "tileable/cuts.h"
#include "tileable/shift.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static void *
xmalloc (size_t bytes)
{
  void *p = malloc (bytes);
  if (!p)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  return p;
}

static TsImage
new_output (const TsImage *like)
{
  TsImage out = { like->width, like->height,
                  xmalloc (like->width * like->height * TS_CHANNELS * sizeof (float)) };
  return out;
}

/* The plan as ts_make_tileable builds it; source and preserve allocated. */
static void
make_plan (const TsTileableParams *p, const TsImage *in, TsTileablePlan *plan,
           int32_t **source, float **preserve)
{
  TsImage working = { in->width, in->height,
                      xmalloc (in->width * in->height * TS_CHANNELS * sizeof (float)) };
  size_t n = in->width * in->height;

  /* The working format only scales alpha, which is 1 here. */
  memcpy (working.pixels, in->pixels, n * TS_CHANNELS * sizeof (float));
  ts_tileable_plan_init (p, in, plan);
  *source = xmalloc (2 * n * sizeof (int32_t));
  *preserve = xmalloc (n * sizeof (float));
  CHECK (ts_tileable_choose_shift (&working, plan) == TS_OK, "shift");
  CHECK (ts_tileable_place_cuts (&working, plan) == TS_OK, "cuts");
  CHECK (ts_tileable_maps (plan, *source, *preserve) == TS_OK, "maps");
  free (working.pixels);
}

static bool
central (size_t x, size_t y, size_t w, size_t h)
{
  return x >= w / 4 && x < w / 4 + w / 2 && y >= h / 4 && y < h / 4 + h / 2;
}

static void
test_plan_shape (void)
{
  TsImage in;
  TsTileableParams p;
  TsTileablePlan plan;
  int32_t *source;
  float *preserve;
  size_t w = 96, h = 80, bad_range = 0, bad_centre = 0, bad_identity = 0, bad_band = 0;
  size_t zeros = 0, edge_kept = 0;

  test_noise_image (&in, w, h, 3);
  ts_tileable_params_init (&p);
  make_plan (&p, &in, &plan, &source, &preserve);
  CHECK (plan.shift_x >= w / 4 && plan.shift_x <= w - w / 4 && plan.shift_y >= h / 4 &&
         plan.shift_y <= h - h / 4, "shift (%zu, %zu) from the middle half", plan.shift_x, plan.shift_y);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t i = y * w + x;
        bool band = ts_tileable_in_band (&plan, x, y);
        bad_range += !(preserve[i] >= 0.0f && preserve[i] <= 1.0f);
        bad_centre += central (x, y, w, h) && (band || preserve[i] != 1.0f);
        bad_identity += !band && (source[2 * i] != (int32_t) x || source[2 * i + 1] != (int32_t) y);
        bad_band += band && (source[2 * i] != (int32_t) ((x + plan.shift_x) % w) ||
                             source[2 * i + 1] != (int32_t) ((y + plan.shift_y) % h));
        zeros += preserve[i] == 0.0f;
        /* The wrap edges themselves are always replaced. */
        edge_kept += (x == 0 || y == 0 || x == w - 1 || y == h - 1) && !band;
      }
  CHECK (bad_range == 0, "%zu preserve weights outside [0, 1]", bad_range);
  CHECK (bad_centre == 0, "%zu pixels of the central half may change", bad_centre);
  CHECK (bad_identity == 0, "%zu kept pixels do not start at themselves", bad_identity);
  CHECK (bad_band == 0, "%zu band pixels do not start at the shifted content", bad_band);
  CHECK (zeros > 0, "the cuts are free (preserve 0)");
  CHECK (edge_kept == 0, "%zu edge pixels kept", edge_kept);
  /* Free at a cut, rising to 1 away from it: along the centre row. */
  {
    size_t y = h / 2, cut = 0;
    while (cut < w / 2 && ts_tileable_in_band (&plan, cut, y))
      cut++;
    CHECK (cut > 0 && cut < w / 4 && preserve[y * w + cut] == 0.0f,
           "preserve 0 where the left band ends (x = %zu)", cut);
    CHECK (preserve[y * w + cut + 1] > 0.0f && preserve[y * w + cut + 1] < 1.0f &&
           preserve[y * w + w / 4] == 1.0f, "preserve rises from the join to 1");
  }
  ts_tileable_plan_clear (&plan);
  free (source);
  free (preserve);

  /* Horizontally only: top and bottom rows are kept away from the sides. */
  p.direction = TS_TILEABLE_HORIZONTAL;
  make_plan (&p, &in, &plan, &source, &preserve);
  CHECK (plan.shift_y == 0 && plan.band_y == 0, "no vertical band");
  for (size_t x = w / 4; x < w - w / 4; x++)
    CHECK (preserve[x] == 1.0f && preserve[(h - 1) * w + x] == 1.0f,
           "top/bottom row kept at x = %zu", x);
  ts_tileable_plan_clear (&plan);
  free (source);
  free (preserve);
  free (in.pixels);
}

static void
test_distance (void)
{
  size_t w = 23, h = 17;
  unsigned char mask[23 * 17] = { 0 };
  float d[23 * 17];
  size_t bad = 0;

  mask[3 * w + 2] = mask[12 * w + 20] = mask[8 * w + 11] = 1;
  CHECK (ts_tileable_distance (mask, w, h, true, false, d) == TS_OK, "distance");
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double best = INFINITY;
        for (size_t q = 0; q < w * h; q++)
          if (mask[q])
            {
              double dx = fabs ((double) x - (double) (q % w)), dy = fabs ((double) y - (double) (q / w));
              dx = fmin (dx, (double) w - dx);   /* wraps in x only */
              best = fmin (best, sqrt (dx * dx + dy * dy));
            }
        bad += fabs (best - d[y * w + x]) > 1e-4;
      }
  CHECK (bad == 0, "%zu distances differ from brute force", bad);
}

static TsStatus
run (const TsTileableParams *p, const TsImage *in, TsImage *out)
{
  TsError error;
  TsStatus status = ts_make_tileable (p, in, out, NULL, NULL, &error);
  if (status != TS_OK)
    fprintf (stderr, "ts_make_tileable: %s\n", error.message);
  return status;
}

static void
test_result (void)
{
  TsImage in, a, b;
  TsTileableParams p;
  TsTileablePlan plan;
  int32_t *source;
  float *preserve;
  size_t n, changed_kept = 0, changed_band = 0, not_exemplar = 0;

  test_load_exemplar ("brick.png", &in);
  n = in.width * in.height;
  ts_tileable_params_init (&p);
  p.seed = 5;
  a = new_output (&in);
  b = new_output (&in);
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  CHECK (run (&p, &in, &a) == TS_OK, "1 thread");
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  CHECK (run (&p, &in, &b) == TS_OK, "2 threads");
  CHECK (memcmp (a.pixels, b.pixels, n * TS_CHANNELS * sizeof (float)) == 0,
         "same result with 1 and 2 threads");

  make_plan (&p, &in, &plan, &source, &preserve);
  for (size_t i = 0; i < n; i++)
    {
      bool same = memcmp (a.pixels + i * 4, in.pixels + i * 4, 16) == 0;
      changed_kept += preserve[i] >= 1.0f && !ts_tileable_in_band (&plan, i % in.width, i / in.width) && !same;
      changed_band += !same;
      /* Every pixel is some input pixel, copied exactly (no blending). */
      bool found = same;
      for (size_t j = 0; j < n && !found; j++)
        found = memcmp (a.pixels + i * 4, in.pixels + j * 4, 16) == 0;
      not_exemplar += !found;
    }
  CHECK (changed_kept == 0, "%zu fully preserved pixels changed", changed_kept);
  CHECK (changed_band > n / 10, "the bands changed (%zu pixels)", changed_band);
  CHECK (not_exemplar == 0, "%zu pixels are not input pixels", not_exemplar);
  ts_tileable_plan_clear (&plan);
  free (source);
  free (preserve);

  p.seed = 6;
  CHECK (run (&p, &in, &b) == TS_OK, "seed 6");
  CHECK (memcmp (a.pixels, b.pixels, n * TS_CHANNELS * sizeof (float)) != 0,
         "another seed, another result");
  free (a.pixels);
  free (b.pixels);
  free (in.pixels);
}

/* A transparent hole in the kept part stays a hole; transparent input
 * pixels never appear in the bands unless copied with their place. */
static void
test_transparency (void)
{
  TsImage in, out;
  TsTileableParams p;
  size_t w = 64, h = 64, wrong = 0;

  test_noise_image (&in, w, h, 9);
  for (size_t y = 24; y < 40; y++)
    for (size_t x = 24; x < 40; x++)
      in.pixels[(y * w + x) * TS_CHANNELS + 3] = 0.0f;
  ts_tileable_params_init (&p);
  out = new_output (&in);
  CHECK (run (&p, &in, &out) == TS_OK, "with a hole");
  for (size_t y = 16; y < 48; y++)
    for (size_t x = 16; x < 48; x++)
      wrong += out.pixels[(y * w + x) * TS_CHANNELS + 3] != in.pixels[(y * w + x) * TS_CHANNELS + 3];
  CHECK (wrong == 0, "%zu alpha values changed in the central half", wrong);
  free (out.pixels);
  free (in.pixels);
}

static void
test_errors (void)
{
  TsImage in, tiny, out;
  TsTileableParams p;
  TsError e;

  test_noise_image (&in, 40, 30, 1);
  test_noise_image (&tiny, 5, 40, 1);
  ts_tileable_params_init (&p);
  out = new_output (&in);
  CHECK (ts_make_tileable (NULL, &in, &out, NULL, NULL, &e) == TS_ERROR_INVALID_ARGUMENT, "NULL params");
  CHECK (ts_make_tileable (&p, NULL, &out, NULL, NULL, &e) == TS_ERROR_INVALID_ARGUMENT, "NULL input");
  p.seam_width = 0.5;
  CHECK (ts_make_tileable (&p, &in, &out, NULL, NULL, &e) == TS_ERROR_BAD_PARAMETER &&
         strstr (e.message, "seam width"), "seam width too large: %s", e.message);
  ts_tileable_params_init (&p);
  p.direction = (TsTileableDirection) 7;
  CHECK (ts_tileable_params_validate (&p, &in, &e) == TS_ERROR_BAD_PARAMETER, "bad direction");
  ts_tileable_params_init (&p);
  p.quality = 0;
  CHECK (ts_tileable_params_validate (&p, &in, &e) == TS_ERROR_BAD_PARAMETER, "bad quality");
  ts_tileable_params_init (&p);
  CHECK (ts_make_tileable (&p, &tiny, &out, NULL, NULL, &e) == TS_ERROR_EXEMPLAR_TOO_SMALL &&
         strstr (e.message, "too small"), "5 px wide: %s", e.message);
  /* ... fine when only the other direction wraps. */
  p.direction = TS_TILEABLE_VERTICAL;
  CHECK (ts_tileable_params_validate (&p, &tiny, &e) == TS_OK, "5 px wide, vertical only: %s", e.message);
  ts_tileable_params_init (&p);
  {
    TsImage wrong = { 41, 30, out.pixels };
    CHECK (ts_make_tileable (&p, &in, &wrong, NULL, NULL, &e) == TS_ERROR_INVALID_ARGUMENT,
           "output of another size");
  }
  for (size_t i = 0; i < in.width * in.height; i++)
    in.pixels[i * TS_CHANNELS + 3] = 0.0f;
  CHECK (ts_make_tileable (&p, &in, &out, NULL, NULL, &e) == TS_ERROR_TRANSPARENT_EXEMPLAR &&
         strstr (e.message, "transparent"), "fully transparent: %s", e.message);
  {
    TsImage empty = { 0, 0, NULL };
    CHECK (ts_make_tileable (&p, &empty, &out, NULL, NULL, &e) == TS_ERROR_EMPTY_EXEMPLAR, "empty");
  }
  free (out.pixels);
  free (tiny.pixels);
  free (in.pixels);
}

int
main (void)
{
  test_distance ();
  test_plan_shape ();
  test_result ();
  test_transparency ();
  test_errors ();
  return test_finish ("test-tileable-engine");
}
