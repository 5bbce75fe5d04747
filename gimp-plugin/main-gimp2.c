/* GIMP 2.10's plug-in: procedure registration, the run dispatcher and the
 * render, tileable and solid procedures (the heal, material-set and
 * guided ones are in heal-gimp2.c, layers-gimp2.c and guided-gimp2.c). The procedures' logic is in
 * plugin-args.c and plugin-run.c, shared with GIMP 3.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <glib/gi18n-lib.h>

#include "texsynth-plugin.h"
#include "compat-gimp2.h"
#include "dialogs-gimp2.h"
#include "heal-gimp2.h"
#include "layers-gimp2.h"
#include "guided-gimp2.h"

static void query (void);
static void run   (const gchar *name, gint n_params, const GimpParam *params,
                   gint *n_return_vals, GimpParam **return_vals);

const GimpPlugInInfo PLUG_IN_INFO = { NULL, NULL, query, run };

MAIN ()

#define AUTHOR    "texsynth contributors"
#define COPYRIGHT "texsynth contributors (GPL-3.0-or-later)"
#define DATE      "2025"

static void
query (void)
{
  static const GimpParamDef render_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode", "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",    "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable", "Exemplar layer (its selected part when there is a selection)" },
    { GIMP_PDB_INT32,    "width",    "Width of the synthesised texture (1-16384)" },
    { GIMP_PDB_INT32,    "height",   "Height of the synthesised texture (1-16384)" },
    { GIMP_PDB_INT32,    "tileable", "Make the result tile seamlessly (TRUE or FALSE)" },
    { GIMP_PDB_INT32,    "quality",  "Candidates compared per pixel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",     "Random seed (0 or more; 0 is a seed like any other)" },
  };
  static const GimpParamDef layers_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode", "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",    "Input image: a material set, layers of one size" },
    { GIMP_PDB_DRAWABLE, "drawable", "Driving layer: the layout is synthesised from it" },
    { GIMP_PDB_INT32,    "width",    "Width of the synthesised layers (1-16384)" },
    { GIMP_PDB_INT32,    "height",   "Height of the synthesised layers (1-16384)" },
    { GIMP_PDB_INT32,    "tileable", "Make the result tile seamlessly (TRUE or FALSE)" },
    { GIMP_PDB_INT32,    "quality",  "Candidates compared per pixel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",     "Random seed (0 or more; 0 is a seed like any other)" },
  };
  static const GimpParamDef tileable_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode", "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",    "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable", "Layer to make seamless in place" },
    { GIMP_PDB_INT32,    "quality",  "Candidates compared per pixel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",     "Random seed (0 or more; 0 is a seed like any other)" },
  };
  static const GimpParamDef solid_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode", "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",    "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable", "Exemplar layer" },
    { GIMP_PDB_INT32,    "size",     "Edge of the cube in voxels (8-512)" },
    { GIMP_PDB_STRING,   "path",     "Volume file to write: .vol, .dds or .png" },
    { GIMP_PDB_INT32,    "quality",  "Search breadth per voxel (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",     "Random seed (0 or more; 0 is a seed like any other)" },
    /* Last: every argument before it keeps its place. */
    /* Once a boolean: FALSE and TRUE keep their meaning as 0 and 1. */
    { GIMP_PDB_INT32,    "cell-structure",
      "Fit a 3D cell tessellation, for light cells in dark joints: 0 off, 1 on (needs an "
      "opaque layer), 2 automatic (on for an opaque layer of separate light stones in "
      "thin dark joints, else off)" },
  };
  static const GimpParamDef heal_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode",    "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",       "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable",    "Layer to heal in place" },
    { GIMP_PDB_INT32,    "context",     "Pixels around the hole to copy from (0-16384, 0 = the whole layer)" },
    { GIMP_PDB_INT32,    "sample-from", "0 all around, 1 sides, 2 above and below" },
    { GIMP_PDB_INT32,    "quality",     "Search effort (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",        "Random seed (0 or more; 0 is a seed like any other)" },
  };
  static const GimpParamDef uncrop_args[] =
  {
    { GIMP_PDB_INT32,    "run-mode", "The run mode { RUN-INTERACTIVE (0), RUN-NONINTERACTIVE (1) }" },
    { GIMP_PDB_IMAGE,    "image",    "Input image" },
    { GIMP_PDB_DRAWABLE, "drawable", "Layer to extend" },
    { GIMP_PDB_INT32,    "percent",  "Border added on each side, percent of the side (1-100)" },
    { GIMP_PDB_INT32,    "quality",  "Search effort (1-10, default 2)" },
    { GIMP_PDB_INT32,    "seed",     "Random seed (0 or more; 0 is a seed like any other)" },
  };
  static const GimpParamDef image_return[] =
  {
    { GIMP_PDB_IMAGE, "new-image", "The new image" },
  };

  gimp_plugin_domain_register (GETTEXT_PACKAGE, ts_plugin_locale_dir ());

  gimp_install_procedure (TS_PROC_RENDER,
                          N_("Synthesise a new texture of any size from the layer"),
                          "Grows a new texture of the chosen size that looks like the active "
                          "layer (or its selected part) everywhere, with the texsynth:synthesize "
                          "GEGL operation, in a new image of the same precision and colour "
                          "profile.",
                          AUTHOR, COPYRIGHT, DATE, N_("Texture _Synthesis..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (render_args), G_N_ELEMENTS (image_return),
                          render_args, image_return);
  gimp_plugin_menu_register (TS_PROC_RENDER, "<Image>/Filters/Render/Pattern");

  gimp_install_procedure (TS_PROC_RENDER_LAYERS,
                          N_("Synthesise all layers (a material set) with one layout"),
                          "Synthesises the active layer with the texsynth:synthesize GEGL "
                          "operation and lays every top-level layer of the image out the same "
                          "way (its layout as a source map, applied with gegl:map-absolute), "
                          "so that colour, normal, roughness and height maps stay aligned. All "
                          "layers must have the same size; the new image has the same layers, "
                          "names and order, precision and colour profile.",
                          AUTHOR, COPYRIGHT, DATE, N_("Texture Synthesis of _All Layers..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (layers_args), G_N_ELEMENTS (image_return),
                          layers_args, image_return);
  gimp_plugin_menu_register (TS_PROC_RENDER_LAYERS, "<Image>/Filters/Render/Pattern");

  gimp_install_procedure (TS_PROC_TILEABLE,
                          N_("Make the layer tile seamlessly by re-synthesising its edges"),
                          "Runs the texsynth:tileable GEGL operation on the layer in place: "
                          "only bands along the edges change. Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("Make Seamless by _Synthesis..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (tileable_args), 0, tileable_args, NULL);
  gimp_plugin_menu_register (TS_PROC_TILEABLE, "<Image>/Filters/Map");

  gimp_install_procedure (TS_PROC_SOLID,
                          N_("Synthesise a solid (volume) texture from the layer"),
                          "Synthesises a size^3 volume whose slices look like the layer, writes "
                          "it to a file (.vol, .dds, or PNG) and opens an image of its three "
                          "middle slices.",
                          AUTHOR, COPYRIGHT, DATE, N_("S_olid Texture..."),
                          "RGB*, GRAY*, INDEXED*", GIMP_PLUGIN,
                          G_N_ELEMENTS (solid_args), G_N_ELEMENTS (image_return),
                          solid_args, image_return);
  gimp_plugin_menu_register (TS_PROC_SOLID, "<Image>/Filters/Render/Pattern");

  gimp_install_procedure (TS_PROC_HEAL_SELECTION,
                          N_("Fill the selection with texture continued from around it"),
                          "Runs the texsynth:heal GEGL operation on the layer with the selection "
                          "as the hole: pixels at least half selected are filled, the others "
                          "stay exactly as they were. Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("_Heal Selection by Synthesis..."),
                          "RGB*, GRAY*", GIMP_PLUGIN, G_N_ELEMENTS (heal_args), 0, heal_args, NULL);
  gimp_plugin_menu_register (TS_PROC_HEAL_SELECTION, "<Image>/Filters/Enhance");
  gimp_install_procedure (TS_PROC_HEAL_TRANSPARENCY,
                          N_("Fill the transparent parts of the layer with texture"),
                          "Runs the texsynth:heal GEGL operation on the layer: its pixels that "
                          "are not fully opaque are filled. Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("Heal _Transparency by Synthesis..."),
                          "RGBA, GRAYA", GIMP_PLUGIN, G_N_ELEMENTS (heal_args), 0, heal_args, NULL);
  gimp_plugin_menu_register (TS_PROC_HEAL_TRANSPARENCY, "<Image>/Filters/Enhance");
  gimp_install_procedure (TS_PROC_UNCROP,
                          N_("Enlarge the canvas and fill the new border with texture"),
                          "Adds a border of the given percentage on each side of the image and "
                          "fills that border only with texsynth:heal (transparent pixels the "
                          "layer already had stay as they are). Undoable.",
                          AUTHOR, COPYRIGHT, DATE, N_("_Uncrop by Synthesis..."),
                          "RGB*, GRAY*", GIMP_PLUGIN, G_N_ELEMENTS (uncrop_args), 0, uncrop_args,
                          NULL);
  gimp_plugin_menu_register (TS_PROC_UNCROP, "<Image>/Filters/Enhance");
  ts_install_guided2 ();
}

/* --- the procedures ---------------------------------------------------- */

static gboolean
run_render (GimpRunMode mode, const GimpParam *params, gint n_params, Outcome *outcome)
{
  gint32 drawable = params[2].data.d_drawable;
  TsExemplar exemplar;
  TsRenderArgs args;
  GeglBuffer *result = NULL;
  GError *error = NULL;
  gchar *message = NULL;
  const gchar *name = _("Texture");

  ts_render_args_init (&args);
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != 8)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes 8 arguments (got %d)."), TS_PROC_RENDER, n_params));
      args.width = params[3].data.d_int32;
      args.height = params[4].data.d_int32;
      args.tileable = params[5].data.d_int32 != 0;
      args.quality = params[6].data.d_int32;
      args.seed = params[7].data.d_int32;
    }
  else
    gimp_get_data (TS_PROC_RENDER, &args);

  if (!read_exemplar (drawable, TRUE, &exemplar, &message))
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);

  if (mode == GIMP_RUN_INTERACTIVE)
    {
      const GeglRectangle *extent = gegl_buffer_get_extent (exemplar.buffer);

      if (args.width < 1)
        {
          args.width = MIN (2 * extent->width, TS_PLUGIN_MAX_SIDE);
          args.height = MIN (2 * extent->height, TS_PLUGIN_MAX_SIDE);
        }
      args.seed = ts_plugin_random_seed ();
      if (!ts_render_dialog2 (&args, &exemplar))
        {
          ts_exemplar_clear (&exemplar);
          return fail (outcome, GIMP_PDB_CANCEL, NULL);
        }
    }

  if ((message = ts_render_args_check (&args)))
    {
      ts_exemplar_clear (&exemplar);
      return fail (outcome, GIMP_PDB_CALLING_ERROR, message);
    }
  if (gimp_drawable_is_indexed (drawable))
    g_message (_("The exemplar is indexed: the new image is RGB."));

  gimp_progress_init (_("Synthesising texture"));
  if (!ts_plugin_render (&exemplar, &args, &result, &error))
    {
      ts_exemplar_clear (&exemplar);
      fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (error->message));
      g_error_free (error);
      return FALSE;
    }
  outcome->new_image = new_image (&exemplar, &result, &name, NULL, 1);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  return finish_with_image (outcome, mode, TS_PROC_RENDER, &args, sizeof args);
}

static gboolean
run_tileable (GimpRunMode mode, const GimpParam *params, gint n_params, Outcome *outcome)
{
  gint32 drawable = params[2].data.d_drawable;
  TsExemplar exemplar;
  TsTileableArgs args;
  GeglBuffer *result = NULL;
  GError *error = NULL;
  gchar *message = NULL;
  gboolean written;

  ts_tileable_args_init (&args);
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != 5)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes 5 arguments (got %d)."), TS_PROC_TILEABLE, n_params));
      args.quality = params[3].data.d_int32;
      args.seed = params[4].data.d_int32;
    }
  else
    gimp_get_data (TS_PROC_TILEABLE, &args);

  if (mode == GIMP_RUN_INTERACTIVE)
    {
      GeglBuffer *buffer = gimp_drawable_get_buffer (drawable);
      TsPreviewInput preview = { .kind = TS_PREVIEW_TILEABLE, .ratio = 1.0 };
      gboolean ok;

      preview.pixels = ts_preview_copy (buffer, TS_PREVIEW_TILE_SIDE, TRUE, &preview.ratio);
      g_object_unref (buffer);
      args.seed = ts_plugin_random_seed ();
      ok = ts_tileable_dialog2 (&args, preview.pixels ? &preview : NULL);
      g_clear_object (&preview.pixels);
      if (!ok)
        return fail (outcome, GIMP_PDB_CANCEL, NULL);
    }
  if ((message = ts_tileable_args_check (&args, gimp_drawable_width (drawable),
                                         gimp_drawable_height (drawable))))
    return fail (outcome, GIMP_PDB_CALLING_ERROR, message);

  if (!read_exemplar (drawable, FALSE, &exemplar, &message))
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
  gimp_progress_init (_("Making the layer seamless"));
  if (!ts_plugin_tileable (&exemplar, &args, &result, &error))
    {
      ts_exemplar_clear (&exemplar);
      fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (error->message));
      g_error_free (error);
      return FALSE;
    }

  /* Only now is the image changed: a cancelled run leaves it as it was. */
  written = ts_replace_layer_pixels2 (drawable, result);
  g_object_unref (result);
  ts_exemplar_clear (&exemplar);
  if (!written)
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (_("Out of memory.")));

  if (mode != GIMP_RUN_NONINTERACTIVE)
    {
      gimp_set_data (TS_PROC_TILEABLE, &args, sizeof args);
      gimp_displays_flush ();
    }
  return TRUE;
}

/* GIMP 2.10 copies the stored bytes over `args` whatever their number:
 * only this struct's size, or the older one without cell_structure
 * (which then keeps its default, automatic), may be read. A stored
 * TRUE/FALSE reads as on/off: the field kept its size and place. */
static void
load_last_solid_args (TsSolidArgs *args)
{
  gint stored = gimp_get_data_size (TS_PROC_SOLID);

  if (stored == (gint) sizeof *args || stored == (gint) offsetof (TsSolidArgs, cell_structure))
    gimp_get_data (TS_PROC_SOLID, args);
  /* Stored bytes are not to be trusted: a choice the dialog cannot show
   * becomes the default. */
  if (args->cell_structure < 0 || args->cell_structure > TS_PLUGIN_MAX_CELL_STRUCTURE)
    args->cell_structure = TS_PLUGIN_CELL_STRUCTURE_AUTO;
}

static gboolean
run_solid (GimpRunMode mode, const GimpParam *params, gint n_params, Outcome *outcome)
{
  gint32 drawable = params[2].data.d_drawable;
  const gchar *names[3] = { _("Slice x = middle"), _("Slice y = middle"), _("Slice z = middle") };
  TsExemplar exemplar;
  TsSolidArgs args;
  GeglBuffer *slices[3] = { NULL, NULL, NULL };
  GError *error = NULL;
  gchar *message = NULL;

  ts_solid_args_init (&args);
  if (mode == GIMP_RUN_NONINTERACTIVE)
    {
      if (n_params != 8)
        return fail (outcome, GIMP_PDB_CALLING_ERROR,
                     g_strdup_printf (_("%s takes 8 arguments (got %d)."), TS_PROC_SOLID, n_params));
      args.size = params[3].data.d_int32;
      g_strlcpy (args.path, params[4].data.d_string ? params[4].data.d_string : "",
                 sizeof args.path);
      args.quality = params[5].data.d_int32;
      args.seed = params[6].data.d_int32;
      args.cell_structure = params[7].data.d_int32;  /* ts_solid_args_check checks it */
    }
  else
    load_last_solid_args (&args);

  if ((message = ts_plugin_check_ops (TS_OP_VOLUME_SAVE, TS_OP_VOLUME_SLICE, NULL)))
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
  /* Before the dialog: its preview grows the exemplar. */
  if (!read_exemplar (drawable, TRUE, &exemplar, &message))
    return fail (outcome, GIMP_PDB_EXECUTION_ERROR, message);
  if (mode == GIMP_RUN_INTERACTIVE)
    {
      args.seed = ts_plugin_random_seed ();
      if (!ts_solid_dialog2 (&args, &exemplar))
        {
          ts_exemplar_clear (&exemplar);
          return fail (outcome, GIMP_PDB_CANCEL, NULL);
        }
    }
  if ((message = ts_solid_args_check (&args, 1)))
    {
      ts_exemplar_clear (&exemplar);
      return fail (outcome, GIMP_PDB_CALLING_ERROR, message);
    }
  gimp_progress_init (_("Synthesising a solid texture"));
  if (!ts_plugin_solid (&exemplar, 1, &args, slices, &error))
    {
      ts_exemplar_clear (&exemplar);
      fail (outcome, GIMP_PDB_EXECUTION_ERROR, g_strdup (error->message));
      g_error_free (error);
      return FALSE;
    }
  outcome->new_image = new_image (&exemplar, slices, names, NULL, 3);
  for (gint i = 0; i < 3; i++)
    g_object_unref (slices[i]);
  ts_exemplar_clear (&exemplar);
  return finish_with_image (outcome, mode, TS_PROC_SOLID, &args, sizeof args);
}

static void
run (const gchar      *name,
     gint              n_params,
     const GimpParam  *params,
     gint             *n_return_vals,
     GimpParam       **return_vals)
{
  static GimpParam values[2];
  Outcome outcome = { .status = GIMP_PDB_SUCCESS, .new_image = -1, .new_layer = -1 };
  GimpRunMode mode = n_params > 0 ? params[0].data.d_int32 : GIMP_RUN_NONINTERACTIVE;
  gchar *message;

  ts_plugin_init_i18n ();
  textdomain (GETTEXT_PACKAGE);
  gegl_init (NULL, NULL);

  if (n_params < 3)
    fail (&outcome, GIMP_PDB_CALLING_ERROR,
          g_strdup_printf (_("%s needs a run mode, an image and a drawable."), name));
  else if ((message = ts_plugin_check_ops (TS_OP_SYNTHESIZE, TS_OP_TILEABLE, TS_OP_HEAL, NULL)))
    fail (&outcome, GIMP_PDB_EXECUTION_ERROR, message);
  else if (!gimp_item_is_layer (params[2].data.d_drawable))
    fail (&outcome, GIMP_PDB_CALLING_ERROR, g_strdup (_("The drawable must be a layer.")));
  else if (g_str_equal (name, TS_PROC_RENDER))
    run_render (mode, params, n_params, &outcome);
  else if (g_str_equal (name, TS_PROC_RENDER_LAYERS))
    ts_run_layers2 (mode, params, n_params, &outcome);
  else if (g_str_equal (name, TS_PROC_TILEABLE))
    run_tileable (mode, params, n_params, &outcome);
  else if (g_str_equal (name, TS_PROC_SOLID))
    run_solid (mode, params, n_params, &outcome);
  else if (g_str_equal (name, TS_PROC_HEAL_SELECTION) || g_str_equal (name, TS_PROC_HEAL_TRANSPARENCY)
           || g_str_equal (name, TS_PROC_UNCROP))
    ts_run_heal2 (name, mode, params, n_params, &outcome);
  else if (g_str_equal (name, TS_PROC_BY_NUMBERS) || g_str_equal (name, TS_PROC_STYLE))
    ts_run_guided2 (name, mode, params, n_params, &outcome);
  else
    fail (&outcome, GIMP_PDB_CALLING_ERROR, g_strdup_printf (_("Unknown procedure %s."), name));

  /* GIMP shows the message of a failed run; interactive runs also get it
   * in a message box, since nobody reads the return value there. */
  if (outcome.message && mode == GIMP_RUN_INTERACTIVE)
    g_message ("%s", outcome.message);

  values[0].type = GIMP_PDB_STATUS;
  values[0].data.d_status = outcome.status;
  *n_return_vals = 1;
  if (outcome.status == GIMP_PDB_SUCCESS && outcome.new_image >= 0)
    {
      values[1].type = GIMP_PDB_IMAGE;
      values[1].data.d_image = outcome.new_image;
      *n_return_vals = 2;
    }
  else if (outcome.status == GIMP_PDB_SUCCESS && outcome.new_layer >= 0)
    {
      values[1].type = GIMP_PDB_LAYER;
      values[1].data.d_layer = outcome.new_layer;
      *n_return_vals = 2;
    }
  else if (outcome.status != GIMP_PDB_SUCCESS && outcome.message)
    {
      values[1].type = GIMP_PDB_STRING;
      values[1].data.d_string = outcome.message; /* GIMP reads it after run returns */
      *n_return_vals = 2;
    }
  *return_vals = values;
}
