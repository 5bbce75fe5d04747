/* Solid synthesis reproduces the exemplar's kind of shapes in every
 * slice: on the ground-truth solids (benchmarks/truth-solids.c)
 * a volume synthesised from the truth's z = 0 slice is measured, across
 * x, y, z and the diagonal x = z, beside the truth's own slices: no more
 * axis-aligned edge energy than 1.08 x the exemplar's (no blocks, seams or
 * extruded dashes), coherence and completeness no worse than 1.15 x the
 * truth's, seamless periodic boundaries. On the bundled real exemplars
 * with no preferred edge orientation (java, leopard), the axis-edges and
 * seam aims, which need no truth.
 *
 * Sharpness at least 0.9 x the truth's, the aim, on all three
 * (met at 128^3 too: see docs/benchmarks.md's solid figures). The truth solids'
 * aims hold on the mean of three seeds (see test_kind). Beside them, a
 * bound on specks (lone pieces of a lightness phase, phase-thickness.h)
 * per slice pixel against the truth's: sharpness counts a speck as edge,
 * so a speckled volume could pass it with ragged mortar.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"
#include "metrics.h"
#include "phase-thickness.h"
#include "slice-figures.h"

#include <stdlib.h>
#include <string.h>

/* Big enough for several stones per slice, small enough for seconds. */
#define SIDE 64
/* Seeds whose figures are averaged (see test_kind). */
#define SEEDS 3
/* Small-size runs (test_small): the same paths, no thresholds. */
#define SMALL_SIDE 32

static size_t
side (void)
{
  return test_small () ? SMALL_SIDE : SIDE;
}

typedef struct
{
  const char *kind;
  double      sharpness_share;    /* of the truth's sharpness, at least   */
  double      completeness_share; /* of the truth's completeness, at most */
  double      axis_edges;         /* over the exemplar's, at most         */
  double      specks_share;       /* of the truth's specks, at most       */
  TsCellStructure cell_structure; /* TsSolidParams.cell_structure        */
  double      sections;           /* light sections over the exemplar's,
                                     at least (phase-thickness.h); 0 = none */
  double      tones;              /* lightness spread within sections, of
                                     the truth's, at most; 0 = none     */
  double      shades;             /* spread of the sections' mean
                                     lightness, of the truth's, at least;
                                     0 = none                           */
  double      thick;              /* the dark phase's thickness, of the
                                     truth's, at least; 0 = none        */
} Case;

/* One seed's figures: ours over the truth's (sharpness, coherence,
 * completeness) and ours alone (axis-edges over the exemplar's, seam). */
typedef struct
{
  double sharpness, coherence, completeness, axis_edges, seam, specks, sections, tones, shades, thick;
} Ratios;

static bool
measure_seed (const char *kind, TsCellStructure cell_structure, uint32_t seed, Ratios *r)
{
  size_t n = side ();
  float *truth = slice_truth_lab (kind, n, seed);
  float *ours = malloc (n * n * n * TS_CHANNELS * sizeof (float));
  TsImage exemplar = { n, n, NULL };
  SliceFigures t, o;
  PhaseFigures truth_phases, our_phases;
  double truth_thick, our_thick;
  TsSolidParams params;
  TsError error;
  bool ok = false;

  if (!truth || !ours)
    {
      CHECK (0, "%s: out of memory or unknown solid", kind);
      free (truth), free (ours);
      return false;
    }
  exemplar.pixels = truth; /* its first n^2 voxels: the slice z = 0 */
  const TsImage *ex3[3] = { &exemplar, &exemplar, &exemplar };
  ts_solid_params_init (&params);
  params.size = n;
  params.seed = seed;
  params.cell_structure = cell_structure;
  if (ts_synthesize_solid (&params, ex3, ours, NULL, NULL, &error) != TS_OK)
    CHECK (0, "%s, seed %u: %s", kind, seed, error.message);
  else if (!slice_figures (&exemplar, truth, n, &t) || !slice_figures (&exemplar, ours, n, &o)
           || !phase_figures (&exemplar, truth, n, &truth_phases)
           || !phase_figures (&exemplar, ours, n, &our_phases) || !(truth_phases.specks > 0.0)
           || !phase_thickness (&exemplar, truth, n, &truth_thick)
           || !phase_thickness (&exemplar, ours, n, &our_thick))
    CHECK (0, "%s, seed %u: figures", kind, seed);
  else
    {
      r->sharpness = o.median_sharpness / t.median_sharpness;
      r->coherence = o.median_coherence / t.median_coherence;
      r->completeness = o.median_completeness / t.median_completeness;
      r->axis_edges = o.median_axis_edges;
      r->seam = o.seam;
      r->specks = our_phases.specks / truth_phases.specks;
      r->sections = our_phases.sections;
      /* The exemplar's spread, the denominator of both, cancels. */
      r->tones = our_phases.tones / truth_phases.tones;
      r->shades = our_phases.shades / truth_phases.shades;
      r->thick = our_thick / truth_thick;
      printf ("%-7s seed %u: ours / truth sharpness %.3f, coherence %.3f, completeness %.3f, "
              "specks %.2f, tones %.2f, shades %.2f, thick %.2f; axis-edges %.3f (truth %.3f), "
              "seam %.3f, sections %.2f\n",
              kind, seed, r->sharpness, r->coherence, r->completeness, r->specks, r->tones,
              r->shades, r->thick, r->axis_edges, t.median_axis_edges, r->seam, r->sections);
      ok = true;
    }
  free (truth);
  free (ours);
  return ok;
}

/* The aims on the mean over SEEDS seeds: one seed's figures are a draw
 * of the exemplar and of four slices, and at 64^3 an independent sample
 * of the truth itself misses 14 of 180 single-seed checks (seeds 1-12;
 * solid-seeds.py -n), so a single seed could not tell engines apart. */
static void
test_kind (const Case *c)
{
  Ratios mean = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 }, r;
  const unsigned seeds = test_small () ? 1 : SEEDS;

  for (uint32_t seed = 1; seed <= seeds; seed++)
    {
      if (!measure_seed (c->kind, c->cell_structure, seed, &r))
        return;
      mean.sharpness += r.sharpness / seeds;
      mean.coherence += r.coherence / seeds;
      mean.completeness += r.completeness / seeds;
      mean.axis_edges += r.axis_edges / seeds;
      mean.seam += r.seam / seeds;
      mean.specks += r.specks / seeds;
      mean.sections += r.sections / seeds;
      mean.tones += r.tones / seeds;
      mean.shades += r.shades / seeds;
      mean.thick += r.thick / seeds;
    }
  printf ("%-7s%s mean of %u seeds: sharpness %.3f, coherence %.3f, completeness %.3f, specks %.2f, "
          "tones %.2f, shades %.2f, thick %.2f x the truth's; axis-edges %.3f, seam %.3f, "
          "sections %.2f\n",
          c->kind, c->cell_structure == TS_CELL_STRUCTURE_ON ? " (cell structure)" : "", seeds, mean.sharpness,
          mean.coherence, mean.completeness, mean.specks, mean.tones, mean.shades, mean.thick,
          mean.axis_edges, mean.seam, mean.sections);
  if (test_small ())
    return;
  CHECK (mean.axis_edges <= c->axis_edges, "%s: axis-edges %.3f <= %.2f", c->kind, mean.axis_edges,
         c->axis_edges);
  CHECK (mean.sharpness >= c->sharpness_share, "%s: sharpness %.3f >= %.2f x the truth's", c->kind,
         mean.sharpness, c->sharpness_share);
  CHECK (mean.coherence <= 1.15, "%s: coherence %.3f <= 1.15 x the truth's", c->kind, mean.coherence);
  CHECK (mean.completeness <= c->completeness_share, "%s: completeness %.3f <= %.2f x the truth's",
         c->kind, mean.completeness, c->completeness_share);
  CHECK (mean.seam <= 1.10, "%s: seam %.3f <= 1.10", c->kind, mean.seam);
  CHECK (mean.specks <= c->specks_share, "%s: specks %.2f <= %.2f x the truth's", c->kind,
         mean.specks, c->specks_share);
  if (c->sections > 0.0)
    CHECK (mean.sections >= c->sections, "%s: sections %.2f >= %.2f x the exemplar's", c->kind,
           mean.sections, c->sections);
  if (c->tones > 0.0)
    CHECK (mean.tones <= c->tones, "%s: tones %.2f <= %.2f x the truth's", c->kind, mean.tones,
           c->tones);
  if (c->shades > 0.0)
    CHECK (mean.shades >= c->shades, "%s: shades %.2f >= %.2f x the truth's", c->kind,
           mean.shades, c->shades);
  if (c->thick > 0.0)
    CHECK (mean.thick >= c->thick, "%s: the dark phase's thickness %.2f >= %.2f x the truth's",
           c->kind, mean.thick, c->thick);
}

/* The cell structure needs opaque exemplars (it carries its distances in
 * the working alpha): a transparent pixel is refused with a message. */
static void
test_cell_structure_refuses_transparency (void)
{
  size_t n = 16;
  TsImage ex = { n, n, calloc (n * n * TS_CHANNELS, sizeof (float)) };
  float *volume = malloc (n * n * n * TS_CHANNELS * sizeof (float));
  TsSolidParams params;
  TsError error;

  if (!ex.pixels || !volume)
    {
      CHECK (0, "out of memory");
      free (ex.pixels), free (volume);
      return;
    }
  for (size_t i = 0; i < n * n; i++)
    {
      ex.pixels[i * TS_CHANNELS] = (float) (i % 7) * 10.0f;
      ex.pixels[i * TS_CHANNELS + 3] = i == 5 ? 0.5f : 1.0f;
    }
  const TsImage *ex3[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&params);
  params.size = n;
  params.cell_structure = TS_CELL_STRUCTURE_ON;
  CHECK (ts_synthesize_solid (&params, ex3, volume, NULL, NULL, &error) == TS_ERROR_BAD_PARAMETER
           && strstr (error.message, "needs opaque exemplars"),
         "a translucent exemplar with the cell structure: %s", error.message);
  ex.pixels[5 * TS_CHANNELS + 3] = 1.0f;
  CHECK (ts_synthesize_solid (&params, ex3, volume, NULL, NULL, &error) == TS_OK,
         "an opaque exemplar with the cell structure: %s", error.message);
  for (size_t i = 0; i < n * n * n; i++)
    if (volume[i * TS_CHANNELS + 3] != 1.0f)
      {
        CHECK (0, "voxel %zu: alpha %g, not opaque", i, (double) volume[i * TS_CHANNELS + 3]);
        break;
      }
  free (ex.pixels);
  free (volume);
}

/* A bundled real exemplar with no preferred edge orientation: without a
 * truth, the aims that need none (axis-edges, seam), and at most
 * `streaks` of edge anisotropy in any slice (slice-figures.h), which
 * axis-edges does not see when the streaks are diagonal. */
static void
test_isotropic (const char *name, double streaks)
{
  size_t n = side ();
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
          "coherence %.3f, completeness %.3f, seam %.3f, streaks %.3f\n", name, anisotropy,
          o.median_axis_edges, o.worst_axis_edges, o.median_sharpness, o.median_coherence,
          o.median_completeness, o.seam, o.worst_slice_anisotropy);
  if (test_small ())
    {
      free (exemplar.pixels);
      free (ours);
      return;
    }
  CHECK (o.median_axis_edges <= 1.08, "%s: axis-edges %.3f <= 1.08", name, o.median_axis_edges);
  CHECK (o.worst_slice_anisotropy <= streaks, "%s: streaks (the worst slice's edge anisotropy) %.3f <= %.2f",
         name, o.worst_slice_anisotropy, streaks);
  CHECK (o.seam <= 1.10, "%s: seam %.3f <= 1.10", name, o.seam);
  free (exemplar.pixels);
  free (ours);
}

int
main (void)
{
  /* Each bound sits between the spread of its figure over seeds and what
   * a clearly worse volume gives. Figures at 64^3: the mean of seeds 1-3
   * (the test's), then in brackets the means of seeds 4-6 (and 7-9),
   * which an engine no worse could give as well (benchmarks/solid-shapes
   * 64 SEED KIND prints each seed's, -c with the cell structure, -f
   * without). The worse volumes: the same volumes blurred by a 3-voxel
   * box along each axis, or with one voxel in 500 (in 2000) turned to the
   * other lightness (L -> 100 - L), and for the cell structure's own
   * bounds the same seeds without it. The aims (axis-edges 1.08
   * x the exemplar's, sharpness 0.90 and coherence and completeness 1.15
   * x the truth's, seam 1.10) are bounds of their own; all figures stay
   * within them: sharpness 0.93 (1.04, 1.06) x for cells, 1.10 (0.94)
   * for blobs, 1.07 for grains, 1.01 (1.06) with the cell structure,
   * against 0.54-0.83 blurred; coherence at most 1.06, completeness at
   * most 1.03, axis-edges at most 1.06, seam at most 1.04.
   * - Specks: cells 3.23 (3.30, 3.68) x the truth's, 3.89 (4.09, 4.47)
   *   with one voxel in 500 turned: bound 4.0. Blobs 1.35 (1.23), single
   *   seeds 1.04-1.53, 1.47-1.97 with one in 2000 turned, 3.14 with one
   *   in 500: bound 1.55. Grains 1.98, 2.11 with one in 2000, 2.53 with
   *   one in 500: bound 2.25.
   *   With the cell structure 1.45 (1.56), 2.17 with one in 500, 3.23
   *   (3.30, 3.68) without it: bound 2.0.
   * - Light sections over the exemplar's: cells 0.81 (0.82, 0.87), 0.66
   *   (0.66, 0.70) blurred: bound 0.75; with the cell structure 0.82
   *   (0.82), 0.71 blurred: bound 0.76.
   * - With the cell structure, the lightness spread within sections 0.89
   *   (1.01) x the truth's, 1.05 (1.19, 1.20) without the cell structure,
   *   1.10 blurred: bound 1.08; the spread of the sections' tones 0.94
   *   (0.91), 0.79 (0.77, 0.92) without it, 0.74 blurred: bound 0.85; the
   *   dark phase's thickness 1.01 (1.33) x the truth's, single seeds
   *   0.83-2.21: bound 0.82, a dark phase a fifth thinner than the
   *   truth's. */
  static const Case cases[] = {
    { "cells", 0.90, 1.15, 1.08, 4.0, TS_CELL_STRUCTURE_OFF, 0.75, 0.0, 0.0, 0.0 },
    { "blobs", 0.90, 1.15, 1.08, 1.55, TS_CELL_STRUCTURE_AUTO, 0.0, 0.0, 0.0, 0.0 },
    { "grains", 0.90, 1.15, 1.08, 2.25, TS_CELL_STRUCTURE_AUTO, 0.0, 0.0, 0.0, 0.0 },
    { "cells", 0.90, 1.15, 1.08, 2.0, TS_CELL_STRUCTURE_ON, 0.76, 1.08, 0.85, 0.82 },
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    test_kind (&cases[i]);
  /* At 64^3, seed 1: axis-edges 1.031 and 1.060, streaks 0.128 and
   * 0.212. Without the E-step's shear rule (estep.c) the streaks reach
   * 0.287 and 0.316 (java's a band of 45-degree streaks across its x
   * slice): both bounds fail then. */
  test_cell_structure_refuses_transparency ();
  test_isotropic ("java.png", 0.20);
  test_isotropic ("leopard.png", 0.30);
  return test_finish ("test-solid-shapes");
}
