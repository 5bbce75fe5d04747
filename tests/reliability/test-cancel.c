/* Cancel: another thread asks the progress callback to stop at several
 * points of a synthesis (default 1024x1024); the engine must return
 * TS_ERROR_CANCELLED within a bound, leave the output untouched and free
 * everything (the leak check is ASan's or valgrind's, see
 * scripts/sanitize.sh). Prints the measured latencies.
 * Usage: test-cancel [SIDE]   (smaller under valgrind)
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Generous against a loaded 2-core machine; the figure itself is printed.
 * Sanitizer builds (scripts/sanitize.sh) run the engine about 10x slower:
 * there a 256x256 run checks that a cancel frees everything. */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LATENCY_BOUND_S 20.0
#define DEFAULT_SIDE 256
#else
#define LATENCY_BOUND_S 2.0
#define DEFAULT_SIDE 1024
#endif

typedef struct
{
  atomic_int    cancel;
  atomic_int    progress_permille;
  double        cancel_time;   /* written by the canceller before `cancel` */
  double        last_call, max_gap;
  int           calls;
  int           permille_target;
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
  return !atomic_load (&s->cancel);
}

/* Waits until the synthesis has passed the target progress, then cancels
 * at once: right after a progress call, the worst moment. */
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

int
main (int argc, char **argv)
{
  size_t side = argc > 1 ? (size_t) strtoul (argv[1], NULL, 10) : DEFAULT_SIDE;
  static const int targets[] = { 1, 300, 600, 800 };
  double worst = 0.0, worst_gap = 0.0;
  TsImage ex, out;
  TsParams p;

  if (side < 16 || side > 4096)
    {
      fprintf (stderr, "usage: test-cancel [SIDE 16..4096]\n");
      return 2;
    }
  test_load_exemplar ("bark.png", &ex);
  ts_params_init (&p);
  p.output_width = p.output_height = side;
  p.seed = 7;
  out.width = out.height = side;
  out.pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  CHECK (out.pixels != NULL, "output allocation");
  if (!out.pixels)
    return 1;

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
      memset (out.pixels, 0xA5, side * side * TS_CHANNELS * sizeof (float));
      if (pthread_create (&thread, NULL, canceller, &s) != 0)
        {
          CHECK (0, "cannot start the canceller thread");
          break;
        }
      status = ts_synthesize (&p, &ex, &out, on_progress, &s, &error);
      latency = now_s () - s.cancel_time;
      /* A synthesis that finished before the cancel is a test failure too. */
      atomic_store (&s.progress_permille, 1000);
      pthread_join (thread, NULL);

      for (size_t i = 0; i < side * side * TS_CHANNELS * sizeof (float) && untouched; i++)
        untouched = ((const unsigned char *) out.pixels)[i] == 0xA5;
      CHECK (status == TS_ERROR_CANCELLED, "cancel after %.1f %%: status %s (%s)",
             targets[t] / 10.0, ts_status_string (status), error.message);
      CHECK (strstr (error.message, "cancel") != NULL, "message says cancelled: %s", error.message);
      CHECK (untouched, "a cancelled synthesis leaves the output untouched");
      CHECK (latency < LATENCY_BOUND_S, "cancel after %.1f %% returned in %.3f s (bound %.1f s)",
             targets[t] / 10.0, latency, LATENCY_BOUND_S);
      printf ("%zux%zu, cancel after %5.1f %% of the work: returned in %.3f s "
              "(longest gap between progress calls so far %.3f s)\n",
              side, side, targets[t] / 10.0, latency, s.max_gap);
      worst = latency > worst ? latency : worst;
      worst_gap = s.max_gap > worst_gap ? s.max_gap : worst_gap;
    }
  printf ("cancel figures: worst latency %.3f s, longest progress gap %.3f s at %zux%zu\n",
          worst, worst_gap, side, side);
  free (out.pixels);
  free (ex.pixels);
  return test_finish ("test-cancel");
}
