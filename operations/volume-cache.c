/* A process-wide cache of synthesised solid textures.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * The one piece of process-global mutable state of the ops, on purpose:
 * it exists to share volumes between op instances. All of it is guarded
 * by `cache_lock`; statically allocated GMutex and GCond need no init.
 */
#include "volume-cache.h"

#include <glib.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define KEY_BYTES 32 /* SHA-256 */
/* Bytes of cached volumes at most, unless TEXSYNTH_VOLUME_CACHE_MIB says
 * otherwise or a quarter of the RAM is less (as the engine's own
 * default limit): four 256^3 volumes of 16 bytes a voxel. */
#define DEFAULT_LIMIT ((size_t) 1 << 30)

typedef enum
{
  ENTRY_BUSY,   /* being synthesised by the thread that created it */
  ENTRY_READY,
  ENTRY_FAILED  /* out of the table; waiters retry on their own */
} EntryState;

struct TsVolumeEntry
{
  guint8     key[KEY_BYTES];
  size_t     size;
  size_t     bytes;
  float     *voxels;
  TsSolidSource *sources; /* every voxel's exemplar pixel, for aligned maps */
  EntryState state;
  guint      holders;   /* requesters holding or waiting for it */
  gboolean   in_table;  /* findable; its bytes count once ready */
  guint64    last_used;
};

static GMutex      cache_lock;
static GCond       cache_changed;
static GHashTable *cache_table;     /* key -> entry */
static size_t      cache_bytes;     /* of the ready entries in the table */
static size_t      cache_limit;
static gboolean    cache_limit_set;
static guint64     cache_clock;
static size_t      cache_syntheses, cache_hits;

static guint
key_hash (gconstpointer key)
{
  guint h;

  memcpy (&h, key, sizeof h); /* already a cryptographic hash */
  return h;
}

static gboolean
key_equal (gconstpointer a, gconstpointer b)
{
  return memcmp (a, b, KEY_BYTES) == 0;
}

static void
debug_note (const char *what, size_t size)
{
  const char *flag = getenv ("TEXSYNTH_DEBUG_CACHE");

  if (flag && flag[0])
    fprintf (stderr, "texsynth: volume cache %s (%zu^3)\n", what, size);
}

static void
hash_u64 (GChecksum *sum, guint64 value)
{
  guint8 bytes[8];

  for (int i = 0; i < 8; i++)
    bytes[i] = (guint8) (value >> (8 * i));
  g_checksum_update (sum, bytes, sizeof bytes);
}

/* Everything that changes the synthesised voxels. */
static void
compute_key (const TsSolidParams *params, const TsImage *const exemplars[3],
             guint8 key[KEY_BYTES])
{
  GChecksum *sum = g_checksum_new (G_CHECKSUM_SHA256);
  gsize length = KEY_BYTES;

  g_checksum_update (sum, (const guchar *) "texsynth-solid-1", 16);
  hash_u64 (sum, params->size);
  hash_u64 (sum, params->periodic);
  hash_u64 (sum, (guint64) (gint64) params->quality);
  hash_u64 (sum, params->seed);
  hash_u64 (sum, (guint64) (gint64) params->patch_size);
  hash_u64 (sum, (guint64) (gint64) params->max_iterations);
  hash_u64 (sum, params->histogram_matching);
  /* What the run will use, so automatic and explicit choices share a
   * volume; only when on: volumes cached before the option keep their
   * keys. */
  if (ts_solid_uses_cell_structure (params, exemplars))
    hash_u64 (sum, TS_CELL_STRUCTURE_ON);
  for (int a = 0; a < 3; a++)
    {
      const TsImage *ex = exemplars[a];

      hash_u64 (sum, ex != NULL);
      if (!ex)
        continue;
      hash_u64 (sum, ex->width);
      hash_u64 (sum, ex->height);
      if (ex->pixels)
        {
          /* In rows: GChecksum takes a gssize length. */
          size_t row = ex->width * TS_CHANNELS * sizeof (float);
          for (size_t y = 0; y < ex->height; y++)
            g_checksum_update (sum, (const guchar *) ex->pixels + y * row, (gssize) row);
        }
    }
  g_checksum_get_digest (sum, key, &length);
  g_checksum_free (sum);
}

static size_t
default_limit (void)
{
  const char *env = getenv ("TEXSYNTH_VOLUME_CACHE_MIB");
  long pages = sysconf (_SC_PHYS_PAGES), page_size = sysconf (_SC_PAGE_SIZE);
  size_t limit = DEFAULT_LIMIT;

  if (env && env[0])
    {
      char *end;
      unsigned long long mib = strtoull (env, &end, 10);
      if (*end == '\0' && mib <= (SIZE_MAX >> 20))
        return (size_t) mib << 20;
    }
  if (pages > 0 && page_size > 0)
    {
      size_t quarter = (size_t) pages / 4 * (size_t) page_size;
      if (quarter < limit)
        limit = quarter;
    }
  return limit;
}

/* Callers hold cache_lock in all the functions below. */

static size_t
limit_locked (void)
{
  if (!cache_limit_set)
    {
      cache_limit = default_limit ();
      cache_limit_set = TRUE;
    }
  return cache_limit;
}

static GHashTable *
table_locked (void)
{
  if (!cache_table)
    cache_table = g_hash_table_new (key_hash, key_equal);
  return cache_table;
}

static void
free_entry (TsVolumeEntry *entry)
{
  g_free (entry->voxels);
  g_free (entry->sources);
  g_free (entry);
}

static void
remove_locked (TsVolumeEntry *entry)
{
  if (!entry->in_table)
    return;
  g_hash_table_remove (cache_table, entry->key);
  entry->in_table = FALSE;
  if (entry->state == ENTRY_READY)
    cache_bytes -= entry->bytes;
}

static void
unhold_locked (TsVolumeEntry *entry)
{
  entry->holders--;
  if (entry->holders == 0 && !entry->in_table)
    free_entry (entry);
}

/* Evict idle volumes, least recently used first, down to the limit. */
static void
evict_locked (void)
{
  size_t limit = limit_locked ();

  while (cache_bytes > limit)
    {
      TsVolumeEntry *oldest = NULL;
      GHashTableIter iter;
      gpointer value;

      g_hash_table_iter_init (&iter, table_locked ());
      while (g_hash_table_iter_next (&iter, NULL, &value))
        {
          TsVolumeEntry *e = value;
          if (e->state == ENTRY_READY && e->holders == 0 &&
              (!oldest || e->last_used < oldest->last_used))
            oldest = e;
        }
      if (!oldest)
        return; /* the rest is in use; evicted once released */
      remove_locked (oldest);
      free_entry (oldest);
    }
}

/* Find the volume of `key`, waiting while it is being synthesised; NULL
 * if there is none (any more). */
static TsVolumeEntry *
find_locked (const guint8 key[KEY_BYTES], size_t size)
{
  TsVolumeEntry *entry;

  while ((entry = g_hash_table_lookup (table_locked (), key)))
    {
      entry->holders++;
      if (entry->state == ENTRY_BUSY)
        {
          debug_note ("wait", size);
          while (entry->state == ENTRY_BUSY)
            g_cond_wait (&cache_changed, &cache_lock);
        }
      if (entry->state == ENTRY_READY)
        {
          entry->last_used = ++cache_clock;
          return entry;
        }
      unhold_locked (entry); /* failed: look again, maybe synthesise */
    }
  return NULL;
}

static TsStatus
synthesize (TsVolumeEntry *entry, const TsSolidParams *params,
            const TsImage *const exemplars[3], TsProgressFunc progress, void *user_data,
            TsError *error)
{
  /* Sources always: a later request for an aligned map then reuses the
   * volume instead of synthesising it again (4 of every 20 bytes kept). */
  TsSolidParams recording = *params;
  TsStatus status;
  size_t voxels = params->size * params->size * params->size;

  recording.record_sources = true;
  status = ts_solid_params_validate (&recording, exemplars, error);
  if (status != TS_OK)
    return status;
  entry->bytes = voxels * (TS_CHANNELS * sizeof (float) + sizeof (TsSolidSource));
  entry->voxels = g_try_malloc (voxels * TS_CHANNELS * sizeof (float));
  entry->sources = g_try_malloc (voxels * sizeof (TsSolidSource));
  if (!entry->voxels || !entry->sources)
    {
      if (error)
        {
          error->status = TS_ERROR_OUT_OF_MEMORY;
          snprintf (error->message, sizeof error->message,
                    "out of memory allocating a %zu^3 volume (%.1f MiB)", params->size,
                    (double) entry->bytes / 1048576.0);
        }
      return TS_ERROR_OUT_OF_MEMORY;
    }
  return ts_synthesize_solid_with_sources (&recording, exemplars, entry->voxels, entry->sources,
                                           progress, user_data, error);
}

TsVolumeEntry *
ts_volume_cache_acquire (const TsSolidParams *params,
                         const TsImage *const exemplars[3],
                         TsProgressFunc       progress,
                         void                *user_data,
                         TsError             *error)
{
  guint8 key[KEY_BYTES];
  TsVolumeEntry *entry;
  TsStatus status;

  if (!params || !exemplars)
    {
      if (error)
        {
          error->status = TS_ERROR_INVALID_ARGUMENT;
          snprintf (error->message, sizeof error->message, "no parameters or no exemplars given");
        }
      return NULL;
    }
  compute_key (params, exemplars, key);

  g_mutex_lock (&cache_lock);
  entry = find_locked (key, params->size);
  if (entry)
    {
      cache_hits++;
      g_mutex_unlock (&cache_lock);
      debug_note ("hit", params->size);
      return entry;
    }
  entry = g_new0 (TsVolumeEntry, 1);
  memcpy (entry->key, key, KEY_BYTES);
  entry->size = params->size;
  entry->state = ENTRY_BUSY;
  entry->holders = 1;
  entry->in_table = TRUE;
  g_hash_table_insert (table_locked (), entry->key, entry);
  g_mutex_unlock (&cache_lock);

  /* Unlocked: other volumes may be requested meanwhile, and requests
   * for this one wait on `cache_changed`. */
  debug_note ("miss", params->size);
  status = synthesize (entry, params, exemplars, progress, user_data, error);

  g_mutex_lock (&cache_lock);
  if (status == TS_OK)
    {
      cache_syntheses++;
      entry->state = ENTRY_READY;
      entry->last_used = ++cache_clock;
      cache_bytes += entry->bytes;
      if (entry->bytes > limit_locked ())
        remove_locked (entry); /* used by the current holders only */
      evict_locked ();
    }
  else
    {
      entry->state = ENTRY_FAILED;
      remove_locked (entry);
      unhold_locked (entry);
      entry = NULL;
    }
  g_cond_broadcast (&cache_changed);
  g_mutex_unlock (&cache_lock);
  return entry;
}

const float *
ts_volume_entry_voxels (const TsVolumeEntry *entry)
{
  return entry->voxels;
}

const TsSolidSource *
ts_volume_entry_sources (const TsVolumeEntry *entry)
{
  return entry->sources;
}

size_t
ts_volume_entry_size (const TsVolumeEntry *entry)
{
  return entry->size;
}

void
ts_volume_cache_release (TsVolumeEntry *entry)
{
  if (!entry)
    return;
  g_mutex_lock (&cache_lock);
  unhold_locked (entry);
  evict_locked ();
  g_mutex_unlock (&cache_lock);
}

void
ts_volume_cache_set_limit (size_t bytes)
{
  g_mutex_lock (&cache_lock);
  cache_limit = bytes;
  cache_limit_set = TRUE;
  evict_locked ();
  g_mutex_unlock (&cache_lock);
}

size_t
ts_volume_cache_get_limit (void)
{
  size_t limit;

  g_mutex_lock (&cache_lock);
  limit = limit_locked ();
  g_mutex_unlock (&cache_lock);
  return limit;
}

void
ts_volume_cache_stats (size_t *syntheses, size_t *hits)
{
  g_mutex_lock (&cache_lock);
  if (syntheses)
    *syntheses = cache_syntheses;
  if (hits)
    *hits = cache_hits;
  g_mutex_unlock (&cache_lock);
}

void
ts_volume_cache_clear (void)
{
  size_t limit;

  g_mutex_lock (&cache_lock);
  limit = limit_locked ();
  cache_limit = 0;
  evict_locked ();
  cache_limit = limit;
  g_mutex_unlock (&cache_lock);
}
