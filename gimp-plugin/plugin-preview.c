/* The dialogs' previews: a small run of the op in a worker thread, its
 * result read back as 8-bit sRGB for GimpPreviewArea.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "plugin-preview.h"

struct _TsPreview
{
  GeglNode   *graph;
  GeglNode   *sink;
  GeglBuffer *exemplars[3];  /* referenced while the worker reads them */
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

/* A preview of `width` x `height` whose op is `op`, fed by up to three
 * exemplars on its input, aux and aux2 pads; started in a worker thread. */
static TsPreview *
start (GeglNode *graph, GeglNode *op, const TsExemplar *exemplars, gint n, gint width,
       gint height)
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
                                              "buffer", exemplars[i].buffer, NULL);

      preview->exemplars[i] = g_object_ref (exemplars[i].buffer);
      ts_plugin_connect_pads (source, op, pads[i]);
    }
  preview->result = gegl_buffer_new (&rect, babl_format ("R'G'B'A float"));
  preview->sink = gegl_node_new_child (graph, "operation", "gegl:write-buffer",
                                       "buffer", preview->result, NULL);
  gegl_node_link (op, preview->sink);
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

  return start (graph, op, exemplar, 1, width, height);
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

  /* The slice the new image shows on top. */
  ts_plugin_set_enum_by_nick (op, "axis", "x");
  return start (graph, op, exemplars, n_exemplars, size, size);
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
    g_clear_object (&preview->exemplars[i]);
  g_free (preview->pixels);
  g_free (preview);
}
