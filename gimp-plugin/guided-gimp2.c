/* GIMP 2.10: texture by numbers and style transfer around
 * texsynth:guided.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "guided-gimp2.h"
#include "guided-plugin.h"
#include "dialogs-gimp2.h"

#define AUTHOR    "texsynth contributors"
#define COPYRIGHT "texsynth contributors (GPL-3.0-or-later)"
#define DATE      "2026"

/* The last values of an interactive run: the arguments and the layers
 * picked (layer IDs, valid only while GIMP runs). */
typedef struct
{
  TsGuidedArgs args;
  gint32       exemplar;
  gint32       guide;
} LastValues;

void
ts_install_guided2 (void)
{
  static const GimpParamDef by_numbers_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode",       "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",          "Image of the target guide" },
    { GIMP_PDB_DRAWABLE, "drawable",       "Target guide: the layout to paint, e.g. a label map" },
    { GIMP_PDB_DRAWABLE, "exemplar",       "Exemplar: the texture (or textures) to paint with" },
    { GIMP_PDB_DRAWABLE, "exemplar-guide", "The exemplar's guide, of the exemplar's size and aligned with it" },
    { GIMP_PDB_FLOAT,    "guide-weight",   "How much following the guides counts against a coherent texture (0-100, default 1; 0 ignores the guides)" },
    { GIMP_PDB_INT32,    "blend-edges",    "Blend the textures across label edges in one synthesis of the whole image (TRUE), or grow each label's area from its own texture and cut it at the label's edges (FALSE)" },
    { GIMP_PDB_INT32,    "tileable",       "Make the result tile seamlessly (TRUE or FALSE)" },
    { GIMP_PDB_INT32,    "quality",        "Candidates compared per pixel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",           "Random seed (0 or more)" },
  };
  static const GimpParamDef style_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode",     "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",        "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable",     "Layer to restyle in place" },
    { GIMP_PDB_DRAWABLE, "style",        "Style: the layer whose texture repaints it" },
    { GIMP_PDB_FLOAT,    "guide-weight", "How much keeping the layer's light and shade counts against a coherent texture (0-100, default 1; 0 ignores the layer)" },
    { GIMP_PDB_INT32,    "quality",      "Candidates compared per pixel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",         "Random seed (0 or more)" },
  };
  static const GimpParamDef layer_return[] =
  {
    { GIMP_PDB_LAYER, "new-layer", "The new layer, above the target guide" },
  };

  gimp_install_procedure (TS_PROC_BY_NUMBERS,
                          N_("Paint a texture along a drawn layout (texture by numbers)"),
                          "Runs the texsynth:guided GEGL operation: the exemplar's texture is "
                          "laid out as the active layer (the target guide) says, where the "
                          "exemplar's guide tells which part of the exemplar each guide colour "
                          "or value stands for. The result is a new layer above the target "
                          "guide, of its size. Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("Texture by _Numbers..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (by_numbers_args), G_N_ELEMENTS (layer_return),
                          by_numbers_args, layer_return);
  gimp_plugin_menu_register (TS_PROC_BY_NUMBERS, "<Image>/Filters/Map");

  gimp_install_procedure (TS_PROC_STYLE,
                          N_("Repaint the layer with the texture of another (style transfer)"),
                          "Runs the texsynth:guided GEGL operation with the layer's lightness "
                          "as the guide: the layer keeps its light and shade, made of the "
                          "style layer's texture. Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("_Style Transfer by Synthesis..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (style_args), 0, style_args, NULL);
  gimp_plugin_menu_register (TS_PROC_STYLE, "<Image>/Filters/Map");
}

/* The arguments of a run in `mode`: from the call, or the last values
 * (then, interactive, from the dialog). FALSE with the outcome set if
 * there are none. */
static gboolean
read_arguments (const gchar *name, GimpRunMode mode, const GimpParam *params, gint n_params,
                gint32 target, LastValues *last, Outcome *outcome)
{
  gboolean by_numbers = g_str_equal (name, TS_PROC_BY_NUMBERS);
  gint expected = by_numbers ? 10 : 7, next = 3;
  TsPreviewInput preview = { .kind = TS_PREVIEW_GUIDED, .ratio = 1.0 };
  GeglBuffer *buffer;
  gboolean ok;

  ts_guided_args_init (&last->args);
  last->exemplar = last->guide = -1;
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != expected)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes %d arguments (got %d)."), name, expected, n_params));
      last->exemplar = params[next++].data.d_drawable;
      if (by_numbers)
        last->guide = params[next++].data.d_drawable;
      last->args.guide_weight = params[next++].data.d_float;
      if (by_numbers)
        {
          last->args.blend_edges = params[next++].data.d_int32 != 0;
          last->args.tileable = params[next++].data.d_int32 != 0;
        }
      last->args.quality = params[next++].data.d_int32;
      last->args.seed = params[next].data.d_int32;
      return TRUE;
    }
  if (gimp_get_data_size (name) == (gint) sizeof *last)
    gimp_get_data (name, last);
  if (mode != GIMP_RUN_INTERACTIVE)
    return TRUE;
  /* Layers closed since are picked anew. */
  if (!gimp_item_is_valid (last->exemplar) || last->exemplar == target)
    last->exemplar = -1;
  if (!gimp_item_is_valid (last->guide) || last->guide == target)
    last->guide = -1;
  last->args.seed = ts_plugin_random_seed ();
  buffer = gimp_drawable_get_buffer (target);
  /* The preview paints the target's middle, at the result's scale. */
  preview.pixels = ts_preview_copy (buffer, TS_PREVIEW_SIDE, FALSE, &preview.ratio);
  g_object_unref (buffer);
  ok = ts_guided_dialog2 (name, &last->args, target, &last->exemplar,
                          by_numbers ? &last->guide : NULL, preview.pixels ? &preview : NULL);
  g_clear_object (&preview.pixels);
  if (!ok)
    return fail (outcome, GIMP_PDB_CANCEL, NULL);
  return TRUE;
}

/* NULL if `id` is a layer, else a copy of `message`. */
static gchar *
check_layer (gint32 id, const gchar *message)
{
  if (id >= 0 && gimp_item_is_valid (id) && gimp_item_is_layer (id))
    return NULL;
  return g_strdup (message);
}

/* A new layer for `result` above `target`, at its place, with alpha if
 * the exemplar has it, as one undo step; -1 if out of memory. */
static gint32
add_result_layer (gint32 target, GeglBuffer *result, gboolean alpha)
{
  gint32 image = gimp_item_get_image (target);
  gboolean gray = gimp_image_base_type (image) == GIMP_GRAY;
  GimpImageType type = gray ? (alpha ? GIMP_GRAYA_IMAGE : GIMP_GRAY_IMAGE)
                            : (alpha ? GIMP_RGBA_IMAGE : GIMP_RGB_IMAGE);
  const GeglRectangle *extent = gegl_buffer_get_extent (result);
  gint32 layer;
  GeglBuffer *buffer;
  gboolean written;
  gint x, y;

  gimp_image_undo_group_start (image);
  if (gimp_image_base_type (image) == GIMP_INDEXED)
    {
      g_message (_("The image is indexed: it is converted to RGB first."));
      gimp_image_convert_rgb (image);
    }
  layer = gimp_layer_new (image, _("Texture by numbers"), extent->width, extent->height, type,
                          100.0, GIMP_LAYER_MODE_NORMAL);
  gimp_drawable_offsets (target, &x, &y);
  gimp_image_insert_layer (image, layer, gimp_item_get_parent (target),
                           gimp_image_get_item_position (image, target));
  gimp_layer_set_offsets (layer, x, y);
  buffer = gimp_drawable_get_buffer (layer);
  written = ts_plugin_transfer (result, extent, buffer, 0, 0, gimp_drawable_get_format (layer));
  g_object_unref (buffer);
  gimp_drawable_update (layer, 0, 0, extent->width, extent->height);
  gimp_image_undo_group_end (image);
  return written ? layer : -1;
}

gboolean
ts_run_guided2 (const gchar *name, GimpRunMode mode, const GimpParam *params, gint n_params,
                Outcome *outcome)
{
  gboolean by_numbers = g_str_equal (name, TS_PROC_BY_NUMBERS);
  gint32 target = params[2].data.d_drawable;
  TsExemplar exemplar, guide, target_copy;
  LastValues last;
  GeglBuffer *result = NULL;
  GError *error = NULL;
  gchar *message = NULL;
  gboolean ok;

  if (!by_numbers && !g_str_equal (name, TS_PROC_STYLE))
    return FALSE;
  if ((message = ts_plugin_check_ops (TS_OP_GUIDED, NULL)))
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
  if (!read_arguments (name, mode, params, n_params, target, &last, outcome))
    return FALSE;
  if ((message = ts_guided_args_check (&last.args))
      || (message = check_layer (last.exemplar, by_numbers ? _("The exemplar must be a layer.")
                                                           : _("The style must be a layer.")))
      || (by_numbers && (message = check_layer (last.guide, _("The exemplar's guide must be a layer."))))
      || (by_numbers && (message = ts_guides_size_check (
                           gimp_item_get_name (last.exemplar), gimp_drawable_width (last.exemplar),
                           gimp_drawable_height (last.exemplar), gimp_item_get_name (last.guide),
                           gimp_drawable_width (last.guide), gimp_drawable_height (last.guide)))))
    return fail (outcome, GIMP_PDB_CALLING_ERROR, message);

  memset (&guide, 0, sizeof guide);
  memset (&target_copy, 0, sizeof target_copy);
  ok = read_exemplar (last.exemplar, FALSE, &exemplar, &message);
  if (ok && by_numbers)
    ok = read_exemplar (last.guide, FALSE, &guide, &message);
  if (ok)
    ok = read_exemplar (target, FALSE, &target_copy, &message);
  if (ok)
    {
      gimp_progress_init (by_numbers ? _("Painting texture by numbers")
                                     : _("Transferring the style"));
      ok = ts_plugin_guided (&exemplar, by_numbers ? guide.buffer : NULL, target_copy.buffer,
                             &last.args, &result, &error);
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
      return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
    }

  /* Only now is the image changed: a cancelled run leaves it as it was. */
  if (by_numbers)
    {
      outcome->new_layer = add_result_layer (target, result, exemplar.has_alpha);
      ok = outcome->new_layer >= 0;
    }
  else
    ok = ts_replace_layer_pixels2 (target, result);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  if (!ok)
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));
  if (mode != GIMP_RUN_NONINTERACTIVE)
    {
      gimp_set_data (name, &last, sizeof last);
      gimp_displays_flush ();
    }
  return TRUE;
}
