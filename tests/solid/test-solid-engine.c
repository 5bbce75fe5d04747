/* Solid synthesis engine: parameters and errors, determinism over seeds
 * and thread counts, exemplar colours only, periodic boundaries, free
 * orientations, histogram bookkeeping and tonal spread, cancel and the
 * memory estimate.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"
#include "solid/solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef struct
{
  int    calls;
  double last;
  bool   monotonic;
  int    cancel_after;   /* return false on this call; 0 = never */
} Progress;

static bool
on_progress (double fraction, const char *stage, void *user_data)
{
  Progress *p = user_data;
  (void) stage;
  if (fraction < p->last)
    p->monotonic = false;
  p->last = fraction;
  p->calls++;
  return !(p->cancel_after && p->calls >= p->cancel_after);
}

static float *
volume_alloc (size_t n)
{
  float *v = malloc (n * n * n * TS_CHANNELS * sizeof (float));
  if (!v)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  return v;
}

static TsStatus
run (const TsImage *const ex[3], const TsSolidParams *p, float **out, Progress *progress)
{
  TsError error;
  TsStatus status;

  *out = volume_alloc (p->size);
  status = ts_synthesize_solid (p, ex, *out, progress ? on_progress : NULL, progress, &error);
  if (status != TS_OK)
    fprintf (stderr, "  (%s)\n", error.message);
  return status;
}

static void
test_errors (void)
{
  TsImage ex, tiny, clear;
  TsSolidParams p;
  TsError e;
  size_t bytes;

  test_noise_image (&ex, 32, 32, 1);
  test_noise_image (&tiny, 2, 2, 1);
  test_noise_image (&clear, 16, 16, 1);
  for (size_t i = 0; i < 16 * 16; i++)
    clear.pixels[i * 4 + 3] = 0.0f;
  const TsImage *all[3] = { &ex, &ex, &ex };

  ts_solid_params_init (&p);
  CHECK (p.size == 128 && p.periodic && p.histogram_matching && p.quality >= 1, "defaults");
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_OK, "defaults are valid: %s", e.message);

  p.size = 0;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_BAD_PARAMETER &&
         strstr (e.message, "size"), "size 0: %s", e.message);
  p.size = TS_SOLID_MAX_SIZE + 1;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_BAD_PARAMETER, "size too large");
  ts_solid_params_init (&p);
  p.quality = 0;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_BAD_PARAMETER &&
         strstr (e.message, "quality"), "quality 0: %s", e.message);
  ts_solid_params_init (&p);
  p.patch_size = 8;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_BAD_PARAMETER, "even patch size");
  ts_solid_params_init (&p);
  p.max_iterations = -1;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_BAD_PARAMETER, "negative iterations");
  ts_solid_params_init (&p);

  const TsImage *one[3] = { NULL, NULL, &ex };
  CHECK (ts_solid_params_validate (&p, one, &e) == TS_ERROR_INVALID_ARGUMENT &&
         strstr (e.message, "two"), "one orientation only: %s", e.message);
  const TsImage *with_tiny[3] = { &ex, &tiny, &ex };
  CHECK (ts_solid_params_validate (&p, with_tiny, &e) == TS_ERROR_EXEMPLAR_TOO_SMALL &&
         strstr (e.message, "across y"), "tiny exemplar named by its axis: %s", e.message);
  const TsImage *with_clear[3] = { &clear, &ex, NULL };
  CHECK (ts_solid_params_validate (&p, with_clear, &e) == TS_ERROR_TRANSPARENT_EXEMPLAR &&
         strstr (e.message, "transparent"), "transparent exemplar: %s", e.message);
  CHECK (ts_solid_params_validate (NULL, all, &e) == TS_ERROR_INVALID_ARGUMENT, "no params");

  /* Refused from the estimate, before anything is allocated. */
  p.size = 1024;
  p.memory_limit = (size_t) 256 << 20;
  CHECK (ts_solid_params_validate (&p, all, &e) == TS_ERROR_TOO_LARGE && strstr (e.message, "MiB"),
         "1024^3 refused under 256 MiB: %s", e.message);
  float dummy[4];
  CHECK (ts_synthesize_solid (&p, all, dummy, NULL, NULL, &e) == TS_ERROR_TOO_LARGE,
         "synthesis refuses it too");

  /* The bound: 128^3 from a 128^2 exemplar within 250 MB. */
  TsImage big;
  test_noise_image (&big, 128, 128, 2);
  const TsImage *big3[3] = { &big, &big, &big };
  ts_solid_params_init (&p);
  CHECK (ts_solid_estimate_memory (&p, big3, &bytes, &e) == TS_OK, "estimate");
  CHECK (bytes < (size_t) 250 * 1000 * 1000, "128^3 estimate %.1f MB < 250 MB", (double) bytes / 1e6);
  printf ("memory estimate: 128^3 %.1f MiB", (double) bytes / 1048576.0);
  p.size = 256;
  ts_solid_estimate_memory (&p, big3, &bytes, &e);
  printf (", 256^3 %.1f MiB\n", (double) bytes / 1048576.0);
  free (big.pixels);
  free (ex.pixels);
  free (tiny.pixels);
  free (clear.pixels);
}

static int
compare_pixel_bytes (const void *a, const void *b)
{
  return memcmp (a, b, 16);
}

/* How many voxels are not exactly (byte for byte) one of the exemplars'
 * pixels: each voxel is looked up in the exemplars' pixels sorted, as a
 * scan of every pixel per voxel takes minutes under sanitizers. */
static size_t
voxels_not_from (const float *v, size_t n, const TsImage *const ex[3])
{
  size_t count = 0, at = 0, bad = 0;
  float *sorted;

  for (int a = 0; a < 3; a++)
    if (ex[a])
      count += ex[a]->width * ex[a]->height;
  sorted = malloc ((count ? count : 1) * 16);
  if (!sorted)
    {
      CHECK (0, "out of memory");
      return n * n * n;
    }
  for (int a = 0; a < 3; a++)
    if (ex[a])
      {
        memcpy (sorted + at * 4, ex[a]->pixels, ex[a]->width * ex[a]->height * 16);
        at += ex[a]->width * ex[a]->height;
      }
  qsort (sorted, count, 16, compare_pixel_bytes);
  for (size_t p = 0; p < n * n * n; p++)
    bad += bsearch (v + p * 4, sorted, count, 16, compare_pixel_bytes) == NULL;
  free (sorted);
  return bad;
}

static void
test_determinism (void)
{
  TsImage ex;
  TsSolidParams p;
  float *a, *b, *c;
  Progress progress = { 0, 0, true, 0 };
  size_t n = 24;

  test_load_exemplar ("granite1.png", &ex);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 5;
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  CHECK (run (all, &p, &a, &progress) == TS_OK, "synthesis");
  CHECK (progress.monotonic && progress.calls > 3 && progress.last == 1.0,
         "progress monotonic to 1 (%d calls, last %f)", progress.calls, progress.last);
  CHECK (voxels_not_from (a, n, all) == 0, "every voxel is an exemplar colour");
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  CHECK (run (all, &p, &b, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a, b, n * n * n * 16) == 0, "1 and 2 threads give identical volumes");
#ifdef _OPENMP
  omp_set_num_threads (4);
#endif
  free (b);
  CHECK (run (all, &p, &b, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a, b, n * n * n * 16) == 0, "1 and 4 threads give identical volumes");
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  p.seed = 6;
  CHECK (run (all, &p, &c, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a, c, n * n * n * 16) != 0, "another seed gives another volume");
  /* The quality is the breadth of the search over all neighbourhoods. */
  free (c);
  p.seed = 5;
  p.quality = TS_MAX_QUALITY;
  CHECK (run (all, &p, &c, NULL) == TS_OK, "synthesis");
  CHECK (memcmp (a, c, n * n * n * 16) != 0, "another quality gives another volume");
  free (a);
  free (b);
  free (c);
  free (ex.pixels);
}

/* Mean absolute L difference between voxels one step apart along `axis`,
 * over the wrap-around pairs (last, first) and over the interior pairs. */
static void
step_differences (const float *v, size_t n, int axis, double *wrap, double *inner)
{
  size_t stride = axis == 0 ? 1 : (axis == 1 ? n : n * n);
  double w = 0, in = 0;
  size_t wn = 0, inn = 0;
  for (size_t p = 0; p < n * n * n; p++)
    {
      size_t t = (p / stride) % n;
      size_t q = t + 1 < n ? p + stride : p - t * stride;
      double d = fabs ((double) v[p * 4] - (double) v[q * 4]);
      if (t + 1 < n)
        in += d, inn++;
      else
        w += d, wn++;
    }
  *wrap = w / (double) wn;
  *inner = in / (double) inn;
}

static void
test_periodic (void)
{
  TsImage ex;
  TsSolidParams p;
  float *v, *m;
  size_t n = 32;
  double wrap, inner, mirror_wrap = 0;

  test_load_exemplar ("granite1.png", &ex);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = n;
  CHECK (run (all, &p, &v, NULL) == TS_OK, "periodic synthesis");
  for (int a = 0; a < 3; a++)
    {
      step_differences (v, n, a, &wrap, &inner);
      CHECK (wrap < 1.5 * inner, "axis %d: across the periodic boundary %.2f, inside %.2f", a, wrap, inner);
    }
  p.periodic = false;
  CHECK (run (all, &p, &m, NULL) == TS_OK, "mirrored synthesis");
  for (int a = 0; a < 3; a++)
    {
      step_differences (m, n, a, &wrap, &inner);
      mirror_wrap += wrap / inner / 3.0;
    }
  printf ("wrap/inner step ratio: non-periodic volume %.2f\n", mirror_wrap);
  CHECK (mirror_wrap > 1.2, "a non-periodic volume does not wrap (ratio %.2f)", mirror_wrap);
  free (v);
  free (m);
  free (ex.pixels);
}

static void
test_orientations (void)
{
  TsImage a, b;
  TsSolidParams p;
  float *v;
  size_t n = 16;

  test_load_exemplar ("granite1.png", &a);
  test_load_exemplar ("java.png", &b);
  const TsImage *two[3] = { &a, NULL, &a };
  ts_solid_params_init (&p);
  p.size = n;
  CHECK (run (two, &p, &v, NULL) == TS_OK, "two constrained orientations");
  CHECK (voxels_not_from (v, n, two) == 0, "voxels from the constrained exemplar");
  free (v);

  const TsImage *mixed[3] = { &a, &b, &b };
  const TsImage *only_a[3] = { &a, NULL, NULL };
  const TsImage *only_b[3] = { NULL, &b, NULL };
  CHECK (run (mixed, &p, &v, NULL) == TS_OK, "one exemplar per orientation");
  CHECK (voxels_not_from (v, n, mixed) == 0, "voxels from the union of the exemplars");
  size_t not_a = voxels_not_from (v, n, only_a), not_b = voxels_not_from (v, n, only_b);
  CHECK (not_a > 0 && not_b > 0, "both exemplars contribute (%zu not from a, %zu not from b)",
         not_a, not_b);
  free (v);
  free (a.pixels);
  free (b.pixels);
}

static void
test_histogram_bookkeeping (void)
{
  TsImage ex;
  TsSolidLevel level;
  TsSolidHistogram h, fresh;
  TsSolidHistogramDelta delta;
  size_t n = 12, voxels = n * n * n;
  uint64_t state = 12345;

  test_noise_image (&ex, 20, 20, 3);
  memset (&level, 0, sizeof level);
  level.n = n;
  level.value = volume_alloc (n);
  for (int a = 0; a < 3; a++)
    level.view[a].exemplar = &ex;
  for (size_t p = 0; p < voxels; p++)
    memcpy (level.value + p * 4, ex.pixels + (p % 400) * 4, 16);
  ts_solid_histogram_init (&h, &level);
  CHECK (h.total == (int64_t) voxels, "every opaque voxel counted");
  memset (delta, 0, sizeof delta);
  for (int step = 0; step < 5000; step++)
    {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      size_t p = (size_t) (state >> 33) % voxels, s = (size_t) (state >> 17) % 400;
      float after[4];
      memcpy (after, ex.pixels + s * 4, 16);
      if (step % 7 == 0)
        after[3] = 0.0f;   /* becomes transparent: leaves the counts */
      ts_solid_histogram_move (&h, delta, level.value + p * 4, after);
      memcpy (level.value + p * 4, after, 16);
      if (step % 100 == 99)
        ts_solid_histogram_apply (&h, delta);
    }
  ts_solid_histogram_apply (&h, delta);
  ts_solid_histogram_init (&fresh, &level);
  CHECK (memcmp (h.count, fresh.count, sizeof h.count) == 0 && h.total == fresh.total,
         "incremental counts equal a recount (%lld vs %lld voxels)", (long long) h.total,
         (long long) fresh.total);
  free (level.value);
  free (ex.pixels);
}

static void
test_cancel (void)
{
  TsImage ex;
  TsSolidParams p;
  float *v;
  Progress progress = { 0, 0, true, 3 };
  TsError e;

  test_noise_image (&ex, 40, 40, 4);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = 32;
  v = volume_alloc (p.size);
  CHECK (ts_synthesize_solid (&p, all, v, on_progress, &progress, &e) == TS_ERROR_CANCELLED &&
         strstr (e.message, "cancel"), "cancel stops the synthesis: %s", e.message);
  CHECK (progress.calls == 3, "no progress after cancelling (%d calls)", progress.calls);
  free (v);
  free (ex.pixels);
}

static double
lightness_deviation (const float *pixels, size_t count)
{
  double sum = 0.0, squares = 0.0;
  for (size_t i = 0; i < count; i++)
    {
      sum += pixels[i * TS_CHANNELS];
      squares += (double) pixels[i * TS_CHANNELS] * pixels[i * TS_CHANNELS];
    }
  return sqrt (fmax (0.0, squares / (double) count - (sum / (double) count) * (sum / (double) count)));
}

/* Histogram matching keeps the exemplar's tonal spread: cracked earth is
 * mostly one flat grey with thin cracks, and a volume that votes by
 * majority alone turns flat grey. */
static void
test_keeps_tonal_spread (void)
{
  TsImage ex;
  TsSolidParams p;
  float *v;
  size_t n = 32;
  double ex_sd, vol_sd;

  test_load_exemplar ("cracked.png", &ex);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = n;
  CHECK (run (all, &p, &v, NULL) == TS_OK, "synthesis");
  ex_sd = lightness_deviation (ex.pixels, ts_image_pixel_count (&ex));
  vol_sd = lightness_deviation (v, n * n * n);
  printf ("cracked.png: L standard deviation %.2f in the volume, %.2f in the exemplar\n", vol_sd, ex_sd);
  CHECK (vol_sd >= 0.3 * ex_sd, "the volume keeps at least 30 %% of the exemplar's L deviation (%.2f of %.2f)",
         vol_sd, ex_sd);
  free (v);
  free (ex.pixels);
}

/* Peak memory of a 64^3 synthesis (32^3 in small-size runs) stays
 * within its estimate. */
static void
test_memory_bound (void)
{
  TsImage ex;
  TsSolidParams p;
  size_t bytes;
  float *v;
  long before, after;

  test_noise_image (&ex, 64, 64, 6);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = test_small () ? 32 : 64;
  ts_solid_estimate_memory (&p, all, &bytes, NULL);
  before = test_peak_rss_kib ();
  CHECK (run (all, &p, &v, NULL) == TS_OK, "%zu^3 synthesis", p.size);
  after = test_peak_rss_kib ();
  printf ("%zu^3: peak %.1f -> %.1f MiB (grew by %.1f MiB), estimate %.1f MiB\n", p.size, (double) before / 1024.0, (double) after / 1024.0, (double) (after - before) / 1024.0,
          (double) bytes / 1048576.0);
#ifndef TEST_SANITIZED
  CHECK ((double) (after - before) * 1024.0 <= (double) bytes,
         "peak growth %.1f MiB within the estimate %.1f MiB", (double) (after - before) / 1024.0,
         (double) bytes / 1048576.0);
#endif
  free (v);
  free (ex.pixels);
}

int
main (void)
{
  test_memory_bound ();   /* first: the process's peak is lowest here */
  test_errors ();
  test_determinism ();
  test_periodic ();
  test_orientations ();
  test_histogram_bookkeeping ();
  test_keeps_tonal_spread ();
  test_cancel ();
  return test_finish ("test-solid-engine");
}
