/* texsynth-heal-measure: quality measures of a healed image against the
 * original and its hole (definitions in heal-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "argument-lists.h"
#include "heal-metrics.h"
#include "image-io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXIT_USAGE 2

static const char usage_text[] =
  "Usage: texsynth-heal-measure [--json] ORIGINAL MASK RESULT\n"
  "       texsynth-heal-measure [--json] --hole-from-alpha ORIGINAL RESULT\n"
  "       texsynth-heal-measure ARGUMENTS + ARGUMENTS...\n"
  "Measures how well RESULT fills the hole of ORIGINAL: the MASK's pixels\n"
  "with L * alpha >= 50 (white on black), or the pixels of ORIGINAL that are\n"
  "not fully opaque. CIE Lab, 7x7 windows; \"near\" = known pixels within 64\n"
  "pixels of the hole. Argument lists joined by '+' (a file named '+' is\n"
  "'./+') are measured in turn in one process, each after a 'result: PATH'\n"
  "line (with --json, one object per line, in order); the first that fails\n"
  "ends the run.\n"
  "\n"
  "  coherence, completeness  mean RMS Lab distance from result windows at\n"
  "                least half in the hole to the nearest hole-free original\n"
  "                window near it, and back; fill_bds is their sum\n"
  "  boundary      mean Lab step across the hole's outline over that between\n"
  "                near known neighbours (boundary_original: the same in ORIGINAL)\n"
  "  sharpness     mean |grad L| in the hole over that of the near known pixels\n"
  "                (sharpness_original: the same in ORIGINAL)\n"
  "  outside_changed  pixels outside the hole that differ by more than 0.01 Lab\n"
  "                (must be 0; a lossless change of bit depth does not count)\n";

static int
fail (const char *message, const char *arg)
{
  fprintf (stderr, "texsynth-heal-measure: ");
  fprintf (stderr, message, arg);
  fputc ('\n', stderr);
  return EXIT_USAGE;
}

static bool
load (const char *path, TsImage *image)
{
  char why[512];
  if (ts_io_load (path, image, why, sizeof why))
    return true;
  fail ("%s", why);
  return false;
}

/* One argument list: argv[1..argc-1], argv[0] unused. `several`: there
 * are other lists, so the text figures are named. */
static int
measure_arguments (int argc, char **argv, bool several)
{
  const char *paths[3];
  int n = 0, code = EXIT_USAGE;
  bool json = false, from_alpha = false;
  TsImage original = { 0 }, mask = { 0 }, result = { 0 };
  uint8_t *hole = NULL;
  TsHealMeasures m;

  for (int i = 1; i < argc; i++)
    {
      if (strcmp (argv[i], "--json") == 0)
        json = true;
      else if (strcmp (argv[i], "--hole-from-alpha") == 0)
        from_alpha = true;
      else if (strcmp (argv[i], "-h") == 0 || strcmp (argv[i], "--help") == 0)
        {
          fputs (usage_text, stdout);
          return EXIT_SUCCESS;
        }
      else if (argv[i][0] == '-' && argv[i][1])
        return fail ("unknown option '%s'", argv[i]);
      else if (n < 3)
        paths[n++] = argv[i];
      else
        return fail ("too many arguments ('%s')", argv[i]);
    }
  if (n != (from_alpha ? 2 : 3))
    return fail ("%s", from_alpha ? "expected ORIGINAL RESULT" : "expected ORIGINAL MASK RESULT");

  ts_io_init ();
  if (!load (paths[0], &original) || (!from_alpha && !load (paths[1], &mask)) ||
      !load (paths[from_alpha ? 1 : 2], &result))
    goto out;
  if (result.width != original.width || result.height != original.height ||
      (!from_alpha && (mask.width != original.width || mask.height != original.height)))
    {
      fail ("%s", "the images must all have the same size");
      goto out;
    }
  hole = malloc (original.width * original.height);
  if (!hole)
    goto out;
  for (size_t p = 0; p < original.width * original.height; p++)
    hole[p] = from_alpha ? original.pixels[p * TS_CHANNELS + 3] < 1.0f
                         : mask.pixels[p * TS_CHANNELS] * mask.pixels[p * TS_CHANNELS + 3] >= 50.0f;
  if (ts_measure_heal (&original, &result, hole, &m) != TS_MEASURE_OK)
    {
      fail ("%s", "cannot measure: out of memory, or no window at least half in the hole "
                  "or no hole-free window near it");
      goto out;
    }
  if (several && !json)
    printf ("result: %s\n", paths[from_alpha ? 1 : 2]);
  if (json)
    printf ("{\"fill_bds\": %.6g, \"coherence\": %.6g, \"completeness\": %.6g, "
            "\"boundary\": %.6g, \"boundary_original\": %.6g, \"sharpness\": %.6g, "
            "\"sharpness_original\": %.6g, "
            "\"outside_changed\": %zu, \"hole_pixels\": %zu}\n",
            m.fill_bds, m.coherence, m.completeness, m.boundary, m.boundary_original,
            m.sharpness, m.sharpness_original, m.outside_changed, m.hole_pixels);
  else
    printf ("fill_bds: %.4f\ncoherence: %.4f\ncompleteness: %.4f\nboundary: %.4f\n"
            "boundary_original: %.4f\nsharpness: %.4f\nsharpness_original: %.4f\n"
            "outside_changed: %zu\nhole_pixels: %zu\n",
            m.fill_bds, m.coherence, m.completeness, m.boundary, m.boundary_original,
            m.sharpness, m.sharpness_original, m.outside_changed, m.hole_pixels);
  code = fflush (stdout) == 0 ? EXIT_SUCCESS : EXIT_USAGE;
out:
  free (hole);
  free (original.pixels);
  free (mask.pixels);
  free (result.pixels);
  return code;
}

int
main (int argc, char **argv)
{
  return ts_run_argument_lists (argc, argv, measure_arguments, EXIT_SUCCESS);
}
