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
  /* sample-from and cell-structure stay integer arguments for scripts;
   * the dialog shows their choices by name (fill_list reuses these
   * widgets). Automatic first: the default, and right for most layers. */
  if (g_list_find_custom (properties, "sample-from", (GCompareFunc) g_strcmp0))
    gimp_procedure_dialog_get_int_combo (GIMP_PROCEDURE_DIALOG (dialog), "sample-from",
                                         GIMP_INT_STORE (gimp_int_store_new (
                                           ts_sample_from_label (0), 0,
                                           ts_sample_from_label (1), 1,
                                           ts_sample_from_label (2), 2, NULL)));
  if (g_list_find_custom (properties, "cell-structure", (GCompareFunc) g_strcmp0))
    gimp_procedure_dialog_get_int_combo (GIMP_PROCEDURE_DIALOG (dialog), "cell-structure",
                                         GIMP_INT_STORE (gimp_int_store_new (
                                           ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_AUTO),
                                           TS_PLUGIN_CELL_STRUCTURE_AUTO,
                                           ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_ON),
                                           TS_PLUGIN_CELL_STRUCTURE_ON,
                                           ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_OFF),
                                           TS_PLUGIN_CELL_STRUCTURE_OFF, NULL)));
  gimp_procedure_dialog_fill_list (GIMP_PROCEDURE_DIALOG (dialog), properties);
  ok = gimp_procedure_dialog_run (GIMP_PROCEDURE_DIALOG (dialog));
  gtk_widget_destroy (dialog);
  g_list_free (properties);
  return ok;
}
