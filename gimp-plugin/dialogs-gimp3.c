/* GIMP 3's dialogs: GimpProcedureDialog builds the widgets from the
 * arguments' specs, so labels, tooltips and ranges are the registered ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdarg.h>

#include "dialogs-gimp3.h"

#include <libgimp/gimpui.h>

gboolean
ts_dialog3 (GimpProcedure       *procedure,
            GimpProcedureConfig *config,
            const gchar         *title,
            const gchar         *first_property,
            ...)
{
  GList *properties = NULL;
  const gchar *property;
  GtkWidget *dialog;
  gboolean ok;
  va_list args;

  va_start (args, first_property);
  for (property = first_property; property; property = va_arg (args, const gchar *))
    properties = g_list_append (properties, (gpointer) property);
  va_end (args);

  gimp_ui_init (TS_PLUGIN_BINARY);
  dialog = gimp_procedure_dialog_new (procedure, config, title);
  gimp_procedure_dialog_fill_list (GIMP_PROCEDURE_DIALOG (dialog), properties);
  ok = gimp_procedure_dialog_run (GIMP_PROCEDURE_DIALOG (dialog));
  gtk_widget_destroy (dialog);
  g_list_free (properties);
  return ok;
}
