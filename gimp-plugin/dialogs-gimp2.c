/* GIMP 2.10's dialogs: GTK2 through libgimpui-2.0, as GIMP 2.10 needs.
 * Labels, tooltips and ranges come from the shared argument table.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
/* GTK2 and GIMP 2.10's libgimpui use GLib API that GLib has deprecated
 * since; they are what GIMP 2.10 needs, so their warnings are noise. */
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

#include <string.h>

#include "dialogs-gimp2.h"
#include "dialog-preview.h"
#include "compat-gimp2.h"

#include <libgimp/gimpui.h>
#include <glib/gi18n-lib.h>

typedef struct
{
  GtkWidget *dialog;
  GtkWidget *vbox;
  GtkWidget *table;
  gint       rows;
} Form;

/* What a preview runs: what was read of GIMP and the dialog's live
 * settings: `args`, of the type of input->kind's procedure, the seed
 * (kept apart by GimpRandomSeed) and the guided procedures' layers (kept
 * by their combo boxes). */
typedef struct
{
  const TsPreviewInput *input;
  gconstpointer         args;
  const guint32        *seed;
  const gint32         *exemplar_layer, *guide_layer;
} PreviewSource;

static void
form_begin (Form *form, const gchar *title, const gchar *help_id)
{
  GtkWidget *vbox;

  gimp_ui_init (TS_PLUGIN_BINARY, FALSE);
  form->dialog = gimp_dialog_new (title, TS_PLUGIN_BINARY, NULL, 0,
                                  gimp_standard_help_func, help_id,
                                  _("_Cancel"), GTK_RESPONSE_CANCEL,
                                  _("_OK"), GTK_RESPONSE_OK,
                                  NULL);
  gtk_dialog_set_alternative_button_order (GTK_DIALOG (form->dialog),
                                           GTK_RESPONSE_OK, GTK_RESPONSE_CANCEL, -1);
  gimp_window_set_transient (GTK_WINDOW (form->dialog));

  vbox = gtk_vbox_new (FALSE, 12);
  gtk_container_set_border_width (GTK_CONTAINER (vbox), 12);
  gtk_box_pack_start (GTK_BOX (gtk_dialog_get_content_area (GTK_DIALOG (form->dialog))),
                      vbox, TRUE, TRUE, 0);
  form->vbox = vbox;
  form->table = gtk_table_new (1, 3, FALSE);
  gtk_table_set_col_spacings (GTK_TABLE (form->table), 6);
  gtk_table_set_row_spacings (GTK_TABLE (form->table), 6);
  gtk_box_pack_start (GTK_BOX (vbox), form->table, FALSE, FALSE, 0);
  form->rows = 0;
}

static gchar *
label_text (const gchar *name)
{
  return g_strdup_printf ("%s:", ts_arg_label (name));
}

/* A slider with a spin button; `soft_max` bounds the slider only. */
static void
form_int (Form *form, const gchar *name, gint *value, gint min, gint max, gint soft_max)
{
  gchar *label = label_text (name);
  GtkObject *adjustment;

  adjustment = gimp_scale_entry_new (GTK_TABLE (form->table), 0, form->rows++, label, 200, 6,
                                     *value, min, MIN (max, soft_max), 1, 10, 0,
                                     soft_max >= max, min, max, ts_arg_tooltip (name), NULL);
  g_signal_connect (adjustment, "value-changed", G_CALLBACK (gimp_int_adjustment_update), value);
  g_free (label);
}

/* An integer argument shown as a choice by name, not a number: `combo`
 * is a GimpIntComboBox of its choices. */
static void
form_int_combo (Form *form, const gchar *name, GtkWidget *combo, gint *value)
{
  gchar *label = label_text (name);

  gimp_int_combo_box_connect (GIMP_INT_COMBO_BOX (combo), *value,
                              G_CALLBACK (gimp_int_combo_box_get_active), value);
  gimp_help_set_help_data (combo, ts_arg_tooltip (name), NULL);
  gimp_table_attach_aligned (GTK_TABLE (form->table), 0, form->rows++, label, 0.0, 0.5,
                             combo, 2, FALSE);
  g_free (label);
}

static void
form_sample_from (Form *form, gint *value)
{
  form_int_combo (form, "sample-from",
                  gimp_int_combo_box_new (ts_sample_from_label (0), 0,
                                          ts_sample_from_label (1), 1,
                                          ts_sample_from_label (2), 2, NULL),
                  value);
}

/* Automatic first: the default, and right for most layers. */
static void
form_cell_structure (Form *form, gint *value)
{
  form_int_combo (form, "cell-structure",
                  gimp_int_combo_box_new (
                    ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_AUTO),
                    TS_PLUGIN_CELL_STRUCTURE_AUTO,
                    ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_ON),
                    TS_PLUGIN_CELL_STRUCTURE_ON,
                    ts_cell_structure_label (TS_PLUGIN_CELL_STRUCTURE_OFF),
                    TS_PLUGIN_CELL_STRUCTURE_OFF, NULL),
                  value);
}

static void
form_toggle (Form *form, const gchar *name, gboolean *value)
{
  GtkWidget *toggle = gtk_check_button_new_with_label (ts_arg_label (name));

  gtk_toggle_button_set_active (GTK_TOGGLE_BUTTON (toggle), *value);
  gimp_help_set_help_data (toggle, ts_arg_tooltip (name), NULL);
  gtk_table_attach (GTK_TABLE (form->table), toggle, 0, 3, form->rows, form->rows + 1,
                    GTK_FILL, GTK_FILL, 0, 0);
  form->rows++;
  g_signal_connect (toggle, "toggled", G_CALLBACK (gimp_toggle_button_update), value);
}

/* The seed: a spin button and GIMP's "New Seed" button. */
static void
form_seed (Form *form, guint32 *seed, gboolean *randomize)
{
  gchar *label = label_text ("seed");
  GtkWidget *widget = gimp_random_seed_new (seed, randomize);

  /* The seed is chosen anew for each interactive run anyway. */
  gtk_widget_set_no_show_all (GIMP_RANDOM_SEED_TOGGLE (widget), TRUE);
  gtk_widget_hide (GIMP_RANDOM_SEED_TOGGLE (widget));
  gimp_help_set_help_data (GIMP_RANDOM_SEED_SPINBUTTON (widget), ts_arg_tooltip ("seed"), NULL);
  gimp_table_attach_aligned (GTK_TABLE (form->table), 0, form->rows++, label, 0.0, 0.5,
                             widget, 2, TRUE);
  g_free (label);
}

/* A private copy of the layer `id` for the preview; NULL if there is
 * none (or no memory). */
static GeglBuffer *
read_layer (const gint32 *id)
{
  TsExemplar exemplar;
  GeglBuffer *buffer;
  gchar *message = NULL;

  if (!id || *id < 0 || !gimp_item_is_valid (*id) || !read_exemplar (*id, FALSE, &exemplar, &message))
    {
      g_free (message);
      return NULL;
    }
  buffer = g_object_ref (exemplar.buffer);
  ts_exemplar_clear (&exemplar);
  return buffer;
}

static TsPreview *
start_preview (gpointer data)
{
  const PreviewSource *source = data;
  gint seed = (gint) (*source->seed & G_MAXINT);
  TsPreviewSettings settings;
  TsPreview *preview;

  memset (&settings, 0, sizeof settings);
  switch (source->input->kind)
    {
    case TS_PREVIEW_RENDER:
    case TS_PREVIEW_LAYERS:
      settings.render = *(const TsRenderArgs *) source->args;
      settings.render.seed = seed;
      break;
    case TS_PREVIEW_SOLID:
      settings.solid = *(const TsSolidArgs *) source->args;
      settings.solid.seed = seed;
      break;
    case TS_PREVIEW_HEAL_SELECTION:
    case TS_PREVIEW_HEAL_TRANSPARENCY:
    case TS_PREVIEW_UNCROP:
      settings.heal = *(const TsHealArgs *) source->args;
      settings.heal.seed = seed;
      break;
    case TS_PREVIEW_TILEABLE:
      settings.tileable = *(const TsTileableArgs *) source->args;
      settings.tileable.seed = seed;
      break;
    case TS_PREVIEW_GUIDED:
      settings.guided = *(const TsGuidedArgs *) source->args;
      settings.guided.seed = seed;
      /* The layers the dialog picks now: read anew for each run. */
      settings.exemplar = read_layer (source->exemplar_layer);
      settings.exemplar_guide = read_layer (source->guide_layer);
      break;
    }
  preview = ts_preview_start (source->input, &settings);
  g_clear_object (&settings.exemplar);
  g_clear_object (&settings.exemplar_guide);
  return preview;
}

/* GIMP's filter dialogs show their preview first. */
static void
form_preview (Form *form, PreviewSource *source)
{
  GtkWidget *preview = ts_preview_widget_new (start_preview, source,
                                              ts_preview_caption (source->input->kind));

  gtk_box_pack_start (GTK_BOX (form->vbox), preview, FALSE, FALSE, 0);
  gtk_box_reorder_child (GTK_BOX (form->vbox), preview, 0);
}

static gboolean
form_run (Form *form)
{
  gboolean ok;

  gtk_widget_show_all (form->dialog);
  ok = gimp_dialog_run (GIMP_DIALOG (form->dialog)) == GTK_RESPONSE_OK;
  gtk_widget_destroy (form->dialog);
  return ok;
}

/* `exemplar`: what the preview grows. */
static gboolean
render_form (TsRenderArgs *args, const gchar *title, const gchar *procedure,
             TsPreviewKind kind, const TsExemplar *exemplar)
{
  Form form;
  guint32 seed = (guint32) args->seed;
  gboolean randomize = FALSE, ok;
  TsPreviewInput input = { .kind = kind, .exemplars = exemplar, .n_exemplars = 1 };
  PreviewSource source = { &input, args, &seed, NULL, NULL };

  form_begin (&form, title, procedure);
  form_preview (&form, &source);
  form_int (&form, "width", &args->width, 1, TS_PLUGIN_MAX_SIDE, 4096);
  form_int (&form, "height", &args->height, 1, TS_PLUGIN_MAX_SIDE, 4096);
  form_toggle (&form, "tileable", &args->tileable);
  form_int (&form, "quality", &args->quality, TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY,
            TS_PLUGIN_MAX_QUALITY);
  form_seed (&form, &seed, &randomize);
  ok = form_run (&form);
  args->seed = (gint) (seed & G_MAXINT);
  return ok;
}

gboolean
ts_render_dialog2 (TsRenderArgs *args, const TsExemplar *exemplar)
{
  return render_form (args, _("Texture Synthesis"), TS_PROC_RENDER, TS_PREVIEW_RENDER, exemplar);
}

gboolean
ts_layers_dialog2 (TsRenderArgs *args, const TsExemplar *driver)
{
  return render_form (args, _("Texture Synthesis of All Layers"), TS_PROC_RENDER_LAYERS,
                      TS_PREVIEW_LAYERS, driver);
}

gboolean
ts_tileable_dialog2 (TsTileableArgs *args, const TsPreviewInput *preview)
{
  Form form;
  guint32 seed = (guint32) args->seed;
  gboolean randomize = FALSE, ok;
  PreviewSource source = { preview, args, &seed, NULL, NULL };

  form_begin (&form, _("Make Seamless by Synthesis"), TS_PROC_TILEABLE);
  if (preview)
    form_preview (&form, &source);
  form_int (&form, "quality", &args->quality, TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY,
            TS_PLUGIN_MAX_QUALITY);
  form_seed (&form, &seed, &randomize);
  ok = form_run (&form);
  args->seed = (gint) (seed & G_MAXINT);
  return ok;
}

gboolean
ts_heal_dialog2 (TsHealArgs *args, const gchar *procedure, const gchar *title,
                 const TsPreviewInput *preview)
{
  Form form;
  guint32 seed = (guint32) args->seed;
  gboolean randomize = FALSE, ok;
  PreviewSource source = { preview, args, &seed, NULL, NULL };

  form_begin (&form, title, procedure);
  if (preview)
    form_preview (&form, &source);
  if (g_str_equal (procedure, TS_PROC_UNCROP))
    form_int (&form, "percent", &args->percent, 1, TS_PLUGIN_MAX_UNCROP, 50);
  else
    {
      form_int (&form, "context", &args->context, 0, TS_PLUGIN_MAX_CONTEXT, 500);
      form_sample_from (&form, &args->sample_from);
    }
  form_int (&form, "quality", &args->quality, TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY,
            TS_PLUGIN_MAX_QUALITY);
  form_seed (&form, &seed, &randomize);
  ok = form_run (&form);
  args->seed = (gint) (seed & G_MAXINT);
  return ok;
}

/* --- the volume file ---------------------------------------------------- */

static void
on_browse (GtkWidget *button G_GNUC_UNUSED, GtkEntry *entry)
{
  GtkWidget *chooser = gtk_file_chooser_dialog_new (_("Save the Volume As"),
                                                    NULL, GTK_FILE_CHOOSER_ACTION_SAVE,
                                                    _("_Cancel"), GTK_RESPONSE_CANCEL,
                                                    _("_Save"), GTK_RESPONSE_ACCEPT,
                                                    NULL);

  gtk_file_chooser_set_do_overwrite_confirmation (GTK_FILE_CHOOSER (chooser), TRUE);
  gtk_file_chooser_set_filename (GTK_FILE_CHOOSER (chooser), gtk_entry_get_text (entry));
  if (gtk_dialog_run (GTK_DIALOG (chooser)) == GTK_RESPONSE_ACCEPT)
    {
      gchar *path = gtk_file_chooser_get_filename (GTK_FILE_CHOOSER (chooser));

      if (path)
        gtk_entry_set_text (entry, path);
      g_free (path);
    }
  gtk_widget_destroy (chooser);
}

static void
form_path (Form *form, gchar *path, gsize size, GtkWidget **entry_out)
{
  gchar *label = label_text ("path");
  GtkWidget *hbox = gtk_hbox_new (FALSE, 6);
  GtkWidget *entry = gtk_entry_new ();
  GtkWidget *browse = gtk_button_new_with_mnemonic (_("_Browse\342\200\246"));

  gtk_entry_set_max_length (GTK_ENTRY (entry), (gint) size - 1);
  gtk_entry_set_text (GTK_ENTRY (entry), path);
  gtk_entry_set_width_chars (GTK_ENTRY (entry), 36);
  gimp_help_set_help_data (entry, ts_arg_tooltip ("path"), NULL);
  gtk_box_pack_start (GTK_BOX (hbox), entry, TRUE, TRUE, 0);
  gtk_box_pack_start (GTK_BOX (hbox), browse, FALSE, FALSE, 0);
  g_signal_connect (browse, "clicked", G_CALLBACK (on_browse), entry);
  gimp_table_attach_aligned (GTK_TABLE (form->table), 0, form->rows++, label, 0.0, 0.5,
                             hbox, 2, FALSE);
  *entry_out = entry;
  g_free (label);
}

gboolean
ts_solid_dialog2 (TsSolidArgs *args, const TsExemplar *exemplar)
{
  Form form;
  guint32 seed = (guint32) args->seed;
  gboolean randomize = FALSE, ok;
  GtkWidget *entry;
  TsPreviewInput input = { .kind = TS_PREVIEW_SOLID, .exemplars = exemplar, .n_exemplars = 1 };
  PreviewSource source = { &input, args, &seed, NULL, NULL };

  form_begin (&form, _("Solid Texture"), TS_PROC_SOLID);
  form_preview (&form, &source);
  form_int (&form, "size", &args->size, TS_PLUGIN_MIN_SOLID, TS_PLUGIN_MAX_SOLID,
            TS_PLUGIN_MAX_SOLID);
  form_path (&form, args->path, sizeof args->path, &entry);
  form_cell_structure (&form, &args->cell_structure);
  form_int (&form, "solid-quality", &args->quality, TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY,
            TS_PLUGIN_MAX_QUALITY);
  form_seed (&form, &seed, &randomize);

  gtk_widget_show_all (form.dialog);
  ok = gimp_dialog_run (GIMP_DIALOG (form.dialog)) == GTK_RESPONSE_OK;
  if (ok)
    g_strlcpy (args->path, gtk_entry_get_text (GTK_ENTRY (entry)), sizeof args->path);
  gtk_widget_destroy (form.dialog);
  args->seed = (gint) (seed & G_MAXINT);
  return ok;
}

/* --- the guided procedures --------------------------------------------- */

/* Any layer but the one the procedure runs on. */
static gboolean
not_target (gint32 image G_GNUC_UNUSED, gint32 item, gpointer data)
{
  return item != GPOINTER_TO_INT (data);
}

/* A layer picked from every open image; -1 in *layer picks the first. */
static void
form_layer (Form *form, const gchar *name, gint32 target, gint32 *layer)
{
  gchar *label = label_text (name);
  GtkWidget *combo = gimp_layer_combo_box_new (not_target, GINT_TO_POINTER (target));

  gimp_int_combo_box_connect (GIMP_INT_COMBO_BOX (combo), *layer,
                              G_CALLBACK (gimp_int_combo_box_get_active), layer);
  if (!gimp_int_combo_box_get_active (GIMP_INT_COMBO_BOX (combo), layer))
    *layer = -1;
  gimp_help_set_help_data (combo, ts_arg_tooltip (name), NULL);
  gimp_table_attach_aligned (GTK_TABLE (form->table), 0, form->rows++, label, 0.0, 0.5,
                             combo, 2, FALSE);
  g_free (label);
}

/* A slider with a spin button, two decimals; `soft_max` bounds the slider. */
static void
form_double (Form *form, const gchar *name, gdouble *value, gdouble min, gdouble max,
             gdouble soft_max)
{
  gchar *label = label_text (name);
  GtkObject *adjustment;

  adjustment = gimp_scale_entry_new (GTK_TABLE (form->table), 0, form->rows++, label, 200, 6,
                                     *value, min, MIN (max, soft_max), 0.1, 1.0, 2,
                                     soft_max >= max, min, max, ts_arg_tooltip (name), NULL);
  g_signal_connect (adjustment, "value-changed", G_CALLBACK (gimp_double_adjustment_update),
                    value);
  g_free (label);
}

gboolean
ts_guided_dialog2 (const gchar *procedure, TsGuidedArgs *args, gint32 target, gint32 *exemplar,
                   gint32 *guide, const TsPreviewInput *preview)
{
  Form form;
  guint32 seed = (guint32) args->seed;
  gboolean randomize = FALSE, ok;
  PreviewSource source = { preview, args, &seed, exemplar, guide };

  form_begin (&form, guide ? _("Texture by Numbers") : _("Style Transfer by Synthesis"),
              procedure);
  if (preview)
    form_preview (&form, &source);
  form_layer (&form, guide ? "exemplar" : "style", target, exemplar);
  if (guide)
    form_layer (&form, "exemplar-guide", target, guide);
  form_double (&form, guide ? "guide-weight" : "style-weight", &args->guide_weight, 0.0,
               TS_PLUGIN_MAX_GUIDE_WEIGHT, 10.0);
  if (guide)
    {
      form_toggle (&form, "blend-edges", &args->blend_edges);
      form_toggle (&form, "tileable", &args->tileable);
    }
  form_int (&form, "quality", &args->quality, TS_PLUGIN_MIN_QUALITY, TS_PLUGIN_MAX_QUALITY,
            TS_PLUGIN_MAX_QUALITY);
  form_seed (&form, &seed, &randomize);
  ok = form_run (&form);
  args->seed = (gint) (seed & G_MAXINT);
  return ok;
}
