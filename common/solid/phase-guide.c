/* The phase guide of the finest level, for exemplars whose light phase
 * lies in separate pieces (stones in mortar, cells, beans), or else
 * their dark phase (spots on a ground: blobs, a leopard's fur): each
 * exemplar pixel and each voxel carries its signed distance to the
 * boundary between the two phases (phase-split.c), and the E-step
 * weighs down a vote whose source lies at another distance than the
 * voxel (estep.c). Why: the finest level's slice neighbourhoods alone
 * erode the start's joints, and neighbouring stones merge (a slice
 * then shows about a third of the sections a real solid's does).
 * The voxels' distances are taken once, from the start after its necks
 * got walls (neck-walls.c), and held for the whole level.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/distance.h"

#include <stdlib.h>

/* Only the distances near the boundary matter: a stone's middle may copy
 * any stone's middle. */
static float
clipped (float d)
{
  return d > TS_SOLID_PHASE_CLIP ? TS_SOLID_PHASE_CLIP : d < -TS_SOLID_PHASE_CLIP ? -TS_SOLID_PHASE_CLIP : d;
}

/* Clipped signed distances (light positive, half a sample off the
 * boundary on either side) of the samples of `light` (1 light, 0 dark)
 * into `out`. */
static TsStatus
signed_distances (const uint8_t *light, const size_t dims[3], const bool wrap[3], float *out,
                  TsCancel *cancel)
{
  size_t count = dims[0] * dims[1] * dims[2];
  float *to_light = malloc (count * sizeof (float));
  TsStatus status = to_light ? TS_OK : TS_ERROR_OUT_OF_MEMORY;

  for (size_t i = 0; i < count && status == TS_OK; i++)
    {
      out[i] = light[i] ? TS_DISTANCE_FAR : 0.0f;
      to_light[i] = light[i] ? 0.0f : TS_DISTANCE_FAR;
    }
  if (status == TS_OK)
    status = ts_solid_distance_transforms ((float *const[]) { out, to_light }, 2, dims, wrap,
                                           cancel);
  for (size_t i = 0; i < count && status == TS_OK; i++)
    out[i] = clipped (light[i] ? out[i] - 0.5f : 0.5f - to_light[i]);
  free (to_light);
  return status;
}

typedef struct
{
  size_t pixels, largest; /* of the phase looked at, and of its largest piece */
} Pieces;

static void
add_piece (const size_t *pixels, size_t area, void *data)
{
  Pieces *p = data;

  (void) pixels;
  p->pixels += area;
  p->largest = area > p->largest ? area : p->largest;
}

/* Whether the opaque pixels on one side of the split (`light` or dark)
 * lie apart: their largest 4-connected piece holds at most
 * TS_SOLID_PIECES_APART of them. Without the memory to look, no: the
 * default path. */
static bool
side_apart (const TsImage *ex, float split, bool light)
{
  size_t count = ts_image_pixel_count (ex);
  uint8_t *mask = malloc (count);
  Pieces pieces = { 0, 0 };
  bool apart = false;

  for (size_t i = 0; mask && i < count; i++)
    {
      const float *p = ex->pixels + i * TS_CHANNELS;
      mask[i] = p[3] > 0.0f && ts_solid_is_light (p, split) == light;
    }
  if (mask && ts_solid_mask_pieces (mask, ex->width, ex->height, add_piece, &pieces) == TS_OK
      && pieces.pixels > 0)
    apart = (double) pieces.largest <= TS_SOLID_PIECES_APART * (double) pieces.pixels;
  free (mask);
  return apart;
}

TsSolidPieces
ts_solid_phase_in_pieces (const TsImage *ex, float split)
{
  return side_apart (ex, split, true) ? TS_SOLID_LIGHT_PIECES
         : side_apart (ex, split, false) ? TS_SOLID_DARK_PIECES
                                          : TS_SOLID_NO_PIECES;
}

TsStatus
ts_solid_exemplar_stones (const TsImage *ex, float split, bool *stones)
{
  size_t count = ts_image_pixel_count (ex), light = 0, deep = 0;
  float *distance = NULL;
  TsStatus status;

  status = ts_solid_phase_distances (ex, split, &distance);
  /* A light pixel's signed distance lies half a pixel short of its
   * distance to the dark phase. */
  for (size_t i = 0; i < count && status == TS_OK; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f && distance[i] > 0.0f)
      {
        light++;
        deep += distance[i] >= TS_SOLID_STONE_DEPTH - 0.5f;
      }
  free (distance);
  *stones = status == TS_OK && light > 0 && (double) deep >= TS_SOLID_STONE_SHARE * (double) light;
  return status;
}

/* Clipped signed distances of `count` working-format pixels (a grid of
 * dims) to the phase boundary at `split`, in a new array. */
static TsStatus
pixel_distances (const float *pixels, const size_t dims[3], const bool wrap[3], float split,
                 float **out, TsCancel *cancel)
{
  size_t count = dims[0] * dims[1] * dims[2];
  uint8_t *light = malloc (count);
  float *distance = malloc (count * sizeof (float));
  TsStatus status = light && distance ? TS_OK : TS_ERROR_OUT_OF_MEMORY;

  for (size_t i = 0; i < count && status == TS_OK; i++)
    light[i] = ts_solid_is_light (pixels + i * TS_CHANNELS, split);
  if (status == TS_OK)
    status = signed_distances (light, dims, wrap, distance, cancel);
  free (light);
  if (status != TS_OK)
    {
      free (distance);
      return status;
    }
  *out = distance;
  return TS_OK;
}

TsStatus
ts_solid_phase_distances (const TsImage *ex, float split, float **out)
{
  size_t dims[3] = { ex->width, ex->height, 1 };
  bool wrap[3] = { false, false, false };

  return pixel_distances (ex->pixels, dims, wrap, split, out, NULL);
}

TsStatus
ts_solid_phase_field (const TsSolidLevel *level, float split, float **out, TsCancel *cancel)
{
  size_t dims[3] = { level->n, level->n, level->n };
  bool wrap[3] = { level->periodic, level->periodic, level->periodic };

  return pixel_distances (level->value, dims, wrap, split, out, cancel);
}
