/* Cancel: another thread asks the progress callback to stop at several
 * points of a 2D synthesis (default 1024x1024) and of a solid one
 * (default 64^3; also with the cell structure, early), once in the finest
 * level of a solid of the engine's default size (128^3), and inside the
 * exemplar matching of both from a large exemplar (default 512x512:
 * MRPM's candidate sets in 2D, the index of all neighbourhoods in the
 * solid engine);
 * the engine must return TS_ERROR_CANCELLED within a bound (and the solid
 * engine call the callback no further apart than it), leave a 2D
 * output untouched, leave a volume either untouched or wholly written
 * (see check_output) and free everything (the leak check is ASan's or
 * valgrind's, see scripts/sanitize.sh). Prints the measured latencies.
 * Usage: test-cancel [SIDE [SOLID_SIZE [LARGE_EXEMPLAR [BOUND_S [LARGE_SOLID]]]]]
 * (smaller, with a longer bound, under valgrind)
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The bound: within a second. The engine asks the callback every
 * 0.05 s from inside its steps (common/engine/cancel.h), so even a loaded
 * 2-core machine stays far below it; the figure itself is printed.
 * The solid engine's progress calls (midway asks included) come no
 * further apart than the same bound at any stretch of its work before
 * the cancel, the start of the finest level among them: its gaps are
 * what a caller that cancels from the callback waits at worst.
 * Sanitizer builds run the engine about 10x slower: there smaller runs
 * check that a cancel frees everything. Their large exemplar is 256:
 * the solid engine's exemplar matching (indexing all neighbourhoods) of
 * a 200x200 one ends within one 0.05 s report interval natively, so
 * would never be cancelled midway.
 * The solid's points are spread over a 64^3 volume: its levels and passes
 * are those of a 128^3 one for an eighth of the work (the spread's last
 * point alone is most of a run). A step's work between two asks of the
 * callback grows with the volume: one point is in the finest level of a
 * volume of the engine's default size, where steps are largest. */
#ifdef TEST_SANITIZED
#define DEFAULT_BOUND_S 10.0
#define DEFAULT_SIDE 256
#define DEFAULT_SOLID_SIZE 32
#define DEFAULT_LARGE_SOLID 40
#define DEFAULT_LARGE_EXEMPLAR 256
#else
#define DEFAULT_BOUND_S 1.0
#define DEFAULT_SIDE 1024
#define DEFAULT_SOLID_SIZE 64
#define DEFAULT_LARGE_SOLID 128
#define DEFAULT_LARGE_EXEMPLAR 512
#endif

/* The output is filled with this byte before each run: as a float
 * (0xFFFFFFFF) it is a NaN, which the engine never writes. */
#define FILL_BYTE 0xFF

/* A target of MATCHING_TARGET cancels at the first progress call made
 * from inside the exemplar matching: a midway call, which repeats the
 * previous call's fraction, with the stage "matching exemplar". */
#define MATCHING_TARGET (-1)

typedef struct
{
  atomic_int    cancel;
  atomic_int    reached;       /* the callback has reached the target */
  double        cancel_time;   /* written by the canceller before `cancel` */
  double        last_call, max_gap, last_fraction;
  int           calls;
  int           permille_target; /* or MATCHING_TARGET */
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
  bool reached = s->permille_target == MATCHING_TARGET
                 ? s->calls > 0 && fraction == s->last_fraction
                   && strcmp (stage, "matching exemplar") == 0
                 : s->permille_target <= (int) (fraction * 1000.0);
  if (s->calls++ > 0 && t - s->last_call > s->max_gap)
    s->max_gap = t - s->last_call;
  s->last_call = t;
  s->last_fraction = fraction;
  /* At the target, wait for the other thread's cancel (a scheduler or
   * valgrind's one-thread-at-a-time may otherwise never run it before the
   * synthesis ends), then still say "go on" this once: the engine must
   * see the cancel at a later call, the worst case the latency covers. */
  if (reached && !s->waited)
    {
      struct timespec ms = { 0, 1000000 };
      s->waited = true;
      atomic_store (&s->reached, 1);
      for (int i = 0; i < 60000 && !atomic_load (&s->cancel); i++)
        nanosleep (&ms, NULL);
      return true;
    }
  return !atomic_load (&s->cancel);
}

/* Waits until the synthesis has reached the target, then cancels at once,
 * while the callback that reached it waits: right after a progress call,
 * the worst moment. */
static void *
canceller (void *data)
{
  Shared *s = data;
  struct timespec ms = { 0, 1000000 };

  while (!atomic_load (&s->reached))
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
  bool          is_solid;    /* written in place: see check_output */
  bool          finest;      /* every cancel must come in the finest level */
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

static bool
untouched_float (const float *value)
{
  const unsigned char *bytes = (const unsigned char *) value;
  for (size_t b = 0; b < sizeof *value; b++)
    if (bytes[b] != FILL_BYTE)
      return false;
  return true;
}

/* A 2D output must be untouched. The solid engine synthesises its finest
 * level in the caller's volume, so a cancel leaves the volume's contents
 * unspecified; what still holds is that the volume is written only once
 * the finest level starts, and then every voxel at once: so it is either
 * untouched (a cancel in the coarser levels) or has no untouched float
 * and no NaN or infinity left (a cancel in the finest level). A half
 * written volume, or garbage, fails. */
static void
check_output (const Job *job, const char *when)
{
  size_t floats = job->bytes / sizeof (float), untouched = 0, not_finite = 0;

  for (size_t i = 0; i < floats; i++)
    {
      if (untouched_float (&job->out[i]))
        untouched++;
      else if (!isfinite (job->out[i]))
        not_finite++;
    }
  if (!job->is_solid)
    {
      CHECK (untouched == floats, "%s, cancel %s: the output is untouched (%zu of %zu floats "
             "written)", job->name, when, floats - untouched, floats);
      return;
    }
  CHECK (untouched == floats || (untouched == 0 && not_finite == 0),
         "%s, cancel %s: the volume is untouched or wholly written (%zu of %zu floats untouched, "
         "%zu not finite)", job->name, when, untouched, floats, not_finite);
  CHECK (!job->finest || untouched == 0,
         "%s, cancel %s: in the finest level, as meant (an earlier point than the finest "
         "level's start: move the point)", job->name, when);
  printf ("%s, cancel %s: volume %s\n", job->name, when,
          untouched == floats ? "untouched (cancelled in a coarser level)"
                              : "wholly written (cancelled in the finest level)");
}

static void
describe_target (int target, char *text, size_t size)
{
  if (target == MATCHING_TARGET)
    snprintf (text, size, "inside the exemplar matching");
  else
    snprintf (text, size, "after %.1f %% of the work", target / 10.0);
}

/* Cancels `job` at each of `count` targets (permille, or MATCHING_TARGET);
 * returns its worst latency. */
static double
cancel_at (Job *job, const int *targets, size_t count, double bound)
{
  double worst = 0.0, worst_gap = 0.0;

  for (size_t t = 0; t < count; t++)
    {
      Shared s;
      TsError error = { TS_OK, "" };
      pthread_t thread;
      TsStatus status;
      double latency;
      char when[64];

      describe_target (targets[t], when, sizeof when);
      memset (&s, 0, sizeof s);
      atomic_init (&s.cancel, 0);
      atomic_init (&s.reached, 0);
      s.permille_target = targets[t];
      memset (job->out, FILL_BYTE, job->bytes);
      if (pthread_create (&thread, NULL, canceller, &s) != 0)
        {
          CHECK (0, "cannot start the canceller thread");
          break;
        }
      status = run_job (job, &s, &error);
      latency = now_s () - s.cancel_time;
      atomic_store (&s.reached, 1);  /* lets the canceller end */
      pthread_join (thread, NULL);
      /* A synthesis that ended without reaching the target cannot have
       * been cancelled there: a failure (say, an exemplar too small for
       * the matching to report midway). */
      if (!s.waited)
        {
          CHECK (0, "%s: the synthesis ended (%s) without reaching the cancel point (%s)",
                 job->name, ts_status_string (status), when);
          continue;
        }

      CHECK (status == TS_ERROR_CANCELLED, "%s, cancel %s: status %s (%s)", job->name, when,
             ts_status_string (status), error.message);
      CHECK (strstr (error.message, "cancel") != NULL, "message says cancelled: %s", error.message);
      check_output (job, when);
      CHECK (latency < bound, "%s, cancel %s returned in %.3f s (bound %.1f s)", job->name, when,
             latency, bound);
      CHECK (!job->is_solid || s.max_gap < bound, "%s, cancel %s: longest gap between progress "
             "calls %.3f s (bound %.1f s)", job->name, when, s.max_gap, bound);
      printf ("%s, cancel %s: returned in %.3f s (longest gap between progress calls so far %.3f s)\n",
              job->name, when, latency, s.max_gap);
      worst = latency > worst ? latency : worst;
      worst_gap = s.max_gap > worst_gap ? s.max_gap : worst_gap;
    }
  printf ("cancel figures: %s, worst latency %.3f s, longest progress gap %.3f s\n",
          job->name, worst, worst_gap);
  return worst;
}

/* A `side` x `side` exemplar from `tile` mirrored: large, and still a texture. */
static bool
mirror_tile (const TsImage *tile, size_t side, TsImage *out)
{
  out->width = out->height = side;
  out->pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  if (!out->pixels)
    return false;
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        size_t tx = x % (2 * tile->width), ty = y % (2 * tile->height);
        tx = tx < tile->width ? tx : 2 * tile->width - 1 - tx;
        ty = ty < tile->height ? ty : 2 * tile->height - 1 - ty;
        memcpy (out->pixels + (y * side + x) * TS_CHANNELS,
                tile->pixels + (ty * tile->width + tx) * TS_CHANNELS, TS_CHANNELS * sizeof (float));
      }
  return true;
}

/* Runs `job` (its `out` allocated here, `bytes` long) at `targets`. */
static void
run_cancels (Job *job, const int *targets, size_t count, double bound)
{
  job->out = malloc (job->bytes);
  CHECK (job->out != NULL, "%s: output allocation", job->name);
  if (job->out)
    cancel_at (job, targets, count, bound);
  free (job->out);
  job->out = NULL;
}

static void
job_2d (Job *job, const char *name, const TsImage *ex, size_t side)
{
  memset (job, 0, sizeof *job);
  job->name = name;
  job->ex = ex;
  ts_params_init (&job->params);
  job->params.output_width = job->params.output_height = side;
  job->params.seed = 7;
  job->bytes = side * side * TS_CHANNELS * sizeof (float);
}

static void
job_solid (Job *job, const char *name, const TsImage *ex, size_t size)
{
  memset (job, 0, sizeof *job);
  job->name = name;
  job->ex = ex;
  job->is_solid = true;
  ts_solid_params_init (&job->solid);
  job->solid.size = size;
  job->solid.seed = 7;
  job->bytes = size * size * size * TS_CHANNELS * sizeof (float);
}

int
main (int argc, char **argv)
{
  static const int spread[] = { 1, 300, 600, 800 };
  static const int matching[] = { MATCHING_TARGET };
  /* The cell structure's own stretches (the exemplar's distances, each
   * level's tessellation) come first: the early points reach them. */
  static const int early[] = { 1, 300 };
  /* The finest level of a 128^3 volume starts at about 14 % of the work. */
  static const int finest[] = { 300 };
  size_t side = argc > 1 ? (size_t) strtoul (argv[1], NULL, 10) : DEFAULT_SIDE;
  size_t solid = argc > 2 ? (size_t) strtoul (argv[2], NULL, 10) : DEFAULT_SOLID_SIZE;
  size_t large = argc > 3 ? (size_t) strtoul (argv[3], NULL, 10) : DEFAULT_LARGE_EXEMPLAR;
  double bound = argc > 4 ? strtod (argv[4], NULL) : DEFAULT_BOUND_S;
  size_t large_solid = argc > 5 ? (size_t) strtoul (argv[5], NULL, 10) : DEFAULT_LARGE_SOLID;
  char name[7][48];
  TsImage ex, big;
  Job job;

  if (side < 16 || side > 4096 || solid < TS_SOLID_MIN_SIZE || solid > 256 || large < 64
      || large > 2048 || !(bound > 0.0 && bound <= 60.0) || large_solid < TS_SOLID_MIN_SIZE
      || large_solid > 256)
    {
      fprintf (stderr, "usage: test-cancel [SIDE 16..4096 [SOLID_SIZE %d..256 "
               "[LARGE_EXEMPLAR 64..2048 [BOUND_S 0..60 [LARGE_SOLID %d..256]]]]]\n",
               TS_SOLID_MIN_SIZE, TS_SOLID_MIN_SIZE);
      return 2;
    }
  test_load_exemplar ("bark.png", &ex);

  snprintf (name[0], sizeof name[0], "%zux%zu", side, side);
  job_2d (&job, name[0], &ex, side);
  run_cancels (&job, spread, sizeof spread / sizeof spread[0], bound);

  /* Texture by numbers in layers: the exemplar's halves as two labels, a
   * disc of one on the other; the cancels fall in either label's
   * synthesis. */
  {
    float *ex_guide = malloc (ex.width * ex.height * sizeof (float));
    float *target = malloc (side * side * sizeof (float));
    TsGuides guides;
    CHECK (ex_guide && target, "guide allocation");
    if (ex_guide && target)
      {
        for (size_t i = 0; i < ex.width * ex.height; i++)
          ex_guide[i] = i % ex.width < ex.width / 2 ? 0.0f : 1.0f;
        for (size_t y = 0; y < side; y++)
          for (size_t x = 0; x < side; x++)
            {
              double dx = (double) x - side / 2.0, dy = (double) y - side / 2.0;
              target[y * side + x] = dx * dx + dy * dy < side * side / 9.0 ? 1.0f : 0.0f;
            }
        ts_guides_init (&guides);
        guides.exemplar_guide = ex_guide;
        guides.target_guide = target;
        snprintf (name[6], sizeof name[6], "%zux%zu by numbers", side, side);
        job_2d (&job, name[6], &ex, side);
        job.params.guides = &guides;
        run_cancels (&job, spread, sizeof spread / sizeof spread[0], bound);
      }
    free (ex_guide);
    free (target);
  }

  snprintf (name[1], sizeof name[1], "solid %zu^3", solid);
  job_solid (&job, name[1], &ex, solid);
  run_cancels (&job, spread, sizeof spread / sizeof spread[0], bound);

  snprintf (name[4], sizeof name[4], "solid %zu^3, cell structure", solid);
  job_solid (&job, name[4], &ex, solid);
  job.solid.cell_structure = TS_CELL_STRUCTURE_ON;
  run_cancels (&job, early, sizeof early / sizeof early[0], bound);

  snprintf (name[5], sizeof name[5], "solid %zu^3", large_solid);
  job_solid (&job, name[5], &ex, large_solid);
  job.finest = true;
  run_cancels (&job, finest, sizeof finest / sizeof finest[0], bound);

  CHECK (mirror_tile (&ex, large, &big), "large exemplar allocation");
  if (big.pixels)
    {
      snprintf (name[2], sizeof name[2], "128x128 from %zux%zu", large, large);
      job_2d (&job, name[2], &big, 128);
      run_cancels (&job, matching, 1, bound);
      snprintf (name[3], sizeof name[3], "solid 32^3 from %zux%zu", large, large);
      job_solid (&job, name[3], &big, 32);
      run_cancels (&job, matching, 1, bound);
    }
  free (big.pixels);
  free (ex.pixels);
  return test_finish ("test-cancel");
}
