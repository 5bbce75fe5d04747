/* The guided procedures' shared part: their arguments and the run of
 * texsynth:guided on private copies of the layers.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "guided-plugin.h"
#include "plugin-graph.h"

void
ts_guided_args_init (TsGuidedArgs *args)
{
  args->guide_weight = TS_PLUGIN_DEFAULT_GUIDE_WEIGHT;
  args->blend_edges = FALSE;
  args->tileable = FALSE;
  args->quality = TS_PLUGIN_DEFAULT_QUALITY;
  args->seed = 0;
}

gchar *
ts_guided_args_check (const TsGuidedArgs *args)
{
  /* Written so that NaN fails too. */
  if (!(args->guide_weight >= 0.0 && args->guide_weight <= TS_PLUGIN_MAX_GUIDE_WEIGHT))
    return g_strdup_printf (_("The guide weight must be between 0 and %g (got %g)."),
                            TS_PLUGIN_MAX_GUIDE_WEIGHT, args->guide_weight);
  if (args->quality < TS_PLUGIN_MIN_QUALITY || args->quality > TS_PLUGIN_MAX_QUALITY)
    return g_strdup_printf (_("Quality must be between %d and %d (got %d)."),
                            TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY, args->quality);
  if (args->seed < 0)
    return g_strdup_printf (_("The seed must be 0 or more (got %d)."), args->seed);
  return NULL;
}

gchar *
ts_guides_size_check (const gchar *exemplar, gint exemplar_width, gint exemplar_height,
                      const gchar *guide, gint guide_width, gint guide_height)
{
  if (guide_width == exemplar_width && guide_height == exemplar_height)
    return NULL;
  return g_strdup_printf (_("The exemplar's guide \"%s\" is %d\303\227%d pixels, but the "
                            "exemplar \"%s\" is %d\303\227%d: a guide must be aligned with its "
                            "exemplar, pixel for pixel."),
                          guide, guide_width, guide_height, exemplar, exemplar_width,
                          exemplar_height);
}

gboolean
ts_plugin_guided (const TsExemplar   *exemplar,
                  GeglBuffer         *exemplar_guide,
                  GeglBuffer         *target,
                  const TsGuidedArgs *args,
                  GeglBuffer        **result,
                  GError            **error)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (target);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_GUIDED,
                                      "guide-weight", args->guide_weight,
                                      "blend-edges", args->blend_edges,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, NULL);
  gboolean ok;

  gegl_node_link (ts_plugin_source_node (graph, target), op);
  ts_plugin_connect_pads (ts_plugin_source_node (graph, exemplar->buffer), op, "aux");
  if (exemplar_guide)
    ts_plugin_connect_pads (ts_plugin_source_node (graph, exemplar_guide), op, "aux2");
  ok = ts_plugin_run_op (op, extent->width, extent->height, NULL, 0.0, 1.0,
                         _("Guided synthesis failed: the exemplar may be too small or fully "
                           "transparent, the target smaller than 3\303\2273 pixels, or the "
                           "result too large for the memory (see the error console for the "
                           "details)."), result, error);
  g_object_unref (graph);
  return ok;
}
