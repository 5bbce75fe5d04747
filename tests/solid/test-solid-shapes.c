/* Solid synthesis reproduces the exemplar's kind of shapes in every
 * slice (issue 14): on the ground-truth solids (benchmarks/truth-solids.c)
 * a volume synthesised from the truth's z = 0 slice is measured, across
 * x, y, z and the diagonal x = z, beside the truth's own slices: no more
 * axis-aligned edge energy than 1.08 x the exemplar's (no blocks, seams or
 * extruded dashes), coherence and completeness no worse than 1.15 x the
 * truth's, seamless periodic boundaries. On the bundled real exemplars
 * with no preferred edge orientation (java, leopard), the axis-edges and
 * seam aims, which need no truth.
 *
 * Sharpness at least 0.9 x the truth's, the aim, on all three
 * (met at 128^3 too: see the README's solid figures).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"
#include "metrics.h"
#include "slice-figures.h"
#include "truth-solids.h"

#include <stdlib.h>
#include <string.h>

/* Big enough for several stones per slice, small enough for seconds. */
#define SIDE 64

typedef struct
{
  const char *kind;
  double      sharpness_share;    /* of the truth's sharpness, at least   */
  double      completeness_share; /* of the truth's completeness, at most */
  double      axis_edges;         /* over the exemplar's, at most         */
} Case;

static void
test_kind (const Case *c)
{
  size_t n = SIDE, voxels = n * n * n;
  uint8_t *rgb = malloc (voxels * 3);
  float *truth = malloc (voxels * TS_CHANNELS * sizeof (float));
  float *ours = malloc (voxels * TS_CHANNELS * sizeof (float));
  TsImage exemplar = { n, n, NULL };
  SliceFigures t, o;
  TsSolidParams params;
  TsError error;

  if (!rgb || !truth || !ours || !truth_solid_render (c->kind, n, 1, rgb))
    {
      CHECK (0, "%s: out of memory or unknown solid", c->kind);
      free (rgb), free (truth), free (ours);
      return;
    }
  slice_rgb8_to_lab (rgb, voxels, truth);
  exemplar.pixels = truth; /* its first n^2 voxels: the slice z = 0 */
  const TsImage *ex3[3] = { &exemplar, &exemplar, &exemplar };
  ts_solid_params_init (&params);
  params.size = n;
  params.seed = 1;
  CHECK (ts_synthesize_solid (&params, ex3, ours, NULL, NULL, &error) == TS_OK, "%s: %s", c->kind,
         error.message);
  CHECK (slice_figures (&exemplar, truth, n, &t) && slice_figures (&exemplar, ours, n, &o),
         "%s: figures", c->kind);
  printf ("%-7s truth / ours: axis-edges %.3f / %.3f (worst slice %.3f / %.3f), sharpness %.3f / %.3f, "
          "coherence %.3f / %.3f, completeness %.3f / %.3f, seam %.3f / %.3f\n",
          c->kind, t.median_axis_edges, o.median_axis_edges, t.worst_axis_edges, o.worst_axis_edges,
          t.median_sharpness, o.median_sharpness, t.median_coherence, o.median_coherence,
          t.median_completeness, o.median_completeness, t.seam, o.seam);
  CHECK (o.median_axis_edges <= c->axis_edges, "%s: axis-edges %.3f <= %.2f", c->kind,
         o.median_axis_edges, c->axis_edges);
  CHECK (o.median_sharpness >= c->sharpness_share * t.median_sharpness,
         "%s: sharpness %.3f >= %.2f x the truth's %.3f", c->kind, o.median_sharpness,
         c->sharpness_share, t.median_sharpness);
  CHECK (o.median_coherence <= 1.15 * t.median_coherence, "%s: coherence %.3f <= 1.15 x %.3f",
         c->kind, o.median_coherence, t.median_coherence);
  CHECK (o.median_completeness <= c->completeness_share * t.median_completeness,
         "%s: completeness %.3f <= %.2f x %.3f", c->kind, o.median_completeness,
         c->completeness_share, t.median_completeness);
  CHECK (o.seam <= 1.10, "%s: seam %.3f <= 1.10", c->kind, o.seam);
  free (rgb);
  free (truth);
  free (ours);
}

/* A bundled real exemplar with no preferred edge orientation: without a
 * truth, the aims that need none (axis-edges, seam). */
static void
test_isotropic (const char *name)
{
  size_t n = SIDE;
  float *ours = malloc (n * n * n * TS_CHANNELS * sizeof (float));
  TsImage exemplar;
  SliceFigures o;
  TsSolidParams params;
  TsError error;
  double anisotropy;

  test_load_exemplar (name, &exemplar);
  if (!ours)
    {
      CHECK (0, "%s: out of memory", name);
      free (exemplar.pixels);
      return;
    }
  /* The aim compares like with like only on isotropic exemplars. */
  CHECK (ts_measure_anisotropy (&exemplar, &anisotropy) == TS_MEASURE_OK && anisotropy < 0.1,
         "%s: anisotropy %.3f, not an isotropic exemplar", name, anisotropy);
  const TsImage *ex3[3] = { &exemplar, &exemplar, &exemplar };
  ts_solid_params_init (&params);
  params.size = n;
  params.seed = 1;
  CHECK (ts_synthesize_solid (&params, ex3, ours, NULL, NULL, &error) == TS_OK, "%s: %s", name,
         error.message);
  CHECK (slice_figures (&exemplar, ours, n, &o), "%s: figures", name);
  printf ("%-11s anisotropy %.3f, ours: axis-edges %.3f (worst slice %.3f), sharpness %.3f, "
          "coherence %.3f, completeness %.3f, seam %.3f\n", name, anisotropy, o.median_axis_edges,
          o.worst_axis_edges, o.median_sharpness, o.median_coherence, o.median_completeness, o.seam);
  CHECK (o.median_axis_edges <= 1.08, "%s: axis-edges %.3f <= 1.08", name, o.median_axis_edges);
  CHECK (o.seam <= 1.10, "%s: seam %.3f <= 1.10", name, o.seam);
  free (exemplar.pixels);
  free (ours);
}

int
main (void)
{
  static const Case cases[] = {
    /* At 64^3: sharpness cells 1.04, blobs 1.17, grains 1.08 x the truth's;
     * coherence 1.06, 1.11, 1.00 x. */
    { "cells", 0.90, 1.15, 1.08 }, { "blobs", 0.90, 1.15, 1.08 }, { "grains", 0.90, 1.15, 1.08 },
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    test_kind (&cases[i]);
  /* At 64^3: axis-edges 1.028 and 0.971 (128^3, solid-shapes' central
   * crops: 1.057, 1.068). */
  test_isotropic ("java.png");
  test_isotropic ("leopard.png");
  return test_finish ("test-solid-shapes");
}
