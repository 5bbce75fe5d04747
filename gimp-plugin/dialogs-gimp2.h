/* GIMP 2.10's dialogs (GTK2, libgimpui-2.0). Each returns TRUE on OK,
 * with the arguments as the user left them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_DIALOGS_GIMP2_H
#define TEXSYNTH_DIALOGS_GIMP2_H

#include "texsynth-plugin.h"
#include "guided-plugin.h"
#include "plugin-preview.h"

/* The render, material-set and solid dialogs preview a small run on
 * `exemplar` (the driving layer's); the others on `preview` (NULL: no
 * preview), which the caller read of GIMP. */
gboolean ts_render_dialog2   (TsRenderArgs *args, const TsExemplar *exemplar);
gboolean ts_layers_dialog2   (TsRenderArgs *args, const TsExemplar *driver);
gboolean ts_tileable_dialog2 (TsTileableArgs *args, const TsPreviewInput *preview);
gboolean ts_solid_dialog2    (TsSolidArgs *args, const TsExemplar *exemplar);
/* `procedure` chooses the fields: context and sample-from, or percent. */
gboolean ts_heal_dialog2     (TsHealArgs *args, const gchar *procedure, const gchar *title,
                              const TsPreviewInput *preview);

/* Texture by numbers (`guide` not NULL) or style transfer: the exemplar
 * (or style) layer and the exemplar's guide are picked from every open
 * image but `target`; -1 picks the first. The preview reads the layers
 * picked when it starts. */
gboolean ts_guided_dialog2   (const gchar *procedure, TsGuidedArgs *args, gint32 target,
                              gint32 *exemplar, gint32 *guide, const TsPreviewInput *preview);

#endif /* TEXSYNTH_DIALOGS_GIMP2_H */
