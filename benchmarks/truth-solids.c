/* Ground-truth solids: periodic, isotropic volumes whose slices in every
 * direction are samples of one and the same 2D texture, for solid-truth,
 * solid-shapes and the solid tests. This file holds the seeded hash and
 * noise the kinds share, the stones, spots and granite grains drawn voxel
 * by voxel, and the choice of a kind's renderer (the other families:
 * truth-solids-pieces.c, truth-solids-foam.c, truth-solids-fields.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "truth-solids.h"
#include "truth-solids-internal.h"
#include "engine/rng.h"

#include <math.h>
#include <string.h>

/* Mean spacing of the Voronoi sites of "cells", in voxels. */
#define CELL_SPACING 14.0

typedef TruthSolid Solid;

double
truth_uniform (const Solid *s, uint32_t stream, uint64_t key)
{
  uint64_t h = ts_mix64 (ts_mix64 (((uint64_t) s->seed << 32 | stream) + 0x9e3779b97f4a7c15ULL)
                         ^ key);
  return (double) (h >> 11) * (1.0 / 9007199254740992.0);
}

size_t
truth_wrap (long i, size_t period)
{
  long p = (long) period, r = i % p;
  return (size_t) (r < 0 ? r + p : r);
}

static uint64_t
lattice_key (size_t x, size_t y, size_t z)
{
  return ((uint64_t) z << 42) | ((uint64_t) y << 21) | (uint64_t) x;
}

double
truth_value_noise (const Solid *s, uint32_t stream, size_t period, const double p[3])
{
  double f[3], sum = 0.0;
  long base[3];
  for (int a = 0; a < 3; a++)
    {
      double c = p[a] * (double) period / (double) s->n;
      base[a] = (long) floor (c);
      f[a] = c - (double) base[a];
      f[a] = f[a] * f[a] * (3.0 - 2.0 * f[a]);
    }
  for (int corner = 0; corner < 8; corner++)
    {
      double w = 1.0;
      size_t q[3];
      for (int a = 0; a < 3; a++)
        {
          int bit = (corner >> a) & 1;
          w *= bit ? f[a] : 1.0 - f[a];
          q[a] = truth_wrap (base[a] + bit, period);
        }
      sum += w * truth_uniform (s, stream, lattice_key (q[0], q[1], q[2]));
    }
  return sum;
}

size_t
truth_lattice_period (const Solid *s, double spacing)
{
  double p = floor ((double) s->n / spacing + 0.5);
  return p < 1.0 ? 1 : (size_t) p;
}

/* Stones: periodic Voronoi cells (one jittered site per grid cell), each
 * of its own shade, separated by dark mortar. */
static void
cells (const Solid *s, const double p[3], double rgb[3])
{
  size_t g = truth_lattice_period (s, CELL_SPACING);
  double cell = (double) s->n / (double) g, d1 = INFINITY, d2 = INFINITY;
  uint64_t nearest = 0;
  long c[3];
  for (int a = 0; a < 3; a++)
    c[a] = (long) floor (p[a] / cell);
  for (int dz = -1; dz <= 1; dz++)
    for (int dy = -1; dy <= 1; dy++)
      for (int dx = -1; dx <= 1; dx++)
        {
          long k[3] = { c[0] + dx, c[1] + dy, c[2] + dz };
          uint64_t key = lattice_key (truth_wrap (k[0], g), truth_wrap (k[1], g), truth_wrap (k[2], g));
          double d = 0.0;
          for (int a = 0; a < 3; a++)
            {
              double site = ((double) k[a] + truth_uniform (s, 1 + (uint32_t) a, key)) * cell;
              d += (p[a] - site) * (p[a] - site);
            }
          d = sqrt (d);
          if (d < d1)
            {
              d2 = d1;
              d1 = d;
              nearest = key;
            }
          else if (d < d2)
            d2 = d;
        }
  double shade = 95.0 + 90.0 * truth_uniform (s, 4, nearest)
                 + 30.0 * (truth_value_noise (s, 5, truth_lattice_period (s, 4.0), p) - 0.5);
  double tint = 12.0 * truth_uniform (s, 6, nearest);
  double mortar = fmin (1.0, (d2 - d1) / 2.0);
  rgb[0] = (shade - tint) * mortar + 40.0 * (1.0 - mortar);
  rgb[1] = (shade - 0.5 * tint) * mortar + 38.0 * (1.0 - mortar);
  rgb[2] = (shade + 20.0) * mortar + 36.0 * (1.0 - mortar);
}

/* A mineral's colour, lightened or darkened by `amount`. */
static void
shade (const double base[3], double amount, double rgb[3])
{
  for (int c = 0; c < 3; c++)
    rgb[c] = base[c] + amount;
}

/* Spots: two octaves of noise, thresholded into dark spots with a brown
 * rim on a tan ground with fine grain. */
static void
blobs (const Solid *s, const double p[3], double rgb[3])
{
  double v = 0.6 * truth_value_noise (s, 7, truth_lattice_period (s, 10.0), p)
             + 0.4 * truth_value_noise (s, 8, truth_lattice_period (s, 5.0), p);
  static const double spot[3] = { 45, 32, 20 }, rim[3] = { 130, 80, 35 },
                      ground[3] = { 215, 165, 105 };
  shade (v < 0.38 ? spot : v < 0.43 ? rim : ground, 24.0 * (truth_value_noise (s, 9, truth_lattice_period (s, 2.0), p) - 0.5),
         rgb);
}

/* Granite: fine speckles of three minerals from two noise fields. */
static void
grains (const Solid *s, const double p[3], double rgb[3])
{
  size_t fine = truth_lattice_period (s, 3.0);
  double a = truth_value_noise (s, 10, fine, p), b = truth_value_noise (s, 11, fine, p);
  static const double dark[3] = { 40, 38, 42 }, pink[3] = { 190, 130, 120 },
                      white[3] = { 225, 220, 215 };
  shade (a < 0.4 ? dark : b < 0.5 ? pink : white, 30.0 * (truth_value_noise (s, 12, truth_lattice_period (s, 1.5), p) - 0.5),
         rgb);
}

uint8_t
truth_byte (double v)
{
  return (uint8_t) (v < 0.0 ? 0 : v > 255.0 ? 255 : v + 0.5);
}

bool
truth_solid_render (const char *kind, size_t n, uint32_t seed, uint8_t *rgb)
{
  void (*render) (const Solid *, const double[3], double[3])
    = !strcmp (kind, "cells") ? cells : !strcmp (kind, "blobs") ? blobs
      : !strcmp (kind, "grains") ? grains : NULL;
  Solid s = { n, seed };

  if (!render)
    {
      TruthStatus status = !strcmp (kind, "foam") ? truth_render_foam (&s, rgb)
                                                  : truth_render_pieces (kind, &s, rgb);
      if (status == TRUTH_UNKNOWN)
        status = truth_render_fields (kind, &s, rgb);
      return status == TRUTH_DONE;
    }
  for (size_t z = 0; z < n; z++)
    for (size_t y = 0; y < n; y++)
      for (size_t x = 0; x < n; x++)
        {
          double p[3] = { (double) x, (double) y, (double) z }, c[3];
          uint8_t *out = rgb + ((z * n + y) * n + x) * 3;
          render (&s, p, c);
          for (int k = 0; k < 3; k++)
            out[k] = truth_byte (c[k]);
        }
  return true;
}

const char *const *
truth_solid_kinds (void)
{
  static const char *const names[] = { TRUTH_SOLID_KINDS, NULL };
  return names;
}
