/* GIMP 3's dialogs: GimpProcedureDialog (GTK3) on the procedure's config.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_DIALOGS_GIMP3_H
#define TEXSYNTH_DIALOGS_GIMP3_H

#include "texsynth-plugin.h"
#include "plugin-preview.h"

/* Shows the listed arguments (NULL-terminated), and a preview of what
 * `preview` holds (read of GIMP by the caller) with the config's values
 * of the moment, unless it is NULL; TRUE on OK, with the config updated. */
gboolean ts_dialog3 (GimpProcedure         *procedure,
                     GimpProcedureConfig   *config,
                     const gchar           *title,
                     const TsPreviewInput  *preview,
                     const gchar           *first_property,
                     ...) G_GNUC_NULL_TERMINATED;

#endif /* TEXSYNTH_DIALOGS_GIMP3_H */
