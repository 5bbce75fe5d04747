/* GIMP 3: texture by numbers and style transfer around texsynth:guided.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "guided-gimp3.h"
#include "guided-plugin.h"
#include "compat-gimp3.h"
#include "dialogs-gimp3.h"

/* NULL if `drawable` is a layer, else a copy of `message`. */
static gchar *
check_layer (GimpDrawable *drawable, const gchar *message)
{
  return drawable && GIMP_IS_LAYER (drawable) ? NULL : g_strdup (message);
}

/* A new layer for `result` above `target`, at its place, with alpha if
 * the exemplar has it, as one undo step; NULL if out of memory. */
static GimpLayer *
add_result_layer (GimpDrawable *target, GeglBuffer *result, gboolean alpha)
{
  GimpImage *image = gimp_item_get_image (GIMP_ITEM (target));
  gboolean gray = gimp_image_get_base_type (image) == GIMP_GRAY;
  GimpImageType type = gray ? (alpha ? GIMP_GRAYA_IMAGE : GIMP_GRAY_IMAGE)
                            : (alpha ? GIMP_RGBA_IMAGE : GIMP_RGB_IMAGE);
  const GeglRectangle *extent = gegl_buffer_get_extent (result);
  GimpItem *parent = gimp_item_get_parent (GIMP_ITEM (target));
  GimpLayer *layer;
  GeglBuffer *buffer;
  gboolean written;
  gint x, y;

  gimp_image_undo_group_start (image);
  if (gimp_image_get_base_type (image) == GIMP_INDEXED)
    {
      g_message (_("The image is indexed: it is converted to RGB first."));
      gimp_image_convert_rgb (image);
    }
  layer = gimp_layer_new (image, _("Texture by numbers"), extent->width, extent->height, type,
                          100.0, GIMP_LAYER_MODE_NORMAL);
  gimp_drawable_get_offsets (target, &x, &y);
  gimp_image_insert_layer (image, layer, parent ? GIMP_LAYER (parent) : NULL,
                           gimp_image_get_item_position (image, GIMP_ITEM (target)));
  gimp_layer_set_offsets (layer, x, y);
  buffer = gimp_drawable_get_buffer (GIMP_DRAWABLE (layer));
  written = ts_plugin_transfer (result, extent, buffer, 0, 0,
                                gimp_drawable_get_format (GIMP_DRAWABLE (layer)));
  g_object_unref (buffer);
  gimp_drawable_update (GIMP_DRAWABLE (layer), 0, 0, extent->width, extent->height);
  gimp_image_undo_group_end (image);
  return written ? layer : NULL;
}

static GimpValueArray *
run_guided (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image G_GNUC_UNUSED,
            GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  gboolean by_numbers = g_str_equal (gimp_procedure_get_name (procedure), TS_PROC_BY_NUMBERS);
  GimpDrawable *target, *exemplar_layer = NULL, *guide_layer = NULL;
  TsExemplar exemplar, guide, target_copy;
  TsGuidedArgs args;
  GeglBuffer *result = NULL;
  GimpLayer *layer = NULL;
  GimpValueArray *values;
  GError *error = NULL;
  gchar *message;
  gboolean ok;

  if ((message = check_drawables (drawables, 1)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  if ((message = ts_plugin_check_ops (TS_OP_GUIDED, NULL)))
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
  target = drawables[0];
  if (mode == GIMP_RUN_INTERACTIVE)
    {
      GeglBuffer *buffer = gimp_drawable_get_buffer (target);
      TsPreviewInput preview = { .kind = TS_PREVIEW_GUIDED, .ratio = 1.0 };
      const TsPreviewInput *shown;

      /* The preview paints the target's middle, at the result's scale. */
      preview.pixels = ts_preview_copy (buffer, TS_PREVIEW_SIDE, FALSE, &preview.ratio);
      g_object_unref (buffer);
      shown = preview.pixels ? &preview : NULL;
      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      ok = by_numbers ? ts_dialog3 (procedure, config, _("Texture by Numbers"), shown,
                                    "exemplar", "exemplar-guide", "guide-weight", "blend-edges",
                                    "tileable", "quality", "seed", NULL)
                      : ts_dialog3 (procedure, config, _("Style Transfer by Synthesis"), shown,
                                    "style", "guide-weight", "quality", "seed", NULL);
      g_clear_object (&preview.pixels);
      if (!ok)
        return failure (procedure, GIMP_PDB_CANCEL, NULL);
    }
  ts_guided_args_init (&args);
  g_object_get (config, by_numbers ? "exemplar" : "style", &exemplar_layer,
                "guide-weight", &args.guide_weight, "quality", &args.quality,
                "seed", &args.seed, NULL);
  if (by_numbers)
    g_object_get (config, "exemplar-guide", &guide_layer, "blend-edges", &args.blend_edges,
                  "tileable", &args.tileable, NULL);
  message = ts_guided_args_check (&args);
  if (!message)
    message = check_layer (exemplar_layer, by_numbers ? _("The exemplar must be a layer.")
                                                      : _("The style must be a layer."));
  if (!message && by_numbers)
    message = check_layer (guide_layer, _("The exemplar's guide must be a layer."));
  if (!message && by_numbers)
    message = ts_guides_size_check (gimp_item_get_name (GIMP_ITEM (exemplar_layer)),
                                    gimp_drawable_get_width (exemplar_layer),
                                    gimp_drawable_get_height (exemplar_layer),
                                    gimp_item_get_name (GIMP_ITEM (guide_layer)),
                                    gimp_drawable_get_width (guide_layer),
                                    gimp_drawable_get_height (guide_layer));
  if (message)
    {
      g_clear_object (&exemplar_layer);
      g_clear_object (&guide_layer);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
    }

  memset (&guide, 0, sizeof guide);
  memset (&target_copy, 0, sizeof target_copy);
  ok = read_exemplar (exemplar_layer, FALSE, &exemplar, &message);
  if (ok && by_numbers)
    ok = read_exemplar (guide_layer, FALSE, &guide, &message);
  if (ok)
    ok = read_exemplar (target, FALSE, &target_copy, &message);
  g_clear_object (&exemplar_layer);
  g_clear_object (&guide_layer);
  if (ok)
    {
      gimp_progress_init (by_numbers ? _("Painting texture by numbers")
                                     : _("Transferring the style"));
      ok = ts_plugin_guided (&exemplar, by_numbers ? guide.buffer : NULL, target_copy.buffer,
                             &args, &result, &error);
      if (!ok)
        {
          message = g_strdup (error->message);
          g_error_free (error);
        }
    }
  ts_exemplar_clear (&guide);
  ts_exemplar_clear (&target_copy);
  if (!ok)
    {
      ts_exemplar_clear (&exemplar);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }

  /* Only now is the image changed: a cancelled run leaves it as it was. */
  if (by_numbers)
    ok = (layer = add_result_layer (target, result, exemplar.has_alpha)) != NULL;
  else
    ok = ts_replace_layer_pixels3 (target, result);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  if (!ok)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));
  if (mode == GIMP_RUN_INTERACTIVE)
    gimp_displays_flush ();
  values = gimp_procedure_new_return_values (procedure, GIMP_PDB_SUCCESS, NULL);
  if (layer)
    GIMP_VALUES_SET_LAYER (values, 1, layer);
  return values;
}

GList *
ts_guided_names3 (GList *names)
{
  names = g_list_append (names, g_strdup (TS_PROC_BY_NUMBERS));
  return g_list_append (names, g_strdup (TS_PROC_STYLE));
}

GimpProcedure *
ts_guided_procedure3 (GimpPlugIn *plug_in, const gchar *name)
{
  gboolean by_numbers = g_str_equal (name, TS_PROC_BY_NUMBERS);
  GimpProcedure *procedure;

  if (!by_numbers && !g_str_equal (name, TS_PROC_STYLE))
    return NULL;
  procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN, run_guided,
                                        NULL, NULL);
  if (by_numbers)
    ts_describe3 (procedure, _("Texture by _Numbers..."), "<Image>/Filters/Map",
                  _("Paint a texture along a drawn layout (texture by numbers)"),
                  _("Runs the texsynth:guided GEGL operation: the exemplar's texture is laid "
                    "out as the selected layer (the target guide) says, where the exemplar's "
                    "guide tells which part of the exemplar each guide colour or value stands "
                    "for. The result is a new layer above the target guide, of its size. "
                    "Undoable."));
  else
    ts_describe3 (procedure, _("_Style Transfer by Synthesis..."), "<Image>/Filters/Map",
                  _("Repaint the layer with the texture of another (style transfer)"),
                  _("Runs the texsynth:guided GEGL operation with the layer's lightness as the "
                    "guide: the layer keeps its light and shade, made of the style layer's "
                    "texture. Undoable."));
  gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE);
  gimp_procedure_add_drawable_argument (procedure, by_numbers ? "exemplar" : "style",
                                        ts_arg_label (by_numbers ? "exemplar" : "style"),
                                        ts_arg_tooltip (by_numbers ? "exemplar" : "style"),
                                        TRUE, G_PARAM_READWRITE);
  if (by_numbers)
    gimp_procedure_add_drawable_argument (procedure, "exemplar-guide",
                                          ts_arg_label ("exemplar-guide"),
                                          ts_arg_tooltip ("exemplar-guide"), TRUE,
                                          G_PARAM_READWRITE);
  gimp_procedure_add_double_argument (procedure, "guide-weight",
                                      ts_arg_label (by_numbers ? "guide-weight" : "style-weight"),
                                      ts_arg_tooltip (by_numbers ? "guide-weight" : "style-weight"),
                                      0.0, TS_PLUGIN_MAX_GUIDE_WEIGHT,
                                      TS_PLUGIN_DEFAULT_GUIDE_WEIGHT, G_PARAM_READWRITE);
  if (by_numbers)
    gimp_procedure_add_boolean_argument (procedure, "blend-edges", ts_arg_label ("blend-edges"),
                                         ts_arg_tooltip ("blend-edges"), FALSE,
                                         G_PARAM_READWRITE);
  if (by_numbers)
    gimp_procedure_add_boolean_argument (procedure, "tileable", ts_arg_label ("tileable"),
                                         ts_arg_tooltip ("tileable"), FALSE, G_PARAM_READWRITE);
  ts_add_quality_and_seed3 (procedure, "quality");
  if (by_numbers)
    gimp_procedure_add_layer_return_value (procedure, "new-layer", _("New layer"),
                                           _("The new layer, above the target guide"), FALSE,
                                           G_PARAM_READWRITE);
  return procedure;
}
