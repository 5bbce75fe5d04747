/* Argument defaults and checks, seeds, gettext and op availability: the
 * parts of the procedures' logic that GIMP 2.10 and GIMP 3 share.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdarg.h>
#include <string.h>
#include <unistd.h>

#include <glib/gi18n-lib.h>
#include <glib/gstdio.h>

#include "texsynth-plugin.h"

G_DEFINE_QUARK (texsynth-plugin-error-quark, ts_plugin_error)

void
ts_render_args_init (TsRenderArgs *args)
{
  memset (args, 0, sizeof *args);
  args->quality = TS_PLUGIN_DEFAULT_QUALITY;
}

void
ts_heal_args_init (TsHealArgs *args)
{
  memset (args, 0, sizeof *args);
  args->percent = 20;
  args->quality = TS_PLUGIN_DEFAULT_QUALITY;
}

void
ts_tileable_args_init (TsTileableArgs *args)
{
  memset (args, 0, sizeof *args);
  args->quality = TS_PLUGIN_DEFAULT_QUALITY;
}

void
ts_solid_args_init (TsSolidArgs *args)
{
  gchar *path = g_build_filename (g_get_home_dir (), "solid-texture.vol", NULL);

  memset (args, 0, sizeof *args);
  args->size = TS_PLUGIN_DEFAULT_SOLID;
  args->quality = TS_PLUGIN_DEFAULT_QUALITY;
  args->cell_structure = TS_PLUGIN_CELL_STRUCTURE_AUTO;  /* the ops' default */
  g_strlcpy (args->path, path, sizeof args->path);
  g_free (path);
}

static gchar *
check_quality_and_seed (gint quality, gint seed)
{
  if (quality < TS_PLUGIN_MIN_QUALITY || quality > TS_PLUGIN_MAX_QUALITY)
    return g_strdup_printf (_("Quality must be between %d and %d (got %d)."),
                            TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY, quality);
  if (seed < 0)
    return g_strdup_printf (_("The seed must be 0 or more (got %d)."), seed);
  return NULL;
}

gchar *
ts_render_args_check (const TsRenderArgs *args)
{
  if (args->width < 1 || args->width > TS_PLUGIN_MAX_SIDE)
    return g_strdup_printf (_("The width must be between 1 and %d pixels (got %d)."),
                            TS_PLUGIN_MAX_SIDE, args->width);
  if (args->height < 1 || args->height > TS_PLUGIN_MAX_SIDE)
    return g_strdup_printf (_("The height must be between 1 and %d pixels (got %d)."),
                            TS_PLUGIN_MAX_SIDE, args->height);
  return check_quality_and_seed (args->quality, args->seed);
}

gchar *
ts_heal_args_check (const TsHealArgs *args)
{
  if (args->context < 0 || args->context > TS_PLUGIN_MAX_CONTEXT)
    return g_strdup_printf (_("The context width must be between 0 and %d pixels (got %d)."),
                            TS_PLUGIN_MAX_CONTEXT, args->context);
  if (args->sample_from < 0 || args->sample_from > TS_PLUGIN_MAX_SAMPLE_FROM)
    return g_strdup_printf (_("Sample from must be 0 (all around), 1 (sides) or 2 (above and "
                              "below) (got %d)."), args->sample_from);
  if (args->percent < 1 || args->percent > TS_PLUGIN_MAX_UNCROP)
    return g_strdup_printf (_("The border must be between 1 and %d percent (got %d)."),
                            TS_PLUGIN_MAX_UNCROP, args->percent);
  return check_quality_and_seed (args->quality, args->seed);
}

gchar *
ts_tileable_args_check (const TsTileableArgs *args, gint width, gint height)
{
  /* The op's own lower limit (TS_TILEABLE_MIN_SIDE): below it, it would
   * leave the layer unchanged with only a warning on the console. */
  if (width < 8 || height < 8)
    return g_strdup_printf (_("The layer is %d\303\227%d pixels: it must be at least 8\303\2278 "
                              "to be made seamless."), width, height);
  return check_quality_and_seed (args->quality, args->seed);
}

gchar *
ts_layers_size_check (const gchar *layer, gint width, gint height,
                      const gchar *driver, gint driver_width, gint driver_height)
{
  if (width == driver_width && height == driver_height)
    return NULL;
  return g_strdup_printf (_("All layers must have the same size to share one layout: \"%s\" is "
                            "%d\303\227%d pixels but the driving layer \"%s\" is %d\303\227%d. "
                            "Scale or crop the layers to one size first."),
                          layer, width, height, driver, driver_width, driver_height);
}

/* The formats texsynth:volume-save infers from a file name. */
static gboolean
has_volume_extension (const gchar *path)
{
  static const gchar *const extensions[] = { ".vol", ".dds", ".png" };
  gchar *lower = g_ascii_strdown (path, -1);
  gboolean found = FALSE;

  for (gsize i = 0; i < G_N_ELEMENTS (extensions); i++)
    found = found || g_str_has_suffix (lower, extensions[i]);
  g_free (lower);
  return found;
}

gchar *
ts_solid_args_check (const TsSolidArgs *args, gint n_exemplars)
{
  gchar *message, *folder;

  if (args->size < TS_PLUGIN_MIN_SOLID || args->size > TS_PLUGIN_MAX_SOLID)
    return g_strdup_printf (_("The size must be between %d and %d voxels (got %d)."),
                            TS_PLUGIN_MIN_SOLID, TS_PLUGIN_MAX_SOLID, args->size);
  if (n_exemplars < 1 || n_exemplars > 3)
    return g_strdup_printf (_("Select one to three layers as exemplars (got %d)."),
                            n_exemplars);
  if ((message = check_quality_and_seed (args->quality, args->seed)))
    return message;
  if (args->cell_structure < 0 || args->cell_structure > TS_PLUGIN_MAX_CELL_STRUCTURE)
    return g_strdup_printf (_("Cell structure must be 0 (off), 1 (on) or 2 (automatic) "
                              "(got %d)."), args->cell_structure);
  if (!args->path[0] || strnlen (args->path, sizeof args->path) >= sizeof args->path)
    return g_strdup (_("The path of the volume file is empty or too long."));
  if (!has_volume_extension (args->path))
    return g_strdup_printf (_("Cannot tell the volume format from \"%s\": the file name must "
                              "end in .vol, .dds or .png."), args->path);
  if (g_file_test (args->path, G_FILE_TEST_IS_DIR))
    return g_strdup_printf (_("\"%s\" is a folder: give a file name."), args->path);

  folder = g_path_get_dirname (args->path);
  if (!g_file_test (folder, G_FILE_TEST_IS_DIR))
    message = g_strdup_printf (_("Cannot write \"%s\": the folder \"%s\" does not exist."),
                               args->path, folder);
  else if (g_access (folder, W_OK) != 0)
    message = g_strdup_printf (_("Cannot write \"%s\": the folder \"%s\" is not writable."),
                               args->path, folder);
  else if (g_file_test (args->path, G_FILE_TEST_EXISTS) && g_access (args->path, W_OK) != 0)
    message = g_strdup_printf (_("Cannot write \"%s\": the file is not writable."), args->path);
  else
    message = NULL;
  g_free (folder);
  return message;
}

static const struct
{
  const gchar *name;
  const gchar *label;
  const gchar *tooltip;
} arg_texts[] =
{
  { "width", N_("Width"), N_("Width of the new image, in pixels") },
  { "height", N_("Height"), N_("Height of the new image, in pixels") },
  { "tileable", N_("Tileable"),
    N_("Make the result tile seamlessly: its left edge continues its right edge "
       "and its top edge its bottom edge") },
  { "quality", N_("Quality"),
    N_("Candidates compared per pixel (k = quality + 1): higher searches more and "
       "is slower; 2 measured best on average") },
  /* The solid engine's quality is its search's breadth (the volume ops'
   * text). */
  { "solid-quality", N_("Quality"),
    N_("Search breadth per voxel and orientation (3 x quality tree leaves): higher "
       "searches more and is slower") },
  { "seed", N_("Random seed"),
    N_("The same seed with the same settings gives the same result, whatever the "
       "number of threads; change it for another variation. 0 is a seed like any "
       "other, not a random one") },
  { "context", N_("Context width (0 = whole layer)"),
    N_("How far around the hole, in pixels, the texture may be copied from; 0 uses "
       "the whole layer") },
  { "sample-from", N_("Sample from"),
    N_("0: all around the hole; 1: only its sides; 2: only above and below it") },
  { "percent", N_("Border (%)"),
    N_("Border added on each side, as a percentage of the image's width or height") },
  { "size", N_("Size"),
    N_("Edge of the cube in voxels: the volume has size \303\227 size \303\227 size voxels") },
  { "path", N_("File"),
    N_("Where to write the volume; the name's ending chooses the format: .vol "
       "(raw floats), .dds (volume texture) or .png (slices)") },
  { "exemplar", N_("Exemplar"),
    N_("The texture to paint with: one layer holding every texture the guides name, "
       "e.g. grass beside gravel") },
  { "exemplar-guide", N_("Exemplar's guide"),
    N_("A layer of the exemplar's size that marks, pixel for pixel, which texture each "
       "part of the exemplar is: flat colours for labels, or grey values") },
  { "guide-weight", N_("Guide weight"),
    N_("How closely the result follows the target guide against how coherent its "
       "texture is: at 1 a pixel whose guide disagrees costs as much as two unrelated "
       "pixels of the texture; 0 ignores the guides") },
  { "blend-edges", N_("Blend label edges"),
    /* The op's own description, so that its translations serve. */
    N_("Labels only. Off: each label's area is grown from its own texture alone and "
       "cut at the label's edges, so areas of any width keep their texture. On: one "
       "synthesis over the whole image, whose textures blend across label edges as they "
       "do in the exemplar, but areas narrower than about 30 pixels lose some of their "
       "texture") },
  { "style", N_("Style"),
    N_("The layer whose texture repaints this one, e.g. a painting or a material") },
  { "style-weight", N_("Keep the layer's shading"),
    N_("How closely the result keeps this layer's light and shade against how coherent "
       "the style's texture is; 0 ignores the layer and grows the style's texture") },
  { "cell-structure", N_("Cell structure"),
    N_("For layers of light cells in dark joints, such as stones in mortar, cobbles "
       "or cracked mud: a 3D tessellation fitted to the layer decides where the walls "
       "between cells go, so every slice shows whole cells with closed joints. "
       "Automatic (2): on for an opaque layer of separate light stones in thin dark "
       "joints that run every way (not rows of tiles or bricks), off otherwise. On (1): "
       "always; needs an opaque layer, and is wrong for "
       "other textures (round pebbles turn into polygons). Off (0): never") },
};

static gsize
arg_index (const gchar *name)
{
  gsize i;

  for (i = 0; i < G_N_ELEMENTS (arg_texts); i++)
    if (g_str_equal (arg_texts[i].name, name))
      break;
  return i;
}

const gchar *
ts_arg_label (const gchar *name)
{
  gsize i = arg_index (name);

  return i < G_N_ELEMENTS (arg_texts) ? _(arg_texts[i].label) : NULL;
}

const gchar *
ts_arg_tooltip (const gchar *name)
{
  gsize i = arg_index (name);

  return i < G_N_ELEMENTS (arg_texts) ? _(arg_texts[i].tooltip) : NULL;
}

const gchar *
ts_sample_from_label (gint value)
{
  static const gchar *const labels[TS_PLUGIN_MAX_SAMPLE_FROM + 1] =
  {
    N_("All around"), N_("Sides only"), N_("Above and below only")
  };

  return value >= 0 && value <= TS_PLUGIN_MAX_SAMPLE_FROM ? _(labels[value]) : NULL;
}

const gchar *
ts_cell_structure_label (gint value)
{
  static const gchar *const labels[TS_PLUGIN_MAX_CELL_STRUCTURE + 1] =
  {
    N_("Off"), N_("On"), N_("Automatic")
  };

  return value >= 0 && value <= TS_PLUGIN_MAX_CELL_STRUCTURE ? _(labels[value]) : NULL;
}

gint
ts_plugin_random_seed (void)
{
  return g_random_int_range (0, G_MAXINT);
}

const gchar *
ts_plugin_locale_dir (void)
{
  const gchar *dir = g_getenv ("TEXSYNTH_LOCALEDIR");

  return dir && *dir ? dir : LOCALEDIR;
}

void
ts_plugin_init_i18n (void)
{
  bindtextdomain (GETTEXT_PACKAGE, ts_plugin_locale_dir ());
  bind_textdomain_codeset (GETTEXT_PACKAGE, "UTF-8");
}

gchar *
ts_plugin_check_ops (const gchar *first_op, ...)
{
  GString *missing = g_string_new (NULL);
  const gchar *op;
  gchar *names, *message;
  va_list ops;

  va_start (ops, first_op);
  for (op = first_op; op; op = va_arg (ops, const gchar *))
    if (!gegl_has_operation (op))
      g_string_append_printf (missing, "%s%s", missing->len ? ", " : "", op);
  va_end (ops);

  if (!missing->len)
    {
      g_string_free (missing, TRUE);
      return NULL;
    }
  op = g_getenv ("GEGL_PATH");
  names = g_string_free (missing, FALSE);
  message = g_strdup_printf (_("GEGL cannot find the operation(s) %s (GEGL_PATH=%s): install "
                               "texsynth's operations into GEGL's plug-in folder or "
                               "~/.local/share/gegl-0.4/plug-ins."),
                             names, op ? op : _("unset"));
  g_free (names);
  return message;
}
