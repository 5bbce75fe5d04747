/* The preview in the dialogs of GIMP 2.10 (GTK2) and GIMP 3 (GTK3): a
 * GimpPreviewArea showing a small run with the dialog's settings, and a
 * button that runs it again after they change.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_DIALOG_PREVIEW_H
#define TEXSYNTH_DIALOG_PREVIEW_H

#include "plugin-preview.h"

#include <libgimp/gimpui.h>

/* Starts a preview run with the dialog's current settings; NULL if it
 * cannot. */
typedef TsPreview *(*TsPreviewStart) (gpointer data);

/* The preview, `caption` under it (what it shows), and its button. The
 * first run starts when the dialog is shown; `start` and `data` must
 * outlive the widget, whose destruction waits for a run still going. */
GtkWidget *ts_preview_widget_new (TsPreviewStart start, gpointer data, const gchar *caption);

#endif /* TEXSYNTH_DIALOG_PREVIEW_H */
