/* The dialogs' previews: a small run of the op in a worker thread, its
 * result read back as 8-bit sRGB for GimpPreviewArea.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "plugin-preview.h"

struct _TsPreview
{
  GeglNode   *graph;
  GeglNode   *sink;
  GeglBuffer *inputs[3];     /* referenced while the worker reads them */
  GeglBuffer *result;
  guchar     *pixels;
  gint        width, height;
  gint        done;          /* atomic */
  GThread    *thread;
};

static gpointer
process_preview (gpointer data)
{
  TsPreview *preview = data;

  gegl_node_process (preview->sink);
  /* Read back here, so that the main thread only draws. */
  gegl_buffer_get (preview->result, NULL, 1.0, babl_format ("R'G'B'A u8"), preview->pixels,
                   GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
  g_atomic_int_set (&preview->done, 1);
  return NULL;
}

/* A preview of `width` x `height` that `output` gives, in a worker
 * thread: inputs[0] feeds the input pad of `entry` (the op, or the
 * scaling before it), inputs[1] and inputs[2] the aux and aux2 pads of
 * `op`; NULL inputs are left out. */
static TsPreview *
start (GeglNode *graph, GeglNode *entry, GeglNode *op, GeglNode *output, GeglBuffer **inputs,
       gint n, gint width, gint height)
{
  static const gchar *const pads[] = { "input", "aux", "aux2" };
  GeglRectangle rect = { 0, 0, width, height };
  TsPreview *preview = g_try_new0 (TsPreview, 1);

  if (preview)
    preview->pixels = g_try_malloc ((gsize) width * (gsize) height * 4);
  if (!preview || !preview->pixels)
    {
      g_free (preview);
      g_object_unref (graph);
      return NULL;
    }
  preview->graph = graph;
  preview->width = width;
  preview->height = height;
  for (gint i = 0; i < n && i < 3; i++)
    {
      GeglNode *source;

      if (!inputs[i])
        continue;
      source = gegl_node_new_child (graph, "operation", "gegl:buffer-source",
                                    "buffer", inputs[i], NULL);
      preview->inputs[i] = g_object_ref (inputs[i]);
      ts_plugin_connect_pads (source, i == 0 ? entry : op, pads[i]);
    }
  preview->result = gegl_buffer_new (&rect, babl_format ("R'G'B'A float"));
  preview->sink = gegl_node_new_child (graph, "operation", "gegl:write-buffer",
                                       "buffer", preview->result, NULL);
  gegl_node_link (output, preview->sink);
  preview->thread = g_thread_new ("texsynth-preview", process_preview, preview);
  return preview;
}

/* A node cropping to x, y, width x height. */
static GeglNode *
crop_node (GeglNode *graph, gint x, gint y, gint width, gint height)
{
  return gegl_node_new_child (graph, "operation", "gegl:crop", "x", (gdouble) x,
                              "y", (gdouble) y, "width", (gdouble) width,
                              "height", (gdouble) height, NULL);
}

const gchar *
ts_preview_caption (TsPreviewKind kind)
{
  switch (kind)
    {
    case TS_PREVIEW_RENDER:
      return _("A small piece of the texture, at the result's scale");
    case TS_PREVIEW_LAYERS:
      return _("A small piece of the driving layer's texture, at the result's scale");
    case TS_PREVIEW_SOLID:
      return _("The middle slice of a small cube, at the result's scale");
    case TS_PREVIEW_HEAL_SELECTION:
      return _("The selection healed within a crop around it");
    case TS_PREVIEW_HEAL_TRANSPARENCY:
      return _("A small copy of the layer, its transparency healed");
    case TS_PREVIEW_UNCROP:
      return _("A small copy of the layer, its new border filled");
    case TS_PREVIEW_TILEABLE:
      return _("A small copy of the layer, made seamless and repeated 2\303\2272");
    case TS_PREVIEW_GUIDED:
      return _("The middle of the result, at the result's scale");
    }
  return "";
}

GeglBuffer *
ts_preview_copy (GeglBuffer *source, gint side, gboolean scale_down, gdouble *ratio)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (source);
  const Babl *format = babl_format_with_space ("R'G'B'A float", gegl_buffer_get_format (source));
  gdouble scale = 1.0;
  GeglRectangle rect = { 0, 0, MIN (side, extent->width), MIN (side, extent->height) };
  GeglBuffer *full, *copy;
  gfloat *pixels;

  if (!scale_down)
    {
      /* The middle, at full scale. */
      rect.x = (extent->width - rect.width) / 2;
      rect.y = (extent->height - rect.height) / 2;
      if (ratio)
        *ratio = 1.0;
      return ts_plugin_copy_buffer (source, &rect, format);
    }
  scale = MIN (1.0, (gdouble) side / MAX (extent->width, extent->height));
  rect.width = MAX (1, (gint) (extent->width * scale));
  rect.height = MAX (1, (gint) (extent->height * scale));
  /* A GIMP buffer is read row by row in this thread (ts_plugin_transfer),
   * in its own format to keep the copy small; GEGL scales that copy. */
  full = ts_plugin_copy_buffer (source, extent, gegl_buffer_get_format (source));
  pixels = g_try_new (gfloat, (gsize) rect.width * (gsize) rect.height * 4);
  copy = full && pixels ? gegl_buffer_new (&rect, format) : NULL;
  if (copy)
    {
      gegl_buffer_get (full, &rect, scale, format, pixels, GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
      gegl_buffer_set (copy, &rect, 0, format, pixels, GEGL_AUTO_ROWSTRIDE);
    }
  g_clear_object (&full);
  g_free (pixels);
  if (ratio)
    *ratio = scale;
  return copy;
}

/* texsynth:synthesize at min(width, TS_PREVIEW_SIDE) x min(height,
 * TS_PREVIEW_SIDE): a crop-sized texture at the result's scale. */
static TsPreview *
start_render (const TsExemplar *exemplar, const TsRenderArgs *args)
{
  gint width = CLAMP (args->width, 1, TS_PREVIEW_SIDE);
  gint height = CLAMP (args->height, 1, TS_PREVIEW_SIDE);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_SYNTHESIZE,
                                      "width", width, "height", height,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, NULL);
  GeglBuffer *inputs[1] = { exemplar->buffer };

  return start (graph, op, op, op, inputs, 1, width, height);
}

/* The middle slice across x of a cube of min(size, TS_PREVIEW_SOLID_SIZE)
 * through texsynth:volume-slice; no file is written. */
static TsPreview *
start_solid (const TsExemplar *exemplars, gint n_exemplars, const TsSolidArgs *args)
{
  gint size = CLAMP (args->size, TS_PLUGIN_MIN_SOLID, TS_PREVIEW_SOLID_SIZE);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_VOLUME_SLICE,
                                      "size", size, "index", size / 2,
                                      "quality", args->quality, "seed", args->seed,
                                      "cell-structure", args->cell_structure, NULL);
  GeglBuffer *inputs[3] = { NULL, NULL, NULL };

  for (gint i = 0; i < n_exemplars && i < 3; i++)
    inputs[i] = exemplars[i].buffer;
  /* The slice the new image shows on top. */
  ts_plugin_set_enum_by_nick (op, "axis", "x");
  return start (graph, op, op, op, inputs, MIN (n_exemplars, 3), size, size);
}

/* texsynth:heal on the crop around a selection (ts_heal_preview_crop's),
 * scaled down to fit TS_PREVIEW_SIDE when larger. */
static TsPreview *
start_heal (GeglBuffer *pixels, GeglBuffer *mask, const TsHealArgs *args)
{
  const GeglRectangle *crop = gegl_buffer_get_extent (pixels);
  gdouble ratio = MIN (1.0, (gdouble) TS_PREVIEW_SIDE / MAX (crop->width, crop->height));
  GeglBuffer *inputs[2] = { pixels, mask };
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_HEAL,
                                      "context", args->context,
                                      "sample-from", args->sample_from,
                                      "quality", args->quality, "seed", args->seed, NULL);
  GeglNode *scale = gegl_node_new_child (graph, "operation", "gegl:scale-ratio",
                                         "x", ratio, "y", ratio, NULL);

  gegl_node_link (op, scale);
  return start (graph, op, op, scale, inputs, 2, MAX (1, (gint) (crop->width * ratio)),
                MAX (1, (gint) (crop->height * ratio)));
}

/* texsynth:heal without a mask on the scaled-down layer: its pixels that
 * are not fully opaque are filled. The context is scaled with it. */
static TsPreview *
start_heal_transparency (GeglBuffer *layer, gdouble ratio, const TsHealArgs *args)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (layer);
  /* 0 stays "the whole layer"; any other context keeps at least a pixel. */
  gint context = args->context > 0 ? MAX (1, (gint) (args->context * ratio + 0.5)) : 0;
  GeglBuffer *inputs[1] = { layer };
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_HEAL, "context", context,
                                      "sample-from", args->sample_from,
                                      "quality", args->quality, "seed", args->seed, NULL);

  return start (graph, op, op, op, inputs, 1, extent->width, extent->height);
}

/* Uncrop of the scaled-down layer (by `ratio`) in an image of
 * image_width x image_height: scaled further so that the layer and its
 * border fit TS_PREVIEW_SIDE, and the border healed. */
static TsPreview *
start_uncrop (GeglBuffer *layer, gdouble ratio, gint image_width, gint image_height,
              const TsHealArgs *args)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (layer);
  /* The run's border, in the copy's pixels, then all of it scaled to fit. */
  gdouble border_x = MAX (1, image_width * args->percent / 100) * ratio;
  gdouble border_y = MAX (1, image_height * args->percent / 100) * ratio;
  gdouble fit = MIN (1.0, TS_PREVIEW_SIDE / MAX (extent->width + 2.0 * border_x,
                                                 extent->height + 2.0 * border_y));
  /* Whole pixels; the margin keeps an exact product (96 x 160 / 192) whole. */
  gint width = MAX (1, (gint) (extent->width * fit + 1e-6));
  gint height = MAX (1, (gint) (extent->height * fit + 1e-6));
  gint bx = MAX (1, (gint) (border_x * fit + 1e-6)), by = MAX (1, (gint) (border_y * fit + 1e-6));
  GeglRectangle inner = { bx, by, width, height };
  GeglBuffer *mask = ts_plugin_border_mask (width + 2 * bx, height + 2 * by, &inner);
  GeglBuffer *inputs[2] = { layer, mask };
  GeglNode *graph, *scale, *translate, *op;
  TsPreview *preview;

  if (!mask)
    return NULL;
  /* Whole pixels only, then a transparent border around them. */
  graph = gegl_node_new ();
  scale = gegl_node_new_child (graph, "operation", "gegl:scale-ratio", "x", fit, "y", fit, NULL);
  translate = gegl_node_new_child (graph, "operation", "gegl:translate", "x", (gdouble) bx,
                                   "y", (gdouble) by, NULL);
  op = gegl_node_new_child (graph, "operation", TS_OP_HEAL, "context", args->context,
                            "sample-from", args->sample_from, "quality", args->quality,
                            "seed", args->seed, NULL);
  gegl_node_link_many (scale, crop_node (graph, 0, 0, width, height), translate,
                       crop_node (graph, 0, 0, width + 2 * bx, height + 2 * by), op, NULL);
  preview = start (graph, scale, op, op, inputs, 2, width + 2 * bx, height + 2 * by);
  g_object_unref (mask);
  return preview;
}

/* texsynth:tileable on the layer scaled to fit TS_PREVIEW_TILE_SIDE,
 * repeated 2x2. */
static TsPreview *
start_tileable (GeglBuffer *layer, const TsTileableArgs *args)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (layer);
  GeglBuffer *inputs[1] = { layer };
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_TILEABLE,
                                      "quality", args->quality, "seed", args->seed, NULL);
  GeglNode *tile = gegl_node_new_child (graph, "operation", "gegl:tile", NULL);
  GeglNode *crop = crop_node (graph, 0, 0, 2 * extent->width, 2 * extent->height);

  gegl_node_link_many (op, tile, crop, NULL);
  return start (graph, op, op, crop, inputs, 1, 2 * extent->width, 2 * extent->height);
}

/* texsynth:guided on the middle of the target with the exemplar and its
 * guide (NULL for style transfer). */
static TsPreview *
start_guided (GeglBuffer *exemplar, GeglBuffer *exemplar_guide, GeglBuffer *target,
              const TsGuidedArgs *args)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (target);
  GeglBuffer *inputs[3] = { target, exemplar, exemplar_guide };
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_GUIDED,
                                      "guide-weight", args->guide_weight,
                                      "blend-edges", args->blend_edges,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, NULL);

  return start (graph, op, op, op, inputs, 3, extent->width, extent->height);
}

TsPreview *
ts_preview_start (const TsPreviewInput *input, const TsPreviewSettings *settings)
{
  switch (input->kind)
    {
    case TS_PREVIEW_RENDER:
    case TS_PREVIEW_LAYERS:
      return start_render (input->exemplars, &settings->render);
    case TS_PREVIEW_SOLID:
      return start_solid (input->exemplars, input->n_exemplars, &settings->solid);
    case TS_PREVIEW_HEAL_SELECTION:
      return start_heal (input->pixels, input->mask, &settings->heal);
    case TS_PREVIEW_HEAL_TRANSPARENCY:
      return start_heal_transparency (input->pixels, input->ratio, &settings->heal);
    case TS_PREVIEW_UNCROP:
      return start_uncrop (input->pixels, input->ratio, input->image_width, input->image_height,
                           &settings->heal);
    case TS_PREVIEW_TILEABLE:
      return start_tileable (input->pixels, &settings->tileable);
    case TS_PREVIEW_GUIDED:
      /* The run refuses a guide of another size; so does its preview. */
      if (!settings->exemplar ||
          (settings->exemplar_guide &&
           !gegl_rectangle_equal (gegl_buffer_get_extent (settings->exemplar),
                                  gegl_buffer_get_extent (settings->exemplar_guide))))
        return NULL;
      return start_guided (settings->exemplar, settings->exemplar_guide, input->pixels,
                           &settings->guided);
    }
  return NULL;
}

gboolean
ts_preview_done (TsPreview *preview)
{
  return g_atomic_int_get (&preview->done) != 0;
}

const guchar *
ts_preview_pixels (TsPreview *preview, gint *width, gint *height)
{
  *width = preview->width;
  *height = preview->height;
  return preview->pixels;
}

void
ts_preview_free (TsPreview *preview)
{
  if (!preview)
    return;
  g_thread_join (preview->thread);
  g_object_unref (preview->graph);
  g_object_unref (preview->result);
  for (gint i = 0; i < 3; i++)
    g_clear_object (&preview->inputs[i]);
  g_free (preview->pixels);
  g_free (preview);
}
