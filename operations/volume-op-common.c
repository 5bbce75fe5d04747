/* Helpers shared by the volume ops.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "volume-op-common.h"
#include "op-lab.h"

#include <glib/gi18n-lib.h>
#include <stdio.h>

static const gchar *const pad_names[3] = { "input", "aux", "aux2" };

TsSolidParams
ts_volume_op_default_params (void)
{
  TsSolidParams params;

  ts_solid_params_init (&params);
  return params;
}

static gboolean
too_large (const GeglRectangle *rect)
{
  return rect->width > TS_MAX_OUTPUT_SIDE || rect->height > TS_MAX_OUTPUT_SIDE;
}

GeglRectangle
ts_volume_op_required_input (GeglOperation *operation, const gchar *pad)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, pad);
  GeglRectangle empty = { 0, 0, 0, 0 };

  return box && !too_large (box) ? *box : empty;
}

void
ts_volume_op_prepare_inputs (GeglOperation *operation)
{
  for (int i = 0; i < 3; i++)
    gegl_operation_set_format (operation, pad_names[i], babl_format (TS_OP_FORMAT));
}

/* As ts_op_read_input, for any pad: an empty pad gives a 0x0 image. */
static gboolean
read_pad (GeglOperation *operation, const gchar *pad, GeglBuffer *buffer, TsImage *image,
          TsError *error)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, pad);
  GeglRectangle rect = { 0, 0, 0, 0 };
  gsize bytes;

  image->width = image->height = 0;
  image->pixels = NULL;
  if (buffer && box)
    rect = *box;
  if (rect.width <= 0 || rect.height <= 0)
    return TRUE;
  if (gegl_rectangle_is_infinite_plane (&rect) || too_large (&rect))
    {
      error->status = TS_ERROR_BAD_PARAMETER;
      snprintf (error->message, sizeof error->message,
                _("the exemplar on the '%s' pad is unbounded or larger than %dx%d pixels; "
                  "crop it"), pad, TS_MAX_OUTPUT_SIDE, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }
  bytes = (gsize) rect.width * (gsize) rect.height * TS_CHANNELS * sizeof (float);
  image->pixels = g_try_malloc (bytes);
  if (!image->pixels)
    {
      error->status = TS_ERROR_OUT_OF_MEMORY;
      snprintf (error->message, sizeof error->message,
                _("out of memory reading the %dx%d exemplar on the '%s' pad (%.1f MiB)"),
                rect.width, rect.height, pad, (double) bytes / 1048576.0);
      return FALSE;
    }
  ts_op_read_lab (buffer, &rect, image->pixels);
  image->width = (size_t) rect.width;
  image->height = (size_t) rect.height;
  return TRUE;
}

/* The engine names orientations; say which pad gave each exemplar. */
static void
name_pads (const TsImage *const exemplars[3], const TsImage *const pads[3], TsError *error)
{
  static const char *const axis_names[3] = { "x", "y", "z" };
  GString *text;

  if (error->status != TS_ERROR_EMPTY_EXEMPLAR && error->status != TS_ERROR_TRANSPARENT_EXEMPLAR &&
      error->status != TS_ERROR_EXEMPLAR_TOO_SMALL)
    return;
  text = g_string_new (error->message);
  g_string_append (text, " (");
  for (int p = 0, listed = 0; p < 3; p++)
    {
      int axes = 0;
      if (!pads[p])
        continue;
      g_string_append_printf (text, "%s'%s' gives the slices across", listed++ ? "; " : "",
                              pad_names[p]);
      for (int a = 0; a < 3; a++)
        if (exemplars[a] == pads[p])
          g_string_append_printf (text, "%s %s", axes++ ? "," : "", axis_names[a]);
      if (!axes)
        g_string_append (text, " none");
    }
  g_string_append (text, ")");
  g_strlcpy (error->message, text->str, sizeof error->message);
  g_string_free (text, TRUE);
}

TsVolumeEntry *
ts_volume_op_acquire (GeglOperation       *operation,
                      GeglBuffer          *input,
                      GeglBuffer          *aux,
                      GeglBuffer          *aux2,
                      const TsSolidParams *params,
                      int                  free_axis,
                      TsError             *error)
{
  GeglBuffer *buffers[3] = { input, aux, aux2 };
  TsImage images[3] = { { 0, 0, NULL }, { 0, 0, NULL }, { 0, 0, NULL } };
  const TsImage *pads[3] = { NULL, NULL, NULL };
  const TsImage *exemplars[3];
  TsVolumeEntry *entry = NULL;
  gboolean ok = TRUE;

  for (int i = 0; i < 3 && ok; i++)
    {
      /* An unconnected pad is absent; a connected but empty one is an
       * empty exemplar, which the engine reports. */
      if (!gegl_operation_get_source_node (operation, pad_names[i]))
        continue;
      ok = read_pad (operation, pad_names[i], buffers[i], &images[i], error);
      pads[i] = &images[i];
    }

  if (ok)
    {
      TsOpProgress progress;

      exemplars[TS_AXIS_X] = pads[1] ? pads[1] : pads[0];
      exemplars[TS_AXIS_Y] = pads[2] ? pads[2] : pads[0];
      exemplars[TS_AXIS_Z] = pads[0];
      if (free_axis >= TS_VOLUME_OP_FREE_X && free_axis <= TS_VOLUME_OP_FREE_Z)
        exemplars[free_axis - TS_VOLUME_OP_FREE_X] = NULL;

      ts_op_progress_init (&progress, operation);
      ts_op_progress_func (0.0, "starting", &progress);
      entry = ts_volume_cache_acquire (params, exemplars, ts_op_progress_func, &progress, error);
      ts_op_progress_func (1.0, "done", &progress);
      ts_op_progress_clear (&progress);
      if (!entry)
        name_pads (exemplars, pads, error);
    }

  for (int i = 0; i < 3; i++)
    g_free (images[i].pixels);
  return entry;
}
