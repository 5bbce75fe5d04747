/* The synthesis's layout as a gegl:map-absolute map (see op-source-map.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "op-source-map.h"
#include "op-common.h"

#include <gegl-plugin.h>

const Babl *
ts_op_source_map_format (void)
{
  return babl_format_n (babl_type ("float"), 2);
}

void
ts_op_prepare_source_map (GeglOperation *operation, gboolean source_map)
{
  gegl_operation_set_format (operation, "input", babl_format (TS_OP_FORMAT));
  gegl_operation_set_format (operation, "output", source_map ? ts_op_source_map_format ()
                                                             : ts_op_result_format (operation));
}

gboolean
ts_op_write_source_map (GeglBuffer          *output,
                        const GeglRectangle *roi,
                        const int32_t       *map,
                        size_t               width,
                        size_t               height,
                        gint                 x,
                        gint                 y,
                        gint                 origin_x,
                        gint                 origin_y)
{
  GeglRectangle whole = { x, y, (gint) width, (gint) height };
  GeglRectangle part;
  float *coords;

  if (!gegl_rectangle_intersect (&part, &whole, roi))
    return TRUE;
  coords = g_try_malloc ((gsize) part.width * (gsize) part.height * 2 * sizeof (float));
  if (!coords)
    {
      gegl_buffer_clear (output, roi);
      return FALSE;
    }
  for (gint j = 0; j < part.height; j++)
    for (gint i = 0; i < part.width; i++)
      {
        size_t u = (size_t) (part.x - x + i), v = (size_t) (part.y - y + j);
        const int32_t *s = map ? map + 2 * (v * width + u) : NULL;
        float *c = coords + 2 * ((size_t) j * (size_t) part.width + (size_t) i);
        /* Whole numbers plus one half: exact in float up to 2^23. */
        c[0] = (float) origin_x + (float) (s ? s[0] : (int32_t) u) + 0.5f;
        c[1] = (float) origin_y + (float) (s ? s[1] : (int32_t) v) + 0.5f;
      }
  gegl_buffer_set (output, &part, 0, ts_op_source_map_format (), coords, GEGL_AUTO_ROWSTRIDE);
  g_free (coords);
  return TRUE;
}
