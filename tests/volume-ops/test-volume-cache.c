/* The volume ops' cache (operations/volume-cache.c) on small volumes:
 * reuse, keys, LRU eviction under the byte limit, volumes larger than the
 * limit, failures that are not kept, and concurrent requests for one
 * volume that synthesise it once.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "test-util.h"
#include "volume-cache.h"

#include <glib.h>

#include <stdlib.h>
#include <string.h>

#define SIZE 8
#define VOLUME_BYTES ((size_t) SIZE * SIZE * SIZE * TS_CHANNELS * sizeof (float))
/* What the cache keeps per volume: the voxels and every voxel's source. */
#define ENTRY_BYTES (VOLUME_BYTES + (size_t) SIZE * SIZE * SIZE * sizeof (TsSolidSource))
#define THREADS 4

typedef struct
{
  TsSolidParams  params;
  const TsImage *exemplars[3];
} Request;

static Request
request (const TsImage *exemplar, uint32_t seed)
{
  Request r;

  ts_solid_params_init (&r.params);
  r.params.size = SIZE;
  r.params.seed = seed;
  r.params.max_iterations = 1;
  for (int a = 0; a < 3; a++)
    r.exemplars[a] = exemplar;
  return r;
}

static size_t
syntheses (void)
{
  size_t n;

  ts_volume_cache_stats (&n, NULL);
  return n;
}

static TsVolumeEntry *
acquire (const Request *r)
{
  TsError error = { TS_OK, "" };
  TsVolumeEntry *entry = ts_volume_cache_acquire (&r->params, r->exemplars, NULL, NULL, &error);

  CHECK (entry != NULL, "acquire failed: %s", error.message);
  return entry;
}

/* The first progress call of a synthesis waits a little, so that the
 * other threads ask for the volume while it is being made. */
static bool
slow_progress (double fraction, const char *stage, void *user_data)
{
  (void) fraction;
  (void) stage;
  if (g_atomic_int_compare_and_exchange ((gint *) user_data, 0, 1))
    g_usleep (200000);
  return true;
}

typedef struct
{
  const Request *request;
  gint          *slept;
  const float   *voxels;
} ThreadJob;

static gpointer
thread_acquire (gpointer data)
{
  ThreadJob *job = data;
  TsError error = { TS_OK, "" };
  TsVolumeEntry *entry = ts_volume_cache_acquire (&job->request->params,
                                                  job->request->exemplars, slow_progress,
                                                  job->slept, &error);

  CHECK (entry != NULL, "threaded acquire failed: %s", error.message);
  job->voxels = entry ? ts_volume_entry_voxels (entry) : NULL;
  ts_volume_cache_release (entry);
  return NULL;
}

int
main (void)
{
  TsImage noise, other, transparent;
  TsVolumeEntry *a, *b, *c;
  size_t before;

  test_noise_image (&noise, 24, 24, 1);
  test_noise_image (&other, 24, 24, 2);
  transparent = noise;
  transparent.pixels = calloc (24 * 24 * TS_CHANNELS, sizeof (float));
  if (!transparent.pixels)
    return 1;

  Request r1 = request (&noise, 1), r2 = request (&noise, 2), r3 = request (&other, 1);
  ts_volume_cache_set_limit (ENTRY_BYTES * 4);

  /* Reuse: the same request is answered from the cache. */
  before = syntheses ();
  a = acquire (&r1);
  b = acquire (&r1);
  CHECK (a && a == b, "a second request gets the same volume");
  CHECK (syntheses () == before + 1, "one synthesis for two requests");
  CHECK (a && ts_volume_entry_size (a) == SIZE, "size %zu", a ? ts_volume_entry_size (a) : 0);
  ts_volume_cache_release (b);

  /* Every parameter and the exemplar pixels are part of the key. */
  b = acquire (&r2);
  c = acquire (&r3);
  CHECK (syntheses () == before + 3, "another seed or exemplar is synthesised anew");
  CHECK (a && b && c && memcmp (ts_volume_entry_voxels (a), ts_volume_entry_voxels (b),
                                VOLUME_BYTES) != 0, "another seed gives another volume");
  CHECK (a && ts_volume_entry_sources (a) != NULL, "cached volumes keep their sources");
  Request r1_free = r1;
  r1_free.exemplars[TS_AXIS_X] = NULL;
  ts_volume_cache_release (acquire (&r1_free));
  CHECK (syntheses () == before + 4, "a free orientation is part of the key");
  ts_volume_cache_release (a);
  ts_volume_cache_release (b);
  ts_volume_cache_release (c);

  /* LRU: with room for two, using r1 then r3 then r2 evicts r1. */
  ts_volume_cache_clear ();
  ts_volume_cache_set_limit (ENTRY_BYTES * 2);
  before = syntheses ();
  ts_volume_cache_release (acquire (&r1));
  ts_volume_cache_release (acquire (&r3));
  ts_volume_cache_release (acquire (&r1)); /* r1 is now the most recent */
  ts_volume_cache_release (acquire (&r2)); /* evicts r3 */
  CHECK (syntheses () == before + 3, "r1 reused: %zu syntheses", syntheses () - before);
  ts_volume_cache_release (acquire (&r1));
  CHECK (syntheses () == before + 3, "r1 kept, as the most recently used");
  ts_volume_cache_release (acquire (&r3));
  CHECK (syntheses () == before + 4, "r3 was evicted");

  /* A volume larger than the limit serves its request and is dropped. */
  ts_volume_cache_set_limit (ENTRY_BYTES - 1);
  before = syntheses ();
  a = acquire (&r1);
  CHECK (a != NULL, "served although larger than the limit");
  ts_volume_cache_release (a);
  ts_volume_cache_release (acquire (&r1));
  CHECK (syntheses () == before + 2, "not kept: synthesised again");
  ts_volume_cache_set_limit (ENTRY_BYTES * 4);

  /* Failures give a message and are not kept. */
  {
    Request bad = request (&transparent, 1);
    TsError error = { TS_OK, "" };
    before = syntheses ();
    for (int i = 0; i < 2; i++)
      {
        TsVolumeEntry *e = ts_volume_cache_acquire (&bad.params, bad.exemplars, NULL, NULL,
                                                    &error);
        CHECK (e == NULL && error.status == TS_ERROR_TRANSPARENT_EXEMPLAR &&
               strstr (error.message, "transparent"), "refused: %s", error.message);
      }
    CHECK (syntheses () == before, "no synthesis counted for a refusal");
  }

  /* Concurrent requests for one volume: one synthesis, one volume. */
  {
    GThread *threads[THREADS];
    ThreadJob jobs[THREADS];
    gint slept = 0;
    Request r4 = request (&noise, 4);

    ts_volume_cache_clear ();
    before = syntheses ();
    for (int i = 0; i < THREADS; i++)
      {
        jobs[i] = (ThreadJob) { &r4, &slept, NULL };
        threads[i] = g_thread_new ("acquire", thread_acquire, &jobs[i]);
      }
    for (int i = 0; i < THREADS; i++)
      g_thread_join (threads[i]);
    CHECK (syntheses () == before + 1, "%d threads, %zu syntheses", THREADS,
           syntheses () - before);
    for (int i = 1; i < THREADS; i++)
      CHECK (jobs[i].voxels && jobs[i].voxels == jobs[0].voxels, "thread %d shares the volume",
             i);
  }

  ts_volume_cache_clear ();
  free (noise.pixels);
  free (other.pixels);
  free (transparent.pixels);
  return test_finish ("test-volume-cache");
}
