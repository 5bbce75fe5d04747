/* GIMP 3: the heal procedures (heal selection, heal transparency, uncrop)
 * around texsynth:heal.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "heal-gimp3.h"
#include "compat-gimp3.h"
#include "dialogs-gimp3.h"

/* What the dialog's preview heals (ts_heal_preview_read). */
static gboolean
read_preview (GimpDrawable *drawable, GimpImage *image, const gchar *name,
              TsPreviewInput *input)
{
  GeglRectangle hole;
  gboolean over = !gimp_selection_is_empty (image) &&
                  gimp_drawable_mask_intersect (drawable, &hole.x, &hole.y, &hole.width,
                                                &hole.height);
  TsHealLayer layer = {
    .buffer = gimp_drawable_get_buffer (drawable),
    .format = gimp_drawable_get_format (drawable),
    .width = gimp_drawable_get_width (drawable), .height = gimp_drawable_get_height (drawable),
    .selection = gimp_drawable_get_buffer (GIMP_DRAWABLE (gimp_image_get_selection (image))),
  };
  gboolean read;

  gimp_drawable_get_offsets (drawable, &layer.offset_x, &layer.offset_y);
  read = ts_heal_preview_read (&layer, name, over ? &hole : NULL, gimp_image_get_width (image),
                               gimp_image_get_height (image), input);
  g_object_unref (layer.buffer);
  g_object_unref (layer.selection);
  return read;
}

/* The three heal procedures: read the layer (and the selection over it),
 * run texsynth:heal, write the result back as one undo step; for uncrop
 * the layer with a transparent border is healed before GIMP is touched. */
GimpValueArray *
ts_run_heal3 (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image,
              GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  const gchar *name = gimp_procedure_get_name (procedure);
  gboolean uncrop = g_str_equal (name, TS_PROC_UNCROP);
  gboolean selection = g_str_equal (name, TS_PROC_HEAL_SELECTION);
  TsHealArgs args;
  GimpDrawable *drawable;
  TsHealLayer layer;
  GeglBuffer *result = NULL, *shadow;
  GeglRectangle rect;
  GError *error = NULL;
  gchar *message;
  gint x, y, dx, dy;
  gboolean ok;

  if ((message = check_drawables (drawables, 1)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  drawable = drawables[0];
  if (mode == GIMP_RUN_INTERACTIVE)
    {
      TsPreviewInput preview;
      gboolean previewed = read_preview (drawable, image, name, &preview);

      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      ok = uncrop ? ts_dialog3 (procedure, config, _("Uncrop by Synthesis"),
                                previewed ? &preview : NULL, "percent", "quality", "seed", NULL)
                  : ts_dialog3 (procedure, config,
                                selection ? _("Heal Selection by Synthesis")
                                          : _("Heal Transparency by Synthesis"),
                                previewed ? &preview : NULL,
                                "context", "sample-from", "quality", "seed", NULL);
      g_clear_object (&preview.pixels);
      g_clear_object (&preview.mask);
      if (!ok)
        return failure (procedure, GIMP_PDB_CANCEL, NULL);
    }
  ts_heal_args_init (&args);
  if (uncrop)
    g_object_get (config, "percent", &args.percent, NULL);
  else
    g_object_get (config, "context", &args.context, "sample-from", &args.sample_from, NULL);
  g_object_get (config, "quality", &args.quality, "seed", &args.seed, NULL);
  if ((message = ts_heal_args_check (&args)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  if (selection && gimp_selection_is_empty (image))
    return failure (procedure, GIMP_PDB_CALLING_ERROR,
                    g_strdup (_("There is no selection: select what to heal.")));
  if (!selection && !uncrop && !gimp_drawable_has_alpha (drawable))
    return failure (procedure, GIMP_PDB_CALLING_ERROR,
                    g_strdup (_("The layer has no alpha channel: there is no transparency to heal.")));

  /* Uncrop: the layer with a transparent border of `percent` of the
   * image's sides, healed before GIMP is touched. */
  dx = uncrop ? MAX (1, gimp_image_get_width (image) * args.percent / 100) : 0;
  dy = uncrop ? MAX (1, gimp_image_get_height (image) * args.percent / 100) : 0;
  gimp_drawable_get_offsets (drawable, &x, &y);
  layer = (TsHealLayer) {
    .buffer = gimp_drawable_get_buffer (drawable),
    .format = gimp_drawable_get_format (drawable),
    .width = gimp_drawable_get_width (drawable), .height = gimp_drawable_get_height (drawable),
    .is_gray = gimp_drawable_is_gray (drawable),
    .selection = selection ? gimp_drawable_get_buffer (GIMP_DRAWABLE (gimp_image_get_selection (image)))
                           : NULL,
    .offset_x = x, .offset_y = y, .border_x = dx, .border_y = dy,
  };
  ok = ts_plugin_heal_layer (&layer, &args, &result, &error);
  g_object_unref (layer.buffer);
  g_clear_object (&layer.selection);
  if (!ok)
    {
      message = g_strdup (error->message);
      g_error_free (error);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }
  rect = (GeglRectangle) { 0, 0, layer.width, layer.height };

  /* Only now is the image changed, as one undo step. */
  gimp_image_undo_group_start (image);
  if (uncrop)
    {
      gimp_image_resize (image, gimp_image_get_width (image) + 2 * dx,
                         gimp_image_get_height (image) + 2 * dy, dx, dy);
      if (!gimp_drawable_has_alpha (drawable))
        gimp_layer_add_alpha (GIMP_LAYER (drawable));
      gimp_layer_resize (GIMP_LAYER (drawable), rect.width + 2 * dx, rect.height + 2 * dy, dx, dy);
      rect.width += 2 * dx;
      rect.height += 2 * dy;
    }
  shadow = gimp_drawable_get_shadow_buffer (drawable);
  ok = ts_plugin_transfer (result, &rect, shadow, 0, 0, gimp_drawable_get_format (drawable));
  g_object_unref (shadow);
  if (ok)
    {
      gimp_drawable_merge_shadow (drawable, TRUE);
      gimp_drawable_update (drawable, 0, 0, rect.width, rect.height);
    }
  gimp_image_undo_group_end (image);
  g_object_unref (result);
  if (!ok)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));
  if (mode == GIMP_RUN_INTERACTIVE)
    gimp_displays_flush ();
  return gimp_procedure_new_return_values (procedure, GIMP_PDB_SUCCESS, NULL);
}
