/* Cancelling from inside the parallel steps (internal).
 *
 * The user's progress callback may only run on the thread that called the
 * engine, which is OpenMP thread 0 of every team it starts. So inside a
 * step, thread 0 asks the callback at most every TS_CANCEL_INTERVAL seconds
 * and raises a flag when it says stop; every thread reads the flag before
 * each unit of work (a neighbourhood centre, a row) and skips the rest.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_CANCEL_H
#define TS_CANCEL_H

#include <stdbool.h>
#include <stddef.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* Short enough that a cancel is seen within about a tenth of a second,
 * long enough that a slow callback (a GUI progress bar) costs nothing. */
#define TS_CANCEL_INTERVAL 0.05

typedef struct
{
  int    requested;         /* 1 once the callback said stop (omp atomic)  */
  bool (*ask) (void *data); /* calls the user's callback; false = stop; or NULL */
  void  *data;
  double last_ask;          /* seconds; used by thread 0 only              */
} TsCancel;

static inline double
ts_cancel_clock (void)
{
  struct timespec t;
  if (timespec_get (&t, TIME_UTC) != TIME_UTC)
    return 0.0;
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static inline void
ts_cancel_init (TsCancel *c, bool (*ask) (void *data), void *data)
{
  c->requested = 0;
  c->ask = ask;
  c->data = data;
  c->last_ask = ts_cancel_clock ();
}

static inline void
ts_cancel_request (TsCancel *c)
{
#pragma omp atomic write
  c->requested = 1;
}

static inline bool
ts_cancel_requested (TsCancel *c)
{
  int r;
  if (!c)
    return false;
#pragma omp atomic read
  r = c->requested;
  return r != 0;
}

/* From any thread of a team (or outside one): true if work should stop.
 * `c` may be NULL (never cancelled). */
static inline bool
ts_cancel_poll (TsCancel *c)
{
  if (!c)
    return false;
  if (ts_cancel_requested (c))
    return true;   /* the callback is never asked again after a stop */
#ifdef _OPENMP
  if (c->ask && omp_get_thread_num () == 0)
#else
  if (c->ask)
#endif
    {
      double now = ts_cancel_clock ();
      /* A clock stepped backwards counts as an interval passed. */
      if (now - c->last_ask >= TS_CANCEL_INTERVAL || now < c->last_ask)
        {
          c->last_ask = now;
          if (!c->ask (c->data))
            ts_cancel_request (c);
        }
    }
  return ts_cancel_requested (c);
}

#endif
