/* Solid synthesis sources: every voxel's recorded vote,
 * applied to the exemplars, gives the volume bit for bit; aligned maps
 * come out as the same function of the volume; sources are the same at 1
 * and 2 threads (translucent alpha: within 1 ulp, exact in 8 bits);
 * recording changes nothing else and is counted in the
 * memory estimate; bad arguments fail cleanly.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define VOXEL_BYTES (TS_CHANNELS * sizeof (float))

static void *
checked_malloc (size_t bytes)
{
  void *p = malloc (bytes);
  if (!p)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  return p;
}

static size_t
cube (size_t n)
{
  return n * n * n;
}

/* Synthesises with sources (`sources` may be NULL: then without). */
static TsStatus
run (const TsImage *const ex[3], TsSolidParams p, float **volume, TsSolidSource **sources)
{
  TsError error;
  TsStatus status;

  *volume = checked_malloc (cube (p.size) * VOXEL_BYTES);
  p.record_sources = sources != NULL;
  if (sources)
    *sources = checked_malloc (cube (p.size) * sizeof (TsSolidSource));
  status = ts_synthesize_solid_with_sources (&p, ex, *volume, sources ? *sources : NULL, NULL,
                                             NULL, &error);
  if (status != TS_OK)
    fprintf (stderr, "  (%s)\n", error.message);
  return status;
}

/* Voxels whose colour differs from the exemplar pixels their sources name. */
static size_t
round_trip_errors (const TsImage *const ex[3], const float *volume, const TsSolidSource *sources,
                   size_t n)
{
  const void *maps[3];
  size_t pixels[3], bad = 0;
  float *laid = checked_malloc (cube (n) * VOXEL_BYTES);
  TsError error;

  for (int a = 0; a < 3; a++)
    {
      maps[a] = ex[a] ? ex[a]->pixels : NULL;
      pixels[a] = ex[a] ? ex[a]->width * ex[a]->height : 0;
    }
  CHECK (ts_solid_apply_sources (sources, cube (n), maps, pixels, VOXEL_BYTES, laid, &error)
         == TS_OK, "applying the sources: %s", error.message);
  for (size_t p = 0; p < cube (n); p++)
    bad += memcmp (laid + p * TS_CHANNELS, volume + p * TS_CHANNELS, VOXEL_BYTES) != 0;
  free (laid);
  return bad;
}

static void
test_round_trip (void)
{
  TsImage granite, bark, brick;
  TsSolidParams p;
  size_t n = 24;

  test_load_exemplar ("granite1.png", &granite);
  test_load_exemplar ("bark.png", &bark);
  test_load_exemplar ("brick.png", &brick);
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 3;

  const TsImage *same[3] = { &granite, &granite, &granite };
  const TsImage *per_axis[3] = { &bark, &brick, &granite };
  const TsImage *free_y[3] = { &brick, NULL, &brick };
  const TsImage *const *cases[3] = { same, per_axis, free_y };
  const char *names[3] = { "one exemplar", "three exemplars", "y free" };
  for (int c = 0; c < 3; c++)
    for (int hm = 0; hm < 2; hm++)
      {
        float *volume, *plain;
        TsSolidSource *sources;
        size_t wrong, axes[3] = { 0, 0, 0 };
        p.histogram_matching = hm;
        p.periodic = c != 2;
        CHECK (run (cases[c], p, &volume, &sources) == TS_OK, "%s: synthesis", names[c]);
        wrong = round_trip_errors (cases[c], volume, sources, n);
        CHECK (wrong == 0, "%s, histogram matching %d: %zu of %zu voxels differ from their "
               "sources' pixels", names[c], hm, wrong, cube (n));
        for (size_t v = 0; v < cube (n); v++)
          axes[ts_solid_source_axis (sources[v])]++;
        CHECK (c != 2 || axes[1] == 0, "%s: no voxel copies the free orientation", names[c]);
        CHECK (c == 2 || (axes[0] && axes[1] && axes[2]),
               "%s: every orientation supplies voxels (%zu, %zu, %zu)", names[c], axes[0],
               axes[1], axes[2]);
        CHECK (run (cases[c], p, &plain, NULL) == TS_OK, "%s: synthesis", names[c]);
        CHECK (memcmp (plain, volume, cube (n) * VOXEL_BYTES) == 0,
               "%s: recording sources leaves the volume as it was", names[c]);
        fprintf (stderr, "  %s, histogram matching %d: %zu voxels exact, from x %zu, y %zu, z %zu\n",
                 names[c], hm, cube (n) - wrong, axes[0], axes[1], axes[2]);
        free (volume);
        free (plain);
        free (sources);
      }
  free (granite.pixels);
  free (bark.pixels);
  free (brick.pixels);
}

/* Translucent exemplar pixels: colours exact, alpha within 1 ulp (the
 * engine's working scale, x 100 / 100), the same in 8 bits. */
static void
test_translucent (void)
{
  TsImage ex;
  TsSolidParams p;
  float *volume, *laid;
  TsSolidSource *sources;
  size_t n = 16, colour_differ = 0, alpha_far = 0, alpha_8bit = 0, alpha_ulp = 0;
  TsError error;

  test_noise_image (&ex, 32, 32, 4);
  for (size_t i = 0; i < 32 * 32; i++)
    ex.pixels[i * TS_CHANNELS + 3] = (float) (1 + i % 255) / 255.0f;
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 2;
  CHECK (run (all, p, &volume, &sources) == TS_OK, "synthesis");
  laid = checked_malloc (cube (n) * VOXEL_BYTES);
  const void *maps[3] = { ex.pixels, ex.pixels, ex.pixels };
  size_t counts[3] = { 32 * 32, 32 * 32, 32 * 32 };
  CHECK (ts_solid_apply_sources (sources, cube (n), maps, counts, VOXEL_BYTES, laid, &error)
         == TS_OK, "applying the sources: %s", error.message);
  for (size_t v = 0; v < cube (n); v++)
    {
      const float *a = laid + v * TS_CHANNELS, *b = volume + v * TS_CHANNELS;
      colour_differ += memcmp (a, b, 3 * sizeof (float)) != 0;
      alpha_ulp += a[3] != b[3];
      alpha_far += a[3] != b[3] && nextafterf (a[3], b[3]) != b[3];
      alpha_8bit += lroundf (a[3] * 255.0f) != lroundf (b[3] * 255.0f);
    }
  CHECK (colour_differ == 0, "translucent: %zu voxels' colours differ", colour_differ);
  CHECK (alpha_far == 0 && alpha_8bit == 0, "translucent: alpha more than 1 ulp off in %zu "
         "voxels, another 8-bit value in %zu", alpha_far, alpha_8bit);
  fprintf (stderr, "  translucent exemplar: colours exact, alpha 1 ulp off in %zu of %zu voxels, "
           "8-bit alpha exact\n", alpha_ulp, cube (n));
  free (volume);
  free (laid);
  free (sources);
  free (ex.pixels);
}

/* A map that is a pixel-wise function of the exemplar (inverted
 * lightness, alpha kept) comes out as that function of the volume. */
static void
invert_lightness (float *pixels, size_t count)
{
  for (size_t i = 0; i < count; i++)
    pixels[i * TS_CHANNELS] = 100.0f - pixels[i * TS_CHANNELS];
}

static void
test_alignment (void)
{
  TsImage brick;
  TsSolidParams p;
  float *volume, *map, *laid;
  TsSolidSource *sources;
  size_t n = 32, pixels, worst_at = 0;
  double worst = 0.0;
  TsError error;

  test_load_exemplar ("brick.png", &brick);
  pixels = brick.width * brick.height;
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 11;
  const TsImage *all[3] = { &brick, &brick, &brick };
  CHECK (run (all, p, &volume, &sources) == TS_OK, "synthesis");
  map = checked_malloc (pixels * VOXEL_BYTES);
  laid = checked_malloc (cube (n) * VOXEL_BYTES);
  memcpy (map, brick.pixels, pixels * VOXEL_BYTES);
  invert_lightness (map, pixels);
  const void *maps[3] = { map, map, map };
  size_t counts[3] = { pixels, pixels, pixels };
  CHECK (ts_solid_apply_sources (sources, cube (n), maps, counts, VOXEL_BYTES, laid, &error)
         == TS_OK, "applying the sources: %s", error.message);
  invert_lightness (volume, cube (n));
  for (size_t v = 0; v < cube (n); v++)
    {
      double d = fabs ((double) laid[v * TS_CHANNELS] - (double) volume[v * TS_CHANNELS]);
      if (d > worst)
        {
          worst = d;
          worst_at = v;
        }
    }
  /* Range of L is 100: 1 % is 1.0; copies must in fact be exact. */
  CHECK (worst == 0.0, "the laid-out map differs from the function of the volume by %g at "
         "voxel %zu", worst, worst_at);
  fprintf (stderr, "  inverted-lightness map: max error %g of 100\n", worst);
  free (volume);
  free (sources);
  free (map);
  free (laid);
  free (brick.pixels);
}

static void
test_threads (void)
{
#ifdef _OPENMP
  TsImage bark;
  TsSolidParams p;
  float *v1, *v2;
  TsSolidSource *s1, *s2;
  size_t n = 40; /* above the engine's one-thread edge of 32 */

  test_load_exemplar ("bark.png", &bark);
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 8;
  p.max_iterations = 2;
  const TsImage *all[3] = { &bark, &bark, &bark };
  omp_set_num_threads (1);
  CHECK (run (all, p, &v1, &s1) == TS_OK, "synthesis at 1 thread");
  omp_set_num_threads (2);
  CHECK (run (all, p, &v2, &s2) == TS_OK, "synthesis at 2 threads");
  CHECK (memcmp (s1, s2, cube (n) * sizeof (TsSolidSource)) == 0,
         "1 and 2 threads record the same sources");
  CHECK (memcmp (v1, v2, cube (n) * VOXEL_BYTES) == 0, "1 and 2 threads give the same volume");
  free (v1);
  free (v2);
  free (s1);
  free (s2);
  free (bark.pixels);
#else
  CHECK (false, "built without OpenMP: the thread test cannot run");
#endif
}

static void
test_bad_arguments (void)
{
  TsImage ex;
  TsSolidParams p;
  TsError e;
  size_t without, with, n = 16;
  float *volume = checked_malloc (cube (n) * VOXEL_BYTES);
  TsSolidSource *sources = checked_malloc (cube (n) * sizeof (TsSolidSource));

  test_noise_image (&ex, 32, 32, 2);
  const TsImage *all[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&p);
  p.size = n;
  CHECK (ts_synthesize_solid_with_sources (&p, all, volume, sources, NULL, NULL, &e)
         == TS_ERROR_INVALID_ARGUMENT, "sources without record_sources are refused");
  p.record_sources = true;
  CHECK (ts_synthesize_solid_with_sources (&p, all, volume, NULL, NULL, NULL, &e)
         == TS_ERROR_INVALID_ARGUMENT, "record_sources without a buffer is refused");
  CHECK (ts_synthesize_solid (&p, all, volume, NULL, NULL, &e) == TS_OK,
         "ts_synthesize_solid ignores record_sources: %s", e.message);

  /* The position histogram keeps every voxel's source whether or not
   * the caller records them; without it (no histogram matching, or the
   * cell structure) recording adds them. */
  p.size = 128;
  for (int c = 0; c < 3; c++)
    {
      bool keeps = c == 0; /* histogram matching without the cell structure */
      p.histogram_matching = c != 1;
      p.cell_structure = c == 2 ? TS_CELL_STRUCTURE_ON : TS_CELL_STRUCTURE_OFF;
      p.record_sources = false;
      CHECK (ts_solid_estimate_memory (&p, all, &without, &e) == TS_OK, "estimate: %s", e.message);
      p.record_sources = true;
      CHECK (ts_solid_estimate_memory (&p, all, &with, &e) == TS_OK, "estimate: %s", e.message);
      CHECK (with - without == (keeps ? 0 : cube (128) * sizeof (TsSolidSource)),
             "case %d: recording adds %zu bytes to the estimate (%zu -> %zu)", c, with - without,
             without, with);
    }
  p.histogram_matching = true;
  p.cell_structure = TS_CELL_STRUCTURE_OFF;

  /* A map too small, or missing for an orientation that voxels copy. */
  for (size_t v = 0; v < cube (n); v++)
    sources[v] = ts_solid_source_pack ((int) (v % 3), (uint32_t) (v % 1024));
  float small[4 * 16] = { 0 }, out[4] = { -1, -1, -1, -1 };
  const void *maps[3] = { small, small, small };
  size_t counts[3] = { 16, 16, 16 };
  CHECK (ts_solid_apply_sources (sources, cube (n), maps, counts, VOXEL_BYTES, out, &e)
         == TS_ERROR_INVALID_ARGUMENT && out[0] == -1, "a map smaller than the exemplar is "
         "refused and nothing written");
  maps[1] = NULL;
  counts[0] = counts[1] = counts[2] = 1024;
  CHECK (ts_solid_apply_sources (sources, 3, maps, counts, VOXEL_BYTES, out, &e)
         == TS_ERROR_INVALID_ARGUMENT && strstr (e.message, "across y"),
         "a missing map is named: %s", e.message);
  free (volume);
  free (sources);
  free (ex.pixels);
}

int
main (void)
{
  test_bad_arguments ();
  test_round_trip ();
  test_translucent ();
  test_alignment ();
  test_threads ();
  return test_finish ("test-solid-sources");
}
