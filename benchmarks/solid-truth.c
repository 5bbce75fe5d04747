/* solid-truth: writes a periodic, isotropic solid texture whose slices in
 * every direction are samples of one and the same 2D texture, as an RGB
 * .vol file. quality-solid.py --truth takes its z = 0 slice as the
 * exemplar and measures other slices of it: what a perfect solid scores
 * on the quality figures, against which synthesised volumes are judged.
 * Usage: solid-truth KIND SIZE SEED OUT.vol  (KIND: one of truth-solids.h's)
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "truth-solids.h"
#include "volume/volume.h"

#include <stdio.h>
#include <stdlib.h>

int
main (int argc, char **argv)
{
  TsVolume8 v;
  TsError error;
  size_t bytes, n;
  long size = argc == 5 ? atol (argv[2]) : 0;

  if (size < 8 || size > 1024)
    {
      fprintf (stderr, "usage: solid-truth KIND SIZE(8..1024) SEED OUT.vol; KIND:");
      for (const char *const *kind = truth_solid_kinds (); *kind; kind++)
        fprintf (stderr, " %s", *kind);
      fputc ('\n', stderr);
      return 2;
    }
  n = (size_t) size;
  if (!ts_volume_bytes (n, 3, &bytes) || !(v.voxels = malloc (bytes)))
    {
      fprintf (stderr, "solid-truth: out of memory for a %zu^3 volume\n", n);
      return 1;
    }
  v.size = n;
  v.channels = 3;
  v.wrap = true;
  if (!truth_solid_render (argv[1], n, (uint32_t) strtoul (argv[3], NULL, 10), v.voxels))
    {
      fprintf (stderr, "solid-truth: unknown kind '%s' or out of memory\n", argv[1]);
      free (v.voxels);
      return 2;
    }
  if (ts_volume_write_vol (argv[4], argv[1], &v, &error) != TS_OK)
    {
      fprintf (stderr, "solid-truth: %s\n", error.message);
      free (v.voxels);
      return 1;
    }
  free (v.voxels);
  return 0;
}
