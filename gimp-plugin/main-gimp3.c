/* GIMP 3's plug-in: the GimpPlugIn class, procedure registration and the
 * render, tileable and solid procedures (the heal, material-set and
 * guided ones are in heal-gimp3.c, layers-gimp3.c and guided-gimp3.c). The procedures' logic is in
 * plugin-args.c and plugin-run.c, shared with GIMP 2.10.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <string.h>

#include <glib/gi18n-lib.h>

#include "texsynth-plugin.h"
#include "compat-gimp3.h"
#include "dialogs-gimp3.h"
#include "heal-gimp3.h"
#include "guided-gimp3.h"
#include "layers-gimp3.h"

#define TS_TYPE_PLUG_IN (ts_plug_in_get_type ())
G_DECLARE_FINAL_TYPE (TsPlugIn, ts_plug_in, TS, PLUG_IN, GimpPlugIn)

struct _TsPlugIn
{
  GimpPlugIn parent_instance;
};

G_DEFINE_TYPE (TsPlugIn, ts_plug_in, GIMP_TYPE_PLUG_IN)

GIMP_MAIN (TS_TYPE_PLUG_IN)

/* --- the procedures ---------------------------------------------------- */

static GimpValueArray *
run_render (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image G_GNUC_UNUSED,
            GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  const gchar *name = _("Texture");
  TsExemplar exemplar;
  TsRenderArgs args;
  GeglBuffer *result = NULL;
  GimpImage *output;
  GError *error = NULL;
  gchar *message;

  if ((message = check_drawables (drawables, 1)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  if (!read_exemplar (drawables[0], TRUE, &exemplar, &message))
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);

  if (mode == GIMP_RUN_INTERACTIVE)
    {
      const GeglRectangle *extent = gegl_buffer_get_extent (exemplar.buffer);
      gboolean size_chosen;
      TsPreviewInput preview = { .kind = TS_PREVIEW_RENDER, .exemplars = &exemplar,
                                 .n_exemplars = 1 };

      /* Twice the exemplar until the user has chosen a size once. */
      g_object_get (config, "size-chosen", &size_chosen, NULL);
      if (!size_chosen)
        g_object_set (config,
                      "width", MIN (2 * extent->width, TS_PLUGIN_MAX_SIDE),
                      "height", MIN (2 * extent->height, TS_PLUGIN_MAX_SIDE), NULL);
      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      if (!ts_dialog3 (procedure, config, _("Texture Synthesis"), &preview,
                       "width", "height", "tileable", "quality", "seed", NULL))
        {
          ts_exemplar_clear (&exemplar);
          return failure (procedure, GIMP_PDB_CANCEL, NULL);
        }
      g_object_set (config, "size-chosen", TRUE, NULL);
    }

  g_object_get (config, "width", &args.width, "height", &args.height,
                "tileable", &args.tileable, "quality", &args.quality, "seed", &args.seed, NULL);
  if ((message = ts_render_args_check (&args)))
    {
      ts_exemplar_clear (&exemplar);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
    }
  if (gimp_drawable_is_indexed (drawables[0]))
    g_message (_("The exemplar is indexed: the new image is RGB."));

  gimp_progress_init (_("Synthesising texture"));
  if (!ts_plugin_render (&exemplar, &args, &result, &error))
    {
      ts_exemplar_clear (&exemplar);
      message = g_strdup (error->message);
      g_error_free (error);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }
  output = new_image (&exemplar, &result, &name, NULL, 1);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  if (!output)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Could not make the new image.")));
  return success_with_image (procedure, mode, output);
}

static GimpValueArray *
run_tileable (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image G_GNUC_UNUSED,
              GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  TsExemplar exemplar;
  TsTileableArgs args;
  GimpDrawable *drawable;
  GeglBuffer *result = NULL;
  GError *error = NULL;
  gchar *message;
  gboolean ok;

  if ((message = check_drawables (drawables, 1)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  drawable = drawables[0];

  if (mode == GIMP_RUN_INTERACTIVE)
    {
      GeglBuffer *buffer = gimp_drawable_get_buffer (drawable);
      TsPreviewInput preview = { .kind = TS_PREVIEW_TILEABLE, .ratio = 1.0 };

      preview.pixels = ts_preview_copy (buffer, TS_PREVIEW_TILE_SIDE, TRUE, &preview.ratio);
      g_object_unref (buffer);
      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      ok = ts_dialog3 (procedure, config, _("Make Seamless by Synthesis"),
                       preview.pixels ? &preview : NULL, "quality", "seed", NULL);
      g_clear_object (&preview.pixels);
      if (!ok)
        return failure (procedure, GIMP_PDB_CANCEL, NULL);
    }
  g_object_get (config, "quality", &args.quality, "seed", &args.seed, NULL);
  if ((message = ts_tileable_args_check (&args, gimp_drawable_get_width (drawable),
                                         gimp_drawable_get_height (drawable))))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  if (!read_exemplar (drawable, FALSE, &exemplar, &message))
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);

  gimp_progress_init (_("Making the layer seamless"));
  if (!ts_plugin_tileable (&exemplar, &args, &result, &error))
    {
      ts_exemplar_clear (&exemplar);
      message = g_strdup (error->message);
      g_error_free (error);
      return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
    }

  /* Only now is the image changed: a cancelled run leaves it as it was. */
  ok = ts_replace_layer_pixels3 (drawable, result);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  if (!ok)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));

  if (mode == GIMP_RUN_INTERACTIVE)
    gimp_displays_flush ();
  return gimp_procedure_new_return_values (procedure, GIMP_PDB_SUCCESS, NULL);
}

static GimpValueArray *
run_solid (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image G_GNUC_UNUSED,
           GimpDrawable **drawables, GimpProcedureConfig *config, gpointer data G_GNUC_UNUSED)
{
  const gchar *names[3] = { _("Slice x = middle"), _("Slice y = middle"), _("Slice z = middle") };
  TsExemplar exemplars[3];
  TsSolidArgs args;
  GeglBuffer *slices[3] = { NULL, NULL, NULL };
  GimpImage *output;
  GError *error = NULL;
  gchar *message = NULL, *path = NULL;
  GFile *file = NULL;
  gint n = count_drawables (drawables), n_read = 0;
  gboolean ok;

  if ((message = check_drawables (drawables, 3)))
    return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
  if ((message = ts_plugin_check_ops (TS_OP_VOLUME_SAVE, TS_OP_VOLUME_SLICE, NULL)))
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);

  /* Before the dialog: its preview grows the exemplars. */
  for (n_read = 0; n_read < n; n_read++)
    if (!read_exemplar (drawables[n_read], n == 1, &exemplars[n_read], &message))
      break;
  ok = n_read == n;
  if (ok && mode == GIMP_RUN_INTERACTIVE)
    {
      TsPreviewInput preview = { .kind = TS_PREVIEW_SOLID, .exemplars = exemplars,
                                 .n_exemplars = n };

      g_object_set (config, "seed", ts_plugin_random_seed (), NULL);
      if (!ts_dialog3 (procedure, config, _("Solid Texture"), &preview, "size", "path",
                       "cell-structure", "quality", "seed", NULL))
        {
          for (gint i = 0; i < n_read; i++)
            ts_exemplar_clear (&exemplars[i]);
          return failure (procedure, GIMP_PDB_CANCEL, NULL);
        }
    }
  ts_solid_args_init (&args);
  g_object_get (config, "size", &args.size, "path", &file, "quality", &args.quality,
                "seed", &args.seed, "cell-structure", &args.cell_structure, NULL);
  /* A file GIO cannot name by a local path (a remote URI) gives "". */
  path = file ? g_file_get_path (file) : NULL;
  g_strlcpy (args.path, path ? path : "", sizeof args.path);
  if (path && strlen (path) >= sizeof args.path)
    args.path[0] = '\0';
  g_free (path);
  g_clear_object (&file);
  if (ok && (message = ts_solid_args_check (&args, n)))
    {
      for (gint i = 0; i < n_read; i++)
        ts_exemplar_clear (&exemplars[i]);
      return failure (procedure, GIMP_PDB_CALLING_ERROR, message);
    }
  if (ok)
    {
      gimp_progress_init (_("Synthesising a solid texture"));
      ok = ts_plugin_solid (exemplars, n, &args, slices, &error);
      if (!ok)
        {
          message = g_strdup (error->message);
          g_error_free (error);
        }
    }
  output = ok ? new_image (&exemplars[0], slices, names, NULL, 3) : NULL;
  for (gint i = 0; i < n_read; i++)
    ts_exemplar_clear (&exemplars[i]);
  for (gint i = 0; i < 3; i++)
    g_clear_object (&slices[i]);
  if (!ok)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, message);
  if (!output)
    return failure (procedure, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Could not make the new image.")));
  return success_with_image (procedure, mode, output);
}

/* --- registration -------------------------------------------------------- */

/* The arguments and return value of the procedures that make a new
 * image (render and render-layers). */
static void
add_render_arguments (GimpProcedure *procedure, const gchar *new_image_blurb)
{
  gimp_procedure_add_int_argument (procedure, "width", ts_arg_label ("width"),
                                   ts_arg_tooltip ("width"), 1, TS_PLUGIN_MAX_SIDE, 512,
                                   G_PARAM_READWRITE);
  gimp_procedure_add_int_argument (procedure, "height", ts_arg_label ("height"),
                                   ts_arg_tooltip ("height"), 1, TS_PLUGIN_MAX_SIDE, 512,
                                   G_PARAM_READWRITE);
  gimp_procedure_add_boolean_argument (procedure, "tileable", ts_arg_label ("tileable"),
                                       ts_arg_tooltip ("tileable"), FALSE, G_PARAM_READWRITE);
  ts_add_quality_and_seed3 (procedure, "quality");
  gimp_procedure_add_boolean_aux_argument (procedure, "size-chosen", "Size chosen",
                                           "Whether the user has chosen a size once",
                                           FALSE, G_PARAM_READWRITE);
  gimp_procedure_add_image_return_value (procedure, "new-image", _("New image"),
                                         new_image_blurb, FALSE, G_PARAM_READWRITE);
}

static GimpProcedure *
create_procedure (GimpPlugIn *plug_in, const gchar *name)
{
  GimpProcedure *procedure = ts_guided_procedure3 (plug_in, name);

  if (procedure)
    return procedure;
  if (g_str_equal (name, TS_PROC_RENDER))
    {
      procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN,
                                            run_render, NULL, NULL);
      ts_describe3 (procedure, _("Texture _Synthesis..."), "<Image>/Filters/Render/Pattern",
                    _("Synthesise a new texture of any size from the layer"),
                    _("Grows a new texture of the chosen size that looks like the active layer "
                      "(or its selected part) everywhere, with the texsynth:synthesize GEGL "
                      "operation, in a new image of the same precision and colour profile."));
      gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE);
      add_render_arguments (procedure, _("The image with the synthesised texture"));
    }
  else if (g_str_equal (name, TS_PROC_RENDER_LAYERS))
    {
      procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN,
                                            ts_run_layers3, NULL, NULL);
      ts_describe3 (procedure, _("Texture Synthesis of _All Layers..."),
                    "<Image>/Filters/Render/Pattern",
                    _("Synthesise all layers (a material set) with one layout"),
                    _("Synthesises the selected layer with the texsynth:synthesize GEGL operation "
                      "and lays every top-level layer of the image out the same way (its layout "
                      "as a source map, applied with gegl:map-absolute), so that colour, normal, "
                      "roughness and height maps stay aligned. All layers must have the same "
                      "size; the new image has the same layers, names and order, precision and "
                      "colour profile."));
      gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE);
      add_render_arguments (procedure, _("The image with the synthesised layers"));
    }
  else if (g_str_equal (name, TS_PROC_TILEABLE))
    {
      procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN,
                                            run_tileable, NULL, NULL);
      ts_describe3 (procedure, _("Make Seamless by _Synthesis..."), "<Image>/Filters/Map",
                    _("Make the layer tile seamlessly by re-synthesising its edges"),
                    _("Runs the texsynth:tileable GEGL operation on the layer in place: only "
                      "bands along the edges change. Undoable."));
      gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE);
      ts_add_quality_and_seed3 (procedure, "quality");
    }
  else if (g_str_equal (name, TS_PROC_SOLID))
    {
      gchar *path = g_build_filename (g_get_home_dir (), "solid-texture.vol", NULL);
      GFile *file = g_file_new_for_path (path);

      procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN,
                                            run_solid, NULL, NULL);
      ts_describe3 (procedure, _("S_olid Texture..."), "<Image>/Filters/Render/Pattern",
                    _("Synthesise a solid (volume) texture from one to three layers"),
                    _("Synthesises a size\302\263 volume whose slices look like the layer (up to "
                      "three selected layers give the slices orthogonal to x, y and z), writes it "
                      "to a file (.vol, .dds or PNG) and opens an image of its three middle "
                      "slices."));
      gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE |
                                                      GIMP_PROCEDURE_SENSITIVE_DRAWABLES);
      gimp_procedure_add_int_argument (procedure, "size", ts_arg_label ("size"),
                                       ts_arg_tooltip ("size"), TS_PLUGIN_MIN_SOLID,
                                       TS_PLUGIN_MAX_SOLID, TS_PLUGIN_DEFAULT_SOLID,
                                       G_PARAM_READWRITE);
      /* A file argument: GimpProcedureDialog shows GIMP's file chooser
       * for it, and Script-Fu still passes the file name as a string. */
      gimp_procedure_add_file_argument (procedure, "path", ts_arg_label ("path"),
                                        ts_arg_tooltip ("path"), GIMP_FILE_CHOOSER_ACTION_SAVE,
                                        FALSE, file, G_PARAM_READWRITE);
      ts_add_quality_and_seed3 (procedure, "solid-quality");
      /* After seed, as in GIMP 2.10: positional calls keep their meaning.
       * 0 off, 1 on, 2 automatic (the ops' default). */
      gimp_procedure_add_int_argument (procedure, "cell-structure",
                                       ts_arg_label ("cell-structure"),
                                       ts_arg_tooltip ("cell-structure"),
                                       TS_PLUGIN_CELL_STRUCTURE_OFF,
                                       TS_PLUGIN_MAX_CELL_STRUCTURE,
                                       TS_PLUGIN_CELL_STRUCTURE_AUTO, G_PARAM_READWRITE);
      gimp_procedure_add_image_return_value (procedure, "new-image", _("New image"),
                                             _("An image of the volume's three middle slices"),
                                             FALSE, G_PARAM_READWRITE);
      g_object_unref (file);
      g_free (path);
    }
  else if (g_str_equal (name, TS_PROC_HEAL_SELECTION) || g_str_equal (name, TS_PROC_HEAL_TRANSPARENCY)
           || g_str_equal (name, TS_PROC_UNCROP))
    {
      procedure = gimp_image_procedure_new (plug_in, name, GIMP_PDB_PROC_TYPE_PLUGIN,
                                            ts_run_heal3, NULL, NULL);
      if (g_str_equal (name, TS_PROC_HEAL_SELECTION))
        ts_describe3 (procedure, _("_Heal Selection by Synthesis..."), "<Image>/Filters/Enhance",
                      _("Fill the selection with texture continued from around it"),
                      "Runs the texsynth:heal GEGL operation on the layer with the selection as "
                      "the hole: pixels at least half selected are filled, the others stay "
                      "exactly as they were. Undoable.");
      else if (g_str_equal (name, TS_PROC_HEAL_TRANSPARENCY))
        ts_describe3 (procedure, _("Heal _Transparency by Synthesis..."), "<Image>/Filters/Enhance",
                      _("Fill the transparent parts of the layer with texture"),
                      "Runs the texsynth:heal GEGL operation on the layer: its pixels that are "
                      "not fully opaque are filled. Undoable.");
      else
        ts_describe3 (procedure, _("_Uncrop by Synthesis..."), "<Image>/Filters/Enhance",
                      _("Enlarge the canvas and fill the new border with texture"),
                      "Adds a border of the given percentage on each side of the image and fills "
                      "that border only with texsynth:heal (transparent pixels the layer "
                      "already had stay as they are). Undoable.");
      gimp_procedure_set_image_types (procedure, "RGB*, GRAY*");
      gimp_procedure_set_sensitivity_mask (procedure, GIMP_PROCEDURE_SENSITIVE_DRAWABLE);
      if (g_str_equal (name, TS_PROC_UNCROP))
        gimp_procedure_add_int_argument (procedure, "percent", ts_arg_label ("percent"),
                                         ts_arg_tooltip ("percent"), 1, TS_PLUGIN_MAX_UNCROP, 20,
                                         G_PARAM_READWRITE);
      else
        {
          gimp_procedure_add_int_argument (procedure, "context", ts_arg_label ("context"),
                                           ts_arg_tooltip ("context"), 0, TS_PLUGIN_MAX_CONTEXT,
                                           0, G_PARAM_READWRITE);
          gimp_procedure_add_int_argument (procedure, "sample-from", ts_arg_label ("sample-from"),
                                           ts_arg_tooltip ("sample-from"), 0,
                                           TS_PLUGIN_MAX_SAMPLE_FROM, 0, G_PARAM_READWRITE);
        }
      ts_add_quality_and_seed3 (procedure, "quality");
    }
  return procedure;
}

static GList *
query_procedures (GimpPlugIn *plug_in G_GNUC_UNUSED)
{
  GList *names = NULL;

  names = g_list_append (names, g_strdup (TS_PROC_RENDER));
  names = g_list_append (names, g_strdup (TS_PROC_RENDER_LAYERS));
  names = g_list_append (names, g_strdup (TS_PROC_TILEABLE));
  names = g_list_append (names, g_strdup (TS_PROC_SOLID));
  names = g_list_append (names, g_strdup (TS_PROC_HEAL_SELECTION));
  names = g_list_append (names, g_strdup (TS_PROC_HEAL_TRANSPARENCY));
  names = g_list_append (names, g_strdup (TS_PROC_UNCROP));
  return ts_guided_names3 (names);
}

static gboolean
set_i18n (GimpPlugIn  *plug_in G_GNUC_UNUSED,
          const gchar *procedure_name G_GNUC_UNUSED,
          gchar      **gettext_domain,
          gchar      **catalog_dir)
{
  /* GIMP 3 takes the catalogs for menu labels and argument texts only
   * from below the plug-in's folder (NULL: its locale/) and refuses any
   * other; the plug-in's own dialogs and messages use texsynth's
   * installed catalogs, bound by ts_plugin_init_i18n. */
  gchar *folder = g_path_get_dirname (gimp_get_progname ());
  gchar *catalogs = g_build_filename (folder, "locale", NULL);
  gboolean found = g_file_test (catalogs, G_FILE_TEST_IS_DIR);

  g_free (catalogs);
  g_free (folder);
  ts_plugin_init_i18n ();
  *gettext_domain = g_strdup (GETTEXT_PACKAGE);
  *catalog_dir = NULL;
  return found;
}

static void
ts_plug_in_class_init (TsPlugInClass *klass)
{
  GimpPlugInClass *plug_in_class = GIMP_PLUG_IN_CLASS (klass);

  plug_in_class->query_procedures = query_procedures;
  plug_in_class->create_procedure = create_procedure;
  plug_in_class->set_i18n = set_i18n;
}

static void
ts_plug_in_init (TsPlugIn *plug_in G_GNUC_UNUSED)
{
}
