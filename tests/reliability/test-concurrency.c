/* The engine called from several threads at once: each of THREADS threads
 * runs the same jobs as a serial run did (synthesis, tileable synthesis,
 * make-tileable, a refused request) in a different order, and every
 * result must be bit-identical to the serial one. Run under
 * ThreadSanitizer by scripts/sanitize.sh to find data races.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "test-util.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define THREADS 3
#define JOBS 4

typedef struct
{
  const TsImage *exemplar;
  TsImage        result[JOBS];
  TsStatus       status[JOBS];
  int            first_job;     /* threads start at different jobs */
} Worker;

static void
job_params (int job, TsParams *p)
{
  ts_params_init (p);
  p->output_width = 72 + 8 * (size_t) job;
  p->output_height = 64;
  p->seed = 100u + (uint32_t) job;
  p->wrap_x = p->wrap_y = job == 1;
  if (job == 3)
    p->memory_limit = 1024;   /* refused: exercises the error path */
}

static TsStatus
run_job (int job, const TsImage *exemplar, TsImage *result)
{
  TsError error = { TS_OK, "" };
  TsStatus status;

  if (job == 2)
    {
      TsTileableParams tp;
      ts_tileable_params_init (&tp);
      tp.seed = 4;
      result->width = exemplar->width;
      result->height = exemplar->height;
      result->pixels = calloc (result->width * result->height * TS_CHANNELS, sizeof (float));
      if (!result->pixels)
        return TS_ERROR_OUT_OF_MEMORY;
      return ts_make_tileable (&tp, exemplar, result, NULL, NULL, &error);
    }
  TsParams p;
  job_params (job, &p);
  result->width = p.output_width;
  result->height = p.output_height;
  result->pixels = calloc (result->width * result->height * TS_CHANNELS, sizeof (float));
  if (!result->pixels)
    return TS_ERROR_OUT_OF_MEMORY;
  status = ts_synthesize (&p, exemplar, result, NULL, NULL, &error);
  return status;
}

static void *
worker_main (void *data)
{
  Worker *w = data;
  for (int i = 0; i < JOBS; i++)
    {
      int job = (w->first_job + i) % JOBS;
      w->status[job] = run_job (job, w->exemplar, &w->result[job]);
    }
  return NULL;
}

static bool
same_image (const TsImage *a, const TsImage *b)
{
  return a->width == b->width && a->height == b->height &&
         memcmp (a->pixels, b->pixels, a->width * a->height * TS_CHANNELS * sizeof (float)) == 0;
}

int
main (void)
{
  TsImage exemplar, serial[JOBS];
  TsStatus serial_status[JOBS];
  Worker workers[THREADS];
  pthread_t threads[THREADS];
  int identical = 0, compared = 0;

  test_load_exemplar ("brick.png", &exemplar);
  for (int job = 0; job < JOBS; job++)
    serial_status[job] = run_job (job, &exemplar, &serial[job]);
  CHECK (serial_status[0] == TS_OK && serial_status[1] == TS_OK && serial_status[2] == TS_OK,
         "serial jobs succeed: %d %d %d", serial_status[0], serial_status[1], serial_status[2]);
  CHECK (serial_status[3] == TS_ERROR_TOO_LARGE, "job 3 is refused: %d", serial_status[3]);

  for (int t = 0; t < THREADS; t++)
    {
      memset (&workers[t], 0, sizeof workers[t]);
      workers[t].exemplar = &exemplar;
      workers[t].first_job = t % JOBS;
      if (pthread_create (&threads[t], NULL, worker_main, &workers[t]) != 0)
        {
          fprintf (stderr, "cannot start thread %d\n", t);
          return 1;
        }
    }
  for (int t = 0; t < THREADS; t++)
    pthread_join (threads[t], NULL);

  for (int t = 0; t < THREADS; t++)
    for (int job = 0; job < JOBS; job++)
      {
        bool same = workers[t].status[job] == serial_status[job] &&
                    (serial_status[job] != TS_OK || same_image (&workers[t].result[job], &serial[job]));
        CHECK (same, "thread %d, job %d: status %d, differs from the serial run", t, job,
               (int) workers[t].status[job]);
        identical += same;
        compared++;
        free (workers[t].result[job].pixels);
      }
  printf ("concurrency figures: %d threads x %d jobs at once, %d of %d results identical "
          "to the serial run\n", THREADS, JOBS, identical, compared);
  for (int job = 0; job < JOBS; job++)
    free (serial[job].pixels);
  free (exemplar.pixels);
  return test_finish ("test-concurrency");
}
