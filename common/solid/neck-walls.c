/* Walls at the necks of the phase in pieces, once, at the start of the
 * finest level, for exemplars whose light phase, or else dark phase,
 * lies in separate pieces (phase-guide.c): the piece phase, stones or
 * spots, and the ground phase around them. The start (the coarser
 * level's layout, upsampled) merges neighbouring stones through necks; a
 * watershed of the piece voxels' distance to the ground finds them:
 * flooding from the deepest voxels down, two basins whose peaks both
 * rise at least the neck height above the voxel where they meet stay
 * apart, and that voxel becomes wall. The walls, thickened by one
 * voxel, copy the nearest ground voxel; the phase guide then holds them
 * through the level, whose slice neighbourhoods turn them into joints.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/distance.h"

#include <math.h>
#include <stdlib.h>

/* The ground voxel a wall copies lies at most this far along each axis:
 * a neck is at most a few voxels across, so ground lies this near on
 * either side; a wall with none within reach keeps its value. */
#define TS_SOLID_WALL_REACH 3

/* The sequential loops ask the cancel callback once per this many
 * voxels (its clock costs). */
#define POLL_VOXELS 4096

/* Each voxel's phase. */
#define GROUND 0
#define PIECE 1
#define WALL 2

/* The watershed's parent of a voxel not yet flooded, and of a wall. */
#define UNSEEN (-1)
#define WALLED (-2)

static int32_t
find_root (int32_t *parent, int32_t p)
{
  while (parent[p] != p)
    {
      parent[p] = parent[parent[p]];
      p = parent[p];
    }
  return p;
}

/* The piece voxels by falling distance, ties by index: a counting sort
 * on the squared distance, an integer. */
static TsStatus
deepest_first (const uint8_t *phase, const float *distance, size_t voxels, int32_t *order,
               size_t *count)
{
  size_t keys = 1;
  for (size_t p = 0; p < voxels; p++)
    if (phase[p] == PIECE)
      {
        size_t k = (size_t) lroundf (distance[p] * distance[p]);
        keys = k + 1 > keys ? k + 1 : keys;
      }
  size_t *start = calloc (keys + 1, sizeof (size_t));
  if (!start)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t p = 0; p < voxels; p++)
    if (phase[p] == PIECE)
      start[keys - 1 - (size_t) lroundf (distance[p] * distance[p]) + 1]++;
  for (size_t k = 0; k < keys; k++)
    start[k + 1] += start[k];
  *count = start[keys];
  for (size_t p = 0; p < voxels; p++)
    if (phase[p] == PIECE)
      order[start[keys - 1 - (size_t) lroundf (distance[p] * distance[p])]++] = (int32_t) p;
  free (start);
  return TS_OK;
}

/* Floods the piece voxels in `order`; marks the voxels where two
 * distinct basins meet WALL in `phase`. A basin's root is its deepest
 * voxel, so its peak is distance[root]. */
static void
flood (const TsSolidLevel *level, uint8_t *phase, const float *distance, const int32_t *order,
       size_t count_in_order, float neck_height, int32_t *parent, TsCancel *cancel)
{
  size_t n = level->n;

  for (size_t i = 0; i < count_in_order; i++)
    {
      if (i % POLL_VOXELS == 0 && ts_cancel_poll (cancel))
        return;
      int32_t p = order[i], roots[6], deepest = -1;
      int count = 0;
      bool apart = false;
      size_t xyz[3] = { (size_t) p % n, (size_t) p / n % n, (size_t) p / n / n };
      for (int k = 0; k < 6; k++)
        {
          int32_t q = (int32_t) ts_solid_face_neighbour (level, xyz, k / 2, k & 1);
          if (parent[q] < 0)
            continue;
          int32_t r = find_root (parent, q);
          bool known = false;
          for (int j = 0; j < count; j++)
            known = known || roots[j] == r;
          if (!known)
            roots[count++] = r;
        }
      for (int j = 0; j < count; j++)
        if (deepest < 0 || distance[roots[j]] > distance[deepest]
            || (distance[roots[j]] == distance[deepest] && roots[j] < deepest))
          deepest = roots[j];
      for (int j = 0; j < count; j++)
        apart = apart || (roots[j] != deepest && distance[roots[j]] - distance[p] >= neck_height);
      if (apart)
        {
          parent[p] = WALLED;
          phase[p] = WALL;
          continue;
        }
      for (int j = 0; j < count; j++)
        parent[roots[j]] = deepest;
      parent[p] = count > 0 ? deepest : p;
    }
}

/* Piece face neighbours of the walls become walls too. */
static void
thicken (const TsSolidLevel *level, uint8_t *phase, size_t voxels)
{
  size_t n = level->n;

  for (size_t p = 0; p < voxels; p++)
    if (phase[p] == WALL)
      {
        size_t xyz[3] = { p % n, p / n % n, p / n / n };
        for (int k = 0; k < 6; k++)
          {
            size_t q = ts_solid_face_neighbour (level, xyz, k / 2, k & 1);
            /* Marked apart from the walls, so the new ones do not grow. */
            if (phase[q] == PIECE)
              phase[q] = WALL + 1;
          }
      }
  for (size_t p = 0; p < voxels; p++)
    if (phase[p] == WALL + 1)
      phase[p] = WALL;
}

/* Each wall copies the nearest ground voxel within reach (the first in
 * scan order among equals): reads ground voxels only, writes walls only. */
static void
copy_ground (TsSolidLevel *level, const uint8_t *phase)
{
  long n = (long) level->n, reach = TS_SOLID_WALL_REACH;

#pragma omp parallel for schedule(static) if (level->n >= TS_SOLID_PARALLEL_EDGE)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) (n * n * n); i++)
    {
      long x = (long) i % n, y = (long) i / n % n, z = (long) i / n / n, best = -1;
      size_t p = (size_t) i, from = 0;
      if (phase[p] != WALL)
        continue;
      for (long dz = -reach; dz <= reach; dz++)
        for (long dy = -reach; dy <= reach; dy++)
          for (long dx = -reach; dx <= reach; dx++)
            {
              long qx = x + dx, qy = y + dy, qz = z + dz, d2 = dx * dx + dy * dy + dz * dz;
              if (!level->periodic && (qx < 0 || qy < 0 || qz < 0 || qx >= n || qy >= n || qz >= n))
                continue;
              size_t q = (size_t) ((((qz + n) % n) * n + (qy + n) % n) * n + (qx + n) % n);
              if (phase[q] == GROUND && (best < 0 || d2 < best))
                {
                  best = d2;
                  from = q;
                }
            }
      if (best >= 0)
        ts_solid_copy_voxel (level, p, from);
    }
}

TsStatus
ts_solid_wall_necks (TsSolidLevel *level, float split, TsSolidPieces pieces, float neck_height,
                     TsCancel *cancel)
{
  size_t n = level->n, voxels = n * n * n, in_pieces = 0, dims[3] = { n, n, n };
  bool wrap[3] = { level->periodic, level->periodic, level->periodic };
  uint8_t *phase = malloc (voxels);
  float *distance = malloc (voxels * sizeof (float));
  int32_t *order = malloc (voxels * sizeof (int32_t)), *parent = malloc (voxels * sizeof (int32_t));
  TsStatus status = phase && distance && order && parent ? TS_OK : TS_ERROR_OUT_OF_MEMORY;
  size_t grounds = 0;

  for (size_t p = 0; p < voxels && status == TS_OK; p++)
    {
      const float *v = level->value + p * TS_CHANNELS;
      if (p % POLL_VOXELS == 0 && ts_cancel_poll (cancel))
        status = TS_ERROR_CANCELLED;
      bool light = ts_solid_is_light (v, split);
      phase[p] = (pieces == TS_SOLID_LIGHT_PIECES ? light : v[3] > 0.0f && !light) ? PIECE : GROUND;
      distance[p] = phase[p] == PIECE ? TS_DISTANCE_FAR : 0.0f;
      parent[p] = UNSEEN;
      grounds += phase[p] == GROUND;
    }
  /* All pieces: no neck, and no distance to sort by. */
  bool necks = pieces != TS_SOLID_NO_PIECES && grounds > 0;
  if (status == TS_OK && necks)
    status = ts_solid_distance_transforms (&distance, 1, dims, wrap, cancel);
  if (status == TS_OK && necks)
    status = deepest_first (phase, distance, voxels, order, &in_pieces);
  if (status == TS_OK && necks)
    flood (level, phase, distance, order, in_pieces, neck_height, parent, cancel);
  /* A stop leaves the start's values as they were. */
  if (status == TS_OK && necks && !ts_cancel_poll (cancel))
    {
      thicken (level, phase, voxels);
      copy_ground (level, phase);
    }
  if (status == TS_OK && ts_cancel_requested (cancel))
    status = TS_ERROR_CANCELLED;
  free (phase);
  free (distance);
  free (order);
  free (parent);
  return status;
}
