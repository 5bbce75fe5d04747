/* GIMP 3's dialogs: GimpProcedureDialog (GTK3) on the procedure's config.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_DIALOGS_GIMP3_H
#define TEXSYNTH_DIALOGS_GIMP3_H

#include "texsynth-plugin.h"

/* What a dialog's preview grows: the render or the solid procedure's
 * small run on `exemplars` with the config's current values. */
typedef struct
{
  const TsExemplar *exemplars;
  gint              n_exemplars;
  gboolean          solid;
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
