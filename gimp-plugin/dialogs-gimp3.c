/* GIMP 3's dialogs: GimpProcedureDialog builds the widgets from the
 * arguments' specs, so labels, tooltips and ranges are the registered ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdarg.h>

#include "dialogs-gimp3.h"
#include "dialog-preview.h"

#include <libgimp/gimpui.h>

typedef struct
{
  const TsDialogPreview *preview;
  GimpProcedureConfig   *config;
} PreviewSource;

/* The widgets write every change into the config: it holds the settings
 * as the dialog shows them. */
static TsPreview *
start_preview (gpointer data)
{
  const PreviewSource *source = data;

  if (source->preview->kind == TS_DIALOG_PREVIEW_HEAL)
    {
      TsHealArgs args;

      ts_heal_args_init (&args);
      g_object_get (source->config, "context", &args.context, "sample-from", &args.sample_from,
                    "quality", &args.quality, "seed", &args.seed, NULL);
      return ts_preview_start_heal (source->preview->heal_pixels, source->preview->heal_mask,
                                    &args);
    }
  else if (source->preview->kind == TS_DIALOG_PREVIEW_SOLID)
    {
      TsSolidArgs args;

      ts_solid_args_init (&args);
      g_object_get (source->config, "size", &args.size, "quality", &args.quality,
                    "seed", &args.seed, "cell-structure", &args.cell_structure, NULL);
      return ts_preview_start_solid (source->preview->exemplars, source->preview->n_exemplars,
                                     &args);
    }
  else
    {
      TsRenderArgs args;

      g_object_get (source->config, "width", &args.width, "height", &args.height,
                    "tileable", &args.tileable, "quality", &args.quality,
                    "seed", &args.seed, NULL);
      return ts_preview_start_render (source->preview->exemplars, &args);
    }
}

gboolean
ts_dialog3 (GimpProcedure         *procedure,
            GimpProcedureConfig   *config,
            const gchar           *title,
            const TsDialogPreview *preview,
            const gchar           *first_property,
            ...)
{
  PreviewSource source = { preview, config };
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
  if (preview)
    {
      /* First, as in GIMP's own filter dialogs. */
      GtkWidget *content = gtk_dialog_get_content_area (GTK_DIALOG (dialog));
      GtkWidget *widget = ts_preview_widget_new (start_preview, &source);

      gtk_box_pack_start (GTK_BOX (content), widget, FALSE, FALSE, 0);
      gtk_box_reorder_child (GTK_BOX (content), widget, 0);
    }
  ok = gimp_procedure_dialog_run (GIMP_PROCEDURE_DIALOG (dialog));
  gtk_widget_destroy (dialog);
  g_list_free (properties);
  return ok;
}
