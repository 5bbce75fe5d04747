/* Distance transforms (engine/distance.h) of whole volumes while the
 * caller's thread keeps asking the cancel callback. One transform of a
 * 128^3 volume takes a few tenths of a second and cannot ask midway, so
 * the other threads of a team take the grids and OpenMP thread 0 (the
 * caller's) asks every millisecond until they are done. A team of one
 * transforms the grids in turn and asks between them. Each grid is
 * transformed whole by one thread: the results do not depend on the
 * thread count or on the asks.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/distance.h"

#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* Thread 0's sleep between asks: far below the ask interval, and a
 * sleeping thread leaves its core to the transforms. */
#define WAIT_NS 1000000L

TsStatus
ts_solid_distance_transforms (float *const grids[], size_t count, const size_t dims[3],
                              const bool wrap[3], TsCancel *cancel)
{
  TsStatus status[TS_SOLID_MAX_POLLED_GRIDS];
  int next = 0, done = 0, team = (int) count + 1;

  if (count > TS_SOLID_MAX_POLLED_GRIDS)
    return TS_ERROR_INVALID_ARGUMENT;
  for (size_t g = 0; g < count; g++)
    status[g] = TS_OK;
#ifdef _OPENMP
  /* No more threads than the caller allows. */
  team = omp_get_max_threads () < team ? omp_get_max_threads () : team;
#else
  (void) team;
#endif
#pragma omp parallel num_threads (team) if (team > 1 && cancel != NULL && cancel->ask != NULL)
  {
    int threads = 1, me = 0;
#ifdef _OPENMP
    threads = omp_get_num_threads ();
    me = omp_get_thread_num ();
#endif
    if (threads == 1)
      for (size_t g = 0; g < count; g++)
        {
          if (!ts_cancel_poll (cancel))
            status[g] = ts_distance_transform (grids[g], dims, wrap);
        }
    else if (me == 0)
      for (;;)
        {
          int finished;
          struct timespec wait = { 0, WAIT_NS };
#pragma omp atomic read
          finished = done;
          if (finished == (int) count)
            break;
          ts_cancel_poll (cancel);
          nanosleep (&wait, NULL);
        }
    else
      for (;;)
        {
          int g;
#pragma omp atomic capture
          g = next++;
          if (g >= (int) count)
            break;
          status[g] = ts_distance_transform (grids[g], dims, wrap);
#pragma omp atomic update
          done++;
        }
  }
  for (size_t g = 0; g < count; g++)
    if (status[g] != TS_OK)
      return status[g];
  return ts_cancel_requested (cancel) ? TS_ERROR_CANCELLED : TS_OK;
}
