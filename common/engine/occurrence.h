/* Occurrence penalty (Kaspar et al. 2015, "self tuning texture
 * optimization"): exemplar neighbourhoods already used more than their fair
 * share cost extra in the M-step, which stops the output collapsing onto a
 * few flat regions and keeps the whole exemplar in use (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_OCCURRENCE_H
#define TS_OCCURRENCE_H

#include "image.h"

typedef struct
{
  size_t  width, height;   /* exemplar level size                       */
  float   scale;           /* penalty per unit of excess use, in SSD    */
  float  *penalty;         /* per exemplar centre                       */
  double *integral;        /* (w + 1) x (h + 1) summed-area table       */
} TsOccurrence;

/* `strength` times the exemplar's mean per-pixel variance sets the scale. */
TsStatus ts_occurrence_init (TsOccurrence *occ, const TsImage *exemplar, float strength);
void     ts_occurrence_free (TsOccurrence *occ);

/* How many of the `count` output pixels (those `mask` marks, or all if
 * it is NULL) use each exemplar pixel as their source: `usage` gets one
 * entry per exemplar pixel (`exemplar_pixels`). The one pass over the
 * output that both the penalty and the histogram need. */
void     ts_occurrence_count (const int32_t *source, const uint8_t *mask, size_t count,
                              uint32_t *usage, size_t exemplar_pixels);

/* Recomputes the penalty of every centre for neighbourhoods of side
 * `patch` from the usage counts of `count` output pixels. */
void     ts_occurrence_update (TsOccurrence *occ, const uint32_t *usage, size_t count,
                               size_t patch, size_t opaque_pixels);

#endif
