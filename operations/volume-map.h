/* Aligned maps for both volume ops: the optional "aux3" pad holds an
 * image aligned with the exemplar (a material's roughness, height ...),
 * laid out with the cached volume's sources, so that the map's volume
 * matches the colour volume voxel for voxel without a second synthesis;
 * and the sources themselves as x, y, orientation.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#ifndef TEXSYNTH_VOLUME_MAP_H
#define TEXSYNTH_VOLUME_MAP_H

#include "volume-op-common.h"

#define TS_VOLUME_MAP_PAD "aux3"

/* Add the map pad (from an op's attach). */
void ts_volume_map_add_pad (GeglOperation *operation);

gboolean ts_volume_map_connected (GeglOperation *operation);

/* Checked before any synthesis: the map has the input's size, and every
 * orientation the volume copies uses "input" (a map is aligned with one
 * exemplar; with "aux" or "aux2" connected, write the sources instead). */
gboolean ts_volume_map_check (GeglOperation *operation, int free_axis, TsError *error);

/* The map's pixels in `format`, laid out with the entry's sources:
 * size^3 pixels, x fastest (g_free them), or NULL with `error` set. */
void *ts_volume_map_lay_out (GeglOperation *operation, const TsVolumeEntry *entry,
                             const Babl *format, TsError *error);

/* Every voxel's source as four guint16: the exemplar pixel's x and y, the
 * orientation (0, 1, 2 = the exemplar of the slices across x, y, z) and
 * 65535 (g_free them), or NULL with `error` set. */
guint16 *ts_volume_sources_xy (GeglOperation *operation, const TsVolumeEntry *entry,
                               TsError *error);

#endif /* TEXSYNTH_VOLUME_MAP_H */
