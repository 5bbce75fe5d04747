/* GIMP 3's dialogs: GimpProcedureDialog (GTK3) on the procedure's config.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_DIALOGS_GIMP3_H
#define TEXSYNTH_DIALOGS_GIMP3_H

#include "texsynth-plugin.h"

/* What a dialog's preview runs with the config's current values: the
 * render or the solid procedure's small run on `exemplars`, or healing
 * heal_pixels with heal_mask (ts_heal_preview_crop's). */
typedef enum
{
  TS_DIALOG_PREVIEW_RENDER,
  TS_DIALOG_PREVIEW_SOLID,
  TS_DIALOG_PREVIEW_HEAL
} TsDialogPreviewKind;

typedef struct
{
  TsDialogPreviewKind kind;
  const TsExemplar   *exemplars;
  gint                n_exemplars;
  GeglBuffer         *heal_pixels;
  GeglBuffer         *heal_mask;
} TsDialogPreview;

/* Shows the listed arguments (NULL-terminated), and a preview unless
 * `preview` is NULL; TRUE on OK, with the config updated. */
gboolean ts_dialog3 (GimpProcedure         *procedure,
                     GimpProcedureConfig   *config,
                     const gchar           *title,
                     const TsDialogPreview *preview,
                     const gchar           *first_property,
                     ...) G_GNUC_NULL_TERMINATED;

#endif /* TEXSYNTH_DIALOGS_GIMP3_H */
