/* engine-time: times ts_synthesize alone (no GEGL start-up, loading or
 * saving) per exemplar, splits the time by stage, and prints a hash of
 * each result so that an optimisation can be checked to change nothing.
 * Beside the wall-clock time it prints the process's CPU time (user +
 * sys, all threads) of the same run, which other work on a busy machine
 * barely changes.
 *
 * Usage: engine-time [-s SIZE] [-c CROP] [-r RUNS] [-e SEED] [-q QUALITY]
 *                    [-T] [-p] [-I] [-m] [-w DIR] EXEMPLAR.png|EXEMPLAR.WxH.f32...
 *   -s  output side (256)         -c  central CROP x CROP of the exemplar
 *   -r  runs, the median is shown (1)   -e  seed (1)   -q  quality (default)
 *   -T  tileable                  -p  per-stage seconds (last run)
 *   -m  also ask for the source map (what source-map=true costs)
 *   -I  re-synthesise the exemplar from itself (output = exemplar size,
 *       identity initial map, preserve weight 1 at the border falling to 0
 *       in the middle): the data-term path that texsynth:tileable uses
 *   -w DIR  also write each (cropped) exemplar, as the engine reads it,
 *       into DIR as NAME.WxH.f32 (raw Lab + alpha floats, native order)
 * An exemplar named *.WxH.f32 is read raw, without GEGL: with only such
 * inputs valgrind can run this program (GEGL's start-up stops it).
 * Threads: OMP_NUM_THREADS.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "image-io.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_STAGES 8
#define MAX_RUNS 99

typedef struct
{
  double      last;
  const char *name[MAX_STAGES];
  double      seconds[MAX_STAGES];
  size_t      count;
} Stages;

static double
clock_seconds (clockid_t clock)
{
  struct timespec t;
  clock_gettime (clock, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

static double
now (void)
{
  return clock_seconds (CLOCK_MONOTONIC);
}

/* The time since the previous report belongs to the stage now reported
 * (the engine reports a stage when a piece of it is done). */
static bool
on_progress (double fraction, const char *stage, void *user_data)
{
  Stages *s = user_data;
  double t = now ();
  size_t i;
  (void) fraction;

  for (i = 0; i < s->count && strcmp (s->name[i], stage) != 0; i++)
    ;
  if (i == s->count && s->count < MAX_STAGES)
    {
      s->name[s->count] = stage;
      s->seconds[s->count++] = 0.0;
    }
  if (i < MAX_STAGES)
    s->seconds[i] += t - s->last;
  s->last = t;
  return true;
}

static uint64_t
hash_image (const TsImage *image)
{
  const unsigned char *bytes = (const unsigned char *) image->pixels;
  size_t n = image->width * image->height * TS_CHANNELS * sizeof (float);
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < n; i++)
    h = (h ^ bytes[i]) * 1099511628211ull;
  return h;
}

static bool
crop_centre (TsImage *image, size_t side)
{
  size_t x0, y0;
  float *pixels;

  if (side == 0 || image->width < side || image->height < side)
    return false;
  x0 = (image->width - side) / 2;
  y0 = (image->height - side) / 2;
  pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  if (!pixels)
    return false;
  for (size_t y = 0; y < side; y++)
    memcpy (pixels + y * side * TS_CHANNELS,
            image->pixels + ((y0 + y) * image->width + x0) * TS_CHANNELS,
            side * TS_CHANNELS * sizeof (float));
  free (image->pixels);
  image->pixels = pixels;
  image->width = image->height = side;
  return true;
}

/* A raw exemplar, NAME.WxH.f32: false (with `why`) if the name has no
 * size or the file does not hold exactly that many pixels. */
static bool
load_raw (const char *path, TsImage *image, char *why, size_t why_size)
{
  size_t len = strlen (path), start = len - 4, w = 0, h = 0, n;
  FILE *file;
  long length;
  char end;

  image->pixels = NULL;
  while (start > 0 && path[start - 1] != '.')   /* the "WxH" before ".f32" */
    start--;
  if (start == 0 || sscanf (path + start, "%zux%zu%c", &w, &h, &end) != 3 || end != '.'
      || w == 0 || h == 0 || w > 65536 || h > 65536)
    {
      snprintf (why, why_size, "%s: a raw exemplar is named NAME.WxH.f32", path);
      return false;
    }
  n = w * h * TS_CHANNELS;
  file = fopen (path, "rb");
  if (!file || fseek (file, 0, SEEK_END) != 0 || (length = ftell (file)) < 0
      || (size_t) length != n * sizeof (float) || fseek (file, 0, SEEK_SET) != 0
      || !(image->pixels = malloc (n * sizeof (float)))
      || fread (image->pixels, sizeof (float), n, file) != n)
    {
      snprintf (why, why_size, "%s: cannot read %zux%zu raw pixels", path, w, h);
      free (image->pixels);
      image->pixels = NULL;
      if (file)
        fclose (file);
      return false;
    }
  fclose (file);
  image->width = w;
  image->height = h;
  return true;
}

static bool
is_raw (const char *path)
{
  size_t n = strlen (path);
  return n > 4 && strcmp (path + n - 4, ".f32") == 0;
}

/* Writes `image` as DIR/NAME.WxH.f32 (NAME without its extension). */
static bool
save_raw (const char *dir, const char *name, const TsImage *image)
{
  char path[4096];
  size_t n = image->width * image->height * TS_CHANNELS, stem = strcspn (name, ".");
  FILE *file;
  bool ok;

  snprintf (path, sizeof path, "%s/%.*s.%zux%zu.f32", dir, (int) stem, name, image->width,
            image->height);
  file = fopen (path, "wb");
  if (!file)
    return false;
  ok = fwrite (image->pixels, sizeof (float), n, file) == n;
  return fclose (file) == 0 && ok;
}

static int
compare_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

int
main (int argc, char **argv)
{
  size_t side = 256, crop = 0;
  int runs = 1, quality = 0, opt, failures = 0;
  uint32_t seed = 1;
  bool tileable = false, per_stage = false, identity = false, source_map = false, gegl = false;
  const char *raw_dir = NULL;

  while ((opt = getopt (argc, argv, "s:c:r:e:q:TpImw:")) != -1)
    switch (opt)
      {
      case 's': side = (size_t) strtoul (optarg, NULL, 10); break;
      case 'c': crop = (size_t) strtoul (optarg, NULL, 10); break;
      case 'r': runs = atoi (optarg); break;
      case 'e': seed = (uint32_t) strtoul (optarg, NULL, 10); break;
      case 'q': quality = atoi (optarg); break;
      case 'T': tileable = true; break;
      case 'm': source_map = true; break;
      case 'p': per_stage = true; break;
      case 'I': identity = true; break;
      case 'w': raw_dir = optarg; break;
      default:
        fprintf (stderr, "usage: %s [-s SIZE] [-c CROP] [-r RUNS] [-e SEED] [-q QUALITY] "
                 "[-T] [-p] [-I] [-m] [-w DIR] EXEMPLAR.png|EXEMPLAR.WxH.f32...\n", argv[0]);
        return 2;
      }
  if (optind >= argc || side == 0 || runs < 1 || runs > MAX_RUNS)
    {
      fprintf (stderr, "%s: give at least one exemplar, a size > 0 and 1..%d runs\n",
               argv[0], MAX_RUNS);
      return 2;
    }
  for (int a = optind; a < argc && !gegl; a++)
    gegl = !is_raw (argv[a]);
  if (gegl)
    ts_io_init ();

  for (int a = optind; a < argc; a++)
    {
      TsImage exemplar, result;
      TsParams params;
      TsError error = { TS_OK, "" };
      char why[256] = "";
      double seconds[MAX_RUNS], cpu_seconds[MAX_RUNS];
      Stages stages;
      uint64_t hash = 0;
      int32_t *initial = NULL;
      float *preserve = NULL;
      const char *name = strrchr (argv[a], '/') ? strrchr (argv[a], '/') + 1 : argv[a];

      if (is_raw (argv[a]) ? !load_raw (argv[a], &exemplar, why, sizeof why)
                           : !ts_io_load (argv[a], &exemplar, why, sizeof why))
        {
          fprintf (stderr, "%s\n", why);
          failures++;
          continue;
        }
      if (crop && !crop_centre (&exemplar, crop))
        {
          printf ("%-14s skipped (smaller than %zux%zu)\n", name, crop, crop);
          free (exemplar.pixels);
          continue;
        }
      if (raw_dir && !save_raw (raw_dir, name, &exemplar))
        {
          fprintf (stderr, "%s: cannot write its raw copy into %s\n", name, raw_dir);
          failures++;
        }
      ts_params_init (&params);
      params.output_width = params.output_height = side;
      if (identity)
        {
          size_t w = exemplar.width, h = exemplar.height;
          initial = malloc (w * h * 2 * sizeof (int32_t));
          preserve = malloc (w * h * sizeof (float));
          if (!initial || !preserve)
            {
              fprintf (stderr, "out of memory\n");
              return 1;
            }
          for (size_t y = 0; y < h; y++)
            for (size_t x = 0; x < w; x++)
              {
                double dx = fabs ((double) x / (double) w - 0.5), dy = fabs ((double) y / (double) h - 0.5);
                double d = (dx > dy ? dx : dy) * 4.0 - 0.6;   /* 0 inside, 1 at the border */
                initial[2 * (y * w + x)] = (int32_t) x;
                initial[2 * (y * w + x) + 1] = (int32_t) y;
                preserve[y * w + x] = (float) (d < 0.0 ? 0.0 : d > 1.0 ? 1.0 : d);
              }
          params.output_width = w;
          params.output_height = h;
          params.initial_source = initial;
          params.preserve = preserve;
        }
      params.seed = seed;
      params.wrap_x = params.wrap_y = tileable;
      if (quality)
        params.quality = quality;
      result.width = params.output_width;
      result.height = params.output_height;
      result.pixels = malloc (result.width * result.height * TS_CHANNELS * sizeof (float));
      params.source_map = source_map ? malloc (result.width * result.height * 2 * sizeof (int32_t))
                                     : NULL;
      if (!result.pixels || (source_map && !params.source_map))
        {
          fprintf (stderr, "out of memory\n");
          return 1;
        }
      for (int r = 0; r < runs; r++)
        {
          double start = now (), cpu_start = clock_seconds (CLOCK_PROCESS_CPUTIME_ID);
          memset (&stages, 0, sizeof stages);
          stages.last = start;
          if (ts_synthesize (&params, &exemplar, &result, on_progress, &stages, &error) != TS_OK)
            {
              fprintf (stderr, "%s: %s\n", name, error.message);
              failures++;
              break;
            }
          seconds[r] = now () - start;
          cpu_seconds[r] = clock_seconds (CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
        }
      if (error.status == TS_OK)
        {
          hash = hash_image (&result);
          qsort (seconds, (size_t) runs, sizeof (double), compare_double);
          qsort (cpu_seconds, (size_t) runs, sizeof (double), compare_double);
          printf ("%-14s %5zu %8.3f s  cpu %8.3f s  %016" PRIx64, name, result.width,
                  seconds[runs / 2], cpu_seconds[runs / 2], hash);
          for (size_t i = 0; per_stage && i < stages.count; i++)
            printf ("  %s %.3f", stages.name[i], stages.seconds[i]);
          printf ("\n");
        }
      free (result.pixels);
      free (params.source_map);
      free (exemplar.pixels);
      free (initial);
      free (preserve);
    }
  return failures ? 1 : 0;
}
