/* Reading a feature map for the match (see op-features.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "op-features.h"

#include <gegl-plugin.h>
#include <glib/gi18n-lib.h>
#include <stdio.h>

gboolean
ts_op_read_features (GeglOperation *operation,
                     GeglBuffer    *aux,
                     TsFeatureMap  *features,
                     gchar         *message,
                     gsize          message_size)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, "aux");
  gsize pixels;
  float *rgb;
  gboolean grey = TRUE;

  memset (features, 0, sizeof *features);
  if (!aux || !box || box->width <= 0 || box->height <= 0 ||
      gegl_rectangle_is_infinite_plane (box) ||
      box->width > TS_MAX_OUTPUT_SIDE || box->height > TS_MAX_OUTPUT_SIDE)
    {
      snprintf (message, message_size,
                _("the feature map (aux) is empty, unbounded or larger than %dx%d"),
                TS_MAX_OUTPUT_SIDE, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }
  pixels = (gsize) box->width * (gsize) box->height;
  rgb = g_try_malloc (pixels * 3 * sizeof (float));
  if (!rgb)
    {
      snprintf (message, message_size, _("out of memory reading the %dx%d feature map"),
                box->width, box->height);
      return FALSE;
    }
  gegl_buffer_get (aux, box, 1.0, babl_format ("R'G'B' float"), rgb,
                   GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
  for (gsize i = 0; i < pixels && grey; i++)
    grey = rgb[3 * i] == rgb[3 * i + 1] && rgb[3 * i] == rgb[3 * i + 2];
  if (grey)
    for (gsize i = 0; i < pixels; i++)
      rgb[i] = rgb[3 * i];
  features->width = (size_t) box->width;
  features->height = (size_t) box->height;
  features->channels = grey ? 1 : 3;
  features->values = rgb;
  return TRUE;
}
