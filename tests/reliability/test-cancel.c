/* Cancel: another thread asks the progress callback to stop at several
 * points of a 2D synthesis (default 1024x1024) and of a solid one
 * (default 128^3); the engine must return TS_ERROR_CANCELLED within a
 * bound, leave a 2D output untouched (a volume is synthesised in place:
 * its contents are then unspecified) and free everything (the leak check
 * is ASan's or valgrind's, see scripts/sanitize.sh). Prints the measured
 * latencies.
 * Usage: test-cancel [SIDE [SOLID_SIZE]]   (smaller under valgrind)
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The bound: within a second. The engine asks the callback every
 * 0.05 s from inside its steps (common/cancel.h), so even a loaded 2-core
 * machine stays far below it; the figure itself is printed. Sanitizer
 * builds run the engine about 10x slower: there smaller runs check that a
 * cancel frees everything. */
#ifdef TEST_SANITIZED
#define LATENCY_BOUND_S 10.0
#define DEFAULT_SIDE 256
#define DEFAULT_SOLID_SIZE 32
#else
#define LATENCY_BOUND_S 1.0
#define DEFAULT_SIDE 1024
#define DEFAULT_SOLID_SIZE 128
#endif

typedef struct
{
  atomic_int    cancel;
  atomic_int    progress_permille;
  double        cancel_time;   /* written by the canceller before `cancel` */
  double        last_call, max_gap;
  int           calls;
  int           permille_target;
  bool          waited;        /* the callback has waited for the cancel */
} Shared;

static double
now_s (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static bool
on_progress (double fraction, const char *stage, void *data)
{
  Shared *s = data;
  double t = now_s ();
  (void) stage;
  if (s->calls++ > 0 && t - s->last_call > s->max_gap)
    s->max_gap = t - s->last_call;
  s->last_call = t;
  atomic_store (&s->progress_permille, (int) (fraction * 1000.0));
  /* Past the target, wait for the other thread's cancel (a scheduler or
   * valgrind's one-thread-at-a-time may otherwise never run it before the
   * synthesis ends), then still say "go on" this once: the engine must
   * see the cancel at a later call, the worst case the latency covers. */
  if (s->permille_target <= (int) (fraction * 1000.0) && !s->waited)
    {
      struct timespec ms = { 0, 1000000 };
      s->waited = true;
      for (int i = 0; i < 60000 && !atomic_load (&s->cancel); i++)
        nanosleep (&ms, NULL);
      return true;
    }
  return !atomic_load (&s->cancel);
}

/* Waits until the synthesis has passed the target progress, then cancels
 * at once, while the callback that reached it waits: right after a
 * progress call, the worst moment. */
static void *
canceller (void *data)
{
  Shared *s = data;
  struct timespec ms = { 0, 1000000 };

  while (atomic_load (&s->progress_permille) < s->permille_target)
    nanosleep (&ms, NULL);
  s->cancel_time = now_s ();
  atomic_store (&s->cancel, 1);
  return NULL;
}

/* One synthesis of either engine into `out` (`bytes` long). */
typedef struct
{
  const char   *name;
  const TsImage *ex;
  TsParams      params;      /* 2D */
  TsSolidParams solid;       /* solid, when `is_solid` */
  bool          is_solid;    /* the volume is written in place: no untouched check */
  float        *out;
  size_t        bytes;
} Job;

static TsStatus
run_job (Job *job, Shared *s, TsError *error)
{
  if (job->is_solid)
    {
      const TsImage *all[3] = { job->ex, job->ex, job->ex };
      return ts_synthesize_solid (&job->solid, all, job->out, on_progress, s, error);
    }
  TsImage out = { job->params.output_width, job->params.output_height, job->out };
  return ts_synthesize (&job->params, job->ex, &out, on_progress, s, error);
}

/* Cancels `job` at several points; returns its worst latency. */
static double
cancel_at_several_points (Job *job)
{
  static const int targets[] = { 1, 300, 600, 800 };
  double worst = 0.0, worst_gap = 0.0;

  for (size_t t = 0; t < sizeof targets / sizeof targets[0]; t++)
    {
      Shared s;
      TsError error = { TS_OK, "" };
      pthread_t thread;
      TsStatus status;
      double latency;
      bool untouched = true;

      memset (&s, 0, sizeof s);
      atomic_init (&s.cancel, 0);
      atomic_init (&s.progress_permille, 0);
      s.permille_target = targets[t];
      memset (job->out, 0xA5, job->bytes);
      if (pthread_create (&thread, NULL, canceller, &s) != 0)
        {
          CHECK (0, "cannot start the canceller thread");
          break;
        }
      status = run_job (job, &s, &error);
      latency = now_s () - s.cancel_time;
      /* A synthesis that finished before the cancel is a test failure too. */
      atomic_store (&s.progress_permille, 1000);
      pthread_join (thread, NULL);

      for (size_t i = 0; i < job->bytes && untouched; i++)
        untouched = ((const unsigned char *) job->out)[i] == 0xA5;
      CHECK (status == TS_ERROR_CANCELLED, "%s, cancel after %.1f %%: status %s (%s)", job->name,
             targets[t] / 10.0, ts_status_string (status), error.message);
      CHECK (strstr (error.message, "cancel") != NULL, "message says cancelled: %s", error.message);
      CHECK (untouched || job->is_solid, "%s: a cancelled synthesis leaves the output untouched",
             job->name);
      CHECK (latency < LATENCY_BOUND_S, "%s, cancel after %.1f %% returned in %.3f s (bound %.1f s)",
             job->name, targets[t] / 10.0, latency, LATENCY_BOUND_S);
      printf ("%s, cancel after %5.1f %% of the work: returned in %.3f s "
              "(longest gap between progress calls so far %.3f s)\n",
              job->name, targets[t] / 10.0, latency, s.max_gap);
      worst = latency > worst ? latency : worst;
      worst_gap = s.max_gap > worst_gap ? s.max_gap : worst_gap;
    }
  printf ("cancel figures: %s, worst latency %.3f s, longest progress gap %.3f s\n",
          job->name, worst, worst_gap);
  return worst;
}

int
main (int argc, char **argv)
{
  size_t side = argc > 1 ? (size_t) strtoul (argv[1], NULL, 10) : DEFAULT_SIDE;
  size_t solid = argc > 2 ? (size_t) strtoul (argv[2], NULL, 10) : DEFAULT_SOLID_SIZE;
  char name2d[32], name3d[32];
  TsImage ex;
  Job job;

  if (side < 16 || side > 4096 || solid < TS_SOLID_MIN_SIZE || solid > 256)
    {
      fprintf (stderr, "usage: test-cancel [SIDE 16..4096 [SOLID_SIZE %d..256]]\n",
               TS_SOLID_MIN_SIZE);
      return 2;
    }
  test_load_exemplar ("bark.png", &ex);

  memset (&job, 0, sizeof job);
  snprintf (name2d, sizeof name2d, "%zux%zu", side, side);
  job.name = name2d;
  job.ex = &ex;
  ts_params_init (&job.params);
  job.params.output_width = job.params.output_height = side;
  job.params.seed = 7;
  job.bytes = side * side * TS_CHANNELS * sizeof (float);
  job.out = malloc (job.bytes);
  CHECK (job.out != NULL, "output allocation");
  if (job.out)
    cancel_at_several_points (&job);
  free (job.out);

  snprintf (name3d, sizeof name3d, "solid %zu^3", solid);
  job.name = name3d;
  job.is_solid = true;
  ts_solid_params_init (&job.solid);
  job.solid.size = solid;
  job.solid.seed = 7;
  job.bytes = solid * solid * solid * TS_CHANNELS * sizeof (float);
  job.out = malloc (job.bytes);
  CHECK (job.out != NULL, "volume allocation");
  if (job.out)
    cancel_at_several_points (&job);
  free (job.out);

  free (ex.pixels);
  return test_finish ("test-cancel");
}
