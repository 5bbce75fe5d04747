/* What each pyramid level does: neighbourhood sizes, iterations and
 * candidate counts, derived from the parameters in one place (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SCHEDULE_H
#define TS_SCHEDULE_H

#include "texsynth.h"

typedef struct
{
  size_t patch;          /* odd neighbourhood side                        */
  size_t spacing;        /* distance between neighbourhood centres        */
  size_t max_iterations;
  size_t propose_step;   /* every n-th pixel of a neighbourhood proposes  */
} TsPass;

typedef struct
{
  size_t k_level;  /* similar neighbourhoods MRPM keeps per pixel         */
  size_t k_use;    /* of which the M-step uses per proposed position      */
  size_t passes;
  TsPass pass[2];
} TsLevelPlan;

/* The best median quality over the bundled exemplars, and fast
 * (params.c). */
#define TS_DEFAULT_QUALITY 2

/* Default memory limit: a quarter of the RAM, at least 1 GiB. */
size_t ts_default_memory_limit (void);

/* Coarsest exemplar level's shorter side the pyramid aims for: room
 * for a few of the largest neighbourhoods, so the layout has choices. */
#define TS_COARSEST_SIDE 32

int    ts_schedule_threads (void);
size_t ts_schedule_max_candidates (int quality);
size_t ts_schedule_levels (const TsImage *exemplar);
/* Plan of `level` (0 = finest) whose exemplar level is ex_w x ex_h. */
void   ts_schedule_level (const TsParams *params, size_t level, size_t levels,
                          size_t ex_w, size_t ex_h, TsLevelPlan *plan);

/* Range checks shared by every entry point: quality, the (large) patch
 * size and the iteration limit. */
TsStatus ts_validate_search_params (int quality, int patch_size, int max_iterations,
                                    TsError *error);
/* Stores a memory estimate in *bytes (saturating at SIZE_MAX). */
TsStatus ts_store_estimate (double estimate, size_t *bytes, TsError *error);

#endif
