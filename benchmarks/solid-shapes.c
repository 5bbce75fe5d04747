/* solid-shapes: how alike in kind a synthesised solid's slices are to its
 * exemplar, beside the ground truth. For each ground-truth solid
 * (truth-solids.c) the truth's z = 0 slice is the exemplar; a volume of the
 * same size is synthesised from it, and both volumes' middle slices across
 * x, y, z and the diagonal x = z are measured against the exemplar
 * (slice-figures.c): coherence, completeness, sharpness, axis-edges (the
 * share of gradient energy within 10 degrees of the axes, over the
 * exemplar's) and the seam. An image path instead of a kind measures the
 * synthesis from its central SIZE x SIZE crop alone (no truth).
 * Usage: solid-shapes SIZE SEED [-o DIR] [-i ITERATIONS] [-p PATCH] [-q QUALITY] [-n] [-c|-f]
 *                     [cells|blobs|grains|IMAGE.png]...
 * -c turns the cell structure guide on (TsSolidParams.cell_structure) for
 * the solids named after it, -f off (the free path); by default it is
 * chosen automatically, and the first line says which way.
 * -o DIR saves, per solid, NAME-slices.png: the exemplar, the truth's
 * middle slice across x (blank without truth), and ours across x, y, z
 * and the diagonal. Each row ends with the sharpness averaged over every
 * x, y and z slice ("sharp-all"), steadier than the middle slices', and
 * the phase thickness over them ("thick", phase-thickness.h), then the
 * lowest and highest seam figure across interior lines of the seam's
 * slices ("planes", seam-planes.h): a seam only counts when it stands
 * out from them, and the largest edge anisotropy of any x, y or z slice
 * ("streaks", slice-figures.h): extrusion in any direction, then
 * how far the steps across a lattice of voxel planes stand from the
 * others ("grid", plane-steps.h): axis-aligned blocks, and last the specks per
 * 1000 pixels over every x, y and z slice ("specks", phase-thickness.h):
 * ragged, speckled edges that sharpness counts as edge, and the light
 * sections per slice over the exemplar's ("sections", phase-thickness.h):
 * stones merged or fragmented, and the lightness spread within those
 * sections over the exemplar's ("tones", phase-thickness.h): stones
 * pieced together from several of the exemplar's tones, and the spread
 * of the sections' mean lightness over the exemplar's ("shades"): stones
 * all of one middling tone where the exemplar's are light and dark, and
 * the lightness step between neighbours of the same phase over the
 * exemplar's ("grain", stones then joints): rough stones or joints. -i
 * sets the iterations per level and pass, -p the large neighbourhood's
 * side (0 = the schedule's), -q the quality (the search's breadth,
 * TsSolidParams.quality; 0 = the default). The exemplar's anisotropy
 * (metrics.h) says whether the axis-edges aim applies: only near 0 does
 * an isotropic solid's slice compare like with like. Beside it, the
 * exemplar's own axis-edge share and the share of edges spread evenly
 * over every direction (2 x TS_AXIS_EDGE_DEGREES / 90, 0.222): a soft
 * exemplar whose share lies below that has its edges turned off the axes
 * (granite1's veins: 0.199), and a slice that keeps its texture but not
 * that orientation reads their ratio (1.12), not 1. The share of voxels
 * copied from each orientation's votes shows when one orientation
 * dominates (its layers streak the other slices). -n adds a "sample"
 * row: the same truth solid drawn with another seed, measured against
 * this exemplar, which is what a perfect engine (a genuinely new sample
 * of the texture) would score: the aims it misses are the measures' own
 * spread.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "image-io.h"
#include "metrics.h"
#include "phase-thickness.h"
#include "plane-steps.h"
#include "seam-planes.h"
#include "slice-figures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Added to the seed to draw the independent sample of -n. */
#define NEW_SAMPLE_SEED_OFFSET 1000003u

static double
now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

/* The figures and the phase thickness `thick` (nan where it has no
 * meaning or memory ran out: see phase-thickness.h). */
/* The lowest and highest seam figure of the interior lines (seam-planes.h),
 * NAN if not measured. */
typedef struct
{
  double lo, hi;
} PlaneRange;

static PlaneRange
interior_planes (const TsImage *exemplar, const float *volume, size_t n)
{
  double planes[SEAM_PLANES];
  PlaneRange range = { NAN, NAN };

  if (!seam_planes (exemplar, volume, n, planes))
    return range;
  range.lo = range.hi = planes[1];
  for (int k = 2; k < SEAM_PLANES; k++)
    {
      range.lo = fmin (range.lo, planes[k]);
      range.hi = fmax (range.hi, planes[k]);
    }
  return range;
}

/* phase_figures', all NAN if out of memory. */
static PhaseFigures
phase_row (const TsImage *exemplar, const float *volume, size_t n)
{
  PhaseFigures figures = { NAN, NAN, NAN, NAN, { NAN, NAN } };
  if (!phase_figures (exemplar, volume, n, &figures))
    {
      figures.specks = figures.sections = figures.tones = figures.shades = NAN;
      figures.grain[0] = figures.grain[1] = NAN;
    }
  return figures;
}

/* plane_step_lattice's ratio, NAN if out of memory. */
static double
lattice (const float *volume, size_t n)
{
  double ratio;
  return plane_step_lattice (volume, n, &ratio) ? ratio : NAN;
}

static void
print_row (const char *name, const char *what, const SliceFigures *f, double thick,
           PlaneRange planes, double grid, PhaseFigures phases)
{
  printf ("%-9s %-6s coherence %6.3f completeness %6.3f sharpness %5.3f axis-edges %5.3f "
          "(x %.2f y %.2f z %.2f diag %.2f; worst %.3f) seam %5.3f sharp x %.2f y %.2f z %.2f d %.2f "
          "sharp-all %.3f thick %.3f planes %.3f %.3f streaks %.3f grid %.3f specks %.2f sections %.2f tones %.2f shades %.2f grain %.2f %.2f\n",
          name, what, f->median_coherence, f->median_completeness, f->median_sharpness,
          f->median_axis_edges, f->axis_edges[0], f->axis_edges[1], f->axis_edges[2],
          f->axis_edges[3], f->worst_axis_edges, f->seam, f->sharpness[0], f->sharpness[1],
          f->sharpness[2], f->sharpness[3], f->all_slices_sharpness, thick, planes.lo, planes.hi,
          f->worst_slice_anisotropy, grid, phases.specks, phases.sections, phases.tones,
          phases.shades, phases.grain[0], phases.grain[1]);
}

/* The truth solid `name` drawn with another seed, measured against the
 * exemplar of `seed`'s: an independent sample of the same texture. */
static bool
print_new_sample (const char *name, const TsImage *exemplar, size_t n, uint32_t seed)
{
  float *sample = slice_truth_lab (name, n, seed + NEW_SAMPLE_SEED_OFFSET);
  SliceFigures f;
  double thick = NAN;
  bool ok = sample && slice_figures (exemplar, sample, n, &f);

  if (ok)
    {
      phase_thickness (exemplar, sample, n, &thick);
      print_row (name, "sample", &f, thick, interior_planes (exemplar, sample, n), lattice (sample, n),
                 phase_row (exemplar, sample, n));
    }
  else
    fprintf (stderr, "solid-shapes: %s: could not render or measure a new sample\n", name);
  free (sample);
  return ok;
}

static void
save (const char *dir, const char *name, const char *what, const TsImage *image)
{
  char path[4096], why[256];
  if (!dir)
    return;
  snprintf (path, sizeof path, "%s/%s-%s.png", dir, name, what);
  if (!ts_io_save (path, image, why, sizeof why))
    fprintf (stderr, "solid-shapes: %s\n", why);
}

/* Copies `part` into column `column` of `strip` (panels n wide, a gap of
 * 4 pixels between them). */
static void
place (TsImage *strip, size_t column, const TsImage *part)
{
  size_t n = part->width;
  if (!strip->pixels)
    return;
  for (size_t y = 0; y < n; y++)
    memcpy (strip->pixels + (y * strip->width + column * (n + 4)) * TS_CHANNELS,
            part->pixels + y * n * TS_CHANNELS, n * TS_CHANNELS * sizeof (float));
}

/* The central n x n crop of an image file as the exemplar. */
static bool
load_crop (const char *path, size_t n, TsImage *out)
{
  TsImage whole;
  char why[256];
  if (!ts_io_load (path, &whole, why, sizeof why))
    {
      fprintf (stderr, "solid-shapes: %s\n", why);
      return false;
    }
  n = n < whole.width ? n : whole.width;
  n = n < whole.height ? n : whole.height;
  out->width = out->height = n;
  out->pixels = malloc (n * n * TS_CHANNELS * sizeof (float));
  if (out->pixels)
    for (size_t y = 0; y < n; y++)
      memcpy (out->pixels + y * n * TS_CHANNELS,
              whole.pixels + (((whole.height - n) / 2 + y) * whole.width + (whole.width - n) / 2) * TS_CHANNELS,
              n * TS_CHANNELS * sizeof (float));
  free (whole.pixels);
  return out->pixels != NULL;
}

int
main (int argc, char **argv)
{
  const char *dir = NULL;
  int iterations = 0, patch = 0, quality = 0;
  bool new_sample = false;
  TsCellStructure cell_structure = TS_CELL_STRUCTURE_AUTO;
  size_t n = argc > 2 ? (size_t) atol (argv[1]) : 0;
  uint32_t seed = argc > 2 ? (uint32_t) strtoul (argv[2], NULL, 10) : 0;
  int status = 0;

  if (n < 16 || n > 512)
    {
      fprintf (stderr, "usage: solid-shapes SIZE(16..512) SEED [-o DIR] [-i ITERATIONS] [-p PATCH] [-q QUALITY] [-n] [-c|-f] "
                       "[cells|blobs|grains|IMAGE.png]...\n");
      return 2;
    }
  ts_io_init ();
  for (int i = 3; i < argc; i++)
    {
      const char *name = argv[i];
      TsImage exemplar = { n, n, NULL }, slice = { n, n, NULL };
      float *truth = NULL, *ours = malloc (n * n * n * TS_CHANNELS * sizeof (float));
      TsSolidSource *sources = NULL;
      SliceFigures f;
      TsSolidParams params;
      TsError error;
      double start;

      if (!strcmp (name, "-o") && i + 1 < argc)
        {
          dir = argv[++i];
          free (ours);
          continue;
        }
      if (!strcmp (name, "-p") && i + 1 < argc)
        {
          patch = atoi (argv[++i]);
          free (ours);
          continue;
        }
      if (!strcmp (name, "-q") && i + 1 < argc)
        {
          quality = atoi (argv[++i]);
          free (ours);
          continue;
        }
      if (!strcmp (name, "-c") || !strcmp (name, "-f"))
        {
          cell_structure = name[1] == 'c' ? TS_CELL_STRUCTURE_ON : TS_CELL_STRUCTURE_OFF;
          free (ours);
          continue;
        }
      if (!strcmp (name, "-n"))
        {
          new_sample = true;
          free (ours);
          continue;
        }
      if (!strcmp (name, "-i") && i + 1 < argc)
        {
          iterations = atoi (argv[++i]);
          free (ours);
          continue;
        }
      slice.pixels = malloc (n * n * TS_CHANNELS * sizeof (float));
      sources = malloc (n * n * n * sizeof (TsSolidSource));
      if (strstr (name, ".png") ? !load_crop (name, n, &exemplar) : false)
        status = 1;
      else if (!strstr (name, ".png"))
        {
          truth = slice_truth_lab (name, n, seed);
          exemplar.pixels = malloc (n * n * TS_CHANNELS * sizeof (float));
          if (!truth || !exemplar.pixels)
            {
              fprintf (stderr, "solid-shapes: unknown solid '%s' or out of memory\n", name);
              free (truth);
              truth = NULL;
              status = 1;
            }
          else
            memcpy (exemplar.pixels, truth, n * n * TS_CHANNELS * sizeof (float));
        }
      if (status == 0 && (!ours || !slice.pixels || !exemplar.pixels || !sources))
        {
          fprintf (stderr, "solid-shapes: %s: out of memory\n", name);
          status = 1;
        }
      if (status == 0)
        {
          const TsImage *ex3[3] = { &exemplar, &exemplar, &exemplar };
          const char *base = strrchr (name, '/') ? strrchr (name, '/') + 1 : name;
          ts_solid_params_init (&params);
          params.size = n;
          params.seed = seed;
          params.max_iterations = iterations;
          params.patch_size = patch;
          if (quality)
            params.quality = quality;
          params.record_sources = true;
          params.cell_structure = cell_structure;
          start = now ();
          if (ts_synthesize_solid_with_sources (&params, ex3, ours, sources, NULL, NULL, &error)
              != TS_OK)
            {
              fprintf (stderr, "solid-shapes: %s\n", error.message);
              status = 1;
            }
          else
            {
              double seconds = now () - start, anisotropy = NAN, axis_share = NAN, thick;
              size_t wins[3] = { 0, 0, 0 }, voxels = n * n * n;
              ts_measure_anisotropy (&exemplar, &anisotropy);
              ts_measure_axis_edge_share (&exemplar, &axis_share);
              for (size_t p = 0; p < voxels; p++)
                wins[ts_solid_source_axis (sources[p]) % 3]++;
              printf ("%-9s %zu^3 synthesised in %.2f s, cell structure %s (exemplar anisotropy "
                      "%.3f, axis-edge share %.3f against %.3f for edges in every direction; voxels "
                      "copied by x %.0f %%, y %.0f %%, z %.0f %%)\n", base, n, seconds,
                      ts_solid_uses_cell_structure (&params, ex3) ? "on" : "off", anisotropy, axis_share,
                      2.0 * TS_AXIS_EDGE_DEGREES / 90.0,
                      100.0 * (double) wins[0] / (double) voxels, 100.0 * (double) wins[1] / (double) voxels,
                      100.0 * (double) wins[2] / (double) voxels);
              /* exemplar | truth across x | ours across x, y, z, diagonal */
              TsImage strip = { 6 * (n + 4) - 4, n, NULL };
              if (dir)
                strip.pixels = calloc (strip.width * n * TS_CHANNELS, sizeof (float));
              for (size_t p = 0; strip.pixels && p < strip.width * n; p++)
                strip.pixels[p * TS_CHANNELS + 3] = 1.0f;
              place (&strip, 0, &exemplar);
              if (truth && slice_figures (&exemplar, truth, n, &f))
                {
                  thick = NAN;
                  phase_thickness (&exemplar, truth, n, &thick);
                  print_row (base, "truth", &f, thick, interior_planes (&exemplar, truth, n),
                             lattice (truth, n), phase_row (&exemplar, truth, n));
                  slice_cut (truth, n, 0, n / 2, &slice);
                  place (&strip, 1, &slice);
                }
              if (slice_figures (&exemplar, ours, n, &f))
                {
                  thick = NAN;
                  phase_thickness (&exemplar, ours, n, &thick);
                  print_row (base, "ours", &f, thick, interior_planes (&exemplar, ours, n),
                             lattice (ours, n), phase_row (&exemplar, ours, n));
                }
              if (truth && new_sample && !print_new_sample (base, &exemplar, n, seed))
                status = 1;
              for (int a = 0; a < 4; a++)
                {
                  slice_cut (ours, n, a, n / 2, &slice);
                  place (&strip, 2 + (size_t) a, &slice);
                }
              if (strip.pixels)
                save (dir, base, "slices", &strip);
              free (strip.pixels);
              fflush (stdout);
            }
        }
      free (exemplar.pixels);
      free (slice.pixels);
      free (truth);
      free (ours);
      free (sources);
    }
  return status;
}
