/* guided-regions: texture by numbers on built cases of any three
 * textures (tools/guided-cases.h): the left 48x96 of each side by side
 * with its label map, grown to 160x160 discs, 24 px stripes and 10 px
 * slanted lines. For labels in layers (the default) and with blended
 * edges, prints the label fidelity, the label edge offset and each
 * region's coherence over that of a plain synthesis of its texture alone
 * at 160x160 (the aim is <= 1.2), medians over SEEDS seeds from 4 (3 by
 * default, as test-guided-metrics; at most 16); with -o DIR also writes
 * the seed-4 results there.
 *
 * Usage: guided-regions [-n SEEDS] [-o DIR] FIRST.png SECOND.png THIRD.png
 * Each texture must be at least 48x96. Threads: OMP_NUM_THREADS.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "guided-cases.h"
#include "image-io.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static int
fail (const char *what, TsStatus status, const TsError *error)
{
  fprintf (stderr, "guided-regions: %s: %s\n", what,
           error->message[0] ? error->message : ts_status_string (status));
  return 1;
}

int
main (int argc, char **argv)
{
  const char *dir = NULL;
  size_t seeds = TS_CASE_SEEDS;
  uint8_t labels[TS_CASE_EX_W * TS_CASE_EX_H];
  TsImage textures[3] = { { 0 } }, ex, out = { TS_CASE_OUT, TS_CASE_OUT, NULL };
  double plain[3];
  TsError error = { TS_OK, "" };
  TsStatus status;
  char why[256];
  int opt;
  bool built;

  while ((opt = getopt (argc, argv, "n:o:")) != -1)
    if (opt == 'o')
      dir = optarg;
    else if (opt == 'n' && atoi (optarg) >= 1 && atoi (optarg) <= TS_CASE_MAX_SEEDS)
      seeds = (size_t) atoi (optarg);
    else
      {
        fprintf (stderr, "usage: guided-regions [-n SEEDS (1-%d)] [-o DIR] FIRST.png "
                 "SECOND.png THIRD.png\n", TS_CASE_MAX_SEEDS);
        return 2;
      }
  if (argc - optind != 3)
    {
      fprintf (stderr,
               "usage: guided-regions [-n SEEDS] [-o DIR] FIRST.png SECOND.png THIRD.png\n");
      return 2;
    }
  ts_io_init ();
  for (size_t l = 0; l < 3; l++)
    if (!ts_io_load (argv[optind + l], &textures[l], why, sizeof why))
      {
        fprintf (stderr, "guided-regions: %s: %s\n", argv[optind + l], why);
        return 1;
      }
  built = ts_case_exemplar (textures, &ex, labels);
  for (size_t l = 0; l < 3; l++)
    free (textures[l].pixels);
  if (!built)
    {
      fprintf (stderr, "guided-regions: each texture must be at least %dx%d\n", TS_CASE_STRIP,
               TS_CASE_EX_H);
      return 1;
    }
  out.pixels = malloc (TS_CASE_OUT * TS_CASE_OUT * TS_CHANNELS * sizeof (float));
  if (!out.pixels)
    return fail ("result", TS_ERROR_OUT_OF_MEMORY, &error);
  for (size_t l = 0; l < 3; l++)
    if ((status = ts_case_plain_coherence (&ex, l, seeds, &plain[l], &error)) != TS_OK)
      return fail ("plain synthesis", status, &error);
  printf ("plain coherence at %dx%d: %.3f %.3f %.3f\n", TS_CASE_OUT, TS_CASE_OUT, plain[0],
          plain[1], plain[2]);
  for (TsCaseLayout layout = TS_CASE_DISCS; layout < TS_CASE_LAYOUTS; layout++)
    for (int blend = 0; blend <= 1; blend++)
      {
        const char *how = blend ? "blended" : "layers";
        TsCaseFigures f;
        status = ts_case_guided (&ex, labels, layout, blend, seeds, &f, &out, &error);
        if (status != TS_OK)
          return fail ("guided synthesis", status, &error);
        printf ("%-8s %-7s fidelity %.3f  edge offset %.2f px  coherence / plain:",
                ts_case_layout_name[layout], how, ts_case_median (f.fidelity, seeds),
                ts_case_median (f.offset, seeds));
        for (size_t l = 0; l < 3; l++)
          printf (" %.2f", ts_case_median (f.region[l], seeds) / plain[l]);
        putchar ('\n');
        if (dir)
          {
            char path[4096];
            snprintf (path, sizeof path, "%s/%s-%s.png", dir, ts_case_layout_name[layout], how);
            if (!ts_io_save (path, &out, why, sizeof why))
              fprintf (stderr, "guided-regions: %s: %s\n", path, why);
          }
      }
  free (ex.pixels);
  free (out.pixels);
  return 0;
}
