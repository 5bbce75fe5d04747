/* heal-time: times ts_heal alone (no GEGL start-up, loading or saving),
 * prints the median of RUNS, the peak memory growth across the heal
 * (the peak above the resident size just before it: the peak is reset
 * through /proc/self/clear_refs, so loading the images through GEGL does
 * not hide it; "peak_reset": false where the kernel refused), the engine's own
 * memory estimate and a hash of the result, and saves the result for texsynth-heal-measure.
 *
 * Usage: heal-time [-r RUNS] [-e SEED] [-q QUALITY] [-c CONTEXT] [-o OUT.png]
 *                  IMAGE.png MASK.png
 * The hole is the MASK's pixels with L * alpha >= 50 (white on black).
 * Threads: OMP_NUM_THREADS.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "image-io.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_RUNS 99

static double
now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

/* A field of /proc/self/status in KiB ("VmHWM: %ld kB"; 0 if unknown). */
static long
status_kib (const char *field_format)
{
  FILE *f = fopen ("/proc/self/status", "r");
  char line[256];
  long kib = 0;
  while (f && fgets (line, sizeof line, f))
    if (sscanf (line, field_format, &kib) == 1)
      break;
  if (f)
    fclose (f);
  return kib;
}

/* Resets VmHWM to the resident size (Linux: "5" to clear_refs). */
static bool
reset_peak (void)
{
  FILE *f = fopen ("/proc/self/clear_refs", "w");
  bool ok = f && fputs ("5", f) >= 0;
  if (f && fclose (f) != 0)
    ok = false;
  return ok;
}

static int
by_value (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

int
main (int argc, char **argv)
{
  TsHealParams params;
  TsImage image = { 0 }, mask = { 0 }, result = { 0 };
  uint8_t *hole;
  TsError error;
  double times[MAX_RUNS];
  int runs = 1, opt;
  const char *out = NULL;
  char why[512];
  uint64_t hash = 1469598103934665603ULL;
  long before;
  bool peak_reset;
  size_t estimate;

  ts_heal_params_init (&params);
  params.seed = 1;
  while ((opt = getopt (argc, argv, "r:e:q:c:o:")) != -1)
    switch (opt)
      {
      case 'r': runs = atoi (optarg); break;
      case 'e': params.seed = (uint32_t) strtoul (optarg, NULL, 10); break;
      case 'q': params.quality = atoi (optarg); break;
      case 'c': params.context = (size_t) strtoul (optarg, NULL, 10); break;
      case 'o': out = optarg; break;
      default: return 2;
      }
  if (optind + 2 != argc || runs < 1 || runs > MAX_RUNS)
    {
      fprintf (stderr, "usage: heal-time [-r RUNS] [-e SEED] [-q QUALITY] [-c CONTEXT] "
                       "[-o OUT.png] IMAGE.png MASK.png\n");
      return 2;
    }
  ts_io_init ();
  if (!ts_io_load (argv[optind], &image, why, sizeof why) ||
      !ts_io_load (argv[optind + 1], &mask, why, sizeof why))
    {
      fprintf (stderr, "heal-time: %s\n", why);
      return 2;
    }
  if (mask.width != image.width || mask.height != image.height)
    {
      fprintf (stderr, "heal-time: the mask must have the image's size\n");
      return 2;
    }
  hole = malloc (image.width * image.height);
  result.width = image.width;
  result.height = image.height;
  result.pixels = malloc (image.width * image.height * TS_CHANNELS * sizeof (float));
  if (!hole || !result.pixels)
    return 2;
  /* Written now (not zeros: malloc + memset 0 may become calloc's
   * untouched pages), so its pages are not counted as the heal's growth. */
  memset (result.pixels, 0xff, image.width * image.height * TS_CHANNELS * sizeof (float));
  for (size_t p = 0; p < image.width * image.height; p++)
    hole[p] = mask.pixels[p * TS_CHANNELS] * mask.pixels[p * TS_CHANNELS + 3] >= 50.0f;
  if (ts_heal_estimate_memory (&params, &image, hole, NULL, &estimate, &error) != TS_OK)
    {
      fprintf (stderr, "heal-time: %s\n", error.message);
      return 1;
    }
  peak_reset = reset_peak ();
  before = peak_reset ? status_kib ("VmRSS: %ld kB") : status_kib ("VmHWM: %ld kB");
  for (int r = 0; r < runs; r++)
    {
      double t0 = now ();
      if (ts_heal (&params, &image, hole, NULL, &result, NULL, NULL, NULL, &error) != TS_OK)
        {
          fprintf (stderr, "heal-time: %s\n", error.message);
          return 1;
        }
      times[r] = now () - t0;
    }
  qsort (times, (size_t) runs, sizeof (double), by_value);
  for (size_t i = 0; i < image.width * image.height * TS_CHANNELS; i++)
    {
      uint32_t bits;
      memcpy (&bits, &result.pixels[i], sizeof bits);
      hash = (hash ^ bits) * 1099511628211ULL;
    }
  printf ("{\"seconds\": %.4f, \"peak_growth_mib\": %.1f, \"peak_reset\": %s, "
          "\"estimate_mib\": %.1f, \"hash\": \"%016" PRIx64 "\", \"width\": %zu, \"height\": %zu}\n",
          times[runs / 2], (double) (status_kib ("VmHWM: %ld kB") - before) / 1024.0,
          peak_reset ? "true" : "false",
          (double) estimate / 1048576.0, hash, image.width, image.height);
  if (out && !ts_io_save (out, &result, why, sizeof why))
    {
      fprintf (stderr, "heal-time: %s\n", why);
      return 1;
    }
  free (hole);
  free (image.pixels);
  free (mask.pixels);
  free (result.pixels);
  return 0;
}
