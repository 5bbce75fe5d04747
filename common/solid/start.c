/* Where each level of a solid synthesis starts: random exemplar blocks
 * at the coarsest, the coarser level's sources refined at the others.
 *
 * A finer voxel takes the refined source of the orientation that won its
 * parent, not the source nearest the mean of its orientations' (which
 * the coarsest start still uses): that in-between choice was a majority
 * filter that rounded every level's shapes off at the start (a level
 * began blunter than the one before had ended), and so the volume kept
 * fewer, larger spots.
 * A level that records sources (the finest, when asked) records the one
 * each start value copies.
 *
 * Along its own axis an orientation's refined source is the same on both
 * children of a parent, so every level's start held pairs of equal
 * planes, and what the short middle level could not undo stayed in the
 * volume as a lattice of blocks at the coarser levels' periods (4 and
 * 8 voxels). Each orientation therefore pairs its children along its
 * own axis at a random shift per block of the slice, which breaks the
 * lattice and costs no sharpness.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/rng.h"

#include <math.h>
#include <string.h>

/* Side, in voxels of the slice, of the blocks that share one pairing
 * shift (below): large enough that edges within a block stay whole
 * (with a shift per line of voxels the slices turned ragged and lost
 * sharpness), small enough to break the lattice. */
#define PAIRING_BLOCK 8

/* Voxel p copies the source of orientation a: its colour, and which
 * source it is where the level records that. */
static void
take_source (TsSolidLevel *l, size_t p, int a)
{
  memcpy (l->value + p * TS_CHANNELS, l->view[a].exemplar->pixels + (size_t) l->source[a][p] * TS_CHANNELS,
          TS_CHANNELS * sizeof (float));
  if (l->chosen)
    l->chosen[p] = ts_solid_source_pack (a, (uint32_t) l->source[a][p]);
}

/* The voxel's value: of its orientations' source colours, the one
 * closest to their mean (a sharp start that agrees with most of them). */
static void
value_from_sources (TsSolidLevel *l, size_t p)
{
  const float *colour[TS_SOLID_AXES];
  float mean[TS_CHANNELS] = { 0, 0, 0, 0 }, best = INFINITY;
  int count = 0, chosen = -1;

  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      colour[a] = NULL;
      if (!l->source[a])
        continue;
      colour[a] = l->view[a].exemplar->pixels + (size_t) l->source[a][p] * TS_CHANNELS;
      for (int c = 0; c < TS_CHANNELS; c++)
        mean[c] += colour[a][c];
      count++;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      float d = 0.0f;
      if (!colour[a])
        continue;
      for (int c = 0; c < TS_CHANNELS; c++)
        {
          float e = colour[a][c] - mean[c] / (float) count;
          d += e * e;
        }
      if (d < best)
        {
          best = d;
          chosen = a;
        }
    }
  take_source (l, p, chosen);
}

/* The voxel's value: the source colour of one of its orientations,
 * drawn at random, so that the start holds each lightness phase in the
 * exemplar's share. The colour nearest the orientations' mean is a
 * majority vote of three unrelated blocks: it keeps a minority phase's
 * voxel only where two orientations agree, so a minority phase starts
 * well under its share; the level then grows the spots it has instead
 * of making new ones, and the volume keeps fewer, larger bodies. */
static void
value_from_random_source (TsSolidLevel *l, size_t p, uint64_t random)
{
  int constrained[TS_SOLID_AXES], count = 0;

  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (l->source[a])
      constrained[count++] = a;
  if (count == 0)
    return;
  take_source (l, p, constrained[ts_random_below (random, (uint64_t) count)]);
}

/* Opaque source at exemplar (sx, sy), mirrored inside; a random opaque
 * pixel where that is transparent. */
static int32_t
opaque_source (const TsSolidView *view, size_t sx, size_t sy, uint64_t random)
{
  const TsImage *ex = view->exemplar;
  size_t s;

  sx = sx < ex->width ? sx : ex->width - 1 - (sx - ex->width) % ex->width;
  sy = sy < ex->height ? sy : ex->height - 1 - (sy - ex->height) % ex->height;
  s = sy * ex->width + sx;
  if (ex->pixels[s * TS_CHANNELS + 3] > 0.0f)
    return (int32_t) s;
  return view->opaque[ts_random_below (random, view->opaque_count)];
}

/* The start block of coordinate x along one axis, of `blocks` blocks
 * that tile the period n, shifted by `phase`. Returns the block's index
 * and sets x's offset inside it. */
static size_t
block_of (size_t x, size_t n, size_t blocks, size_t phase, size_t *offset)
{
  size_t w = (x + phase) % n, index = w * blocks / n;

  *offset = w - (index * n + blocks - 1) / blocks;
  return index;
}

/* Coarsest start: random exemplar blocks per orientation, whose votes
 * agree, rather than single random pixels. The blocks tile the period
 * at a random phase: blocks counted from the wrap made it a block
 * boundary in every volume, and such boundaries survive every level
 * as a visible seam.
 * Each voxel's colour is drawn from one orientation, or with
 * `majority` is the one nearest their mean: the cell structure keeps
 * that, since its guide lays the cells out anyway, and with the draw
 * the three orientations' block edges left more axis-aligned edges. */
void
ts_solid_start_random_blocks (TsSolidLevel *l, size_t level, size_t block, uint32_t seed, bool majority)
{
  size_t n = l->n, blocks = (n + block - 1) / block, phase[3];

  for (int k = 0; k < 3; k++)
    phase[k] = (size_t) ts_random_below (ts_random (seed, (uint32_t) level, 7, 0, 40 + (uint32_t) k), n);
#pragma omp parallel for schedule(static) if (n >= TS_SOLID_PARALLEL_EDGE)
  for (ptrdiff_t zy = 0; zy < (ptrdiff_t) (n * n); zy++)
    for (size_t x = 0; x < n; x++)
      {
        size_t xyz[3] = { x, (size_t) zy % n, (size_t) zy / n }, p = (size_t) zy * n + x;
        size_t index[3], offset[3];
        for (int k = 0; k < 3; k++)
          index[k] = block_of (xyz[k], n, blocks, phase[k], &offset[k]);
        uint64_t cell = ((uint64_t) index[2] * 1024 + index[1]) * 1024 + index[0];
        for (int a = 0; a < TS_SOLID_AXES; a++)
          {
            const TsSolidView *view = &l->view[a];
            int u, v;
            if (!l->source[a])
              continue;
            ts_solid_plane_axes (a, &u, &v);
            uint64_t r = ts_random (seed, (uint32_t) level, 0, cell, 1 + (uint32_t) a);
            int32_t corner = view->opaque[ts_random_below (r, view->opaque_count)];
            size_t w = view->exemplar->width;
            l->source[a][p] = opaque_source (view, (size_t) corner % w + offset[u],
                                             (size_t) corner / w + offset[v],
                                             ts_random (seed, (uint32_t) level, 0, p, 5));
          }
        if (majority)
          value_from_sources (l, p);
        else
          value_from_random_source (l, p, ts_random (seed, (uint32_t) level, 0, p, 9));
      }
}

/* The orientation whose source the coarser voxel `parent` copied (the
 * E-step's winner: its value is that source's colour), or -1. */
static int
winner (const TsSolidLevel *c, size_t parent)
{
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (c->source[a]
        && ts_solid_same_pixel (c->value + parent * TS_CHANNELS,
                                c->view[a].exemplar->pixels
                                  + (size_t) c->source[a][parent] * TS_CHANNELS))
      return a;
  return -1;
}

/* The coarser coordinate of x along one axis when its children pair up
 * shifted by `shift` (0: 2i and 2i + 1 share a parent; 1: 2i - 1 and 2i
 * do), wrapped or clamped at the border. */
static size_t
parent_of (size_t x, size_t shift, size_t cn, bool periodic)
{
  size_t c = (x + shift) / 2;

  if (c >= cn)
    c = periodic ? c - cn : cn - 1;
  return c;
}

void
ts_solid_start_from_coarser (TsSolidLevel *l, const TsSolidLevel *c, size_t level, uint32_t seed,
                             TsCancel *cancel)
{
  size_t n = l->n, cn = c->n;

#pragma omp parallel for schedule(static) if (n >= TS_SOLID_PARALLEL_EDGE)
  for (ptrdiff_t zy = 0; zy < (ptrdiff_t) (n * n); zy++)
    {
      ts_cancel_poll (cancel);
      for (size_t x = 0; x < n; x++)
        {
          size_t xyz[3] = { x, (size_t) zy % n, (size_t) zy / n }, p = (size_t) zy * n + x;
          size_t cxyz[3] = { x / 2, xyz[1] / 2, xyz[2] / 2 };
          size_t parent = (cxyz[2] * cn + cxyz[1]) * cn + cxyz[0];
          for (int a = 0; a < TS_SOLID_AXES; a++)
            {
              int u, v;
              size_t q[3] = { cxyz[0], cxyz[1], cxyz[2] };
              if (!l->source[a])
                continue;
              ts_solid_plane_axes (a, &u, &v);
              /* Along its own axis an orientation's source would repeat
               * on both children of a parent: pair them up at a random
               * shift per block of the slice instead. */
              size_t block = (xyz[(a + 1) % 3] / PAIRING_BLOCK) * n
                             + xyz[(a + 2) % 3] / PAIRING_BLOCK;
              q[a] = parent_of (xyz[a], ts_random (seed, (uint32_t) level, 8, block, 50 + (uint32_t) a) & 1,
                                cn, l->periodic);
              size_t cw = c->view[a].exemplar->width;
              size_t s = (size_t) c->source[a][(q[2] * cn + q[1]) * cn + q[0]];
              l->source[a][p] = opaque_source (&l->view[a], 2 * (s % cw) + (xyz[u] & 1),
                                               2 * (s / cw) + (xyz[v] & 1),
                                               ts_random (seed, (uint32_t) level, 0, p, 6));
            }
          int a = winner (c, parent);
          if (a < 0)
            {
              value_from_sources (l, p);
              continue;
            }
          take_source (l, p, a);
        }
    }
}
