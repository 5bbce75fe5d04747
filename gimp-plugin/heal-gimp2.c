/* GIMP 2.10: the heal procedures (heal selection, heal transparency,
 * uncrop) around texsynth:heal.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "heal-gimp2.h"
#include "compat-gimp2.h"
#include "dialogs-gimp2.h"

/* What the dialog's preview heals (ts_heal_preview_read). */
static gboolean
read_preview (gint32 drawable, gint32 image, const gchar *name, TsPreviewInput *input)
{
  GeglRectangle hole;
  gboolean over = !gimp_selection_is_empty (image) &&
                  gimp_drawable_mask_intersect (drawable, &hole.x, &hole.y, &hole.width,
                                                &hole.height);
  TsHealLayer layer = {
    .buffer = gimp_drawable_get_buffer (drawable),
    .format = gimp_drawable_get_format (drawable),
    .width = gimp_drawable_width (drawable), .height = gimp_drawable_height (drawable),
    .selection = gimp_drawable_get_buffer (gimp_image_get_selection (image)),
  };
  gboolean read;

  gimp_drawable_offsets (drawable, &layer.offset_x, &layer.offset_y);
  read = ts_heal_preview_read (&layer, name, over ? &hole : NULL, gimp_image_width (image),
                               gimp_image_height (image), input);
  g_object_unref (layer.buffer);
  g_object_unref (layer.selection);
  return read;
}

/* The three heal procedures: read the layer (and the selection over it),
 * run texsynth:heal, write the result back as one undo step. */
gboolean
ts_run_heal2 (const gchar *name, GimpRunMode mode, const GimpParam *params, gint n_params,
              Outcome *outcome)
{
  gint32 drawable = params[2].data.d_drawable;
  gint32 image = gimp_item_get_image (drawable);
  gboolean uncrop = g_str_equal (name, TS_PROC_UNCROP);
  gboolean selection = g_str_equal (name, TS_PROC_HEAL_SELECTION);
  gint expected = uncrop ? 6 : 7, x, y, dx, dy;
  TsHealArgs args;
  TsHealLayer layer;
  GeglBuffer *result = NULL, *shadow;
  GeglRectangle rect;
  gboolean healed, written;
  GError *error = NULL;
  gchar *message;

  ts_heal_args_init (&args);
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != expected)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes %d arguments (got %d)."), name, expected, n_params));
      if (uncrop)
        args.percent = params[3].data.d_int32;
      else
        {
          args.context = params[3].data.d_int32;
          args.sample_from = params[4].data.d_int32;
        }
      args.quality = params[expected - 2].data.d_int32;
      args.seed = params[expected - 1].data.d_int32;
    }
  else
    gimp_get_data (name, &args);
  if (mode == GIMP_RUN_INTERACTIVE)
    {
      TsPreviewInput preview;
      gboolean ok, previewed = read_preview (drawable, image, name, &preview);

      args.seed = ts_plugin_random_seed ();
      ok = ts_heal_dialog2 (&args, name, uncrop ? _("Uncrop by Synthesis")
                                         : selection ? _("Heal Selection by Synthesis")
                                                     : _("Heal Transparency by Synthesis"),
                            previewed ? &preview : NULL);
      g_clear_object (&preview.pixels);
      g_clear_object (&preview.mask);
      if (!ok)
        return fail (outcome, GIMP_PDB_CANCEL, NULL);
    }
  if ((message = ts_heal_args_check (&args)))
    return fail (outcome, GIMP_PDB_CALLING_ERROR, message);
  if (selection && gimp_selection_is_empty (image))
    return fail (outcome, GIMP_PDB_CALLING_ERROR,
                 g_strdup (_("There is no selection: select what to heal.")));
  if (!selection && !uncrop && !gimp_drawable_has_alpha (drawable))
    return fail (outcome, GIMP_PDB_CALLING_ERROR,
                 g_strdup (_("The layer has no alpha channel: there is no transparency to heal.")));

  /* Uncrop: the layer with a transparent border of `percent` of the
   * image's sides, healed before GIMP is touched. */
  dx = uncrop ? MAX (1, gimp_image_width (image) * args.percent / 100) : 0;
  dy = uncrop ? MAX (1, gimp_image_height (image) * args.percent / 100) : 0;
  gimp_drawable_offsets (drawable, &x, &y);
  layer = (TsHealLayer) {
    .buffer = gimp_drawable_get_buffer (drawable),
    .format = gimp_drawable_get_format (drawable),
    .width = gimp_drawable_width (drawable), .height = gimp_drawable_height (drawable),
    .is_gray = gimp_drawable_is_gray (drawable),
    .selection = selection ? gimp_drawable_get_buffer (gimp_image_get_selection (image)) : NULL,
    .offset_x = x, .offset_y = y, .border_x = dx, .border_y = dy,
  };
  healed = ts_plugin_heal_layer (&layer, &args, &result, &error);
  g_object_unref (layer.buffer);
  g_clear_object (&layer.selection);
  if (!healed)
    {
      fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (error->message));
      g_error_free (error);
      return FALSE;
    }
  rect = (GeglRectangle) { 0, 0, layer.width, layer.height };

  /* Only now is the image changed, as one undo step. */
  gimp_image_undo_group_start (image);
  if (uncrop)
    {
      gimp_image_resize (image, gimp_image_width (image) + 2 * dx,
                         gimp_image_height (image) + 2 * dy, dx, dy);
      if (!gimp_drawable_has_alpha (drawable))
        gimp_layer_add_alpha (drawable);
      gimp_layer_resize (drawable, rect.width + 2 * dx, rect.height + 2 * dy, dx, dy);
      rect.width += 2 * dx;
      rect.height += 2 * dy;
    }
  shadow = gimp_drawable_get_shadow_buffer (drawable);
  written = ts_plugin_transfer (result, &rect, shadow, 0, 0, gimp_drawable_get_format (drawable));
  g_object_unref (shadow);
  if (written)
    {
      gimp_drawable_merge_shadow (drawable, TRUE);
      gimp_drawable_update (drawable, 0, 0, rect.width, rect.height);
    }
  gimp_image_undo_group_end (image);
  g_object_unref (result);
  if (!written)
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));
  if (mode != GIMP_RUN_NONINTERACTIVE)
    {
      gimp_set_data (name, &args, sizeof args);
      gimp_displays_flush ();
    }
  return TRUE;
}
