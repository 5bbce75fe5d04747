/* GIMP 2.10 glue shared by its procedures: reading the exemplar layer,
 * making new images from the results and ending a run with one.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <string.h>

#include <glib/gi18n-lib.h>

#include "compat-gimp2.h"

static const Babl *
drawable_space (gint32 drawable)
{
  return babl_format_get_space (gimp_drawable_get_format (drawable));
}

/* Indexed layers are read as RGB: the new pixels are not in the palette. */
gboolean
read_exemplar (gint32 drawable, gboolean crop_to_selection, TsExemplar *exemplar,
               gchar **message)
{
  gint32 image = gimp_item_get_image (drawable);
  GeglRectangle rect = { 0, 0, gimp_drawable_width (drawable), gimp_drawable_height (drawable) };
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
  exemplar->base_type = gimp_image_base_type (image);
  exemplar->precision = gimp_image_get_precision (image);
  exemplar->profile = gimp_image_get_color_profile (image);
  if (exemplar->base_type == GIMP_INDEXED)
    {
      exemplar->base_type = GIMP_RGB;
      format = babl_format_with_space (exemplar->has_alpha ? "R'G'B'A u8" : "R'G'B' u8",
                                       drawable_space (drawable));
    }

  buffer = gimp_drawable_get_buffer (drawable);
  exemplar->buffer = ts_plugin_copy_buffer (buffer, &rect, format);
  g_object_unref (buffer);
  if (exemplar->buffer && crop_to_selection && !gimp_selection_is_empty (image))
    {
      gint32 selection = gimp_image_get_selection (image);
      gint x, y;

      gimp_drawable_offsets (drawable, &x, &y);
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

gint32
new_image (const TsExemplar *exemplar, GeglBuffer **layers, const gchar **names,
           const gboolean *alphas, gint n)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (layers[0]);
  gboolean ok = TRUE;
  gint32 image = gimp_image_new_with_precision (extent->width, extent->height,
                                                exemplar->base_type, exemplar->precision);

  if (image < 0)
    return -1;
  gimp_image_undo_disable (image);
  if (exemplar->profile)
    gimp_image_set_color_profile (image, exemplar->profile);

  for (gint i = 0; i < n; i++)
    {
      const GeglRectangle *size = gegl_buffer_get_extent (layers[i]);
      gint32 layer = gimp_layer_new (image, names[i], size->width, size->height,
                                     layer_type (exemplar, alphas ? alphas[i] : exemplar->has_alpha), 100.0, GIMP_LAYER_MODE_NORMAL);
      GeglBuffer *target;

      gimp_image_insert_layer (image, layer, -1, i);
      target = gimp_drawable_get_buffer (layer);
      ok = ok && ts_plugin_transfer (layers[i], size, target, 0, 0,
                                     gimp_drawable_get_format (layer));
      g_object_unref (target);
    }
  gimp_image_undo_enable (image);
  if (!ok)
    {
      gimp_image_delete (image);
      return -1;
    }
  return image;
}

gboolean
finish_with_image (Outcome *outcome, GimpRunMode mode, const gchar *procedure,
                   gconstpointer args, guint32 size)
{
  if (outcome->new_image < 0)
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Could not make the new image.")));

  if (mode != GIMP_RUN_NONINTERACTIVE)
    gimp_set_data (procedure, args, size);
  if (mode == GIMP_RUN_INTERACTIVE)
    gimp_display_new (outcome->new_image);
  return TRUE;
}

gboolean
ts_replace_layer_pixels2 (gint32 drawable, GeglBuffer *result)
{
  gint32 image = gimp_item_get_image (drawable);
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
