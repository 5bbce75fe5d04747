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

/* Recomputes the penalty of every centre for neighbourhoods of side
 * `patch` from the current sources of `count` output pixels. */
void     ts_occurrence_update (TsOccurrence *occ, const int32_t *source, size_t count,
                               size_t patch, size_t opaque_pixels);

#endif
