/* GIMP 3: synthesising a material set, every layer of the image with the
 * layout of one (plug-in-texsynth-render-layers).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "layers-gimp3.h"
#include "compat-gimp3.h"
#include "dialogs-gimp3.h"

/* Checks that the driving layer is one of the layers and that they all
 * have its size; NULL if fine. */
static gchar *
check_layers (GimpLayer **layers, GimpDrawable *driver)
{
  gint width = gimp_drawable_get_width (driver), height = gimp_drawable_get_height (driver);
  gchar *message = NULL;
  gboolean found = FALSE;

  for (gint i = 0; layers[i]; i++)
    found = found || GIMP_DRAWABLE (layers[i]) == driver;
  if (!found)
    return g_strdup (_("The driving layer must be one of the image's top-level layers, "
                       "not inside a layer group."));
  for (gint i = 0; !message && layers[i]; i++)
    {
      GimpDrawable *layer = GIMP_DRAWABLE (layers[i]);
      gchar *name = gimp_item_get_name (GIMP_ITEM (layer));
      gchar *driver_name = gimp_item_get_name (GIMP_ITEM (driver));

      message = ts_layers_size_check (name, gimp_drawable_get_width (layer),
                                      gimp_drawable_get_height (layer), driver_name, width, height);
      g_free (name);
      g_free (driver_name);
    }
  return message;
}

static gboolean
read_set (GimpLayer **layers, GimpDrawable *driver, TsMaterialSet *set, gchar **message)
{
  gint n = 0;

  while (layers[n])
    n++;
  ts_material_set_init (set, n);
  for (gint i = 0; i < n; i++)
    {
      GimpDrawable *layer = GIMP_DRAWABLE (layers[i]);

      if (layer == driver)
        set->driver = i;
      set->names[i] = gimp_item_get_name (GIMP_ITEM (layer));
      set->alphas[i] = gimp_drawable_has_alpha (layer);
      /* Layers are aligned by their own pixels, wherever they lie on the
       * canvas; the whole layer, whatever is selected. */
      if (!read_exemplar (layer, FALSE, &set->exemplars[i], message))
        return FALSE;
    }
  return TRUE;
}

GimpValueArray *
ts_run_layers3 (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image,
                GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  TsMaterialSet set = { 0, 0, NULL, NULL, NULL, NULL };
  TsRenderArgs args;
  GimpDrawable *driver;
  GimpLayer **layers;
  GimpImage *output;
  GError *error = NULL;
  gchar *message;

  if ((message = check_drawables (drawables, 1)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  driver = drawables[0];
  layers = gimp_image_get_layers (image);
  if (!layers || !layers[0])
    {
      g_free (layers);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, g_strdup (_("The image has no layers.")));
    }
  if ((message = check_layers (layers, driver)))
    {
      g_free (layers);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
    }
  /* Before the dialog: its preview grows the driving layer. */
  if (!read_set (layers, driver, &set, &message))
    {
      g_free (layers);
      ts_material_set_clear (&set);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }
  g_free (layers);

  if (mode == GIMP_RUN_INTERACTIVE)
    {
      TsPreviewInput preview = { .kind = TS_PREVIEW_LAYERS,
                                 .exemplars = &set.exemplars[set.driver], .n_exemplars = 1 };
      gboolean size_chosen;

      /* Twice the driving layer until the user has chosen a size once. */
      g_object_get (config, "size-chosen", &size_chosen, NULL);
      if (!size_chosen)
        g_object_set (config,
                      "width", MIN (2 * gimp_drawable_get_width (driver), TS_PLUGIN_MAX_SIDE),
                      "height", MIN (2 * gimp_drawable_get_height (driver), TS_PLUGIN_MAX_SIDE),
                      NULL);
      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      if (!ts_dialog3 (procedure, config, _("Texture Synthesis of All Layers"), &preview,
                       "width", "height", "tileable", "quality", "seed", NULL))
        {
          ts_material_set_clear (&set);
          return failure (procedure, GIMP_PDB_CANCEL, NULL);
        }
      g_object_set (config, "size-chosen", TRUE, NULL);
    }
  g_object_get (config, "width", &args.width, "height", &args.height,
                "tileable", &args.tileable, "quality", &args.quality, "seed", &args.seed, NULL);
  if ((message = ts_render_args_check (&args)))
    {
      ts_material_set_clear (&set);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
    }
  if (gimp_drawable_is_indexed (driver))
    g_message (_("The exemplar is indexed: the new image is RGB."));

  gimp_progress_init (_("Synthesising the layers with one layout"));
  if (!ts_plugin_render_layers (&set, &args, &error))
    {
      ts_material_set_clear (&set);
      message = g_strdup (error->message);
      g_error_free (error);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }
  output = new_image (&set.exemplars[set.driver], set.results, (const gchar **) set.names,
                      set.alphas, set.n);
  ts_material_set_clear (&set);
  if (!output)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Could not make the new image.")));
  return success_with_image (procedure, mode, output);
}
