/* The heal procedures' work between reading GIMP and writing it back,
 * which GIMP 2.10 and GIMP 3 share: a private copy of the layer (with a
 * transparent border for uncrop), the hole's mask, and texsynth:heal.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include <string.h>

#include "texsynth-plugin.h"
#include "plugin-preview.h"

/* The layer's pixels at (0, 0), `border_x`, `border_y` further in for
 * uncrop, in `format`; NULL if out of memory. */
static GeglBuffer *
copy_layer (const TsHealLayer *layer, const Babl *format)
{
  GeglRectangle rect = { 0, 0, layer->width, layer->height };
  GeglRectangle larger = { 0, 0, layer->width + 2 * layer->border_x,
                           layer->height + 2 * layer->border_y };
  GeglBuffer *pixels;

  if (layer->border_x == 0 && layer->border_y == 0)
    return ts_plugin_copy_buffer (layer->buffer, &rect, format);
  pixels = gegl_buffer_new (&larger, format);
  if (pixels && !ts_plugin_transfer (layer->buffer, &rect, pixels, layer->border_x,
                                     layer->border_y, format))
    g_clear_object (&pixels);
  return pixels;
}

gboolean
ts_plugin_heal_layer (const TsHealLayer *layer,
                      const TsHealArgs  *args,
                      GeglBuffer       **result,
                      GError           **error)
{
  gboolean uncrop = layer->border_x > 0 || layer->border_y > 0;
  const Babl *format = layer->format;
  GeglBuffer *pixels, *mask = NULL;
  gboolean healed;

  /* Uncrop's border starts transparent, so the layer needs an alpha. */
  if (uncrop && !babl_format_has_alpha (format))
    format = babl_format_with_space (layer->is_gray ? "Y'A float" : "R'G'B'A float", format);
  pixels = copy_layer (layer, format);
  if (pixels && uncrop)
    {
      /* The hole is the new border only: transparency the layer already
       * had is the user's and stays. */
      GeglRectangle inner = { layer->border_x, layer->border_y, layer->width, layer->height };
      mask = ts_plugin_border_mask (layer->width + 2 * layer->border_x,
                                    layer->height + 2 * layer->border_y, &inner);
    }
  else if (pixels && layer->selection)
    {
      /* The selection over the layer, wherever the layer lies. */
      GeglRectangle over = { layer->offset_x, layer->offset_y, layer->width, layer->height };
      mask = ts_plugin_copy_buffer (layer->selection, &over, babl_format ("Y' float"));
    }
  if (!pixels || ((uncrop || layer->selection) && !mask))
    {
      g_clear_object (&pixels);
      g_set_error (error, TS_PLUGIN_ERROR, 0, "%s", _("Out of memory."));
      return FALSE;
    }
  gimp_progress_init (_("Healing"));
  healed = ts_plugin_heal (pixels, mask, args, result, error);
  g_object_unref (pixels);
  g_clear_object (&mask);
  return healed;
}

gboolean
ts_heal_preview_crop (const TsHealLayer   *layer,
                      const GeglRectangle *hole,
                      GeglBuffer         **pixels,
                      GeglBuffer         **mask)
{
  /* As much texture around the hole as the hole is wide, and some even
   * around a small one, within the layer. */
  gint margin = MAX (MAX (hole->width, hole->height), TS_HEAL_PREVIEW_MIN_MARGIN);
  gint x0 = MAX (0, hole->x - margin), y0 = MAX (0, hole->y - margin);
  gint x1 = MIN (layer->width, hole->x + hole->width + margin);
  gint y1 = MIN (layer->height, hole->y + hole->height + margin);
  GeglRectangle crop = { x0, y0, x1 - x0, y1 - y0 };
  GeglRectangle over = { layer->offset_x + x0, layer->offset_y + y0, crop.width, crop.height };

  *pixels = *mask = NULL;
  if (!layer->selection || crop.width < 1 || crop.height < 1)
    return FALSE;
  *pixels = ts_plugin_copy_buffer (layer->buffer, &crop, layer->format);
  *mask = ts_plugin_copy_buffer (layer->selection, &over, babl_format ("Y' float"));
  if (!*pixels || !*mask)
    {
      g_clear_object (pixels);
      g_clear_object (mask);
      return FALSE;
    }
  return TRUE;
}

gboolean
ts_heal_preview_read (const TsHealLayer *layer, const gchar *procedure, const GeglRectangle *hole,
                      gint image_width, gint image_height, TsPreviewInput *input)
{
  memset (input, 0, sizeof *input);
  input->ratio = 1.0;
  if (g_str_equal (procedure, TS_PROC_HEAL_SELECTION))
    {
      input->kind = TS_PREVIEW_HEAL_SELECTION;
      return hole && ts_heal_preview_crop (layer, hole, &input->pixels, &input->mask);
    }
  input->kind = g_str_equal (procedure, TS_PROC_UNCROP) ? TS_PREVIEW_UNCROP
                                                        : TS_PREVIEW_HEAL_TRANSPARENCY;
  input->image_width = image_width;
  input->image_height = image_height;
  input->pixels = ts_preview_copy (layer->buffer, TS_PREVIEW_SIDE, TRUE, &input->ratio);
  return input->pixels != NULL;
}
