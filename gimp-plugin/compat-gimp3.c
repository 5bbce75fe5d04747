/* GIMP 3 glue shared by its procedures: reading the exemplar layers,
 * making new images from the results, a run's return values and the
 * checks of the selected drawables.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <string.h>

#include <glib/gi18n-lib.h>

#include "compat-gimp3.h"

gboolean
read_exemplar (GimpDrawable *drawable, gboolean crop_to_selection, TsExemplar *exemplar,
               gchar **message)
{
  GimpImage *image = gimp_item_get_image (GIMP_ITEM (drawable));
  GeglRectangle rect = { 0, 0, gimp_drawable_get_width (drawable),
                         gimp_drawable_get_height (drawable) };
  const Babl *format = gimp_drawable_get_format (drawable);
  GeglBuffer *buffer;

  if (crop_to_selection &&
      !gimp_drawable_mask_intersect (drawable, &rect.x, &rect.y, &rect.width, &rect.height))
    {
      *message = g_strdup (_("The selection does not overlap the layer."));
      return FALSE;
    }

  memset (exemplar, 0, sizeof *exemplar);
  exemplar->has_alpha = gimp_drawable_has_alpha (drawable);
  exemplar->base_type = gimp_image_get_base_type (image);
  exemplar->precision = gimp_image_get_precision (image);
  exemplar->profile = gimp_image_get_color_profile (image);
  if (exemplar->base_type == GIMP_INDEXED)
    {
      /* The new pixels are not in the palette: read (and make) RGB. */
      exemplar->base_type = GIMP_RGB;
      format = babl_format_with_space (exemplar->has_alpha ? "R'G'B'A u8" : "R'G'B' u8",
                                       babl_format_get_space (format));
    }

  buffer = gimp_drawable_get_buffer (drawable);
  exemplar->buffer = ts_plugin_copy_buffer (buffer, &rect, format);
  g_object_unref (buffer);
  if (exemplar->buffer && crop_to_selection && !gimp_selection_is_empty (image))
    {
      GimpDrawable *selection = GIMP_DRAWABLE (gimp_image_get_selection (image));
      gint x, y;

      gimp_drawable_get_offsets (drawable, &x, &y);
      ts_exemplar_keep_selected (exemplar, gimp_drawable_get_buffer (selection), &rect, x, y);
    }
  if (!exemplar->buffer)
    {
      ts_exemplar_clear (exemplar);
      *message = g_strdup (_("Out of memory copying the layer."));
      return FALSE;
    }
  return TRUE;
}

static GimpImageType
layer_type (const TsExemplar *exemplar, gboolean has_alpha)
{
  if (exemplar->base_type == GIMP_GRAY)
    return has_alpha ? GIMP_GRAYA_IMAGE : GIMP_GRAY_IMAGE;
  return has_alpha ? GIMP_RGBA_IMAGE : GIMP_RGB_IMAGE;
}

GimpImage *
new_image (const TsExemplar *exemplar, GeglBuffer **layers, const gchar **names,
           const gboolean *alphas, gint n)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (layers[0]);
  GimpImage *image = gimp_image_new_with_precision (extent->width, extent->height,
                                                    exemplar->base_type, exemplar->precision);
  gboolean ok = image != NULL;

  if (!ok)
    return NULL;
  gimp_image_undo_disable (image);
  if (exemplar->profile)
    gimp_image_set_color_profile (image, exemplar->profile);

  for (gint i = 0; ok && i < n; i++)
    {
      const GeglRectangle *size = gegl_buffer_get_extent (layers[i]);
      GimpLayer *layer = gimp_layer_new (image, names[i], size->width, size->height,
                                         layer_type (exemplar, alphas ? alphas[i] : exemplar->has_alpha), 100.0, GIMP_LAYER_MODE_NORMAL);
      GeglBuffer *target;

      gimp_image_insert_layer (image, layer, NULL, i);
      target = gimp_drawable_get_buffer (GIMP_DRAWABLE (layer));
      ok = ts_plugin_transfer (layers[i], size, target, 0, 0,
                               gimp_drawable_get_format (GIMP_DRAWABLE (layer)));
      g_object_unref (target);
    }
  gimp_image_undo_enable (image);
  if (!ok)
    {
      gimp_image_delete (image);
      return NULL;
    }
  return image;
}

/* --- results and checks of every procedure ------------------------------ */

GimpValueArray *
failure (GimpProcedure *procedure, GimpPDBStatusType status, gchar *message)
{
  GError *error = message ? g_error_new_literal (TS_PLUGIN_ERROR, 0, message) : NULL;

  g_free (message);
  return gimp_procedure_new_return_values (procedure, status, error);
}

GimpValueArray *
success_with_image (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image)
{
  GimpValueArray *values = gimp_procedure_new_return_values (procedure, GIMP_PDB_SUCCESS, NULL);

  if (mode == GIMP_RUN_INTERACTIVE)
    gimp_display_new (image);
  GIMP_VALUES_SET_IMAGE (values, 1, image);
  return values;
}

gint
count_drawables (GimpDrawable **drawables)
{
  gint n = 0;

  while (drawables && drawables[n])
    n++;
  return n;
}

/* Checks common to all three procedures; NULL if fine. */
gchar *
check_drawables (GimpDrawable **drawables, gint max)
{
  gint n = count_drawables (drawables);

  /* libgimp initialises GEGL only for its own buffer calls; the ops must
   * be registered before they are looked up. */
  gegl_init (NULL, NULL);
  if (n < 1 || n > max)
    return max == 1 ? g_strdup (_("Select exactly one layer."))
                    : g_strdup_printf (_("Select one to %d layers."), max);
  for (gint i = 0; i < n; i++)
    if (!gimp_item_is_layer (GIMP_ITEM (drawables[i])))
      return g_strdup (_("The drawable must be a layer."));
  return ts_plugin_check_ops (TS_OP_SYNTHESIZE, TS_OP_TILEABLE, NULL);
}

#define AUTHOR    "texsynth contributors"
#define COPYRIGHT "texsynth contributors (GPL-3.0-or-later)"
#define DATE      "2025"

/* `quality_texts`: the plugin-args.c entry whose label and tooltip the
 * "quality" argument shows. */
void
ts_add_quality_and_seed3 (GimpProcedure *procedure, const gchar *quality_texts)
{
  gimp_procedure_add_int_argument (procedure, "quality", ts_arg_label (quality_texts),
                                   ts_arg_tooltip (quality_texts), TS_PLUGIN_MIN_QUALITY,
                                   TS_PLUGIN_MAX_QUALITY, TS_PLUGIN_DEFAULT_QUALITY,
                                   G_PARAM_READWRITE);
  gimp_procedure_add_int_argument (procedure, "seed", ts_arg_label ("seed"),
                                   ts_arg_tooltip ("seed"), 0, G_MAXINT, 0, G_PARAM_READWRITE);
}

void
ts_describe3 (GimpProcedure *procedure, const gchar *label, const gchar *menu,
              const gchar *blurb, const gchar *help)
{
  gimp_procedure_set_image_types (procedure, "RGB*, GRAY*, INDEXED*");
  gimp_procedure_set_menu_label (procedure, label);
  gimp_procedure_add_menu_path (procedure, menu);
  gimp_procedure_set_documentation (procedure, blurb, help, gimp_procedure_get_name (procedure));
  gimp_procedure_set_attribution (procedure, AUTHOR, COPYRIGHT, DATE);
}

gboolean
ts_replace_layer_pixels3 (GimpDrawable *drawable, GeglBuffer *result)
{
  GimpImage *image = gimp_item_get_image (GIMP_ITEM (drawable));
  const GeglRectangle *extent = gegl_buffer_get_extent (result);
  GeglBuffer *shadow;
  gboolean written;

  gimp_image_undo_group_start (image);
  if (gimp_drawable_is_indexed (drawable))
    {
      g_message (_("The image is indexed: it is converted to RGB first."));
      gimp_image_convert_rgb (image);
    }
  shadow = gimp_drawable_get_shadow_buffer (drawable);
  written = ts_plugin_transfer (result, extent, shadow, 0, 0, gimp_drawable_get_format (drawable));
  g_object_unref (shadow);
  if (written)
    {
      gimp_drawable_merge_shadow (drawable, TRUE);
      gimp_drawable_update (drawable, 0, 0, extent->width, extent->height);
    }
  gimp_image_undo_group_end (image);
  return written;
}
