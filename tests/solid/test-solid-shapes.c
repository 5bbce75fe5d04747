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
 * (met at 128^3 too: see the README's solid figures). The truth solids'
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
  static const Case cases[] = {
    /* At 64^3, mean of seeds 1-3: sharpness cells 0.93, blobs 1.10,
     * grains 1.07 x the truth's; coherence 0.95, 1.06, 1.01 x; specks
     * 3.22, 1.35, 1.98 x (cells 0.91, 0.93 and 3.14 before stones were
     * walled at lower necks, stop 68). Grains' specks were 1.80 x
     * before the phase guide took dark pieces too (solid history, stop
     * 64); the 64^2 blobs exemplar's largest dark piece holds 0.60 of
     * its dark pixels, so the guide stays off for it. Cells' specks were
     * 3.74 x before the phase guide; 3.7, 1.35, 1.81 x before the starts paired
     * children at a random shift, start.c; 3.5, 1.3, 1.7 x before the
     * E-step's shear rule; 4.4, 1.5, 1.9 x without specks.c's pass,
     * 6.5, 2.1, 2.5 x without the E-step's lone-voxel rule either (the
     * cells' and blobs' specks bounds catch both). Cells' light sections
     * 0.81 x the exemplar's (the light phase's; the dark stones are
     * stones too since stop 66); 0.73 with the stones' walls at necks
     * of 1.5 voxels, 0.69 before the E-step kept stones apart
     * (piece-topology.c) with the phase guide at the joint split,
     * 0.52 without the phase guide and the walls at necks either
     * (phase-guide.c, neck-walls.c), whose stones merged. Their
     * axis-edges 1.00 (1.03 before stop 66, 1.08 without the guide);
     * sharpness 0.92 x and coherence 0.98 x before stop 66. */
    { "cells", 0.90, 1.15, 1.08, 4.0, TS_CELL_STRUCTURE_OFF, 0.70, 0.0, 0.0, 0.0 },
    { "blobs", 0.90, 1.15, 1.08, 1.42, TS_CELL_STRUCTURE_AUTO, 0.0, 0.0, 0.0, 0.0 },
    { "grains", 0.90, 1.15, 1.08, 2.1, TS_CELL_STRUCTURE_AUTO, 0.0, 0.0, 0.0, 0.0 },
    /* With the cell structure, mean of seeds 1-3: sharpness 1.01,
     * coherence 0.98, completeness 1.00, specks 1.44 x the truth's;
     * axis-edges 1.04; light sections 0.82 x the exemplar's (the
     * truth's 0.95; without the guide 0.54: neighbouring stones merge
     * where the mortar does not close). With one slope of 3 at the
     * finest level (solid.h), specks were 4.3 x and sections 0.81, which
     * the specks bound catches. Lightness spread within sections 0.88 x the
     * truth's (1.10 when cells pieced themselves from stones of several
     * tones, before cell-tone.c). Spread of the stones' tones 0.93 x
     * the truth's (0.80 when each cell's tone was its voxels' mean, not
     * matched to the exemplar's stone tones). The dark phase 0.93 x as
     * thick as the truth's: 0.76 x when the guide's joints ended at the
     * phase split, in the darkest stones (phase-split.c), whose specks
     * were 1.4 x and sections 0.89: the dark stones between the splits
     * now hold specks where their texture crosses the phase split, as
     * the truth's smooth ones seldom do (solid history, stop 44).
     * Specks were 2.95 x before a light voxel with five face neighbours
     * below the phase split counted as lone (estep.c, solid history,
     * stops 45-46), 2.56 x when only neighbours in dark stones counted,
     * 1.83 x before the pieces of up to 4 voxels were removed (specks.c,
     * solid history, stop 47). */
    { "cells", 0.90, 1.15, 1.08, 1.7, TS_CELL_STRUCTURE_ON, 0.80, 1.0, 0.90, 0.82 },
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    test_kind (&cases[i]);
  /* At 64^3: axis-edges 1.020 and 1.060 (leopard 1.018 before the
   * phase guide took its dark spots, solid history, stop 64); streaks
   * 0.115 and 0.212. Before
   * the E-step's shear rule (estep.c) axis-edges were 0.948 and 0.995,
   * and streaks 0.287 and 0.316 (java's a band of 45-degree streaks
   * across its x slice, solid history, stops 49-50): both bounds fail
   * then. */
  test_cell_structure_refuses_transparency ();
  test_isotropic ("java.png", 0.20);
  test_isotropic ("leopard.png", 0.30);
  return test_finish ("test-solid-shapes");
}
