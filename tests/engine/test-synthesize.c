/* Whole-engine properties: exact exemplar pixels, determinism across
 * thread counts, seeds, transparency, cancel, tiny inputs, the E-step,
 * candidate sets shared through a memo. */
#include "test-util.h"
#include "engine/level.h"
#include "engine/synthesize.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef struct
{
  double last;
  int    calls;
  int    cancel_after;  /* 0 = never */
  bool   monotonic;
} Progress;

static bool
on_progress (double fraction, const char *stage, void *data)
{
  Progress *p = data;
  (void) stage;
  p->monotonic &= fraction >= p->last && fraction <= 1.0;
  p->last = fraction;
  p->calls++;
  return p->cancel_after == 0 || p->calls < p->cancel_after;
}

static TsStatus
run (const TsImage *ex, TsParams *p, TsImage *out, int32_t *sources, Progress *progress)
{
  TsError error;
  TsStatus status;
  out->width = p->output_width;
  out->height = p->output_height;
  out->pixels = malloc (out->width * out->height * TS_CHANNELS * sizeof (float));
  p->source_map = sources;
  status = ts_synthesize (p, ex, out, progress ? on_progress : NULL, progress, &error);
  if (status != TS_OK && status != TS_ERROR_CANCELLED)
    fprintf (stderr, "synthesis failed: %s\n", error.message);
  return status;
}

static void
test_exact_and_deterministic (void)
{
  TsImage ex, a, b, c;
  TsParams p;
  size_t n = 96 * 80;
  int32_t *sources = malloc (n * 2 * sizeof (int32_t));
  Progress progress = { 0, 0, 0, true };

  test_load_exemplar ("bark.png", &ex);
  ts_params_init (&p);
  p.output_width = 96;
  p.output_height = 80;
  p.seed = 11;
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  CHECK (run (&ex, &p, &a, sources, &progress) == TS_OK, "synthesis");
  CHECK (progress.monotonic && progress.calls > 3 && progress.last == 1.0,
         "progress monotonic to 1 (%d calls, last %f)", progress.calls, progress.last);
  /* Every output pixel is exactly the exemplar pixel its source names. */
  size_t bad = 0;
  for (size_t i = 0; i < n; i++)
    {
      int32_t x = sources[2 * i], y = sources[2 * i + 1];
      if (x < 0 || y < 0 || (size_t) x >= ex.width || (size_t) y >= ex.height ||
          memcmp (a.pixels + i * 4, ex.pixels + ((size_t) y * ex.width + (size_t) x) * 4, 16) != 0)
        bad++;
    }
  CHECK (bad == 0, "%zu pixels differ from their source", bad);
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  CHECK (run (&ex, &p, &b, NULL, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a.pixels, b.pixels, n * 16) == 0, "1 and 2 threads give identical results");
  p.seed = 12;
  CHECK (run (&ex, &p, &c, NULL, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a.pixels, c.pixels, n * 16) != 0, "another seed gives another result");
  free (a.pixels);
  free (b.pixels);
  free (c.pixels);
  free (ex.pixels);
  free (sources);
}

static void
test_transparent_never_used (void)
{
  TsImage ex, out;
  TsParams p;
  size_t n = 70 * 50;
  int32_t *sources = malloc (n * 2 * sizeof (int32_t));

  test_noise_image (&ex, 60, 60, 5);
  for (size_t y = 0; y < 60; y++)
    for (size_t x = 0; x < 60; x++)
      if (x < 25 || (x + y) % 7 == 0)
        ex.pixels[(y * 60 + x) * TS_CHANNELS + 3] = 0.0f;
  ts_params_init (&p);
  p.output_width = 70;
  p.output_height = 50;
  CHECK (run (&ex, &p, &out, sources, NULL) == TS_OK, "synthesis");
  size_t transparent = 0;
  for (size_t i = 0; i < n; i++)
    if (out.pixels[i * TS_CHANNELS + 3] <= 0.0f)
      transparent++;
  CHECK (transparent == 0, "%zu output pixels came from transparent sources", transparent);
  free (out.pixels);
  free (ex.pixels);
  free (sources);
}

/* Syntheses that share an exemplar memo (texture by numbers' areas of
 * one label) give what each gives alone: the memo only saves matching
 * the exemplar again, at any output size and seed. */
static void
test_exemplar_memo (void)
{
  TsImage ex;
  TsExemplarMemo memo = { 0 };
  const size_t sides[3][2] = { { 96, 80 }, { 150, 64 }, { 96, 80 } };

  test_noise_image (&ex, 70, 60, 9);
  for (size_t i = 0; i < 3; i++)
    {
      size_t w = sides[i][0], h = sides[i][1];
      size_t bytes = w * h * TS_CHANNELS * sizeof (float);
      TsImage alone = { w, h, malloc (bytes) }, shared = { w, h, malloc (bytes) };
      TsParams p;
      TsError error;
      ts_params_init (&p);
      p.output_width = w;
      p.output_height = h;
      p.seed = (uint32_t) (i + 3);
      CHECK (alone.pixels && shared.pixels, "allocation");
      if (!alone.pixels || !shared.pixels)
        break;
      CHECK (ts_synthesize_needed (&p, &ex, NULL, NULL, &alone, NULL, NULL, &error) == TS_OK,
             "alone: %s", error.message);
      CHECK (ts_synthesize_needed (&p, &ex, NULL, &memo, &shared, NULL, NULL, &error) == TS_OK,
             "with the memo: %s", error.message);
      CHECK (memo.levels > 0 && memo.sets[0].index != NULL, "the memo holds the sets");
      CHECK (memcmp (alone.pixels, shared.pixels, bytes) == 0,
             "synthesis %zu (%zux%zu) the same with the memo", i, w, h);
      free (alone.pixels);
      free (shared.pixels);
    }
  ts_exemplar_memo_free (&memo);
  CHECK (memo.levels == 0 && memo.sets == NULL, "memo freed");
  free (ex.pixels);
}

static void
test_cancel_and_errors (void)
{
  TsImage ex, out;
  TsParams p;
  TsError error;
  Progress progress = { 0, 0, 2, true };

  test_noise_image (&ex, 40, 40, 2);
  ts_params_init (&p);
  p.output_width = p.output_height = 64;
  out.width = out.height = 64;
  out.pixels = malloc (64 * 64 * 16);
  for (size_t i = 0; i < 64 * 64 * 4; i++)
    out.pixels[i] = -7.0f;
  CHECK (ts_synthesize (&p, &ex, &out, on_progress, &progress, &error) == TS_ERROR_CANCELLED,
         "cancel is honoured");
  CHECK (strstr (error.message, "cancelled") != NULL, "cancel message: %s", error.message);
  bool untouched = true;
  for (size_t i = 0; i < 64 * 64 * 4; i++)
    untouched &= out.pixels[i] == -7.0f;
  CHECK (untouched, "a cancelled synthesis leaves the output untouched");
  out.width = 63;
  CHECK (ts_synthesize (&p, &ex, &out, NULL, NULL, &error) == TS_ERROR_INVALID_ARGUMENT,
         "output of the wrong size is refused");
  free (out.pixels);
  free (ex.pixels);
}

static void
test_tiny_sizes (void)
{
  static const size_t sizes[][4] = { { 3, 3, 1, 1 }, { 3, 3, 50, 2 }, { 5, 4, 7, 7 },
                                     { 200, 3, 33, 9 }, { 16, 16, 300, 1 } };
  for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
    for (int wrap = 0; wrap < 2; wrap++)
      {
        TsImage ex, out;
        TsParams p;
        test_noise_image (&ex, sizes[i][0], sizes[i][1], 9);
        ts_params_init (&p);
        p.output_width = sizes[i][2];
        p.output_height = sizes[i][3];
        p.wrap_x = p.wrap_y = wrap;
        p.patch_size = 15;
        CHECK (run (&ex, &p, &out, NULL, NULL) == TS_OK, "%zux%zu -> %zux%zu wrap %d",
               sizes[i][0], sizes[i][1], sizes[i][2], sizes[i][3], wrap);
        free (out.pixels);
        free (ex.pixels);
      }
}

/* A hand-made 6x6 level over a 12x12 noise exemplar, a neighbourhood of
 * radius 1 centred at every pixel. */
static void
estep_state (TsImage *ex, TsLevelState *state, int32_t *sources, TsAxisGrid *gx, TsAxisGrid *gy,
             bool wrap)
{
  test_noise_image (ex, 12, 12, 4);
  memset (state, 0, sizeof *state);
  state->exemplar = ex;
  state->width = state->height = 6;
  state->wrap_x = state->wrap_y = wrap;
  state->source = sources;
  CHECK (ts_axis_grid_init (gx, 6, 1, 1, 0, wrap) == TS_OK && gx->centres == 6, "grid x");
  CHECK (ts_axis_grid_init (gy, 6, 1, 1, 0, wrap) == TS_OK && gy->centres == 6, "grid y");
}

/* E-step on a hand-made state: coherent matches reproduce the exemplar
 * shifted; a heavier group of matches wins a pixel. */
static void
test_estep (void)
{
  TsImage ex;
  TsAxisGrid gx, gy;
  TsLevelState state;
  TsMatch matches[36];
  int32_t sources[36];

  estep_state (&ex, &state, sources, &gx, &gy, true);
  for (size_t y = 0; y < 6; y++)
    for (size_t x = 0; x < 6; x++)
      {
        matches[y * 6 + x].centre = (int32_t) ((y + 3) * 12 + x + 3);
        matches[y * 6 + x].weight = 1.0f;
        matches[y * 6 + x].clipped = false;
        sources[y * 6 + x] = -1;
      }
  /* Wrapped neighbourhoods of edge centres vote from beyond the edge. */
  size_t changed = ts_estep (&state, &gx, &gy, matches, NULL);
  CHECK (changed == 36, "all sources set (%zu)", changed);
  bool shifted = true;
  for (size_t y = 1; y < 5; y++)
    for (size_t x = 1; x < 5; x++)
      shifted &= sources[y * 6 + x] == (int32_t) ((y + 3) * 12 + x + 3);
  CHECK (shifted, "coherent matches reproduce the exemplar");
  /* Pixel (2,2) is covered by centres (1..3, 1..3): give five of them a
   * heavier, different match; the pixel follows them. */
  static const int heavy[5][2] = { { 1, 1 }, { 2, 1 }, { 3, 1 }, { 1, 2 }, { 2, 2 } };
  for (int i = 0; i < 5; i++)
    {
      TsMatch *m = &matches[heavy[i][1] * 6 + heavy[i][0]];
      m->centre = (int32_t) ((heavy[i][1] + 5) * 12 + heavy[i][0] + 5);
      m->weight = 10.0f;
    }
  ts_estep (&state, &gx, &gy, matches, NULL);
  CHECK (sources[2 * 6 + 2] == 7 * 12 + 7, "the heavy votes win: source %d", sources[2 * 6 + 2]);
  ts_axis_grid_free (&gx);
  ts_axis_grid_free (&gy);
  free (ex.pixels);
}

/* A window matched over the exemplar's corner votes only for the pixels
 * whose counterparts the exemplar has: the others keep their sources. */
static void
test_estep_clipped (void)
{
  TsImage ex;
  TsAxisGrid gx, gy;
  TsLevelState state;
  TsMatch matches[36];
  int32_t sources[36];

  estep_state (&ex, &state, sources, &gx, &gy, false);
  for (size_t i = 0; i < 36; i++)
    {
      matches[i] = (TsMatch) { -1, 0.0f, false };
      sources[i] = 100;
    }
  /* The only match: output centre (2, 2) on exemplar pixel (0, 0). */
  matches[2 * gx.centres + 2] = (TsMatch) { 0, 1.0f, true };
  ts_estep (&state, &gx, &gy, matches, NULL);
  for (size_t y = 1; y <= 3; y++)
    for (size_t x = 1; x <= 3; x++)
      {
        int32_t want = (x >= 2 && y >= 2) ? (int32_t) ((y - 2) * 12 + (x - 2)) : 100;
        CHECK (sources[y * 6 + x] == want, "pixel (%zu, %zu): source %d, expected %d", x, y,
               sources[y * 6 + x], want);
      }
  ts_axis_grid_free (&gx);
  ts_axis_grid_free (&gy);
  free (ex.pixels);
}

/* Peak memory of a 1024x1024 synthesis (256x256 in small-size runs)
 * stays within its estimate. */
static void
test_memory_bound (void)
{
  const size_t side = test_small () ? 256 : 1024;
  TsImage ex, out = { side, side, NULL };
  TsParams p;
  TsError error;
  size_t bytes = 0;
  long before, after;
  double grew;

  test_noise_image (&ex, 128, 128, 3);
  ts_params_init (&p);
  p.output_width = out.width;
  p.output_height = out.height;
  CHECK (ts_estimate_memory (&p, &ex, &bytes, NULL) == TS_OK, "estimate");
  before = test_peak_rss_kib ();
  out.pixels = malloc (out.width * out.height * TS_CHANNELS * sizeof (float));
  CHECK (out.pixels && ts_synthesize (&p, &ex, &out, NULL, NULL, &error) == TS_OK, "%zux%zu synthesis",
         side, side);
  after = test_peak_rss_kib ();
  grew = (double) (after - before) * 1024.0;
  printf ("%zux%zu: peak grew by %.1f MiB, estimate %.1f MiB\n", side, side, grew / 1048576.0,
          (double) bytes / 1048576.0);
#ifndef TEST_SANITIZED
  CHECK (grew <= (double) bytes, "peak growth %.1f MiB within the estimate %.1f MiB",
         grew / 1048576.0, (double) bytes / 1048576.0);
#endif
  free (out.pixels);
  free (ex.pixels);
}

int
main (void)
{
  test_memory_bound ();   /* first: the process's peak is lowest here */
  test_estep ();
  test_estep_clipped ();
  test_exact_and_deterministic ();
  test_transparent_never_used ();
  test_cancel_and_errors ();
  test_exemplar_memo ();
  test_tiny_sizes ();
  return test_finish ("test-synthesize");
}
