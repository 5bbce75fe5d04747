/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "image-io.h"
#include "op-lab.h"

#include <gegl.h>
#include <stdio.h>
#include <stdlib.h>

#define LAB_FORMAT "CIE Lab alpha float"

void
ts_io_init (void)
{
  static gboolean done = FALSE;
  if (!done)
    {
      gegl_init (NULL, NULL);
      done = TRUE;
    }
}

bool
ts_io_load (const char *path, TsImage *image, char *why, size_t why_size)
{
  GeglNode *graph, *load, *sink;
  GeglBuffer *buffer = NULL;
  GeglRectangle extent;
  size_t floats;

  image->width = image->height = 0;
  image->pixels = NULL;
  if (!g_file_test (path, G_FILE_TEST_IS_REGULAR))
    {
      if (why)
        snprintf (why, why_size, "cannot read '%s': no such file", path);
      return false;
    }
  graph = gegl_node_new ();
  load = gegl_node_new_child (graph, "operation", "gegl:load", "path", path, NULL);
  sink = gegl_node_new_child (graph, "operation", "gegl:buffer-sink", "buffer", &buffer, NULL);
  gegl_node_link (load, sink);
  gegl_node_process (sink);
  g_object_unref (graph);
  if (!buffer)
    {
      if (why)
        snprintf (why, why_size, "cannot decode '%s'", path);
      return false;
    }
  extent = *gegl_buffer_get_extent (buffer);
  if (extent.width <= 0 || extent.height <= 0)
    {
      g_object_unref (buffer);
      if (why)
        snprintf (why, why_size, "'%s' is empty or not an image GEGL can read", path);
      return false;
    }
  floats = (size_t) extent.width * (size_t) extent.height * TS_CHANNELS;
  image->pixels = malloc (floats * sizeof (float));
  if (!image->pixels)
    {
      g_object_unref (buffer);
      if (why)
        snprintf (why, why_size, "out of memory loading '%s'", path);
      return false;
    }
  /* Fixed arithmetic, as the ops read exemplars (op-lab.h): babl's
   * timing-chosen paths would give each process its own numbers. */
  ts_op_read_lab (buffer, &extent, image->pixels);
  g_object_unref (buffer);
  image->width = (size_t) extent.width;
  image->height = (size_t) extent.height;
  return true;
}

bool
ts_io_save (const char *path, const TsImage *image, char *why, size_t why_size)
{
  GeglRectangle extent = { 0, 0, (gint) image->width, (gint) image->height };
  GeglBuffer *buffer = gegl_buffer_new (&extent, babl_format (LAB_FORMAT));
  GeglNode *graph, *source, *save;

  gegl_buffer_set (buffer, &extent, 0, babl_format (LAB_FORMAT), image->pixels,
                   GEGL_AUTO_ROWSTRIDE);
  graph = gegl_node_new ();
  source = gegl_node_new_child (graph, "operation", "gegl:buffer-source", "buffer", buffer, NULL);
  save = gegl_node_new_child (graph, "operation", "gegl:save", "path", path, NULL);
  gegl_node_link (source, save);
  gegl_node_process (save);
  g_object_unref (graph);
  g_object_unref (buffer);
  if (!g_file_test (path, G_FILE_TEST_EXISTS))
    {
      if (why)
        snprintf (why, why_size, "could not write '%s'", path);
      return false;
    }
  return true;
}
