/* Aligned maps and source coordinates for the volume ops.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "volume-map.h"

#include <glib/gi18n-lib.h>
#include <stdio.h>

void
ts_volume_map_add_pad (GeglOperation *operation)
{
  GParamSpec *pspec = g_param_spec_object (TS_VOLUME_MAP_PAD, _("Map"),
                                           _("An image aligned with the exemplar (roughness, "
                                             "height ...): shown or saved laid out as the "
                                             "volume's colours are"),
                                           GEGL_TYPE_BUFFER,
                                           G_PARAM_READWRITE | GEGL_PARAM_PAD_INPUT);

  gegl_operation_create_pad (operation, pspec);
  g_param_spec_sink (pspec);
}

gboolean
ts_volume_map_connected (GeglOperation *operation)
{
  return gegl_operation_get_source_node (operation, TS_VOLUME_MAP_PAD) != NULL;
}

static GeglRectangle
pad_box (GeglOperation *operation, const gchar *pad)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, pad);
  GeglRectangle empty = { 0, 0, 0, 0 };

  return box ? *box : empty;
}

gboolean
ts_volume_map_check (GeglOperation *operation, int free_axis, TsError *error)
{
  GeglRectangle map = pad_box (operation, TS_VOLUME_MAP_PAD);
  GeglRectangle input = pad_box (operation, "input");
  /* "aux" gives the slices across x, "aux2" those across y. */
  gboolean other_x = gegl_operation_get_source_node (operation, "aux") != NULL &&
                     free_axis != TS_VOLUME_OP_FREE_X;
  gboolean other_y = gegl_operation_get_source_node (operation, "aux2") != NULL &&
                     free_axis != TS_VOLUME_OP_FREE_Y;

  if (other_x || other_y)
    return ts_op_set_error (error, TS_ERROR_BAD_PARAMETER,
                            _("a map is aligned with one exemplar, but '%s' gives the slices across %s "
                              "their own: disconnect the map and save content=source, which names each "
                              "voxel's exemplar"), other_x ? "aux" : "aux2", other_x ? "x" : "y");
  if (map.width != input.width || map.height != input.height)
    return ts_op_set_error (error, TS_ERROR_BAD_PARAMETER,
                            _("the map is %dx%d but the exemplar %dx%d: a map must be aligned with the "
                              "exemplar, pixel for pixel"),
                            map.width, map.height, input.width, input.height);
  return TRUE;
}

void *
ts_volume_map_lay_out (GeglOperation *operation, const TsVolumeEntry *entry, const Babl *format,
                       TsError *error)
{
  GeglNode *source = gegl_operation_get_source_node (operation, TS_VOLUME_MAP_PAD);
  GeglRectangle box = pad_box (operation, TS_VOLUME_MAP_PAD);
  size_t size = ts_volume_entry_size (entry), voxels = size * size * size;
  size_t pixel_bytes = (size_t) babl_format_get_bytes_per_pixel (format);
  size_t pixels = (size_t) box.width * (size_t) box.height;
  guint8 *map, *laid;

  if (!source || box.width <= 0 || box.height <= 0)
    {
      ts_op_set_error (error, TS_ERROR_BAD_PARAMETER,
                       _("the map is %dx%d but the exemplar %dx%d: a map "
                         "must be aligned with the exemplar, pixel for pixel"),
                       box.width, box.height, 0, 0);
      return NULL;
    }
  map = g_try_malloc (pixels * pixel_bytes);
  laid = g_try_malloc (voxels * pixel_bytes);
  if (!map || !laid)
    {
      g_free (map);
      g_free (laid);
      ts_op_set_error (error, TS_ERROR_OUT_OF_MEMORY,
                       _("out of memory for a %zux%zu slice"), size, size);
      return NULL;
    }
  /* Straight from the map's node in the asked format: 8-bit maps are
   * copied byte for byte, never through the engine's Lab. */
  gegl_node_blit (source, 1.0, &box, format, map, GEGL_AUTO_ROWSTRIDE, GEGL_BLIT_DEFAULT);
  {
    const void *maps[3] = { map, map, map };
    size_t counts[3] = { pixels, pixels, pixels };
    if (ts_solid_apply_sources (ts_volume_entry_sources (entry), voxels, maps, counts,
                                pixel_bytes, laid, error) != TS_OK)
      g_clear_pointer (&laid, g_free);
  }
  g_free (map);
  return laid;
}

guint16 *
ts_volume_sources_xy (GeglOperation *operation, const TsVolumeEntry *entry, TsError *error)
{
  /* The exemplar rule of volume-op-common.h: x from "aux", y from
   * "aux2", each else from "input"; z always from "input". */
  const gchar *pads[3] = { "aux", "aux2", "input" };
  size_t size = ts_volume_entry_size (entry), voxels = size * size * size, width[3];
  const TsSolidSource *sources = ts_volume_entry_sources (entry);
  guint16 *xy = g_try_malloc (voxels * 4 * sizeof (guint16));

  if (!xy)
    {
      ts_op_set_error (error, TS_ERROR_OUT_OF_MEMORY,
                       _("out of memory for a %zux%zu slice"), size, size);
      return NULL;
    }
  for (int a = 0; a < 3; a++)
    {
      const gchar *pad = gegl_operation_get_source_node (operation, pads[a]) ? pads[a] : "input";
      GeglRectangle box = pad_box (operation, pad);
      width[a] = box.width > 0 ? (size_t) box.width : 1;
    }
  for (size_t p = 0; p < voxels; p++)
    {
      int axis = ts_solid_source_axis (sources[p]);
      size_t index = ts_solid_source_index (sources[p]);
      /* Sides are at most TS_MAX_OUTPUT_SIDE = 16384: 16 bits hold them. */
      xy[p * 4] = (guint16) (index % width[axis]);
      xy[p * 4 + 1] = (guint16) (index / width[axis]);
      xy[p * 4 + 2] = (guint16) axis;
      xy[p * 4 + 3] = 65535;
    }
  return xy;
}
