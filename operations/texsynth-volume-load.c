/* texsynth:volume-load: one slice, or an atlas of all slices, of a solid
 * texture stored as .vol or .dds.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A source op. The volume is read once per file version (path, size,
 * modification time, inode) and kept in the op instance, so moving
 * through the slices of one file does not read it again. Failures follow
 * GEGL's file loaders: a warning "texsynth:volume-load: <message>" and an
 * empty (0x0) result; a slice index outside the volume gives a
 * transparent slice of the volume's size.
 */
#include <glib/gi18n-lib.h>

#ifdef GEGL_PROPERTIES

enum_start (texsynth_volume_load_axis)
  enum_value (TEXSYNTH_VOLUME_LOAD_AXIS_X, "x", N_("X"))
  enum_value (TEXSYNTH_VOLUME_LOAD_AXIS_Y, "y", N_("Y"))
  enum_value (TEXSYNTH_VOLUME_LOAD_AXIS_Z, "z", N_("Z"))
enum_end (TexsynthVolumeLoadAxis)

enum_start (texsynth_volume_load_layout)
  enum_value (TEXSYNTH_VOLUME_LOAD_LAYOUT_SLICE, "slice", N_("One slice"))
  enum_value (TEXSYNTH_VOLUME_LOAD_LAYOUT_ATLAS, "atlas", N_("Atlas of all slices"))
enum_end (TexsynthVolumeLoadLayout)

property_file_path (path, _("File"), "")
  description (_("A solid texture: a .vol file (the format of Kopf et al.'s "
                 "solid texture viewers) or an uncompressed .dds volume "
                 "texture"))

property_enum (axis, _("Axis"), TexsynthVolumeLoadAxis, texsynth_volume_load_axis,
               TEXSYNTH_VOLUME_LOAD_AXIS_Z)
  description (_("The axis the slices are cut across: X shows (y, z), "
                 "Y shows (x, z), Z shows (x, y)"))

property_int (index, _("Slice"), 0)
  description (_("Which slice along the axis, from 0 to the volume's size "
                 "minus 1 (not used for the atlas)"))
  value_range (0, G_MAXINT)
  ui_range (0, 511)

property_enum (layout, _("Layout"), TexsynthVolumeLoadLayout, texsynth_volume_load_layout,
               TEXSYNTH_VOLUME_LOAD_LAYOUT_SLICE)
  description (_("One slice, or all slices along the axis side by side in "
                 "a grid, row by row"))

#else

#define GEGL_OP_SOURCE
#define GEGL_OP_NAME     texsynth_volume_load
#define GEGL_OP_C_SOURCE texsynth-volume-load.c

/* gegl-op.h's generated boilerplate trips -Wextra; our own code must not. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define GEGL_OP_BUNDLE /* TS_OP_MODULE: the module entry points bind the text domain */
#include "gegl-op.h"
#pragma GCC diagnostic pop

#include "op-common.h"
#include "volume/volume.h"
#include "volume/layout.h"

TS_OP_MODULE (texsynth_volume_load)

#include <errno.h>
#include <string.h>
#include <sys/stat.h>

#define OUTPUT_FORMAT "R'G'B'A u8"
/* Voxel memory a file may need; larger files are refused with a message. */
#define MAX_VOLUME_BYTES ((size_t) 2 << 30)

/* What identifies one version of a file. */
typedef struct
{
  gchar  *path;
  dev_t   device;
  ino_t   inode;
  off_t   length;
  gint64  mtime_ns;
} FileKey;

/* What the output image was rendered from. */
typedef struct
{
  gint axis;
  gint index;
  gint layout;
} ImageKey;

typedef struct
{
  GMutex    lock;
  FileKey   file;
  gboolean  loaded;       /* `file` was read: into `volume` or failing */
  TsVolume8 volume;       /* voxels == NULL if the read failed */
  ImageKey  image_key;
  guint8   *image;        /* RGBA u8, width x height */
  gint      width, height;
  gchar    *last_warning; /* not repeated while the problem stays */
} LoadState;

static LoadState *
get_state (GeglProperties *o)
{
  if (!o->user_data)
    {
      LoadState *state = g_new0 (LoadState, 1);
      g_mutex_init (&state->lock);
      o->user_data = state;
    }
  return o->user_data;
}

static void
forget_image (LoadState *state)
{
  g_clear_pointer (&state->image, g_free);
  state->width = state->height = 0;
}

static void
free_state (LoadState *state)
{
  forget_image (state);
  ts_volume8_clear (&state->volume);
  g_free (state->file.path);
  g_free (state->last_warning);
  g_mutex_clear (&state->lock);
  g_free (state);
}

/* Warn about a problem once, not on every bounding-box query. */
static void
warn (GeglOperation *operation, LoadState *state, const gchar *message)
{
  if (g_strcmp0 (state->last_warning, message) == 0)
    return;
  g_free (state->last_warning);
  state->last_warning = g_strdup (message);
  g_warning ("%s: %s", gegl_operation_get_name (operation), message);
}

static gboolean
same_file (const FileKey *a, const FileKey *b)
{
  return g_strcmp0 (a->path, b->path) == 0 && a->device == b->device && a->inode == b->inode
         && a->length == b->length && a->mtime_ns == b->mtime_ns;
}

/* Make state->volume hold the current version of the file at o->path;
 * FALSE (after a warning) if there is no usable volume. */
static gboolean
ensure_volume (GeglOperation *operation, GeglProperties *o, LoadState *state)
{
  FileKey key = { o->path, 0, 0, 0, 0 };
  struct stat st;
  TsError error = { TS_OK, "" };

  if (!o->path || !o->path[0])
    return FALSE; /* nothing chosen yet: not worth a warning */
  if (stat (o->path, &st) == 0)
    {
      key.device = st.st_dev;
      key.inode = st.st_ino;
      key.length = st.st_size;
      key.mtime_ns = (gint64) st.st_mtim.tv_sec * 1000000000 + st.st_mtim.tv_nsec;
    }
  if (state->loaded && same_file (&key, &state->file))
    return state->volume.voxels != NULL;

  forget_image (state);
  ts_volume8_clear (&state->volume);
  g_free (state->file.path);
  state->file = key;
  state->file.path = g_strdup (o->path);
  state->loaded = TRUE;
  if (ts_volume_read (o->path, MAX_VOLUME_BYTES, &state->volume, NULL, &error) != TS_OK)
    {
      warn (operation, state, error.message);
      return FALSE;
    }
  g_clear_pointer (&state->last_warning, g_free);
  return TRUE;
}

static void
output_extent (GeglProperties *o, size_t size, gint *width, gint *height)
{
  size_t w = size, h = size;

  if (o->layout == TEXSYNTH_VOLUME_LOAD_LAYOUT_ATLAS)
    ts_volume_atlas_extent (size, &w, &h);
  /* Sizes are at most TS_VOLUME_MAX_SIZE, so an atlas fits a gint. */
  *width = (gint) w;
  *height = (gint) h;
}

/* size x size voxels of `channels` bytes as RGBA rows `stride` bytes apart. */
static void
expand_to_rgba (const guint8 *in, size_t size, unsigned channels, guint8 *out, size_t stride)
{
  for (size_t v = 0; v < size; v++)
    {
      guint8 *p = out + v * stride;
      for (size_t u = 0; u < size; u++, in += channels, p += 4)
        {
          p[0] = in[0];
          p[1] = channels >= 3 ? in[1] : in[0];
          p[2] = channels >= 3 ? in[2] : in[0];
          p[3] = channels == 2 ? in[1] : channels == 4 ? in[3] : 255;
        }
    }
}

/* Render the slice or atlas the properties ask for into state->image;
 * FALSE (after a warning) if it cannot be. */
static gboolean
ensure_image (GeglOperation *operation, GeglProperties *o, LoadState *state)
{
  /* The index does not change an atlas. */
  ImageKey key = { o->axis, o->layout == TEXSYNTH_VOLUME_LOAD_LAYOUT_ATLAS ? 0 : o->index,
                   o->layout };
  const TsVolume8 *volume = &state->volume;
  size_t size = volume->size, stride, columns = 1, rows = 1, slices = 1, first;
  guint8 *slice;
  gint width, height;

  if (state->image && memcmp (&key, &state->image_key, sizeof key) == 0)
    return TRUE;
  forget_image (state);
  if (o->layout == TEXSYNTH_VOLUME_LOAD_LAYOUT_SLICE && (size_t) o->index >= size)
    {
      gchar *message = g_strdup_printf (_("slice %d does not exist: '%s' is %zu voxels on each "
                                          "side, so the index must be 0 to %zu"),
                                        o->index, o->path, size, size - 1);
      warn (operation, state, message);
      g_free (message);
      return FALSE;
    }

  output_extent (o, size, &width, &height);
  stride = (size_t) width * 4;
  state->image = g_try_malloc0 (stride * (size_t) height);
  slice = g_try_malloc (size * size * volume->channels);
  if (!state->image || !slice)
    {
      gchar *message = g_strdup_printf (_("out of memory showing '%s' (%.1f MiB)"), o->path,
                                        (double) stride * height / 1048576.0);
      g_free (slice);
      forget_image (state);
      warn (operation, state, message);
      g_free (message);
      return FALSE;
    }

  first = (size_t) o->index;
  if (o->layout == TEXSYNTH_VOLUME_LOAD_LAYOUT_ATLAS)
    {
      ts_volume_atlas_grid (size, &columns, &rows);
      slices = size;
      first = 0;
    }
  /* Slice by slice, so only one slice of the volume's own channel count
   * is needed besides the RGBA image; cells without a slice stay 0. */
  for (size_t i = 0; i < slices; i++)
    {
      size_t cell_x = i % columns, cell_y = i / columns;
      ts_volume_extract_slice (volume->voxels, size, volume->channels, o->axis, first + i,
                               slice);
      expand_to_rgba (slice, size, volume->channels,
                      state->image + cell_y * size * stride + cell_x * size * 4, stride);
    }
  g_free (slice);
  state->width = width;
  state->height = height;
  state->image_key = key;
  g_clear_pointer (&state->last_warning, g_free);
  return TRUE;
}

static void
prepare (GeglOperation *operation)
{
  gegl_operation_set_format (operation, "output", babl_format (OUTPUT_FORMAT));
}

static GeglRectangle
get_bounding_box (GeglOperation *operation)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  LoadState *state = get_state (o);
  GeglRectangle box = { 0, 0, 0, 0 };

  g_mutex_lock (&state->lock);
  if (ensure_volume (operation, o, state))
    output_extent (o, state->volume.size, &box.width, &box.height);
  g_mutex_unlock (&state->lock);
  return box;
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *output,
         const GeglRectangle *roi,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  LoadState *state = get_state (o);
  GeglRectangle whole, part;

  g_mutex_lock (&state->lock);
  if (!ensure_volume (operation, o, state) || !ensure_image (operation, o, state))
    {
      gegl_buffer_clear (output, roi);
      g_mutex_unlock (&state->lock);
      return TRUE;
    }
  whole = (GeglRectangle) { 0, 0, state->width, state->height };
  if (gegl_rectangle_intersect (&part, &whole, roi))
    gegl_buffer_set (output, &part, 0, babl_format (OUTPUT_FORMAT),
                     state->image + ((size_t) part.y * (size_t) state->width
                                     + (size_t) part.x) * 4,
                     state->width * 4);
  g_mutex_unlock (&state->lock);
  return TRUE;
}

static void
finalize (GObject *object)
{
  GeglProperties *o = GEGL_PROPERTIES (object);

  if (o && o->user_data)
    {
      free_state (o->user_data);
      o->user_data = NULL;
    }
  G_OBJECT_CLASS (gegl_op_parent_class)->finalize (object);
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GObjectClass             *object_class    = G_OBJECT_CLASS (klass);
  GeglOperationClass       *operation_class = GEGL_OPERATION_CLASS (klass);
  GeglOperationSourceClass *source_class    = GEGL_OPERATION_SOURCE_CLASS (klass);

  object_class->finalize            = finalize;
  operation_class->prepare          = prepare;
  operation_class->get_bounding_box = get_bounding_box;
  operation_class->threaded         = FALSE;
  source_class->process             = process;

  gegl_operation_class_set_keys (operation_class,
    "name",        "texsynth:volume-load",
    "title",       _("Load Solid Texture Slice"),
    "categories",  "input",
    "description", _("Shows one slice of a solid (3D) texture saved as a .vol or "
                     ".dds volume file, or all its slices along one axis side by "
                     "side in an atlas"),
    NULL);
}

#endif
