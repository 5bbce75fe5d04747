/* One pyramid level of image completion and the steps that work on it
 * (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_HEAL_LEVEL_H
#define TS_HEAL_LEVEL_H

#include "texsynth.h"
#include "engine/cancel.h"

#include <stdint.h>

/* Patch sizes chosen when the caller leaves them automatic: 7x7 holds
 * a mortar line with the stone on both sides, so courses and joints
 * carry over, and is the window the measures use. */
#define TS_HEAL_DEFAULT_PATCH 7
/* Loops over fewer items than this run on one thread: a team's start and
 * barrier cost more than they save on small levels, and far more when
 * other processes share the cores. */
#define TS_HEAL_PARALLEL_MIN 16384

/* Wexler et al. 2007's confidence decay per pixel into the hole. */
#define TS_HEAL_CONFIDENCE_BASE 1.3f

static inline size_t
ts_heal_coarse_radius (const TsHealParams *params)
{
  return (size_t) (params->patch_size ? params->patch_size : TS_HEAL_DEFAULT_PATCH) / 2;
}

static inline size_t
ts_heal_fine_radius (const TsHealParams *params)
{
  return (size_t) (params->fine_patch_size ? params->fine_patch_size : TS_HEAL_DEFAULT_PATCH) / 2;
}

/* Where source patch centres may lie, in the level's coordinates. */
typedef struct
{
  size_t x0, y0, x1, y1;       /* allowed box (exclusive ends)             */
  size_t hx0, hy0, hx1, hy1;   /* the hole's bounds, for sample_from       */
  TsHealSampleFrom sample_from;
} TsHealArea;

typedef struct
{
  size_t    width, height;   /* target size                                 */
  float    *target;          /* working Lab, alpha * TS_ALPHA_SCALE; known
                                pixels are never written                    */
  uint8_t  *hole;            /* 1 = to fill (any finer child in the hole)   */
  const float *source;       /* the image copied from: `target` itself, or
                                the separate source image's level           */
  float    *source_own;      /* the separate source's pixels, or NULL       */
  uint8_t  *source_known;    /* separate source: all children opaque        */
  size_t    source_width, source_height;
  size_t    radius;          /* patch radius of this level                  */
  uint8_t  *valid;           /* source centre whose whole patch is known
                                and lies in the allowed area                */
  int32_t  *valid_list;      /* indices of the valid centres, raster order  */
  size_t    valid_count;
  int32_t  *active;          /* target centres whose patch meets the hole   */
  size_t    active_count;
  int32_t  *active_index;    /* per target pixel: index in `active` or -1   */
  int32_t  *nnf;             /* per active centre: matched source centre    */
  float    *dist;            /* its patch distance                          */
  float    *flatness;        /* per source centre: ts_heal_flatness        */
  float    *confidence;      /* its vote's weight for lying near known pixels */
  size_t    hole_pixels;
} TsHealLevel;

void     ts_heal_level_free (TsHealLevel *level);

/* The finest level of a heal: the part of the image ts_heal_region gives
 * (`crop`: x0, y0, x1, y1 in the image) with its hole, the source (the
 * image itself or `source`), indexed for `area`, which it also fills. An
 * empty hole gives an empty crop and no level. */
typedef struct
{
  size_t x0, y0, x1, y1;
  bool   empty;            /* the hole has no pixel                      */
} TsHealCrop;

/* Bounding box [x0, x1) x [y0, y1) of the nonzero pixels of a w x h
 * hole; false (and an empty box) if there is none. */
bool ts_heal_hole_bounds (const uint8_t *hole, size_t w, size_t h, size_t *x0, size_t *y0,
                          size_t *x1, size_t *y1);

TsStatus ts_heal_prepare_finest (const TsHealParams *params, const TsImage *image,
                                 const uint8_t *hole, const TsImage *source,
                                 TsHealLevel *level, TsHealArea *area, TsHealCrop *crop);

/* Target and hole of the next coarser level (2x2 blocks; a block with any
 * hole pixel is hole, the others average their four known pixels); for a
 * separate source, its next level too (`level->source_own` set). */
TsStatus ts_heal_level_downsample (const TsHealLevel *fine, TsHealLevel *coarse);

/* Valid source centres for `area` and the active target centres. */
TsStatus ts_heal_level_index (TsHealLevel *level, const TsHealArea *area);

/* Per valid source centre, a penalty added to its patch distance when
 * the patch is flatter (mean |grad L|) than the known pixels around the
 * hole: blurred first guesses match flat sources best, and without it
 * the fill stays flatter than its surroundings (Wexler et al.'s method
 * has the same pull towards smooth solutions). Needs the level indexed. */
TsStatus ts_heal_flatness (TsHealLevel *level);

/* Chebyshev distance of every pixel to the nearest known one (0 for
 * known pixels), w * h entries to free(); NULL if out of memory. */
uint32_t *ts_heal_distance_to_known (const TsHealLevel *level);

/* Chebyshev distance from the farthest hole pixel to a known one. */
size_t   ts_heal_hole_depth (const TsHealLevel *level);

/* Sum of squared differences between the target patch at active centre
 * `centre` and the source patch at `source` (parts of the target patch
 * outside the image left out); stops early once above `bound`. */
float    ts_heal_patch_distance (const TsHealLevel *level, size_t centre, size_t source,
                                 float bound);

/* Random matches for every active centre (coarsest level). */
void     ts_heal_random_matches (TsHealLevel *level, uint32_t seed, uint32_t level_number);

/* Matches of `fine` from those of `coarse` (each child keeps its parent's
 * offset); invalid ones become random. */
void     ts_heal_upsample_matches (const TsHealLevel *coarse, TsHealLevel *fine, uint32_t seed,
                                   uint32_t level_number);

/* Hole pixels of `fine` from their parents in `coarse`. */
void     ts_heal_upsample_target (const TsHealLevel *coarse, TsHealLevel *fine);

/* Fills the hole from its border inwards, ring by ring, each pixel the
 * mean of its already known or filled 8-neighbours (coarsest level). */
TsStatus ts_heal_fill_from_border (TsHealLevel *level);

/* Recomputes every active centre's distance to its match. */
void     ts_heal_update_distances (TsHealLevel *level, TsCancel *cancel);

/* One PatchMatch pass over the active centres: propagation from the
 * neighbours' matches (rows in parallel, scanned in the pass's direction;
 * other rows' matches read as they were before the pass, so the result
 * does not depend on the thread count), then random search around the
 * best match and `global_tries` uniform samples of the allowed source. */
TsStatus ts_heal_search_pass (TsHealLevel *level, uint32_t seed, uint32_t level_number,
                              uint32_t pass, size_t global_tries, TsCancel *cancel);

/* Votes: each hole pixel becomes the weighted mean of the pixels the
 * matched patches covering it propose, or (`pick`) the proposal of the
 * best-weighted patch, whose source index goes to `picked` (may be NULL).
 * Returns the number of hole pixels that changed noticeably (with
 * `picked`: whose pick changed). */
size_t   ts_heal_vote (TsHealLevel *level, bool pick, int32_t *picked, TsCancel *cancel);

/* Local moves of the finest level's picks (`sweeps` red-black sweeps)
 * towards fewer and cheaper seams between copies, each pick staying in a
 * valid source patch; returns the number of moves, SIZE_MAX if out of
 * memory. */
size_t   ts_heal_consolidate (const TsHealLevel *level, int32_t *picked, size_t sweeps);

/* Colour offsets (L, a, b per pixel of the level, 3 floats) that hide the
 * outline: where a copied pixel meets a known one, the known pixel minus
 * what lay beside the copy's source is spread smoothly over a band of the
 * hole along its outline, fading to 0 inside. Texture (gradients) stays
 * the source's; only the slow colour mismatch is corrected. */
TsStatus ts_heal_outline_offsets (const TsHealLevel *level, const int32_t *picked,
                                  float *offset);

/* Offsets that make the fill keep its sources' colour steps while meeting
 * the known pixels: a Poisson blend, starting from `offset` as given. */
TsStatus ts_heal_gradient_blend (const TsHealLevel *level, const int32_t *picked, float *offset);

#endif
