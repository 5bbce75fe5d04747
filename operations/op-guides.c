/* Reading texsynth:guided's pads (see op-guides.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "op-guides.h"

#include <gegl-plugin.h>
#include <glib/gi18n-lib.h>
#include <stdio.h>

gboolean
ts_op_pad_box (GeglOperation *operation, const gchar *pad, const gchar *what,
               GeglRectangle *box, gchar *message, gsize message_size)
{
  const GeglRectangle *source = gegl_operation_source_get_bounding_box (operation, pad);

  if (!source || source->width <= 0 || source->height <= 0)
    {
      /* TRANSLATORS: %s names an input, e.g. "the exemplar (aux)". */
      snprintf (message, message_size, _("%s is missing or empty"), what);
      return FALSE;
    }
  if (gegl_rectangle_is_infinite_plane (source) || source->width > TS_MAX_OUTPUT_SIDE ||
      source->height > TS_MAX_OUTPUT_SIDE)
    {
      snprintf (message, message_size,
                _("%s is unbounded or larger than %dx%d; crop it"), what,
                TS_MAX_OUTPUT_SIDE, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }
  *box = *source;
  return TRUE;
}

gboolean
ts_op_read_guide (GeglBuffer *buffer, const GeglRectangle *box, float **rgb, gboolean *grey,
                  gchar *message, gsize message_size)
{
  gsize pixels = (gsize) box->width * (gsize) box->height;

  *rgb = g_try_malloc (pixels * 3 * sizeof (float));
  if (!*rgb)
    {
      snprintf (message, message_size, _("out of memory reading a %dx%d guide"), box->width,
                box->height);
      return FALSE;
    }
  gegl_buffer_get (buffer, box, 1.0, babl_format ("R'G'B' float"), *rgb, GEGL_AUTO_ROWSTRIDE,
                   GEGL_ABYSS_NONE);
  *grey = TRUE;
  for (gsize i = 0; i < pixels && *grey; i++)
    *grey = (*rgb)[3 * i] == (*rgb)[3 * i + 1] && (*rgb)[3 * i] == (*rgb)[3 * i + 2];
  return TRUE;
}

void
ts_op_guide_to_grey (float *rgb, gsize pixels)
{
  for (gsize i = 0; i < pixels; i++)
    rgb[i] = rgb[3 * i];
}
