/* A process-wide cache of synthesised solid textures, so that several
 * slices, atlases or files of one volume cost one synthesis.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Shared by texsynth:volume-slice and texsynth:volume-save, which are
 * built into one module for that reason. Entries are keyed by a SHA-256
 * of the exemplars (pixels and sizes, per orientation, absent ones
 * included) and of every parameter that changes the result (not the
 * memory limit). Thread-safe: a request for a volume that is being
 * synthesised waits for it instead of starting another synthesis.
 * Volumes that nobody holds are evicted least recently used first when
 * the kept total exceeds the limit; a volume larger than the limit is
 * given to its requesters and then dropped.
 */
#ifndef TEXSYNTH_VOLUME_CACHE_H
#define TEXSYNTH_VOLUME_CACHE_H

#include "texsynth.h"

#include <stddef.h>

typedef struct TsVolumeEntry TsVolumeEntry;

/* The volume for `params` and `exemplars` (as ts_synthesize_solid takes
 * them), synthesised now with `progress` (may be NULL) or reused. Returns
 * a held entry, or NULL with `error` filled (nothing is kept then). */
TsVolumeEntry *ts_volume_cache_acquire (const TsSolidParams *params,
                                        const TsImage *const exemplars[3],
                                        TsProgressFunc       progress,
                                        void                *user_data,
                                        TsError             *error);

/* The held volume: size^3 voxels of TS_CHANNELS floats, read-only. */
const float *ts_volume_entry_voxels (const TsVolumeEntry *entry);
/* Every voxel's source (see ts_synthesize_solid_with_sources), read-only:
 * cached volumes always have them. */
const TsSolidSource *ts_volume_entry_sources (const TsVolumeEntry *entry);
size_t       ts_volume_entry_size   (const TsVolumeEntry *entry);

/* Let go of an entry from ts_volume_cache_acquire (NULL is ignored). */
void ts_volume_cache_release (TsVolumeEntry *entry);

/* Bytes of volumes kept for reuse at most. The default is the smaller of
 * 1 GiB and a quarter of the RAM, or TEXSYNTH_VOLUME_CACHE_MIB (MiB) from
 * the environment when set. Lowering it evicts at once. */
void   ts_volume_cache_set_limit (size_t bytes);
size_t ts_volume_cache_get_limit (void);

/* Counters since the process started, for tests and debugging: volumes
 * synthesised and requests answered from the cache. With the environment
 * variable TEXSYNTH_DEBUG_CACHE set, every request also prints
 * "texsynth: volume cache hit|miss|wait (SIZE^3)" to stderr. */
void ts_volume_cache_stats (size_t *syntheses, size_t *hits);

/* Drop every volume nobody holds (e.g. before a test). */
void ts_volume_cache_clear (void);

#endif /* TEXSYNTH_VOLUME_CACHE_H */
