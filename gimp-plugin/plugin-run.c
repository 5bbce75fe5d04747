/* Running the texsynth GEGL ops for the plug-in: graphs on private copies
 * of GIMP's pixels, processed in a worker thread while the main thread
 * relays progress to GIMP (libgimp's wire is not thread-safe, and a GIMP
 * buffer reads its tiles over it, so only the main thread talks to GIMP).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <string.h>

#include <glib/gi18n-lib.h>
#include <glib/gstdio.h>

#include "texsynth-plugin.h"
#include "plugin-graph.h"

/* How often the main thread passes the op's progress on to GIMP. */
#define PROGRESS_POLL_US 50000

/* Rows moved per step by ts_plugin_transfer: bounds its memory. */
#define TRANSFER_ROWS 64

gboolean
ts_plugin_transfer (GeglBuffer          *source,
                    const GeglRectangle *source_rect,
                    GeglBuffer          *target,
                    gint                 target_x,
                    gint                 target_y,
                    const Babl          *format)
{
  gsize stride = (gsize) source_rect->width * babl_format_get_bytes_per_pixel (format);
  guchar *rows = g_try_malloc (stride * TRANSFER_ROWS);

  if (!rows)
    return FALSE;
  /* gegl_buffer_copy may split the work over GEGL's threads, but a GIMP
   * buffer fetches its tiles over libgimp's wire, which is not
   * thread-safe: plain get and set run in this thread only. */
  for (gint y = 0; y < source_rect->height; y += TRANSFER_ROWS)
    {
      gint n = MIN (TRANSFER_ROWS, source_rect->height - y);
      GeglRectangle from = { source_rect->x, source_rect->y + y, source_rect->width, n };
      GeglRectangle to = { target_x, target_y + y, source_rect->width, n };

      gegl_buffer_get (source, &from, 1.0, format, rows, (gint) stride, GEGL_ABYSS_NONE);
      gegl_buffer_set (target, &to, 0, format, rows, (gint) stride);
    }
  g_free (rows);
  return TRUE;
}

GeglBuffer *
ts_plugin_border_mask (gint width, gint height, const GeglRectangle *inner)
{
  GeglRectangle extent = { 0, 0, width, height };
  GeglBuffer *mask = gegl_buffer_new (&extent, babl_format ("Y' float"));
  const gfloat fill = 1.0f, keep = 0.0f;

  if (!mask)
    return NULL;
  gegl_buffer_set_color_from_pixel (mask, &extent, &fill, babl_format ("Y' float"));
  gegl_buffer_set_color_from_pixel (mask, inner, &keep, babl_format ("Y' float"));
  return mask;
}

GeglBuffer *
ts_plugin_copy_buffer (GeglBuffer          *source,
                       const GeglRectangle *rect,
                       const Babl          *format)
{
  GeglRectangle target = { 0, 0, rect->width, rect->height };
  GeglBuffer *copy = gegl_buffer_new (&target, format);

  if (!ts_plugin_transfer (source, rect, copy, 0, 0, format))
    g_clear_object (&copy);
  return copy;
}

void
ts_exemplar_clear (TsExemplar *exemplar)
{
  g_clear_object (&exemplar->buffer);
  g_clear_object (&exemplar->profile);
}

void
ts_exemplar_keep_selected (TsExemplar          *exemplar,
                           GeglBuffer          *mask,
                           const GeglRectangle *rect,
                           gint                 offset_x,
                           gint                 offset_y)
{
  const Babl *space = babl_format_get_space (gegl_buffer_get_format (exemplar->buffer));
  gboolean grey = exemplar->base_type == GIMP_GRAY;
  const Babl *format = babl_format_with_space (grey ? "Y'A float" : "R'G'B'A float", space);
  gint channels = grey ? 2 : 4, width = rect->width;
  GeglRectangle whole = { 0, 0, width, rect->height };
  GeglBuffer *masked = gegl_buffer_new (&whole, format);
  gfloat *pixels = g_try_new (gfloat, (gsize) width * channels);
  gfloat *selected = g_try_new (gfloat, (gsize) width);

  if (!masked || !pixels || !selected)
    {
      g_clear_object (&masked);
      g_clear_object (&exemplar->buffer);
      g_object_unref (mask);
      g_free (pixels);
      g_free (selected);
      return;
    }
  /* Row by row in this thread: the mask is a GIMP buffer (see
   * ts_plugin_transfer). */
  for (gint y = 0; y < rect->height; y++)
    {
      GeglRectangle row = { 0, y, width, 1 };
      GeglRectangle mask_row = { offset_x + rect->x, offset_y + rect->y + y, width, 1 };

      gegl_buffer_get (exemplar->buffer, &row, 1.0, format, pixels, GEGL_AUTO_ROWSTRIDE,
                       GEGL_ABYSS_NONE);
      gegl_buffer_get (mask, &mask_row, 1.0, babl_format ("Y float"), selected,
                       GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
      for (gint x = 0; x < width; x++)
        if (!(selected[x] >= 0.5f))
          pixels[(gsize) x * channels + channels - 1] = 0.0f;
      gegl_buffer_set (masked, &row, 0, format, pixels, GEGL_AUTO_ROWSTRIDE);
    }
  g_free (pixels);
  g_free (selected);
  g_object_unref (mask);
  g_object_unref (exemplar->buffer);
  exemplar->buffer = masked;
}

const Babl *
ts_exemplar_layer_format (const TsExemplar *exemplar, const Babl *space)
{
  /* Float keeps every precision's values; GIMP converts on copy. */
  const gchar *name = exemplar->base_type == GIMP_GRAY
                      ? (exemplar->has_alpha ? "Y'A float" : "Y' float")
                      : (exemplar->has_alpha ? "R'G'B'A float" : "R'G'B' float");

  return babl_format_with_space (name, space);
}

/* --- the worker thread ------------------------------------------------- */

typedef struct
{
  GeglNode *sink;
  gint      permille;  /* atomic: the watched node's progress */
  gint      done;      /* atomic */
} Job;

static void
on_progress (GeglNode *node G_GNUC_UNUSED, gdouble fraction, gchar *text G_GNUC_UNUSED,
             gpointer data)
{
  Job *job = data;

  g_atomic_int_set (&job->permille, (gint) (CLAMP (fraction, 0.0, 1.0) * 1000.0));
}

static gpointer
process_job (gpointer data)
{
  Job *job = data;

  gegl_node_process (job->sink);
  g_atomic_int_set (&job->done, 1);
  return NULL;
}

void
ts_plugin_run_graph (GeglNode *sink, GeglNode **watched, gdouble start, gdouble end)
{
  Job job = { sink, 0, 0 };
  gint n_watched = 0, last = -1;
  gulong *handlers;
  GThread *thread;

  while (watched[n_watched])
    n_watched++;
  handlers = g_new0 (gulong, n_watched);

  for (gint i = 0; i < n_watched; i++)
    {
      job.permille = 0;
      handlers[i] = g_signal_connect (watched[i], "progress", G_CALLBACK (on_progress), &job);
    }

  thread = g_thread_new ("texsynth", process_job, &job);
  while (!g_atomic_int_get (&job.done))
    {
      gint permille = g_atomic_int_get (&job.permille);

      if (permille != last)
        {
          gimp_progress_update (start + (end - start) * permille / 1000.0);
          last = permille;
        }
      g_usleep (PROGRESS_POLL_US);
    }
  g_thread_join (thread);

  for (gint i = 0; i < n_watched; i++)
    g_signal_handler_disconnect (watched[i], handlers[i]);
  g_free (handlers);
  gimp_progress_update (end);
}

/* --- graphs ----------------------------------------------------------- */

GeglNode *
ts_plugin_source_node (GeglNode *graph, GeglBuffer *buffer)
{
  return gegl_node_new_child (graph, "operation", "gegl:buffer-source",
                              "buffer", buffer, NULL);
}

GeglBuffer *
ts_plugin_result_buffer (gint width, gint height)
{
  GeglRectangle rect = { 0, 0, width, height };

  return gegl_buffer_new (&rect, babl_format ("CIE Lab alpha float"));
}

/* The lowest and highest alpha of the buffer's pixels (1 without alpha). */
static void
alpha_range (GeglBuffer *buffer, gfloat *lowest, gfloat *highest)
{
  const GeglRectangle *rect = gegl_buffer_get_extent (buffer);
  GeglBufferIterator *it = gegl_buffer_iterator_new (buffer, rect, 0, babl_format ("RGBA float"),
                                                     GEGL_ACCESS_READ, GEGL_ABYSS_NONE, 1);

  *lowest = 1.0f;
  *highest = 0.0f;
  while (gegl_buffer_iterator_next (it))
    {
      const gfloat *pixel = it->items[0].data;

      for (gint i = 0; i < it->length; i++)
        {
          *lowest = MIN (*lowest, pixel[4 * i + 3]);
          *highest = MAX (*highest, pixel[4 * i + 3]);
        }
    }
}

gboolean
ts_plugin_fully_transparent (GeglBuffer *buffer)
{
  gfloat lowest, highest;

  alpha_range (buffer, &lowest, &highest);
  return highest <= 0.0f;
}

gboolean
ts_plugin_run_op (GeglNode    *op,
                  gint         width,
                  gint         height,
                  const Babl  *format,
                  gdouble      start,
                  gdouble      end,
                  const gchar *failure,
                  GeglBuffer **result,
                  GError     **error)
{
  GeglRectangle rect = { 0, 0, width, height };
  GeglNode *watched[] = { op, NULL };
  GeglNode *sink;

  *result = format ? gegl_buffer_new (&rect, format) : ts_plugin_result_buffer (width, height);
  sink = gegl_node_new_child (gegl_node_get_parent (op), "operation", "gegl:write-buffer",
                              "buffer", *result, NULL);
  gegl_node_link (op, sink);
  ts_plugin_run_graph (sink, watched, start, end);

  /* The ops' only failure result is a transparent image, with a warning
   * on the console that says why. */
  if (failure && ts_plugin_fully_transparent (*result))
    {
      g_clear_object (result);
      g_set_error (error, TS_PLUGIN_ERROR, 0, "%s", failure);
      return FALSE;
    }
  return TRUE;
}

gboolean
ts_plugin_render (const TsExemplar   *exemplar,
                  const TsRenderArgs *args,
                  GeglBuffer        **result,
                  GError            **error)
{
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_SYNTHESIZE,
                                      "width", args->width, "height", args->height,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, NULL);
  gboolean ok;

  /* E.g. a fully transparent or too small exemplar fails. */
  gegl_node_link (ts_plugin_source_node (graph, exemplar->buffer), op);
  ok = ts_plugin_run_op (op, args->width, args->height, NULL, 0.0, 1.0,
                         _("Texture synthesis failed: the exemplar may be too small, fully "
                           "transparent, or the result too large for the memory (see the "
                           "error console for the details)."), result, error);
  g_object_unref (graph);
  return ok;
}

gboolean
ts_plugin_tileable (const TsExemplar     *exemplar,
                    const TsTileableArgs *args,
                    GeglBuffer          **result,
                    GError              **error)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (exemplar->buffer);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_TILEABLE,
                                      "quality", args->quality, "seed", args->seed, NULL);
  gboolean ok;

  /* The op's failure leaves the picture as it was, which is what the
   * user gets then too: there is nothing else to report. */
  gegl_node_link (ts_plugin_source_node (graph, exemplar->buffer), op);
  ok = ts_plugin_run_op (op, extent->width, extent->height, NULL, 0.0, 1.0, NULL, result, error);
  g_object_unref (graph);
  return ok;
}

/* A layout the op could not make is cleared (all zeros); a real one holds
 * pixel centres, each coordinate at least 0.5 for an exemplar at (0, 0). */
static gboolean
layout_is_empty (GeglBuffer *layout)
{
  const Babl *format = gegl_buffer_get_format (layout);
  GeglBufferIterator *it = gegl_buffer_iterator_new (layout, gegl_buffer_get_extent (layout), 0,
                                                     format, GEGL_ACCESS_READ,
                                                     GEGL_ABYSS_NONE, 1);
  gboolean empty = FALSE;

  while (gegl_buffer_iterator_next (it))
    {
      const gfloat *coords = it->items[0].data;

      for (gint i = 0; !empty && i < 2 * it->length; i++)
        empty = !(coords[i] >= 0.25f);
    }
  return empty;
}

void
ts_material_set_init (TsMaterialSet *set, gint n)
{
  memset (set, 0, sizeof *set);
  set->n = n;
  set->names = g_new0 (gchar *, n);
  set->alphas = g_new0 (gboolean, n);
  set->exemplars = g_new0 (TsExemplar, n);
  set->results = g_new0 (GeglBuffer *, n);
}

void
ts_material_set_clear (TsMaterialSet *set)
{
  for (gint i = 0; i < set->n; i++)
    {
      g_free (set->names[i]);
      ts_exemplar_clear (&set->exemplars[i]);
      g_clear_object (&set->results[i]);
    }
  g_free (set->names);
  g_free (set->alphas);
  g_free (set->exemplars);
  g_free (set->results);
  memset (set, 0, sizeof *set);
}

gboolean
ts_plugin_render_layers (TsMaterialSet      *set,
                         const TsRenderArgs *args,
                         GError            **error)
{
  const TsExemplar *layers = set->exemplars;
  GeglBuffer **results = set->results;
  gint n_layers = set->n;
  GeglBuffer *layout = NULL;
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_SYNTHESIZE,
                                      "width", args->width, "height", args->height,
                                      "tileable", args->tileable, "quality", args->quality,
                                      "seed", args->seed, "source-map", TRUE, NULL);
  GeglNode *layout_source;

  for (gint i = 0; i < n_layers; i++)
    g_clear_object (&results[i]);
  gegl_node_link (ts_plugin_source_node (graph, layers[set->driver].buffer), op);
  ts_plugin_run_op (op, args->width, args->height, babl_format_n (babl_type ("float"), 2), 0.0,
                    0.9, NULL, &layout, NULL);
  if (layout_is_empty (layout))
    {
      g_object_unref (graph);
      g_object_unref (layout);
      g_set_error (error, TS_PLUGIN_ERROR, 0,
                   _("Texture synthesis failed: the exemplar may be too small, fully "
                     "transparent, or the result too large for the memory (see the "
                     "error console for the details)."));
      return FALSE;
    }

  /* Nearest sampling at pixel centres copies whole pixels: every layer
   * gets exactly the driving layer's layout. map-absolute's extent is its
   * input's, so the crop gives the layout's size. */
  layout_source = ts_plugin_source_node (graph, layout);
  for (gint i = 0; i < n_layers; i++)
    {
      GeglNode *map = gegl_node_new_child (graph, "operation", "gegl:map-absolute",
                                           "sampler-type", GEGL_SAMPLER_NEAREST, NULL);
      GeglNode *crop = gegl_node_new_child (graph, "operation", "gegl:crop",
                                            "x", 0.0, "y", 0.0, "width", (gdouble) args->width,
                                            "height", (gdouble) args->height, NULL);

      gegl_node_link_many (ts_plugin_source_node (graph, layers[i].buffer), map, crop, NULL);
      ts_plugin_connect_pads (layout_source, map, "aux");
      ts_plugin_run_op (crop, args->width, args->height, gegl_buffer_get_format (layers[i].buffer),
                        0.9 + 0.1 * i / n_layers, 0.9 + 0.1 * (i + 1) / n_layers, NULL,
                        &results[i], NULL);
    }
  g_object_unref (graph);
  g_object_unref (layout);
  return TRUE;
}

static gboolean
same_pixels (GeglBuffer *a, GeglBuffer *b)
{
  const GeglRectangle *rect = gegl_buffer_get_extent (a);
  const Babl *format = gegl_buffer_get_format (a);
  gint bpp = babl_format_get_bytes_per_pixel (format);
  GeglBufferIterator *it = gegl_buffer_iterator_new (a, rect, 0, format, GEGL_ACCESS_READ,
                                                     GEGL_ABYSS_NONE, 2);
  gboolean same = TRUE;

  gegl_buffer_iterator_add (it, b, rect, 0, format, GEGL_ACCESS_READ, GEGL_ABYSS_NONE);
  while (gegl_buffer_iterator_next (it))
    same = same && memcmp (it->items[0].data, it->items[1].data, (gsize) it->length * bpp) == 0;
  return same;
}

gboolean
ts_plugin_heal (GeglBuffer        *pixels,
                GeglBuffer        *mask,
                const TsHealArgs  *args,
                GeglBuffer       **result,
                GError           **error)
{
  const GeglRectangle *extent = gegl_buffer_get_extent (pixels);
  GeglNode *graph = gegl_node_new ();
  GeglNode *op = gegl_node_new_child (graph, "operation", TS_OP_HEAL,
                                      "context", args->context, "sample-from", args->sample_from,
                                      "quality", args->quality, "seed", args->seed, NULL);

  gegl_node_link (ts_plugin_source_node (graph, pixels), op);
  if (mask)
    ts_plugin_connect_pads (ts_plugin_source_node (graph, mask), op, "aux");
  /* In the layer's own format: kept pixels come back bit for bit. */
  ts_plugin_run_op (op, extent->width, extent->height, gegl_buffer_get_format (pixels), 0.0, 1.0,
                    NULL, result, error);
  g_object_unref (graph);

  if (same_pixels (pixels, *result))
    {
      g_clear_object (result);
      g_set_error (error, TS_PLUGIN_ERROR, 0,
                   _("Nothing was healed: there is nothing to fill, or nothing to copy from "
                     "(the hole covers everything or the context is too small; the error "
                     "console says which)."));
      return FALSE;
    }
  return TRUE;
}

void
ts_plugin_connect_pads (GeglNode *source, GeglNode *sink, const gchar *sink_pad)
{
  /* GEGL 0.4.44 renamed the call (and deprecated the old name). */
#if GEGL_MINOR_VERSION > 4 || (GEGL_MINOR_VERSION == 4 && GEGL_MICRO_VERSION >= 44)
  gegl_node_connect (source, "output", sink, sink_pad);
#else
  gegl_node_connect_to (source, "output", sink, sink_pad);
#endif
}

/* Links up to three exemplars to the input, aux and aux2 pads of `op`. */
static void
link_exemplars (GeglNode *graph, GeglNode *op, const TsExemplar *exemplars, gint n)
{
  static const gchar *const pads[] = { "input", "aux", "aux2" };

  for (gint i = 0; i < n && i < 3; i++)
    ts_plugin_connect_pads (ts_plugin_source_node (graph, exemplars[i].buffer), op, pads[i]);
}

void
ts_plugin_set_enum_by_nick (GeglNode *node, const gchar *property, const gchar *nick)
{
  GParamSpec *pspec = gegl_node_find_property (node, property);
  GEnumClass *klass;
  GEnumValue *value;

  if (!pspec || !G_IS_PARAM_SPEC_ENUM (pspec))
    return;
  klass = g_type_class_ref (pspec->value_type);
  value = g_enum_get_value_by_nick (klass, nick);
  if (value)
    gegl_node_set (node, property, value->value, NULL);
  g_type_class_unref (klass);
}

gboolean
ts_plugin_solid (const TsExemplar  *exemplars,
                 gint               n_exemplars,
                 const TsSolidArgs *args,
                 GeglBuffer        *slices[3],
                 GError           **error)
{
  static const gchar *const axes[] = { "x", "y", "z" };
  GeglNode *graph = gegl_node_new ();
  GeglNode *save, *watched[2] = { NULL, NULL };
  GStatBuf before, after;
  gboolean existed = g_stat (args->path, &before) == 0;

  /* The engine refuses these too, but only on the console (a sink cannot
   * return an error); the user should learn why and what to do. Only an
   * explicit "on": automatic turns itself off for a translucent layer. */
  for (gint i = 0; args->cell_structure == TS_PLUGIN_CELL_STRUCTURE_ON && i < n_exemplars; i++)
    {
      gfloat lowest, highest;

      alpha_range (exemplars[i].buffer, &lowest, &highest);
      if (lowest < 1.0f)
        {
          g_object_unref (graph);
          g_set_error (error, TS_PLUGIN_ERROR, 0,
                       _("The cell structure needs an opaque exemplar, but the layer (or its "
                         "selected part) has transparent pixels: remove its alpha channel, "
                         "select a rectangle, or set the cell structure to automatic or off."));
          return FALSE;
        }
    }

  save = gegl_node_new_child (graph, "operation", TS_OP_VOLUME_SAVE, "path", args->path,
                              "size", args->size, "quality", args->quality,
                              "seed", args->seed, "cell-structure", args->cell_structure,
                              NULL);
  link_exemplars (graph, save, exemplars, n_exemplars);
  watched[0] = save;
  ts_plugin_run_graph (save, watched, 0.0, 0.9);

  /* A sink cannot return an error: the op warns on the console and the
   * file is not (re)written. */
  if (g_stat (args->path, &after) != 0 || after.st_size == 0 ||
      (existed && after.st_mtime == before.st_mtime && after.st_ino == before.st_ino))
    {
      g_object_unref (graph);
      g_set_error (error, TS_PLUGIN_ERROR, 0,
                   _("The volume could not be written to \"%s\" (see the error console "
                     "for the details)."), args->path);
      return FALSE;
    }

  /* The same parameters give the same volume, which the slice op keeps
   * in its cache between the three slices (the cell structure too, or
   * the slices would come from another volume than the file's). */
  for (gint axis = 0; axis < 3; axis++)
    {
      GeglNode *slice = gegl_node_new_child (graph, "operation", TS_OP_VOLUME_SLICE,
                                             "size", args->size, "index", args->size / 2,
                                             "quality", args->quality, "seed", args->seed,
                                             "cell-structure", args->cell_structure, NULL);

      ts_plugin_set_enum_by_nick (slice, "axis", axes[axis]);
      link_exemplars (graph, slice, exemplars, n_exemplars);
      /* The volume was written: its slices are there to read. */
      ts_plugin_run_op (slice, args->size, args->size, NULL, 0.9 + 0.1 * axis / 3.0,
                        0.9 + 0.1 * (axis + 1) / 3.0, NULL, &slices[axis], NULL);
    }
  g_object_unref (graph);
  return TRUE;
}
