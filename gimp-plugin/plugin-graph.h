/* Running an op graph for a procedure (plugin-run.c), shared by the
 * procedures' runs in other files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_PLUGIN_GRAPH_H
#define TEXSYNTH_PLUGIN_GRAPH_H

#include "texsynth-plugin.h"

/* Processes `sink` in a worker thread; the progress of each node of
 * `watched` (NULL-terminated) fills GIMP's bar from `start` to `end` in
 * equal parts, in turn. */
void        ts_plugin_run_graph (GeglNode *sink, GeglNode **watched, gdouble start, gdouble end);
/* A gegl:buffer-source of `buffer` in `graph`. */
GeglNode   *ts_plugin_source_node (GeglNode *graph, GeglBuffer *buffer);
/* A buffer for an op's output, in the engine's own format so that no
 * precision is lost before GIMP converts it to the layer's. */
GeglBuffer *ts_plugin_result_buffer (gint width, gint height);
/* Processes `op` (its inputs linked, in its graph) into *result, a new
 * width x height buffer in `format` (NULL: ts_plugin_result_buffer's),
 * with GIMP's bar from `start` to `end`. With `failure`, a fully
 * transparent result (the ops' failure, the reason on the error console)
 * is freed and `failure` becomes the error: FALSE. */
gboolean    ts_plugin_run_op (GeglNode    *op,
                              gint         width,
                              gint         height,
                              const Babl  *format,
                              gdouble      start,
                              gdouble      end,
                              const gchar *failure,
                              GeglBuffer **result,
                              GError     **error);
/* Whether every pixel of `buffer` has alpha 0: the ops' failure result. */
gboolean    ts_plugin_fully_transparent (GeglBuffer *buffer);

#endif /* TEXSYNTH_PLUGIN_GRAPH_H */
