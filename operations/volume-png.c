/* A set of PNG files that appears all at once.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "volume-png.h"
#include "op-common.h"
#include "volume/atomic-file.h"

#include <glib/gi18n-lib.h>
#include <glib/gstdio.h>

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const guint8 png_signature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
static const guint8 png_end[12] = { 0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82 };

void
ts_png_set_init (TsPngSet *set, const Babl *space)
{
  set->space = space;
  set->targets = g_ptr_array_new_with_free_func (g_free);
  set->temps = g_ptr_array_new_with_free_func (free); /* ts_atomic_reserve's */
}

static void
clear (TsPngSet *set)
{
  g_clear_pointer (&set->targets, g_ptr_array_unref);
  g_clear_pointer (&set->temps, g_ptr_array_unref);
}

/* gegl:png-save only warns on failure: check that the file holds the
 * whole image (signature, size, end chunk) and make it durable. */
static gboolean
check_png (const gchar *path, const gchar *target, size_t width, size_t height, TsError *error)
{
  guint8 head[24], tail[12];
  gboolean ok = FALSE;
  int fd = g_open (path, O_RDONLY, 0), errnum;
  off_t length;

  if (fd < 0)
    return ts_op_set_error (error, TS_ERROR_IO,
                            _("cannot write '%s': %s"), target, g_strerror (errno));
  length = lseek (fd, 0, SEEK_END);
  if (length >= (off_t) (sizeof head + sizeof tail) &&
      pread (fd, head, sizeof head, 0) == (ssize_t) sizeof head &&
      pread (fd, tail, sizeof tail, length - (off_t) sizeof tail) == (ssize_t) sizeof tail)
    ok = memcmp (head, png_signature, sizeof png_signature) == 0 &&
         memcmp (head + 12, "IHDR", 4) == 0 &&
         ((size_t) head[16] << 24 | (size_t) head[17] << 16 | (size_t) head[18] << 8 | head[19]) == width &&
         ((size_t) head[20] << 24 | (size_t) head[21] << 16 | (size_t) head[22] << 8 | head[23]) == height &&
         memcmp (tail, png_end, sizeof png_end) == 0;
  if (ok && (errnum = ts_atomic_seal (fd, target)) != 0)
    {
      close (fd);
      return ts_op_set_error (error, TS_ERROR_IO,
                              _("cannot write '%s': %s"), target, g_strerror (errnum));
    }
  close (fd);
  if (!ok)
    return ts_op_set_error (error, TS_ERROR_IO,
                            _("cannot write '%s': GEGL's png-save did not write the "
                              "whole image (disk full?)"), target);
  return TRUE;
}

static void
save_png (const gchar *path, GeglBuffer *buffer)
{
  GeglNode *graph = gegl_node_new ();
  GeglNode *source = gegl_node_new_child (graph, "operation", "gegl:buffer-source",
                                          "buffer", buffer, NULL);
  GeglNode *save = gegl_node_new_child (graph, "operation", "gegl:png-save",
                                        "path", path, "bitdepth", 8, NULL);

  gegl_node_link (source, save);
  gegl_node_process (save);
  g_object_unref (graph);
}

gboolean
ts_png_set_add (TsPngSet *set, const gchar *target, const guint8 *rgba,
                size_t width, size_t height, gboolean opaque, TsError *error)
{
  GeglRectangle rect = { 0, 0, (gint) width, (gint) height };
  GeglBuffer *buffer;
  char *temp;

  if (!gegl_has_operation ("gegl:png-save"))
    return ts_op_set_error (error, TS_ERROR_IO,
                            _("GEGL's gegl:png-save operation is not available "
                              "(check GEGL_PATH)"));
  /* Reserve a unique name; png-save then replaces the empty file. */
  temp = ts_atomic_reserve (target, error);
  if (!temp)
    return FALSE;
  g_ptr_array_add (set->targets, g_strdup (target));
  g_ptr_array_add (set->temps, temp);

  /* An RGB buffer makes png-save write an RGB file. */
  buffer = gegl_buffer_new (&rect, babl_format_with_space (opaque ? "R'G'B' u8" : "R'G'B'A u8",
                                                           set->space));
  gegl_buffer_set (buffer, &rect, 0, babl_format_with_space ("R'G'B'A u8", set->space), rgba,
                   (gint) width * 4);
  save_png (temp, buffer);
  g_object_unref (buffer);
  return check_png (temp, target, width, height, error);
}

gboolean
ts_png_set_commit (TsPngSet *set, TsError *error)
{
  for (guint i = 0; i < set->temps->len; i++)
    {
      const gchar *target = g_ptr_array_index (set->targets, i);
      if (g_rename (g_ptr_array_index (set->temps, i), target) != 0)
        {
          int errnum = errno;
          /* Earlier files are already in place; drop only the rest. */
          g_ptr_array_remove_range (set->temps, 0, i);
          ts_png_set_abort (set);
          return ts_op_set_error (error, TS_ERROR_IO, _("cannot write '%s': %s"), target,
                       g_strerror (errnum));
        }
    }
  /* The files of a set share one folder. */
  if (set->targets->len > 0)
    ts_atomic_sync_folder (g_ptr_array_index (set->targets, 0));
  clear (set);
  return TRUE;
}

void
ts_png_set_abort (TsPngSet *set)
{
  if (set->temps)
    for (guint i = 0; i < set->temps->len; i++)
      g_unlink (g_ptr_array_index (set->temps, i));
  clear (set);
}
