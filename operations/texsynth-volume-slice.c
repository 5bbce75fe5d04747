/* texsynth:volume-slice: one slice, or an atlas of all slices along an
 * axis, of a solid texture synthesised from 2D exemplars.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A whole-image composer: "input" is the exemplar of every slice
 * orientation without one of its own, "aux" that of the slices across x
 * and "aux2" that of the slices across y (see volume-op-common.h). The
 * volume comes from the module's volume cache, so other slices, axes and
 * layouts of the same volume, and texsynth:volume-save with the same
 * settings, do not synthesise it again. Failures give a warning
 * "texsynth:volume-slice: <message>" and a transparent result.
 *
 * With a map on "aux3" (an image aligned with the exemplar, see
 * volume-map.h) the op shows the map laid out with the volume's sources
 * instead of its colours, in R'G'B'A float so that the map's own values
 * pass unchanged.
 */
#include <glib/gi18n-lib.h>

#include "volume-op-common.h"

#ifdef GEGL_PROPERTIES

enum_start (texsynth_volume_slice_axis)
  enum_value (TEXSYNTH_VOLUME_SLICE_AXIS_X, "x", N_("X"))
  enum_value (TEXSYNTH_VOLUME_SLICE_AXIS_Y, "y", N_("Y"))
  enum_value (TEXSYNTH_VOLUME_SLICE_AXIS_Z, "z", N_("Z"))
enum_end (TexsynthVolumeSliceAxis)

enum_start (texsynth_volume_slice_layout)
  enum_value (TEXSYNTH_VOLUME_SLICE_LAYOUT_SLICE, "slice", N_("One slice"))
  enum_value (TEXSYNTH_VOLUME_SLICE_LAYOUT_ATLAS, "atlas", N_("Atlas of all slices"))
enum_end (TexsynthVolumeSliceLayout)

enum_start (texsynth_volume_slice_cells)
  enum_value (TEXSYNTH_VOLUME_SLICE_CELLS_OFF, "off", N_("Off"))
  enum_value (TEXSYNTH_VOLUME_SLICE_CELLS_ON, "on", N_("On"))
  enum_value (TEXSYNTH_VOLUME_SLICE_CELLS_AUTO, "auto", N_("Automatic"))
enum_end (TexsynthVolumeSliceCells)

enum_start (texsynth_volume_slice_free_axis)
  enum_value (TEXSYNTH_VOLUME_SLICE_FREE_NONE, "none", N_("None"))
  enum_value (TEXSYNTH_VOLUME_SLICE_FREE_X, "x", N_("X"))
  enum_value (TEXSYNTH_VOLUME_SLICE_FREE_Y, "y", N_("Y"))
  enum_value (TEXSYNTH_VOLUME_SLICE_FREE_Z, "z", N_("Z"))
enum_end (TexsynthVolumeSliceFreeAxis)

property_enum (axis, _("Axis"), TexsynthVolumeSliceAxis, texsynth_volume_slice_axis,
               TEXSYNTH_VOLUME_SLICE_AXIS_Z)
  description (_("The axis the slices are cut across: X shows (y, z), "
                 "Y shows (x, z), Z shows (x, y)"))

property_int (index, _("Slice"), -1)
  description (_("Which slice along the axis, 0 to size - 1; -1 is the "
                 "middle slice (not used for the atlas)"))
  value_range (-1, G_MAXINT)
  ui_range    (-1, 255)

property_enum (layout, _("Layout"), TexsynthVolumeSliceLayout, texsynth_volume_slice_layout,
               TEXSYNTH_VOLUME_SLICE_LAYOUT_SLICE)
  description (_("One slice, or all slices along the axis side by side in "
                 "a grid, row by row"))

property_enum (free_axis, _("Free orientation"), TexsynthVolumeSliceFreeAxis,
               texsynth_volume_slice_free_axis, TEXSYNTH_VOLUME_SLICE_FREE_NONE)
  description (_("Leave the slices across this axis unconstrained, so only "
                 "the other two orientations must look like their exemplars "
                 "(suits exemplars such as wood, whose cross-section differs)"))

/* The cell structure's enum, registered by this op (volume-properties.h). */
#define TS_VOLUME_OP_CELLS      TexsynthVolumeSliceCells
#define TS_VOLUME_OP_CELLS_NAME texsynth_volume_slice_cells
#include "volume-properties.h"

#else

#define GEGL_OP_COMPOSER3
#define GEGL_OP_BUNDLE
#define GEGL_OP_NAME     texsynth_volume_slice
#define GEGL_OP_C_SOURCE texsynth-volume-slice.c

/* gegl-op.h's generated boilerplate trips -Wextra; our own code must not. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-const-variable"
#include "gegl-op.h"

/* The property's values are the engine's (TS_VOLUME_OP_FILL_PARAMS). */
_Static_assert ((int) TEXSYNTH_VOLUME_SLICE_CELLS_OFF == (int) TS_CELL_STRUCTURE_OFF
                && (int) TEXSYNTH_VOLUME_SLICE_CELLS_ON == (int) TS_CELL_STRUCTURE_ON
                && (int) TEXSYNTH_VOLUME_SLICE_CELLS_AUTO == (int) TS_CELL_STRUCTURE_AUTO,
                "the cell-structure property's values are the engine's");
#pragma GCC diagnostic pop

#include "volume/layout.h"
#include "volume-map.h"

#include <stdio.h>

#define VOXEL_BYTES (TS_CHANNELS * sizeof (float))
#define MAP_FORMAT "R'G'B'A float"

static GeglRectangle
get_bounding_box (GeglOperation *operation)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  GeglRectangle box = { 0, 0, o->size, o->size };

  if (o->layout == TEXSYNTH_VOLUME_SLICE_LAYOUT_ATLAS)
    {
      size_t width, height;
      ts_volume_atlas_extent ((size_t) o->size, &width, &height);
      box.width = (gint) width;   /* at most 23 * 512 */
      box.height = (gint) height;
    }
  return box;
}

/* A map's values pass in its own space. */
static const Babl *
map_format (GeglOperation *operation)
{
  return babl_format_with_space (MAP_FORMAT, ts_op_source_space (operation, TS_VOLUME_MAP_PAD));
}

static void
prepare (GeglOperation *operation)
{
  ts_volume_op_prepare_inputs (operation);
  gegl_operation_set_format (operation, TS_VOLUME_MAP_PAD, map_format (operation));
  /* Colours in the input's space, as the other ops give them. */
  gegl_operation_set_format (operation, "output",
                             ts_volume_map_connected (operation) ? map_format (operation)
                                                                 : ts_op_result_format (operation));
}

static void
attach (GeglOperation *operation)
{
  GEGL_OPERATION_CLASS (gegl_op_parent_class)->attach (operation);
  ts_volume_map_add_pad (operation);
}

static GeglRectangle
get_required_for_output (GeglOperation       *operation,
                         const gchar         *input_pad,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  return ts_volume_op_required_input (operation, input_pad);
}

/* The slice the properties ask for, checked before any synthesis. */
static gboolean
slice_index (GeglProperties *o, size_t *index, TsError *error)
{
  if (o->index == -1)
    {
      *index = (size_t) o->size / 2;
      return TRUE;
    }
  if (o->index >= 0 && o->index < o->size)
    {
      *index = (size_t) o->index;
      return TRUE;
    }
  error->status = TS_ERROR_BAD_PARAMETER;
  snprintf (error->message, sizeof error->message,
            _("slice %d does not exist: the volume is %d voxels on each side, so the "
              "index must be 0 to %d (or -1 for the middle slice)"),
            o->index, o->size, o->size - 1);
  return FALSE;
}

/* Write the slices of `voxels` (VOXEL_BYTES each, in `format`, or in Lab
 * when `format` is NULL) that `roi` shows: one slice, or every cell of
 * the atlas (unused cells stay transparent). One slice at a time, so no
 * atlas-sized copy is needed. */
static gboolean
write_slices (GeglProperties *o, const float *voxels, size_t size, const Babl *format,
              size_t index, GeglBuffer *output, const GeglRectangle *roi, TsError *error)
{
  size_t columns = 1, rows = 1, slices = 1;
  TsImage slice = { size, size, NULL };

  if (o->layout == TEXSYNTH_VOLUME_SLICE_LAYOUT_ATLAS)
    {
      ts_volume_atlas_grid (size, &columns, &rows);
      slices = size;
      index = 0;
    }
  slice.pixels = g_try_malloc (size * size * VOXEL_BYTES);
  if (!slice.pixels)
    {
      error->status = TS_ERROR_OUT_OF_MEMORY;
      snprintf (error->message, sizeof error->message, _("out of memory for a %zux%zu slice"),
                size, size);
      return FALSE;
    }
  gegl_buffer_clear (output, roi);
  for (size_t i = 0; i < slices; i++)
    {
      GeglRectangle cell = { (gint) (i % columns * size), (gint) (i / columns * size),
                             (gint) size, (gint) size };
      if (!gegl_rectangle_intersect (NULL, &cell, roi))
        continue;
      GeglRectangle shown;
      ts_volume_extract_slice (voxels, size, VOXEL_BYTES, o->axis, index + i, slice.pixels);
      gegl_rectangle_intersect (&shown, &cell, roi);
      const float *first = slice.pixels + ((size_t) (shown.y - cell.y) * size
                                           + (size_t) (shown.x - cell.x)) * TS_CHANNELS;
      if (format)
        gegl_buffer_set (output, &shown, 0, format, first, (gint) (size * VOXEL_BYTES));
      else
        ts_op_write_lab (output, &shown, first, size * VOXEL_BYTES);
    }
  g_free (slice.pixels);
  return TRUE;
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *input,
         GeglBuffer          *aux,
         GeglBuffer          *aux2,
         GeglBuffer          *output,
         const GeglRectangle *roi,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  TsSolidParams params;
  TsError error = { TS_OK, "" };
  TsVolumeEntry *entry = NULL;
  size_t index = 0;
  gboolean ok;

  gboolean map = ts_volume_map_connected (operation);
  float *laid = NULL;

  TS_VOLUME_OP_FILL_PARAMS (o, &params);
  ok = (o->layout == TEXSYNTH_VOLUME_SLICE_LAYOUT_ATLAS || slice_index (o, &index, &error)) &&
       (!map || ts_volume_map_check (operation, o->free_axis, &error));
  if (ok)
    entry = ts_volume_op_acquire (operation, input, aux, aux2, &params, o->free_axis, &error);
  if (entry && map)
    ok = (laid = ts_volume_map_lay_out (operation, entry, map_format (operation), &error))
         && write_slices (o, laid, ts_volume_entry_size (entry), map_format (operation), index,
                          output, roi, &error);
  else
    ok = entry && write_slices (o, ts_volume_entry_voxels (entry), ts_volume_entry_size (entry),
                                NULL, index, output, roi, &error);
  g_free (laid);
  ts_volume_cache_release (entry);

  /* As the other ops: a defined (transparent) result and TRUE, so that a
   * graph goes on rendering and the warning says what went wrong. */
  if (!ok)
    ts_op_fail (operation, output, roi,
                error.message[0] ? error.message : ts_status_string (error.status));
  return TRUE;
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass          *operation_class = GEGL_OPERATION_CLASS (klass);
  GeglOperationComposer3Class *composer_class  = GEGL_OPERATION_COMPOSER3_CLASS (klass);

  ts_op_class_init_whole_image_methods (operation_class, get_bounding_box);
  operation_class->attach                    = attach;
  operation_class->prepare                   = prepare;
  operation_class->get_required_for_output   = get_required_for_output;
  composer_class->process                    = process;
  composer_class->aux_label                  = _("X exemplar");
  composer_class->aux_description            = _("Exemplar of the slices across x "
                                                 "(default: the input)");
  composer_class->aux2_label                 = _("Y exemplar");
  composer_class->aux2_description           = _("Exemplar of the slices across y "
                                                 "(default: the input)");

  gegl_operation_class_set_keys (operation_class,
    "name",               "texsynth:volume-slice",
    "title",              _("Solid Texture Slice"),
    "categories",         "render:tile",
    "position-dependent", "true",
    "description",        _("Synthesises a solid (3D) texture whose slices look "
                            "like the input image(s), and shows one slice or "
                            "all slices along one axis in an atlas"),
    NULL);
}

#endif
