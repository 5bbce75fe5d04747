/* Search over ALL neighbourhoods of an exemplar level, not only the
 * coherent ones (Kopf et al. 2007): the neighbourhoods projected on their
 * first principal components, in a kd-tree searched approximately
 * (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SOLID_EXEMPLAR_INDEX_H
#define TS_SOLID_EXEMPLAR_INDEX_H

#include "engine/cancel.h"
#include "engine/pyramid.h"

#include <stdint.h>

/* Principal components kept: a multiple of 4 (the PCA's lanes). */
#define TS_SOLID_INDEX_DIMS 8
/* Nearest neighbourhoods a query returns, by projected distance. */
#define TS_SOLID_INDEX_RESULTS 4

typedef struct
{
  uint32_t begin, end;   /* points of this node, in tree order   */
  int32_t  left, right;  /* children, -1 for a leaf              */
  uint32_t dim;
  float    split;
} TsSolidIndexNode;

typedef struct
{
  size_t            patch;    /* neighbourhood side it indexes (0 = no index) */
  size_t            dims;     /* patch^2 * TS_CHANNELS                */
  float            *basis;    /* dims x TS_SOLID_INDEX_DIMS, dimension-major */
  size_t            count;    /* indexed neighbourhoods               */
  int32_t          *centre;   /* exemplar pixel index, tree order     */
  float            *point;    /* count x TS_SOLID_INDEX_DIMS, tree order */
  TsSolidIndexNode *node;
  size_t            nodes;
} TsSolidIndex;

/* Indexes every neighbourhood of side `patch` that lies inside level
 * `level` of `pyramid` with an opaque centre. A level too small for the
 * patch, or without opaque centres, leaves the index empty (patch 0).
 * `cancel` (may be NULL) is polled while projecting and while building
 * the tree; once it is raised the result is TS_ERROR_CANCELLED. */
TsStatus ts_solid_index_build (const TsPyramid *pyramid, size_t level, size_t patch,
                               TsCancel *cancel, TsSolidIndex *index);
void     ts_solid_index_free (TsSolidIndex *index);

/* Projects a gathered neighbourhood (patch^2 pixels, TS_CHANNELS each). */
void ts_solid_index_project (const TsSolidIndex *index, const float *neighbourhood,
                             float projected[TS_SOLID_INDEX_DIMS]);

/* Up to TS_SOLID_INDEX_RESULTS exemplar centres nearest to `projected`,
 * visiting at most `leaves` leaves (approximate); -1 fills the rest. */
void ts_solid_index_query (const TsSolidIndex *index, const float projected[TS_SOLID_INDEX_DIMS],
                           size_t leaves, int32_t found[TS_SOLID_INDEX_RESULTS]);

#endif
