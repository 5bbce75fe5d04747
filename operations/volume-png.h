/* A set of PNG files that appears all at once: every image is written
 * through GEGL's gegl:png-save to a temporary file beside its target, and
 * the temporary files are renamed over the targets only when all of them
 * were written completely. On failure they are removed and older files
 * under the target names stay as they were.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#ifndef TEXSYNTH_VOLUME_PNG_H
#define TEXSYNTH_VOLUME_PNG_H

#include <gegl.h>

#include "texsynth.h"

typedef struct
{
  GPtrArray  *targets; /* gchar *, owned */
  GPtrArray  *temps;   /* gchar *, owned; same order */
  const Babl *space;   /* of every image; NULL = sRGB */
} TsPngSet;

/* A set of images in `space` (NULL = sRGB): png-save tags a file in
 * another space with its profile. */
void ts_png_set_init (TsPngSet *set, const Babl *space);

/* Write `rgba` (R'G'B'A u8 in the set's space, width x height, rows
 * width * 4 bytes apart) to a temporary file for `target`; as RGB when
 * `opaque`. */
gboolean ts_png_set_add (TsPngSet *set, const gchar *target, const guint8 *rgba,
                         size_t width, size_t height, gboolean opaque, TsError *error);

/* Rename every temporary file over its target, then clear the set. If a
 * rename fails, the remaining temporary files are removed. */
gboolean ts_png_set_commit (TsPngSet *set, TsError *error);

/* Remove the temporary files and clear the set. */
void ts_png_set_abort (TsPngSet *set);

#endif /* TEXSYNTH_VOLUME_PNG_H */
