/* The lattice guide: phases of the exemplar's periods as a value guide
 * (declared in lattice.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "lattice.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A period shorter than this many pixels at a level is aliased there:
 * its phase says nothing, and that pair of channels stays 0. */
#define TS_LATTICE_NYQUIST 2.0

static const double two_pi = 6.283185307179586;

/* The reciprocal vectors: phase k of level-0 position p is recip[k] . p,
 * growing by 1 over period k and not at all along the other period. */
static void
reciprocal (const TsLatticeEstimate *lattice, double recip[2][2])
{
  const double *a = lattice->vector[0], *b = lattice->vector[1];

  if (lattice->vectors == 1)
    {
      double aa = a[0] * a[0] + a[1] * a[1];
      recip[0][0] = a[0] / aa;
      recip[0][1] = a[1] / aa;
      return;
    }
  double det = a[0] * b[1] - a[1] * b[0];
  recip[0][0] = b[1] / det;
  recip[0][1] = -b[0] / det;
  recip[1][0] = -a[1] / det;
  recip[1][1] = a[0] / det;
}

/* One level's plane of the phases `recip` (per pixel of that level). */
static TsStatus
phase_plane (TsGuidePlane *plane, size_t width, size_t height, size_t vectors,
             const double recip[2][2], const bool active[2])
{
  TsStatus status = ts_image_alloc (&plane->value, width, height);

  if (status != TS_OK)
    return status;
  plane->width = width;
  plane->height = height;
#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) height; y++)
    for (size_t x = 0; x < width; x++)
      {
        float *p = plane->value.pixels + ((size_t) y * width + x) * TS_CHANNELS;
        memset (p, 0, TS_CHANNELS * sizeof (float));
        for (size_t k = 0; k < vectors; k++)
          if (active[k])
            {
              double phase = two_pi * (recip[k][0] * (double) x + recip[k][1] * (double) y);
              p[2 * k] = (float) cos (phase);
              p[2 * k + 1] = (float) sin (phase);
            }
      }
  return TS_OK;
}

/* Bends `recip` so that `side` pixels hold a whole number of periods. */
static double
whole_periods (double recip, size_t side)
{
  return round (recip * (double) side) / (double) side;
}

TsStatus
ts_lattice_guide_build (const TsLatticeEstimate *lattice, const TsPyramid *pyramid, size_t out_w,
                        size_t out_h, bool wrap_x, bool wrap_y, TsGuidePyramid *guides)
{
  double recip[2][2] = { { 0, 0 }, { 0, 0 } };
  TsStatus status = TS_OK;
  bool guided = false;

  memset (guides, 0, sizeof *guides);
  if (lattice->vectors == 0)
    return TS_OK;
  reciprocal (lattice, recip);
  if (ts_guide_planes_alloc (guides, pyramid->levels) != TS_OK)
    return TS_ERROR_OUT_OF_MEMORY;
  guides->lattice = true;
  guides->channels = 2 * lattice->vectors;
  /* A pixel half a period off costs what two unrelated texture pixels
   * do: a shifted lattice is as wrong as a foreign texture. Where the
   * phases pin each window's place in its cell exactly (two periods, not
   * bent to fit a tile), twice that pull keeps the courses that the
   * texture term lets slip by a cell; one period pins only a stripe,
   * and a bent lattice's phases are off by up to a phase cell: a stronger
   * pull cost texture there and kept no more of the lattice
   * (docs/benchmarks.md, "Lattice guide weight"). */
  guides->weight = lattice->vectors == 2 && !wrap_x && !wrap_y ? 2.0 : 1.0;
  /* The finest level is left free: its neighbourhoods start from the
   * coarser level's coordinates, which already hold the lattice, and it
   * is three quarters of the work and of the guide's memory. */
  for (size_t l = 1; l < pyramid->levels && status == TS_OK; l++)
    {
      double scale = (double) ((size_t) 1 << l), ex_recip[2][2], out_recip[2][2];
      size_t ow = ts_level_side (out_w, l), oh = ts_level_side (out_h, l);
      bool active[2] = { false, false };
      for (size_t k = 0; k < lattice->vectors; k++)
        {
          ex_recip[k][0] = out_recip[k][0] = recip[k][0] * scale;
          ex_recip[k][1] = out_recip[k][1] = recip[k][1] * scale;
          if (wrap_x)
            out_recip[k][0] = whole_periods (out_recip[k][0], ow);
          if (wrap_y)
            out_recip[k][1] = whole_periods (out_recip[k][1], oh);
          /* Bent by more than a phase cell per period (an output only
           * a few periods wide), the period would fight the texture. */
          active[k] = 1.0 / hypot (ex_recip[k][0], ex_recip[k][1]) >= TS_LATTICE_NYQUIST &&
                      hypot (out_recip[k][0] - ex_recip[k][0], out_recip[k][1] - ex_recip[k][1]) <=
                        hypot (ex_recip[k][0], ex_recip[k][1]) / TS_LATTICE_PHASE_BINS;
        }
      if (!active[0] && !active[1])
        continue;
      status = phase_plane (&guides->exemplar[l], pyramid->level[l].width,
                            pyramid->level[l].height, lattice->vectors, ex_recip, active);
      if (status == TS_OK)
        status = phase_plane (&guides->target[l], ow, oh, lattice->vectors, out_recip, active);
      guided = true;
    }
  if (status != TS_OK || !guided)
    {
      /* Periods too fine for any coarser level need no guide: the
       * neighbourhoods hold several of them. */
      ts_guide_pyramid_free (guides);
      return status;
    }
  /* No value range for bins: a lattice guide bins by phase (guide.c). */
  return TS_OK;
}
