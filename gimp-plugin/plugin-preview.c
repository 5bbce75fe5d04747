/* The dialogs' previews: a small run of the op in a worker thread, its
 * result read back as 8-bit sRGB for GimpPreviewArea.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
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

/* A preview of `width` x `height` that `output` gives, from `op` fed by up
 * to three buffers on its input, aux and aux2 pads; started in a worker
 * thread. */
static TsPreview *
start (GeglNode *graph, GeglNode *op, GeglNode *output, GeglBuffer **inputs, gint n,
       gint width, gint height)
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
      GeglNode *source = gegl_node_new_child (graph, "operation", "gegl:buffer-source",
                                              "buffer", inputs[i], NULL);

      preview->inputs[i] = g_object_ref (inputs[i]);
      ts_plugin_connect_pads (source, op, pads[i]);
    }
  preview->result = gegl_buffer_new (&rect, babl_format ("R'G'B'A float"));
  preview->sink = gegl_node_new_child (graph, "operation", "gegl:write-buffer",
                                       "buffer", preview->result, NULL);
  gegl_node_link (output, preview->sink);
  preview->thread = g_thread_new ("texsynth-preview", process_preview, preview);
  return preview;
}

TsPreview *
ts_preview_start_render (const TsExemplar *exemplar, const TsRenderArgs *args)
{
  gint width = CLAMP (args->width, 1, TS_PREVIEW_SIDE);
  gint height = CLAMP (args->height, 1, TS_PREVIEW_SIDE);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_SYNTHESIZE,
                                      "width", width, "height", height,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, NULL);

  GeglBuffer *inputs[1] = { exemplar->buffer };

  return start (graph, op, op, inputs, 1, width, height);
}

TsPreview *
ts_preview_start_solid (const TsExemplar *exemplars, gint n_exemplars, const TsSolidArgs *args)
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
  return start (graph, op, op, inputs, MIN (n_exemplars, 3), size, size);
}

TsPreview *
ts_preview_start_heal (GeglBuffer *pixels, GeglBuffer *mask, const TsHealArgs *args)
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
  return start (graph, op, scale, inputs, 2, MAX (1, (gint) (crop->width * ratio)),
                MAX (1, (gint) (crop->height * ratio)));
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
