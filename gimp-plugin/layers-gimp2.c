/* GIMP 2.10: synthesising a material set, every layer of the image with
 * the layout of one (plug-in-texsynth-render-layers).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "layers-gimp2.h"
#include "compat-gimp2.h"
#include "dialogs-gimp2.h"

/* Checks that the driving layer is one of the layers and that they all
 * have its size; NULL if fine. */
static gchar *
check_layers (const gint *ids, gint n, gint32 driver)
{
  gint width = gimp_drawable_width (driver), height = gimp_drawable_height (driver);
  gchar *message = NULL;
  gboolean found = FALSE;

  for (gint i = 0; i < n; i++)
    found = found || ids[i] == driver;
  if (!found)
    return g_strdup (_("The driving layer must be one of the image's top-level layers, "
                       "not inside a layer group."));
  for (gint i = 0; !message && i < n; i++)
    {
      gchar *name = gimp_item_get_name (ids[i]), *driver_name = gimp_item_get_name (driver);

      message = ts_layers_size_check (name, gimp_drawable_width (ids[i]),
                                      gimp_drawable_height (ids[i]), driver_name, width, height);
      g_free (name);
      g_free (driver_name);
    }
  return message;
}

static gboolean
read_set (const gint *ids, gint n, gint32 driver, TsMaterialSet *set, gchar **message)
{
  ts_material_set_init (set, n);
  for (gint i = 0; i < n; i++)
    {
      if (ids[i] == driver)
        set->driver = i;
      set->names[i] = gimp_item_get_name (ids[i]);
      set->alphas[i] = gimp_drawable_has_alpha (ids[i]);
      /* Layers are aligned by their own pixels, wherever they lie on the
       * canvas; the whole layer, whatever is selected. */
      if (!read_exemplar (ids[i], FALSE, &set->exemplars[i], message))
        return FALSE;
    }
  return TRUE;
}

gboolean
ts_run_layers2 (GimpRunMode mode, const GimpParam *params, gint n_params, Outcome *outcome)
{
  gint32 driver = params[2].data.d_drawable;
  gint32 image = gimp_item_get_image (driver);
  TsMaterialSet set = { 0, 0, NULL, NULL, NULL, NULL };
  TsRenderArgs args;
  GError *error = NULL;
  gchar *message = NULL;
  gint n = 0;
  gint *ids;

  ts_render_args_init (&args);
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != 8)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes 8 arguments (got %d)."), TS_PROC_RENDER_LAYERS,
                                      n_params));
      args.width = params[3].data.d_int32;
      args.height = params[4].data.d_int32;
      args.tileable = params[5].data.d_int32 != 0;
      args.quality = params[6].data.d_int32;
      args.seed = params[7].data.d_int32;
    }
  else
    gimp_get_data (TS_PROC_RENDER_LAYERS, &args);

  ids = gimp_image_get_layers (image, &n);
  if (!ids || n < 1)
    {
      g_free (ids);
      return fail (outcome, GIMP_PDB_CALLING_ERROR, g_strdup (_("The image has no layers.")));
    }
  if ((message = check_layers (ids, n, driver)))
    {
      g_free (ids);
      return fail (outcome, GIMP_PDB_CALLING_ERROR, message);
    }
  /* Before the dialog: its preview grows the driving layer. */
  if (!read_set (ids, n, driver, &set, &message))
    {
      g_free (ids);
      ts_material_set_clear (&set);
      return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
    }
  g_free (ids);
  if (mode == GIMP_RUN_INTERACTIVE)
    {
      if (args.width < 1)
        {
          args.width = MIN (2 * gimp_drawable_width (driver), TS_PLUGIN_MAX_SIDE);
          args.height = MIN (2 * gimp_drawable_height (driver), TS_PLUGIN_MAX_SIDE);
        }
      args.seed = ts_plugin_random_seed ();
      if (!ts_layers_dialog2 (&args, &set.exemplars[set.driver]))
        {
          ts_material_set_clear (&set);
          return fail (outcome, GIMP_PDB_CANCEL, NULL);
        }
    }
  if ((message = ts_render_args_check (&args)))
    {
      ts_material_set_clear (&set);
      return fail (outcome, GIMP_PDB_CALLING_ERROR, message);
    }
  if (gimp_drawable_is_indexed (driver))
    g_message (_("The exemplar is indexed: the new image is RGB."));

  gimp_progress_init (_("Synthesising the layers with one layout"));
  if (!ts_plugin_render_layers (&set, &args, &error))
    {
      ts_material_set_clear (&set);
      fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (error->message));
      g_error_free (error);
      return FALSE;
    }
  outcome->new_image = new_image (&set.exemplars[set.driver], set.results,
                                  (const gchar **) set.names, set.alphas, set.n);
  ts_material_set_clear (&set);
  return finish_with_image (outcome, mode, TS_PROC_RENDER_LAYERS, &args, sizeof args);
}
