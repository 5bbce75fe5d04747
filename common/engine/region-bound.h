/* A bound on the area of coherent regions: output pixels that copy one
 * exemplar area at one offset (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_REGION_BOUND_H
#define TS_REGION_BOUND_H

#include "error.h"
#include "texsynth.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Flag bits per output pixel. */
enum
{
  TS_REGION_SEEN = 1, /* labelled in the current pass   */
  TS_REGION_CUT  = 2  /* beyond its region's bound: may not continue its offset */
};

typedef struct
{
  uint8_t  *flags;    /* per output pixel, TS_REGION_* bits */
  uint8_t  *links;    /* per output pixel: continues into its right / lower neighbour */
  uint32_t *queue;    /* regions' sizes, then their pixels in breadth-first order */
  uint32_t *parent;   /* the regions as disjoint sets */
  size_t   *large;    /* roots of the regions larger than max_area */
  size_t    width, height;
  size_t    max_area; /* output pixels a coherent region may cover */
} TsRegionBound;

/* Whether a synthesis with `params` bounds its copies: only where the
 * engine lays out the whole result. An initial map or a caller's guide
 * lays it out instead; a tileable result, with no free border, grows
 * larger coarse regions that the bound would cut at a high price in
 * coherence (median 1.21 instead of 1.03 on the bundled exemplars),
 * while its copies stay below half the exemplar. */
static inline bool
ts_region_bound_applies (const TsParams *params)
{
  return !params->initial_source && !params->guides && !params->wrap_x && !params->wrap_y;
}

/* A bound for an output level of width x height whose exemplar level is
 * exemplar_width x exemplar_height. */
TsStatus ts_region_bound_init (TsRegionBound *bound, size_t width, size_t height,
                               size_t exemplar_width, size_t exemplar_height);
void     ts_region_bound_free (TsRegionBound *bound);

/* Labels the coherent regions of `source` (4-neighbours whose sources are
 * exemplar neighbours in the same direction; the level does not wrap, as
 * tileable results take no bound) and flags as cut every pixel of a
 * region beyond the first max_area pixels reached breadth-first from its
 * first pixel. */
void     ts_region_bound_mark (TsRegionBound *bound, const int32_t *source, size_t exemplar_width);

static inline bool
ts_region_bound_is_cut (const TsRegionBound *bound, size_t pixel)
{
  return bound && (bound->flags[pixel] & TS_REGION_CUT);
}

#endif
