/* State of one pyramid level during texture optimization, and its
 * M-step / E-step (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_LEVEL_H
#define TS_LEVEL_H

#include "cancel.h"
#include "guide.h"
#include "histogram.h"
#include "mrpm.h"
#include "region-bound.h"
#include "schedule.h"

typedef struct
{
  const TsImage        *exemplar;   /* working exemplar of this level         */
  const TsCandidateSet *candidates; /* MRPM sets of this level                */
  const int32_t        *opaque;     /* indices of exemplar pixels with alpha>0 */
  size_t                opaque_count;
  size_t                width, height; /* output size at this level          */
  bool                  wrap_x, wrap_y;
  int32_t              *source;     /* S: exemplar index of each output pixel; the
                                       output X is never stored: its pixel p is
                                       always exemplar pixel source[p] */
  const float          *preserve;   /* data-term weight per output pixel, or NULL */
  const int32_t        *preserve_source; /* exemplar index to keep, or NULL  */
  const float          *penalty;    /* occurrence penalty per exemplar centre, or NULL */
  float                *disagreement; /* if not NULL, the E-step stores each pixel's
                                         squared distance from its vote mean */
  TsCancel             *cancel;     /* polled by both steps, or NULL        */
  const TsGuideLevel   *guide;      /* guides of this level, or NULL        */
  const TsRegionBound  *region_bound; /* cut pixels of oversized coherent regions, or NULL */
  const uint8_t        *active;     /* per pixel: the E-step updates it, or NULL for all */
  const uint8_t        *active_centres; /* per pixel: the M-step matches there; set with active */
  bool                  consensus;  /* the E-step keeps the source with the most
                                       vote weight, not the vote nearest the mean */
} TsLevelState;

/* Neighbourhood centres of one iteration along one axis, plus for every
 * output coordinate the virtual coordinates (outside [0, n) too) that the
 * border rule maps onto it, so the E-step can gather votes. */
typedef struct
{
  size_t     n;           /* output size along the axis           */
  size_t     radius;
  size_t     spacing;
  size_t     offset;      /* first centre                          */
  size_t     centres;     /* number of centres                     */
  size_t    *virtual_start; /* n + 1 entries into virtual_coord    */
  ptrdiff_t *virtual_coord;
  /* Per virtual_coord entry: the centres within radius of it,
   * [cover_lo, cover_hi], or cover_lo > cover_hi if none. */
  size_t    *cover_lo, *cover_hi;
} TsAxisGrid;

typedef struct
{
  int32_t centre;   /* matched exemplar centre (index), -1 if none   */
  float   weight;   /* robust E-step weight, |x - z|^(r - 2), r = 0.8  */
  bool    clipped;  /* its window crosses the exemplar's border: votes
                       from outside it are skipped                     */
} TsMatch;

/* False if the match's window, offset by (dx, dy) from its centre, falls
 * outside the exemplar (only a clipped window can). */
static inline bool
ts_match_reaches (const TsMatch *m, size_t ew, size_t eh, ptrdiff_t dx, ptrdiff_t dy)
{
  if (!m->clipped)
    return true;
  ptrdiff_t x = (ptrdiff_t) ((size_t) m->centre % ew) + dx;
  ptrdiff_t y = (ptrdiff_t) ((size_t) m->centre / ew) + dy;
  return x >= 0 && y >= 0 && x < (ptrdiff_t) ew && y < (ptrdiff_t) eh;
}

TsStatus ts_axis_grid_init (TsAxisGrid *grid, size_t n, size_t radius, size_t spacing,
                            size_t offset, bool wrap);
void     ts_axis_grid_free (TsAxisGrid *grid);
static inline ptrdiff_t
ts_axis_grid_centre (const TsAxisGrid *grid, size_t j)
{
  return (ptrdiff_t) (grid->offset + j * grid->spacing);
}

static inline ptrdiff_t
ts_floor_div (ptrdiff_t a, ptrdiff_t b)
{
  ptrdiff_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

/* Range [*lo, *hi] of the centre indices within radius of virtual
 * coordinate t; false if empty. */
static inline bool
ts_axis_grid_covering (const TsAxisGrid *g, ptrdiff_t t, size_t *lo, size_t *hi)
{
  ptrdiff_t r = (ptrdiff_t) g->radius, s = (ptrdiff_t) g->spacing, o = (ptrdiff_t) g->offset;
  ptrdiff_t a = -ts_floor_div (-(t - r - o), s);    /* ceil */
  ptrdiff_t b = ts_floor_div (t + r - o, s);

  if (a < 0)
    a = 0;
  if (b > (ptrdiff_t) g->centres - 1)
    b = (ptrdiff_t) g->centres - 1;
  if (a > b)
    return false;
  *lo = (size_t) a;
  *hi = (size_t) b;
  return true;
}

/* M-step: for every centre of gx x gy, the best exemplar neighbourhood of
 * the k-coherence candidate set. `matches` has gx->centres * gy->centres
 * entries. Returns TS_OK, TS_ERROR_OUT_OF_MEMORY or TS_ERROR_CANCELLED
 * (state->cancel raised; `matches` then incomplete). */
TsStatus ts_mstep (const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
                   const TsPass *pass, size_t k_use, uint32_t seed_stream, TsMatch *matches);

/* E-step: every output pixel becomes the vote closest to the robust
 * weighted mean of all matched neighbourhoods covering it (or, with
 * `consensus`, the source they vote for with the most weight); its source
 * follows. Returns the number of pixels whose source changed; if
 * state->cancel is raised meanwhile, some rows are left as they were. */
size_t   ts_estep (TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
                   const TsMatch *matches, const TsHistogram *histogram);

#endif
