/* A run's progress in work units, told to the caller's TsProgressFunc
 * (internal; shared by the 2D, heal and solid drivers).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_PROGRESS_H
#define TS_PROGRESS_H

#include "texsynth.h"

#include <math.h>

typedef struct
{
  TsProgressFunc func;        /* the caller's, or NULL */
  void          *user_data;
  double         done, total; /* work units */
} TsProgress;

/* Counts `units` more work done and tells the caller the fraction (done
 * over total, at most 1; 1 when no work was planned) with `stage`. False
 * when the caller asks to stop; true without a caller. */
static inline bool
ts_progress_report (TsProgress *progress, double units, const char *stage)
{
  progress->done += units;
  if (!progress->func)
    return true;
  return progress->func (progress->total > 0 ? fmin (1.0, progress->done / progress->total) : 1.0,
                         stage, progress->user_data);
}

#endif
