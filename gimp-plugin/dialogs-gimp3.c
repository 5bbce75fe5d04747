/* GIMP 3's dialogs: GimpProcedureDialog builds the widgets from the
 * arguments' specs, so labels, tooltips and ranges are the registered ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdarg.h>
#include <string.h>

#include "dialogs-gimp3.h"
#include "dialog-preview.h"
#include "compat-gimp3.h"

#include <libgimp/gimpui.h>

typedef struct
{
  const TsPreviewInput *preview;
  GimpProcedureConfig  *config;
} PreviewSource;

/* A private copy of the layer in the config's `property`; NULL if none. */
static GeglBuffer *
read_layer (GimpProcedureConfig *config, const gchar *property)
{
  GimpDrawable *drawable = NULL;
  GeglBuffer *buffer = NULL;
  TsExemplar exemplar;
  gchar *message = NULL;

  if (g_object_class_find_property (G_OBJECT_GET_CLASS (config), property))
    g_object_get (config, property, &drawable, NULL);
  if (drawable && read_exemplar (drawable, FALSE, &exemplar, &message))
    {
      buffer = g_object_ref (exemplar.buffer);
      ts_exemplar_clear (&exemplar);
    }
  g_free (message);
  g_clear_object (&drawable);
  return buffer;
}

/* The widgets write every change into the config: it holds the settings
 * as the dialog shows them. */
static TsPreview *
start_preview (gpointer data)
{
  const PreviewSource *source = data;
  GObject *config = G_OBJECT (source->config);
  TsPreviewSettings settings;
  TsPreview *preview;

  memset (&settings, 0, sizeof settings);
  switch (source->preview->kind)
    {
    case TS_PREVIEW_RENDER:
    case TS_PREVIEW_LAYERS:
      g_object_get (config, "width", &settings.render.width, "height", &settings.render.height,
                    "tileable", &settings.render.tileable, "quality", &settings.render.quality,
                    "seed", &settings.render.seed, NULL);
      break;
    case TS_PREVIEW_SOLID:
      ts_solid_args_init (&settings.solid);
      g_object_get (config, "size", &settings.solid.size, "quality", &settings.solid.quality,
                    "seed", &settings.solid.seed,
                    "cell-structure", &settings.solid.cell_structure, NULL);
      break;
    case TS_PREVIEW_HEAL_SELECTION:
    case TS_PREVIEW_HEAL_TRANSPARENCY:
    case TS_PREVIEW_UNCROP:
      ts_heal_args_init (&settings.heal);
      if (source->preview->kind == TS_PREVIEW_UNCROP)
        g_object_get (config, "percent", &settings.heal.percent, NULL);
      else
        g_object_get (config, "context", &settings.heal.context,
                      "sample-from", &settings.heal.sample_from, NULL);
      g_object_get (config, "quality", &settings.heal.quality, "seed", &settings.heal.seed, NULL);
      break;
    case TS_PREVIEW_TILEABLE:
      g_object_get (config, "quality", &settings.tileable.quality,
                    "seed", &settings.tileable.seed, NULL);
      break;
    case TS_PREVIEW_GUIDED:
      ts_guided_args_init (&settings.guided);
      g_object_get (config, "guide-weight", &settings.guided.guide_weight,
                    "quality", &settings.guided.quality, "seed", &settings.guided.seed, NULL);
      /* Texture by numbers has an exemplar, its guide, blended edges and
       * tileable; style transfer only a style. */
      if (g_object_class_find_property (G_OBJECT_GET_CLASS (config), "tileable"))
        g_object_get (config, "blend-edges", &settings.guided.blend_edges,
                      "tileable", &settings.guided.tileable, NULL);
      settings.exemplar = read_layer (source->config, "exemplar");
      if (!settings.exemplar)
        settings.exemplar = read_layer (source->config, "style");
      settings.exemplar_guide = read_layer (source->config, "exemplar-guide");
      break;
    }
  preview = ts_preview_start (source->preview, &settings);
  g_clear_object (&settings.exemplar);
  g_clear_object (&settings.exemplar_guide);
  return preview;
}

gboolean
ts_dialog3 (GimpProcedure         *procedure,
            GimpProcedureConfig   *config,
            const gchar           *title,
            const TsPreviewInput  *preview,
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
      GtkWidget *widget = ts_preview_widget_new (start_preview, &source,
                                                 ts_preview_caption (preview->kind));

      gtk_box_pack_start (GTK_BOX (content), widget, FALSE, FALSE, 0);
      gtk_box_reorder_child (GTK_BOX (content), widget, 0);
    }
  ok = gimp_procedure_dialog_run (GIMP_PROCEDURE_DIALOG (dialog));
  gtk_widget_destroy (dialog);
  g_list_free (properties);
  return ok;
}
