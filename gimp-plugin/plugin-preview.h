/* The dialogs' previews: a small run of the procedure's op with the
 * dialog's settings, in a worker thread so that the dialog stays
 * responsive. Shared by GIMP 2.10 and GIMP 3; no GTK here.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_PLUGIN_PREVIEW_H
#define TEXSYNTH_PLUGIN_PREVIEW_H

#include "texsynth-plugin.h"

/* The preview's largest side in pixels: small enough that a run takes a
 * fraction of a second, large enough to show a texture's structure. */
#define TS_PREVIEW_SIDE 160

/* The solid preview's largest cube: the middle slice across x of a
 * volume of this edge, which keeps the exemplar's scale. */
#define TS_PREVIEW_SOLID_SIZE 48

typedef struct _TsPreview TsPreview;

/* Start texsynth:synthesize at min(width, TS_PREVIEW_SIDE) x
 * min(height, TS_PREVIEW_SIDE) with the other settings of `args`: a
 * crop-sized texture at the result's scale. The exemplar's buffer is
 * referenced, not copied; nothing may write to it until the preview is
 * freed. NULL if out of memory. */
TsPreview *ts_preview_start_render (const TsExemplar *exemplar, const TsRenderArgs *args);

/* Start the middle slice across x of a cube of min(size,
 * TS_PREVIEW_SOLID_SIZE) with the other settings of `args`, through
 * texsynth:volume-slice; no file is written. */
TsPreview *ts_preview_start_solid (const TsExemplar  *exemplars,
                                   gint               n_exemplars,
                                   const TsSolidArgs *args);

/* texsynth:heal on `pixels` with `mask` (the hole, "Y' float", same
 * size), both referenced: the crop around a selection that
 * ts_heal_preview_crop reads. The result is scaled down to fit
 * TS_PREVIEW_SIDE when the crop is larger. */
TsPreview *ts_preview_start_heal (GeglBuffer *pixels, GeglBuffer *mask, const TsHealArgs *args);

/* Whether the run has finished; never blocks. */
gboolean ts_preview_done (TsPreview *preview);

/* After ts_preview_done: the result as sRGB "R'G'B'A u8" rows of
 * width * 4 bytes, owned by `preview`. */
const guchar *ts_preview_pixels (TsPreview *preview, gint *width, gint *height);

/* Waits for the run to finish (a fraction of a second at these sizes;
 * GEGL cannot stop an op midway) and frees everything. NULL is fine. */
void ts_preview_free (TsPreview *preview);

#endif /* TEXSYNTH_PLUGIN_PREVIEW_H */
