/* solid-memory: peak memory of the solid engine alone, without GEGL (whose
 * start-up alone takes a few hundred MiB of RSS on Debian 12), for the
 * solid benchmark. Synthesises a SIZE^3 volume from a generated opaque
 * EXEMPLAR x EXEMPLAR noise image and prints the time and peak RSS.
 * Usage: solid-memory SIZE [EXEMPLAR_SIDE]
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

int
main (int argc, char **argv)
{
  TsSolidParams params;
  TsImage exemplar;
  TsError error;
  struct rusage usage;
  struct timespec t0, t1;
  size_t side = argc > 2 ? (size_t) atol (argv[2]) : 128;
  float *volume;

  if (argc < 2)
    {
      fprintf (stderr, "usage: solid-memory SIZE [EXEMPLAR_SIDE]\n");
      return 2;
    }
  ts_solid_params_init (&params);
  params.size = (size_t) atol (argv[1]);
  exemplar.width = exemplar.height = side;
  exemplar.pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  volume = malloc (params.size * params.size * params.size * TS_CHANNELS * sizeof (float));
  if (!exemplar.pixels || !volume)
    {
      fprintf (stderr, "solid-memory: out of memory\n");
      return 1;
    }
  for (size_t i = 0; i < side * side; i++)
    {
      float *p = exemplar.pixels + i * TS_CHANNELS;
      double x = (double) (i % side), y = (double) (i / side);
      p[0] = (float) (50.0 + 30.0 * sin (x * 0.31) * cos (y * 0.23));
      p[1] = (float) (20.0 * sin ((x + y) * 0.17));
      p[2] = (float) (20.0 * cos ((x - y) * 0.13));
      p[3] = 1.0f;
    }
  const TsImage *exemplars[3] = { &exemplar, &exemplar, &exemplar };
  clock_gettime (CLOCK_MONOTONIC, &t0);
  if (ts_synthesize_solid (&params, exemplars, volume, NULL, NULL, &error) != TS_OK)
    {
      fprintf (stderr, "solid-memory: %s\n", error.message);
      return 1;
    }
  clock_gettime (CLOCK_MONOTONIC, &t1);
  getrusage (RUSAGE_SELF, &usage);
  printf ("%zu^3 from %zux%zu: %.2f s, peak RSS %.1f MiB\n", params.size, side, side,
          (double) (t1.tv_sec - t0.tv_sec) + (double) (t1.tv_nsec - t0.tv_nsec) * 1e-9,
          (double) usage.ru_maxrss / 1024.0);
  free (volume);
  free (exemplar.pixels);
  return 0;
}
