/* solid-memory: peak memory of the solid engine alone, without GEGL (whose
 * start-up alone takes a few hundred MiB of RSS on Debian 12), for the
 * solid benchmark. Synthesises a SIZE^3 volume from a generated opaque
 * EXEMPLAR x EXEMPLAR noise image and prints the time and peak RSS; with
 * --sources also every voxel's source (ts_synthesize_solid_with_sources),
 * which must reproduce the volume exactly.
 * Usage: solid-memory [--sources] SIZE [EXEMPLAR_SIDE]
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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
  bool with_sources = argc > 1 && strcmp (argv[1], "--sources") == 0;
  size_t side, voxels;
  float *volume;
  TsSolidSource *sources = NULL;

  if (with_sources)
    argv++, argc--;
  if (argc < 2)
    {
      fprintf (stderr, "usage: solid-memory [--sources] SIZE [EXEMPLAR_SIDE]\n");
      return 2;
    }
  side = argc > 2 ? (size_t) atol (argv[2]) : 128;
  ts_solid_params_init (&params);
  params.size = (size_t) atol (argv[1]);
  params.record_sources = with_sources;
  voxels = params.size * params.size * params.size;
  exemplar.width = exemplar.height = side;
  exemplar.pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  volume = malloc (voxels * TS_CHANNELS * sizeof (float));
  if (with_sources)
    sources = malloc (voxels * sizeof (TsSolidSource));
  if (!exemplar.pixels || !volume || (with_sources && !sources))
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
  if (ts_synthesize_solid_with_sources (&params, exemplars, volume, sources, NULL, NULL, &error)
      != TS_OK)
    {
      fprintf (stderr, "solid-memory: %s\n", error.message);
      return 1;
    }
  clock_gettime (CLOCK_MONOTONIC, &t1);
  getrusage (RUSAGE_SELF, &usage);
  printf ("%zu^3 from %zux%zu%s, cell structure %s: %.2f s, peak RSS %.1f MiB\n", params.size, side,
          side, with_sources ? " with sources" : "",
          ts_solid_uses_cell_structure (&params, exemplars) ? "on" : "off",
          (double) (t1.tv_sec - t0.tv_sec) + (double) (t1.tv_nsec - t0.tv_nsec) * 1e-9,
          (double) usage.ru_maxrss / 1024.0);
  if (with_sources)
    {
      /* The exemplar's pixels laid out by the sources: alpha is 1, so the
       * volume must come back bit for bit. */
      const void *maps[3] = { exemplar.pixels, exemplar.pixels, exemplar.pixels };
      size_t counts[3] = { side * side, side * side, side * side }, differ = 0;
      float *laid = malloc (voxels * TS_CHANNELS * sizeof (float));
      if (!laid || ts_solid_apply_sources (sources, voxels, maps, counts,
                                           TS_CHANNELS * sizeof (float), laid, &error) != TS_OK)
        {
          fprintf (stderr, "solid-memory: cannot apply the sources\n");
          return 1;
        }
      for (size_t p = 0; p < voxels; p++)
        differ += memcmp (laid + p * TS_CHANNELS, volume + p * TS_CHANNELS,
                          TS_CHANNELS * sizeof (float)) != 0;
      printf ("sources reproduce %zu of %zu voxels exactly\n", voxels - differ, voxels);
      free (laid);
      if (differ)
        return 1;
    }
  free (sources);
  free (volume);
  free (exemplar.pixels);
  return 0;
}
