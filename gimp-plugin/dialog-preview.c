/* The dialogs' preview widget, for GTK2 (GIMP 2.10) and GTK3 (GIMP 3):
 * the run is polled from the main loop, so the dialog stays responsive
 * while the op works in its own thread.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
/* GIMP 2.10's libgimpui and GTK2 use API that GLib has deprecated since. */
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

#include <glib/gi18n-lib.h>

#include "dialog-preview.h"

/* How often the main loop looks whether the run has finished. */
#define POLL_MS 50

typedef struct
{
  GtkWidget     *area;
  GtkWidget     *button;
  TsPreviewStart start;
  gpointer       data;
  TsPreview     *running;
  guint          poll;
} PreviewWidget;

static gboolean
show_result (gpointer user_data)
{
  PreviewWidget *preview = user_data;
  GtkAllocation allocation;
  const guchar *pixels;
  gint width, height;

  if (!ts_preview_done (preview->running))
    return G_SOURCE_CONTINUE;
  pixels = ts_preview_pixels (preview->running, &width, &height);
  gtk_widget_get_allocation (preview->area, &allocation);
  /* Grey around a result smaller than the area; its transparent pixels
   * show GIMP's checks. */
  gimp_preview_area_fill (GIMP_PREVIEW_AREA (preview->area), 0, 0, allocation.width,
                          allocation.height, 0x80, 0x80, 0x80);
  gimp_preview_area_draw (GIMP_PREVIEW_AREA (preview->area),
                          MAX (0, (allocation.width - width) / 2),
                          MAX (0, (allocation.height - height) / 2), width, height,
                          GIMP_RGBA_IMAGE, pixels, width * 4);
  ts_preview_free (preview->running);
  preview->running = NULL;
  preview->poll = 0;
  gtk_widget_set_sensitive (preview->button, TRUE);
  return G_SOURCE_REMOVE;
}

static void
run_preview (PreviewWidget *preview)
{
  if (preview->running)
    return;
  preview->running = preview->start (preview->data);
  if (!preview->running)
    return;
  gtk_widget_set_sensitive (preview->button, FALSE);
  preview->poll = g_timeout_add (POLL_MS, show_result, preview);
}

static void
on_clicked (GtkWidget *button G_GNUC_UNUSED, PreviewWidget *preview)
{
  run_preview (preview);
}

static void
on_map (GtkWidget *area G_GNUC_UNUSED, PreviewWidget *preview)
{
  run_preview (preview);
}

static void
on_destroy (GtkWidget *box G_GNUC_UNUSED, PreviewWidget *preview)
{
  if (preview->poll)
    g_source_remove (preview->poll);
  ts_preview_free (preview->running);
  g_free (preview);
}

GtkWidget *
ts_preview_widget_new (TsPreviewStart start, gpointer data, const gchar *caption)
{
  PreviewWidget *preview = g_new0 (PreviewWidget, 1);
  GtkWidget *frame = gtk_frame_new (NULL);
  GtkWidget *label = gtk_label_new (NULL);
  gchar *markup = g_markup_printf_escaped ("<small>%s</small>", caption);
#if GTK_MAJOR_VERSION >= 3
  GtkWidget *box = gtk_box_new (GTK_ORIENTATION_VERTICAL, 6);
#else
  GtkWidget *box = gtk_vbox_new (FALSE, 6);
#endif

  preview->start = start;
  preview->data = data;
  preview->area = gimp_preview_area_new ();
  gtk_widget_set_size_request (preview->area, TS_PREVIEW_SIDE, TS_PREVIEW_SIDE);
  gtk_frame_set_shadow_type (GTK_FRAME (frame), GTK_SHADOW_IN);
  gtk_container_add (GTK_CONTAINER (frame), preview->area);
#if GTK_MAJOR_VERSION >= 3
  gtk_widget_set_halign (frame, GTK_ALIGN_CENTER);
  gtk_box_pack_start (GTK_BOX (box), frame, FALSE, FALSE, 0);
#else
  {
    GtkWidget *centre = gtk_alignment_new (0.5, 0.5, 0.0, 0.0);

    gtk_container_add (GTK_CONTAINER (centre), frame);
    gtk_box_pack_start (GTK_BOX (box), centre, FALSE, FALSE, 0);
  }
#endif
  gimp_help_set_help_data (preview->area,
                           _("A small, quick run with these settings: how the result will "
                             "look, not the result itself"), NULL);
  /* Says what the preview shows, and how it differs from the result. */
  gtk_label_set_markup (GTK_LABEL (label), markup);
  g_free (markup);
  gtk_label_set_justify (GTK_LABEL (label), GTK_JUSTIFY_CENTER);
  gtk_label_set_line_wrap (GTK_LABEL (label), TRUE);
  gtk_label_set_width_chars (GTK_LABEL (label), 30);
  gtk_box_pack_start (GTK_BOX (box), label, FALSE, FALSE, 0);

  preview->button = gtk_button_new_with_mnemonic (_("_Preview"));
  gimp_help_set_help_data (preview->button, _("Run the preview again with the settings as "
                                              "they are now"), NULL);
#if GTK_MAJOR_VERSION >= 3
  gtk_widget_set_halign (preview->button, GTK_ALIGN_CENTER);
  gtk_box_pack_start (GTK_BOX (box), preview->button, FALSE, FALSE, 0);
#else
  {
    GtkWidget *centre = gtk_alignment_new (0.5, 0.5, 0.0, 0.0);

    gtk_container_add (GTK_CONTAINER (centre), preview->button);
    gtk_box_pack_start (GTK_BOX (box), centre, FALSE, FALSE, 0);
  }
#endif
  g_signal_connect (preview->button, "clicked", G_CALLBACK (on_clicked), preview);
  g_signal_connect_after (preview->area, "map", G_CALLBACK (on_map), preview);
  g_signal_connect (box, "destroy", G_CALLBACK (on_destroy), preview);
  gtk_widget_show_all (box);
  return box;
}
