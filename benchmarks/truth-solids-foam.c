/* Foam: dark cells in light walls of even thickness, the other polarity
 * of truth-solids.c's "cells". The walls lie on the bisector planes of
 * periodic Voronoi sites (one jittered site per lattice cell), measured
 * exactly, so their faces stay flat and their edges smooth in any slice.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "truth-solids-internal.h"

#include <math.h>
#include <stdlib.h>

/* Mean spacing of the sites, in voxels. */
#define FOAM_SPACING 16.0
/* Half a wall's thickness, in voxels. */
#define FOAM_HALF_WALL 1.3
/* Lattice cells searched each way for the two nearest sites: a jittered
 * site can lie up to two cells from a voxel's nearest ones. */
#define FOAM_REACH 2
#define FOAM_STREAM 300
#define FOAM_CANDIDATES ((2 * FOAM_REACH + 1) * (2 * FOAM_REACH + 1) * (2 * FOAM_REACH + 1))

static uint64_t
site_index (size_t x, size_t y, size_t z, size_t g)
{
  return ((uint64_t) z * g + y) * g + x;
}

/* Colours the voxel p, given the sites near its lattice cell. */
static void
foam_voxel (const TruthSolid *s, const double p[3], const double *near, const uint64_t *ids, size_t count,
            size_t fine, uint8_t out[3])
{
  static const double wall[3] = { 225, 215, 190 }, cell[3] = { 48, 52, 62 };
  double d[FOAM_CANDIDATES], d1 = INFINITY, to_wall = INFINITY, colour[3];
  size_t nearest = 0;

  for (size_t j = 0; j < count; j++)
    {
      const double *q = near + 3 * j;
      d[j] = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
      if (d[j] < d1)
        d1 = d[j], nearest = j;
    }
  /* the nearest wall: the closest bisector plane between the nearest
   * site and any other (at least half their distances' difference away) */
  for (size_t j = 0; j < count; j++)
    {
      const double *a = near + 3 * nearest, *b = near + 3 * j;
      double reach = sqrt (d1) + 2.0 * to_wall, apart;
      if (j == nearest || d[j] >= reach * reach)
        continue;
      apart = sqrt ((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
      if (apart > 0.0)
        to_wall = fmin (to_wall, (d[j] - d1) / (2.0 * apart));
    }
  {
    double in_cell = fmin (1.0, fmax (0.0, to_wall - FOAM_HALF_WALL + 0.5));
    double grain = truth_value_noise (s, FOAM_STREAM + 4, fine, p) - 0.5;
    double shade = 36.0 * (truth_uniform (s, FOAM_STREAM + 5, ids[nearest]) - 0.5);
    for (int k = 0; k < 3; k++)
      colour[k] = in_cell * (cell[k] + shade + 14.0 * grain) + (1.0 - in_cell) * (wall[k] + 16.0 * grain);
  }
  for (int k = 0; k < 3; k++)
    out[k] = truth_byte (colour[k]);
}

TruthStatus
truth_render_foam (const TruthSolid *s, uint8_t *rgb)
{
  size_t g = truth_lattice_period (s, FOAM_SPACING), n = s->n, fine = truth_lattice_period (s, 2.0);
  double spacing = (double) n / (double) g;
  double *sites = malloc (g * g * g * 3 * sizeof (double)), near[3 * FOAM_CANDIDATES];
  size_t *cell_of = malloc (n * sizeof (size_t));
  uint64_t ids[FOAM_CANDIDATES];

  if (!sites || !cell_of)
    {
      free (sites);
      free (cell_of);
      return TRUTH_OUT_OF_MEMORY;
    }
  for (size_t x = 0; x < n; x++)
    cell_of[x] = (size_t) floor ((double) x / spacing);
  for (size_t z = 0; z < g; z++)
    for (size_t y = 0; y < g; y++)
      for (size_t x = 0; x < g; x++)
        {
          uint64_t k = site_index (x, y, z, g);
          size_t c[3] = { x, y, z };
          for (int a = 0; a < 3; a++)
            sites[3 * k + (size_t) a] = ((double) c[a] + truth_uniform (s, FOAM_STREAM + (uint32_t) a, k)) * spacing;
        }
  for (size_t cz = 0; cz < g; cz++)
    for (size_t cy = 0; cy < g; cy++)
      for (size_t cx = 0; cx < g; cx++)
        {
          size_t count = 0;
          for (long dz = -FOAM_REACH; dz <= FOAM_REACH; dz++)
            for (long dy = -FOAM_REACH; dy <= FOAM_REACH; dy++)
              for (long dx = -FOAM_REACH; dx <= FOAM_REACH; dx++)
                {
                  long k[3] = { (long) cx + dx, (long) cy + dy, (long) cz + dz };
                  uint64_t id = site_index (truth_wrap (k[0], g), truth_wrap (k[1], g), truth_wrap (k[2], g), g);
                  for (int a = 0; a < 3; a++)
                    /* the site's image in the lattice cell k */
                    near[3 * count + (size_t) a] = sites[3 * id + (size_t) a]
                                                   + (double) (k[a] - (long) truth_wrap (k[a], g)) * spacing;
                  ids[count++] = id;
                }
          for (size_t z = 0; z < n; z++)
            for (size_t y = 0; cell_of[z] == cz && y < n; y++)
              for (size_t x = 0; cell_of[y] == cy && x < n; x++)
                if (cell_of[x] == cx)
                  {
                    double p[3] = { (double) x, (double) y, (double) z };
                    foam_voxel (s, p, near, ids, count, fine, rgb + 3 * ((z * n + y) * n + x));
                  }
        }
  free (sites);
  free (cell_of);
  return TRUTH_DONE;
}
