/* texsynth:volume-save: synthesise a solid texture and save it as a .vol
 * or .dds volume, an atlas PNG, or one PNG per slice.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A sink with the exemplar pads of texsynth:volume-slice ("input", plus
 * optional "aux" and "aux2"; see volume-op-common.h) and its synthesis
 * properties: with the same settings both use one cached volume.
 *
 * format=auto picks the format from the path: a path ending in '/' or
 * naming an existing folder gets PNG slices FOLDER/slice-000.png ...;
 * otherwise .vol, .dds and .png (an atlas) by extension. With
 * format=png-slices and a path that is not a folder, the path less a
 * ".png" is a prefix: "out/wood.png" gives out/wood-000.png .... Folders
 * are never created. Every file appears complete or not at all, and a
 * set of slices all at once; on any failure older files stay as they
 * were and a warning "texsynth:volume-save: <message>" says why.
 *
 * With a map on "aux3" (an image aligned with the exemplar) the files
 * hold the map laid out with the volume's sources instead of its colours;
 * content=source writes the sources themselves (see volume-map.h) as an
 * R16G16B16A16_UINT .dds volume.
 */
#include <glib/gi18n-lib.h>

#include "volume-op-common.h"

#ifdef GEGL_PROPERTIES

enum_start (texsynth_volume_save_format)
  enum_value (TEXSYNTH_VOLUME_SAVE_FORMAT_AUTO, "auto", N_("From the file name"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FORMAT_VOL, "vol", N_(".vol volume"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FORMAT_DDS, "dds", N_(".dds volume texture"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FORMAT_ATLAS, "atlas", N_("Atlas PNG"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FORMAT_PNG_SLICES, "png-slices", N_("One PNG per slice"))
enum_end (TexsynthVolumeSaveFormat)

enum_start (texsynth_volume_save_content)
  enum_value (TEXSYNTH_VOLUME_SAVE_CONTENT_COLOUR, "colour", N_("Colours (or the map)"))
  enum_value (TEXSYNTH_VOLUME_SAVE_CONTENT_SOURCE, "source", N_("Sources: exemplar x, y and orientation"))
enum_end (TexsynthVolumeSaveContent)

enum_start (texsynth_volume_save_axis)
  enum_value (TEXSYNTH_VOLUME_SAVE_AXIS_X, "x", N_("X"))
  enum_value (TEXSYNTH_VOLUME_SAVE_AXIS_Y, "y", N_("Y"))
  enum_value (TEXSYNTH_VOLUME_SAVE_AXIS_Z, "z", N_("Z"))
enum_end (TexsynthVolumeSaveAxis)

enum_start (texsynth_volume_save_cells)
  enum_value (TEXSYNTH_VOLUME_SAVE_CELLS_OFF, "off", N_("Off"))
  enum_value (TEXSYNTH_VOLUME_SAVE_CELLS_ON, "on", N_("On"))
  enum_value (TEXSYNTH_VOLUME_SAVE_CELLS_AUTO, "auto", N_("Automatic"))
enum_end (TexsynthVolumeSaveCells)

enum_start (texsynth_volume_save_free_axis)
  enum_value (TEXSYNTH_VOLUME_SAVE_FREE_NONE, "none", N_("None"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FREE_X, "x", N_("X"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FREE_Y, "y", N_("Y"))
  enum_value (TEXSYNTH_VOLUME_SAVE_FREE_Z, "z", N_("Z"))
enum_end (TexsynthVolumeSaveFreeAxis)

property_file_path (path, _("File"), "")
  description (_("Where to save: a .vol, .dds or .png (atlas) file, or a "
                 "folder ending in '/' for one PNG per slice"))

property_enum (format, _("Format"), TexsynthVolumeSaveFormat, texsynth_volume_save_format,
               TEXSYNTH_VOLUME_SAVE_FORMAT_AUTO)
  description (_("File format; 'auto' chooses it from the path"))

property_enum (content, _("Content"), TexsynthVolumeSaveContent, texsynth_volume_save_content,
               TEXSYNTH_VOLUME_SAVE_CONTENT_COLOUR)
  description (_("What the voxels hold: the colours (or, with a map connected, the map laid "
                 "out the same way), or for each voxel the exemplar pixel it copies, as a "
                 ".dds volume of 16-bit x, y, orientation (0-2), 65535"))

property_enum (axis, _("Axis"), TexsynthVolumeSaveAxis, texsynth_volume_save_axis,
               TEXSYNTH_VOLUME_SAVE_AXIS_Z)
  description (_("For the atlas and PNG slices: the axis the slices are cut "
                 "across (X shows (y, z), Y shows (x, z), Z shows (x, y))"))

property_enum (free_axis, _("Free orientation"), TexsynthVolumeSaveFreeAxis,
               texsynth_volume_save_free_axis, TEXSYNTH_VOLUME_SAVE_FREE_NONE)
  description (_("Leave the slices across this axis unconstrained, so only "
                 "the other two orientations must look like their exemplars"))

/* The cell structure's enum, registered by this op (volume-properties.h). */
#define TS_VOLUME_OP_CELLS      TexsynthVolumeSaveCells
#define TS_VOLUME_OP_CELLS_NAME texsynth_volume_save_cells
#include "volume-properties.h"

#else

#define GEGL_OP_SINK
#define GEGL_OP_BUNDLE
#define GEGL_OP_NAME     texsynth_volume_save
#define GEGL_OP_C_SOURCE texsynth-volume-save.c

/* gegl-op.h's generated boilerplate trips -Wextra; our own code must not. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-const-variable"
#include "gegl-op.h"

/* The property's values are the engine's (TS_VOLUME_OP_FILL_PARAMS). */
_Static_assert ((int) TEXSYNTH_VOLUME_SAVE_CELLS_OFF == (int) TS_CELL_STRUCTURE_OFF
                && (int) TEXSYNTH_VOLUME_SAVE_CELLS_ON == (int) TS_CELL_STRUCTURE_ON
                && (int) TEXSYNTH_VOLUME_SAVE_CELLS_AUTO == (int) TS_CELL_STRUCTURE_AUTO,
                "the cell-structure property's values are the engine's");
#pragma GCC diagnostic pop

#include "volume/volume.h"
#include "volume/layout.h"
#include "volume-png.h"
#include "volume-map.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define RGBA_FORMAT "R'G'B'A u8"

/* Where and how to write, decided before any synthesis. */
typedef struct
{
  gint   format;  /* never AUTO */
  gchar *path;    /* the file, or for PNG slices the prefix of the names */
  gchar *folder;
} Target;

static void
target_clear (Target *target)
{
  g_clear_pointer (&target->path, g_free);
  g_clear_pointer (&target->folder, g_free);
}

static gboolean
has_suffix (const gchar *path, const gchar *suffix)
{
  size_t n = strlen (path), m = strlen (suffix);

  return n >= m && g_ascii_strcasecmp (path + n - m, suffix) == 0;
}

static gboolean
resolve_target (GeglProperties *o, Target *target, TsError *error)
{
  const gchar *path = o->path;
  gboolean folder = path && path[0] &&
                    (g_str_has_suffix (path, "/") || g_file_test (path, G_FILE_TEST_IS_DIR));

  memset (target, 0, sizeof *target);
  if (!path || !path[0])
    return ts_op_set_error (error, TS_ERROR_IO, _("no file name given: set 'path'"));
  target->format = o->format;
  if (target->format == TEXSYNTH_VOLUME_SAVE_FORMAT_AUTO)
    {
      if (folder)
        target->format = TEXSYNTH_VOLUME_SAVE_FORMAT_PNG_SLICES;
      else if (has_suffix (path, ".vol"))
        target->format = TEXSYNTH_VOLUME_SAVE_FORMAT_VOL;
      else if (has_suffix (path, ".dds"))
        target->format = TEXSYNTH_VOLUME_SAVE_FORMAT_DDS;
      else if (has_suffix (path, ".png"))
        target->format = TEXSYNTH_VOLUME_SAVE_FORMAT_ATLAS;
      else
        return ts_op_set_error (error, TS_ERROR_IO,
                                _("cannot tell the format of '%s' from its name: end it with "
                                  ".vol, .dds or .png (an atlas), or with '/' for a folder of PNG "
                                  "slices, or set 'format'"), path);
    }

  if (target->format == TEXSYNTH_VOLUME_SAVE_FORMAT_PNG_SLICES)
    {
      if (folder)
        {
          target->folder = g_strdup (path);
          target->path = g_build_filename (path, "slice-", NULL);
        }
      else
        {
          size_t n = strlen (path) - (has_suffix (path, ".png") ? 4 : 0);
          gchar *stem = g_strndup (path, n);
          target->folder = g_path_get_dirname (path);
          target->path = g_strconcat (stem, "-", NULL);
          g_free (stem);
        }
    }
  else if (folder)
    return ts_op_set_error (error, TS_ERROR_IO,
                            _("'%s' is a folder: give a file name, or use format=png-slices"),
                      path);
  else
    {
      target->folder = g_path_get_dirname (path);
      target->path = g_strdup (path);
    }

  if (!g_file_test (target->folder, G_FILE_TEST_IS_DIR))
    {
      gboolean missing = !g_file_test (target->folder, G_FILE_TEST_EXISTS);
      ts_op_set_error (error, TS_ERROR_IO,
                       missing ? _("the folder '%s' does not exist") : _("'%s' is not a folder"),
                       target->folder);
      target_clear (target);
      return FALSE;
    }
  if (access (target->folder, W_OK) != 0)
    {
      ts_op_set_error (error, TS_ERROR_IO, _("cannot write in the folder '%s': %s"),
                       target->folder, g_strerror (errno));
      target_clear (target);
      return FALSE;
    }
  return TRUE;
}

static gboolean
all_opaque (const guint8 *rgba, size_t size)
{
  for (size_t i = 0; i < size * size * size; i++)
    if (rgba[i * 4 + 3] != 255)
      return FALSE;
  return TRUE;
}

/* The volume as R'G'B'A u8 voxels in `space` (g_free it); *opaque if
 * every voxel is. */
static guint8 *
to_rgba8 (const TsVolumeEntry *entry, const Babl *space, gboolean *opaque, TsError *error)
{
  const Babl *format = babl_format_with_space (RGBA_FORMAT, space);
  size_t size = ts_volume_entry_size (entry), plane = size * size;
  const float *voxels = ts_volume_entry_voxels (entry);
  guint8 *rgba = g_try_malloc (plane * size * 4);

  if (!rgba)
    {
      error->status = TS_ERROR_OUT_OF_MEMORY;
      snprintf (error->message, sizeof error->message,
                _("out of memory converting the %zu^3 volume to 8 bits (%.1f MiB)"), size,
                (double) (plane * size * 4) / 1048576.0);
      return NULL;
    }
  for (size_t z = 0; z < size; z++)
    ts_op_lab_to_format (voxels + z * plane * TS_CHANNELS, format, rgba + z * plane * 4, plane);
  *opaque = all_opaque (rgba, size);
  return rgba;
}

/* Refuse, before any synthesis, what cannot be written. */
static gboolean
check_content (GeglOperation *operation, GeglProperties *o, const Target *target,
               TsError *error)
{
  if (o->content == TEXSYNTH_VOLUME_SAVE_CONTENT_SOURCE)
    {
      if (ts_volume_map_connected (operation))
        return ts_op_set_error (error, TS_ERROR_IO,
                                _("content=source writes the sources, not a map: disconnect "
                                  "the map or set content=colour"));
      if (target->format != TEXSYNTH_VOLUME_SAVE_FORMAT_DDS)
        return ts_op_set_error (error, TS_ERROR_IO,
                                _("content=source is written as a .dds volume only "
                                  "(16-bit x, y, orientation): end the path with .dds"));
      return TRUE;
    }
  return !ts_volume_map_connected (operation) ||
         ts_volume_map_check (operation, o->free_axis, error);
}

static gboolean
write_volume_file (GeglProperties *o, const Target *target, guint8 *rgba, size_t size,
                   gboolean opaque, TsError *error)
{
  TsVolume8 volume = { size, 4, o->periodic, rgba };

  if (target->format == TEXSYNTH_VOLUME_SAVE_FORMAT_DDS)
    return ts_volume_write_dds (target->path, &volume, error) == TS_OK;

  if (opaque) /* .vol keeps RGB when alpha says nothing */
    {
      size_t voxels = size * size * size;
      for (size_t i = 0; i < voxels; i++)
        memmove (rgba + i * 3, rgba + i * 4, 3);
      volume.channels = 3;
    }
  {
    gchar *base = g_path_get_basename (target->path);
    gchar *dot = strrchr (base, '.');
    gboolean ok;
    if (dot && dot != base)
      *dot = '\0';
    ok = ts_volume_write_vol (target->path, base, &volume, error) == TS_OK;
    g_free (base);
    return ok;
  }
}

static gboolean
write_pngs (GeglOperation *operation, GeglProperties *o, const Target *target,
            const guint8 *rgba, const Babl *space, size_t size, gboolean opaque, TsError *error)
{
  gboolean atlas = target->format == TEXSYNTH_VOLUME_SAVE_FORMAT_ATLAS;
  size_t width = size, height = size, columns, rows, images = atlas ? 1 : size;
  int digits = 1;
  guint8 *image;
  gboolean ok = TRUE;
  TsPngSet set;

  for (size_t n = size - 1; n >= 10; n /= 10)
    digits++;
  digits = MAX (3, digits); /* slice-000.png ... sorts by name */
  if (atlas)
    {
      ts_volume_atlas_extent (size, &width, &height);
      ts_volume_atlas_grid (size, &columns, &rows);
      opaque = opaque && columns * rows == size; /* empty cells are transparent */
    }
  image = g_try_malloc (width * height * 4);
  if (!image)
    {
      error->status = TS_ERROR_OUT_OF_MEMORY;
      snprintf (error->message, sizeof error->message, _("out of memory for a %zux%zu image"),
                width, height);
      return FALSE;
    }

  ts_png_set_init (&set, space);
  for (size_t i = 0; i < images && ok; i++)
    {
      gchar *name = atlas ? g_strdup (target->path)
                          : g_strdup_printf ("%s%0*zu.png", target->path, digits, i);
      if (atlas)
        ts_volume_extract_atlas (rgba, size, 4, o->axis, image);
      else
        ts_volume_extract_slice (rgba, size, 4, o->axis, i, image);
      ok = ts_png_set_add (&set, name, image, width, height, opaque, error);
      g_free (name);
      gegl_operation_progress (operation, (double) (i + 1) / (double) images, "writing");
    }
  g_free (image);
  if (ok)
    return ts_png_set_commit (&set, error);
  ts_png_set_abort (&set);
  return FALSE;
}

static void
save (GeglOperation *operation, GeglBuffer *input, GeglBuffer *aux, GeglBuffer *aux2)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  TsSolidParams params;
  TsError error = { TS_OK, "" };
  TsVolumeEntry *entry = NULL;
  Target target;
  guint8 *rgba = NULL;
  gboolean opaque = TRUE, ok;
  /* The exemplar's space, or with a map the map's: files hold their bytes. */
  const Babl *space = ts_op_source_space (operation, ts_volume_map_connected (operation)
                                                     ? TS_VOLUME_MAP_PAD : "input");

  TS_VOLUME_OP_FILL_PARAMS (o, &params);
  ok = resolve_target (o, &target, &error) && check_content (operation, o, &target, &error);
  if (ok)
    entry = ts_volume_op_acquire (operation, input, aux, aux2, &params, o->free_axis, &error);
  if (entry && o->content == TEXSYNTH_VOLUME_SAVE_CONTENT_SOURCE)
    {
      guint16 *xy = ts_volume_sources_xy (operation, entry, &error);
      ok = xy && ts_volume_write_dds_sources (target.path, ts_volume_entry_size (entry), xy,
                                              &error) == TS_OK;
      g_free (xy);
      ts_volume_cache_release (entry);
      entry = NULL;
    }
  else if (entry && ts_volume_map_connected (operation))
    {
      const Babl *format = babl_format_with_space (RGBA_FORMAT, space);
      ok = (rgba = ts_volume_map_lay_out (operation, entry, format, &error))
           != NULL;
      opaque = ok && all_opaque (rgba, ts_volume_entry_size (entry));
    }
  else
    ok = entry && (rgba = to_rgba8 (entry, space, &opaque, &error));
  if (ok && rgba)
    {
      size_t size = ts_volume_entry_size (entry);
      ts_volume_cache_release (entry);  /* the 8-bit copy is enough now */
      entry = NULL;
      if (target.format == TEXSYNTH_VOLUME_SAVE_FORMAT_VOL ||
          target.format == TEXSYNTH_VOLUME_SAVE_FORMAT_DDS)
        ok = write_volume_file (o, &target, rgba, size, opaque, &error);
      else
        ok = write_pngs (operation, o, &target, rgba, space, size, opaque, &error);
    }
  ts_volume_cache_release (entry);
  g_free (rgba);
  target_clear (&target);
  if (!ok)
    g_warning ("%s: %s", gegl_operation_get_name (operation),
               error.message[0] ? error.message : ts_status_string (error.status));
}

/* The buffer of an input pad. GEGL's processor gives a sink that needs
 * all of its input only "input" (the producer's cache), so the exemplar
 * pads added here are rendered on demand. NULL if not connected. */
static GeglBuffer *
pad_buffer (GeglOperation *operation, GeglOperationContext *context, const gchar *pad)
{
  GObject *object = gegl_operation_context_dup_object (context, pad);
  GeglNode *source = gegl_operation_get_source_node (operation, pad);
  GeglRectangle rect;
  GeglBuffer *buffer;
  const Babl *format;

  if (object)
    return GEGL_BUFFER (object);
  if (!source)
    return NULL;
  rect = ts_volume_op_required_input (operation, pad);
  /* In the source's own format, so that op-lab.c reads it as volume-slice
   * reads its pads (and they share the cached volume). */
  format = gegl_operation_get_source_format (operation, pad);
  buffer = gegl_buffer_new (&rect, format ? format : babl_format (TS_OP_FORMAT));
  if (rect.width > 0 && rect.height > 0)
    gegl_node_blit_buffer (source, buffer, &rect, 0, GEGL_ABYSS_NONE);
  return buffer;
}

/* Replaces the sink's processing, which only passes "input" on. */
static gboolean
process (GeglOperation        *operation,
         GeglOperationContext *context,
         const gchar          *output_pad G_GNUC_UNUSED,
         const GeglRectangle  *roi G_GNUC_UNUSED,
         gint                  level G_GNUC_UNUSED)
{
  GeglBuffer *input = pad_buffer (operation, context, "input");
  GeglBuffer *aux = pad_buffer (operation, context, "aux");
  GeglBuffer *aux2 = pad_buffer (operation, context, "aux2");

  save (operation, input, aux, aux2);
  g_clear_object (&input);
  g_clear_object (&aux);
  g_clear_object (&aux2);
  return TRUE;
}

static void
add_input_pad (GeglOperation *operation, const gchar *name, const gchar *label,
               const gchar *blurb)
{
  GParamSpec *pspec = g_param_spec_object (name, label, blurb, GEGL_TYPE_BUFFER,
                                           G_PARAM_READWRITE | GEGL_PARAM_PAD_INPUT);

  gegl_operation_create_pad (operation, pspec);
  g_param_spec_sink (pspec);
}

static void
attach (GeglOperation *operation)
{
  GEGL_OPERATION_CLASS (gegl_op_parent_class)->attach (operation);
  add_input_pad (operation, "aux", _("X exemplar"),
                 _("Exemplar of the slices across x (default: the input)"));
  add_input_pad (operation, "aux2", _("Y exemplar"),
                 _("Exemplar of the slices across y (default: the input)"));
  ts_volume_map_add_pad (operation);
}

static void
prepare (GeglOperation *operation)
{
  ts_volume_op_prepare_inputs (operation);
}

static GeglRectangle
get_required_for_output (GeglOperation       *operation,
                         const gchar         *input_pad,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  return ts_volume_op_required_input (operation, input_pad);
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass     *operation_class = GEGL_OPERATION_CLASS (klass);
  GeglOperationSinkClass *sink_class      = GEGL_OPERATION_SINK_CLASS (klass);

  operation_class->attach                  = attach;
  operation_class->prepare                 = prepare;
  operation_class->process                 = process;
  operation_class->get_required_for_output = get_required_for_output;
  operation_class->threaded                = FALSE;
  /* One call with all of every input, once per processing. */
  sink_class->needs_full                   = TRUE;

  gegl_operation_class_set_keys (operation_class,
    "name",        "texsynth:volume-save",
    "title",       _("Save Solid Texture"),
    "categories",  "output",
    "description", _("Synthesises a solid (3D) texture whose slices look like "
                     "the input image(s) and saves it as a .vol or .dds volume, "
                     "an atlas PNG or one PNG per slice"),
    NULL);
}

#endif
