/* Helpers shared by the texsynth GEGL operations.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "op-common.h"
#include "op-lab.h"

#include <glib/gi18n-lib.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void
ts_op_bind_textdomain (void)
{
#ifdef ENABLE_NLS
  const gchar *dir = g_getenv ("TEXSYNTH_LOCALEDIR");

  bindtextdomain (GETTEXT_PACKAGE, dir && *dir ? dir : LOCALEDIR);
  bind_textdomain_codeset (GETTEXT_PACKAGE, "UTF-8");
#endif
}

TsParams
ts_op_default_params (void)
{
  TsParams params;

  ts_params_init (&params);
  return params;
}

static gboolean
too_large (const GeglRectangle *rect)
{
  return rect->width > TS_MAX_OUTPUT_SIDE || rect->height > TS_MAX_OUTPUT_SIDE;
}

GeglRectangle
ts_op_required_input (GeglOperation *operation)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, "input");
  GeglRectangle empty = { 0, 0, 0, 0 };

  return box && !too_large (box) ? *box : empty;
}

GeglRectangle
ts_op_input_bounding_box (GeglOperation *operation)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, "input");
  GeglRectangle empty = { 0, 0, 0, 0 };

  return box ? *box : empty;
}

gboolean
ts_op_read_input (GeglOperation *operation,
                  GeglBuffer    *input,
                  TsImage       *image,
                  gchar         *message,
                  gsize          message_size)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, "input");
  GeglRectangle rect = { 0, 0, 0, 0 };
  gsize floats;

  image->width = image->height = 0;
  image->pixels = NULL;
  if (input && box)
    rect = *box;
  if (rect.width <= 0 || rect.height <= 0)
    return TRUE;

  /* Checked here as well as in the engine: reading a huge input just to be
   * told it is too large could exhaust memory first. */
  if (gegl_rectangle_is_infinite_plane (&rect))
    {
      snprintf (message, message_size,
                _("the exemplar is unbounded (e.g. a fill or noise without a crop); "
                  "crop it to at most %dx%d pixels"), TS_MAX_OUTPUT_SIDE, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }
  if (too_large (&rect))
    {
      snprintf (message, message_size,
                _("the exemplar is %dx%d; its sides must be at most %d pixels"),
                rect.width, rect.height, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }

  floats = (gsize) rect.width * (gsize) rect.height * TS_CHANNELS;
  image->pixels = g_try_malloc (floats * sizeof (float));
  if (!image->pixels)
    {
      snprintf (message, message_size,
                _("out of memory reading the %dx%d exemplar (%.1f MiB)"),
                rect.width, rect.height, (double) (floats * sizeof (float)) / 1048576.0);
      return FALSE;
    }
  ts_op_read_lab (input, &rect, image->pixels);
  image->width = (size_t) rect.width;
  image->height = (size_t) rect.height;
  return TRUE;
}

TsStatus
ts_op_alloc_output (const TsParams *params,
                    const TsImage  *exemplar,
                    TsImage        *output,
                    TsError        *error)
{
  TsStatus status;
  gsize bytes;

  output->width = output->height = 0;
  output->pixels = NULL;
  /* Validation includes the engine's memory estimate against its limit,
   * so an impossible size is refused before the big allocation. */
  status = ts_params_validate (params, exemplar, error);
  if (status != TS_OK)
    return status;

  bytes = params->output_width * params->output_height * TS_CHANNELS * sizeof (float);
  output->pixels = g_try_malloc (bytes);
  if (!output->pixels)
    {
      if (error)
        {
          error->status = TS_ERROR_OUT_OF_MEMORY;
          snprintf (error->message, sizeof error->message,
                    _("out of memory allocating the %zux%zu output (%.1f MiB)"),
                    params->output_width, params->output_height, (double) bytes / 1048576.0);
        }
      return TS_ERROR_OUT_OF_MEMORY;
    }
  output->width = params->output_width;
  output->height = params->output_height;
  return TS_OK;
}

void
ts_op_progress_init (TsOpProgress *progress, GeglOperation *operation)
{
  progress->operation = operation;
  g_mutex_init (&progress->lock);
  progress->last_fraction = -1.0;
  progress->last_stage = NULL;
}

void
ts_op_progress_clear (TsOpProgress *progress)
{
  g_mutex_clear (&progress->lock);
}

bool
ts_op_progress_func (double fraction, const char *stage, void *user_data)
{
  TsOpProgress *progress = user_data;

  g_mutex_lock (&progress->lock);
  /* Signal handlers (GIMP's progress bar) are slow: emit only on a new
   * stage, every half percent, and at the end; never go backwards. */
  if (fraction >= 1.0 || stage != progress->last_stage ||
      fraction >= progress->last_fraction + 0.005)
    {
      if (fraction < progress->last_fraction)
        fraction = progress->last_fraction;
      progress->last_fraction = fraction;
      progress->last_stage = stage;
      gegl_operation_progress (progress->operation, CLAMP (fraction, 0.0, 1.0),
                               (gchar *) (stage ? stage : ""));
    }
  g_mutex_unlock (&progress->lock);
  return true; /* GEGL 0.4 has no way to cancel an op from outside */
}

const Babl *
ts_op_source_space (GeglOperation *operation, const gchar *pad)
{
  const Babl *source = gegl_operation_get_source_format (operation, pad);
  const Babl *space = source ? babl_format_get_space (source) : NULL;

  /* Results are in colour: a grey or CMYK source's are sRGB. */
  if (space && (babl_space_is_gray (space) || babl_space_is_cmyk (space)))
    return NULL;
  return space;
}

const Babl *
ts_op_result_format (GeglOperation *operation)
{
  const Babl *source = gegl_operation_get_source_format (operation, "input");
  const Babl *space = ts_op_source_space (operation, "input");
  const char *model = source ? babl_get_name (babl_format_get_model (source)) : "";
  static const char *const linear_models[] = { "RGB", "RGBA", "RaGaBaA", "Y", "YA", "YaA" };
  const char *components = strchr (model, '~') ? "R~G~B~A" : "R'G'B'A";
  const char *type = source ? babl_get_name (babl_format_get_type (source, 0)) : "";

  for (size_t i = 0; i < G_N_ELEMENTS (linear_models); i++)
    if (strcmp (model, linear_models[i]) == 0)
      components = "RGBA";
  /* The source's own integer depth, else float: the result's pixels are
   * the source's, so its depth holds them exactly, and GEGL has no
   * float copy of a large result to convert on one thread. */
  if (strcmp (type, "u8") != 0 && strcmp (type, "u16") != 0)
    type = "float";
  gchar *encoding = g_strdup_printf ("%s %s", components, type);
  const Babl *format = babl_format_with_space (encoding, space);
  g_free (encoding);
  return format;
}

void
ts_op_write_output (GeglBuffer          *output,
                    const GeglRectangle *roi,
                    const TsImage       *image,
                    gint                 x,
                    gint                 y)
{
  GeglRectangle whole = { x, y, (gint) image->width, (gint) image->height };
  GeglRectangle part;
  gsize stride = image->width * TS_CHANNELS * sizeof (float);

  if (!gegl_rectangle_intersect (&part, &whole, roi))
    return;
  ts_op_write_lab (output, &part,
                   (const float *) ((const guchar *) image->pixels + (gsize) (part.y - y) * stride
                                    + (gsize) (part.x - x) * TS_CHANNELS * sizeof (float)),
                   stride);
}

void
ts_op_prepare (GeglOperation *operation)
{
  gegl_operation_set_format (operation, "input", babl_format (TS_OP_FORMAT));
  gegl_operation_set_format (operation, "output", ts_op_result_format (operation));
}

GeglRectangle
ts_op_get_required_for_output (GeglOperation       *operation,
                               const gchar         *input_pad G_GNUC_UNUSED,
                               const GeglRectangle *roi G_GNUC_UNUSED)
{
  return ts_op_required_input (operation);
}

GeglRectangle
ts_op_get_cached_region (GeglOperation       *operation,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  return GEGL_OPERATION_GET_CLASS (operation)->get_bounding_box (operation);
}

GeglRectangle
ts_op_get_invalidated_by_change (GeglOperation       *operation,
                                 const gchar         *input_pad G_GNUC_UNUSED,
                                 const GeglRectangle *input_region G_GNUC_UNUSED)
{
  return GEGL_OPERATION_GET_CLASS (operation)->get_bounding_box (operation);
}

void
ts_op_class_init_whole_image (GeglOperationClass *operation_class,
                              GeglRectangle (*get_bounding_box) (GeglOperation *),
                              gboolean (*process) (GeglOperation *, GeglBuffer *, GeglBuffer *,
                                                   const GeglRectangle *, gint))
{
  ts_op_class_init_whole_image_methods (operation_class, get_bounding_box);
  GEGL_OPERATION_FILTER_CLASS (operation_class)->process = process;
}

void
ts_op_class_init_whole_image_methods (GeglOperationClass *operation_class,
                                      GeglRectangle (*get_bounding_box) (GeglOperation *))
{
  operation_class->prepare                   = ts_op_prepare;
  operation_class->get_bounding_box          = get_bounding_box;
  operation_class->get_required_for_output   = ts_op_get_required_for_output;
  operation_class->get_cached_region         = ts_op_get_cached_region;
  operation_class->get_invalidated_by_change = ts_op_get_invalidated_by_change;
  /* The engine has its own threads; GEGL must not split the work. */
  operation_class->threaded                  = FALSE;
  operation_class->want_in_place             = FALSE;
  operation_class->cache_policy              = GEGL_CACHE_POLICY_ALWAYS;
}

static int
odd_size (int size)
{
  if (size <= 0)
    return 0;
  if (size < TS_MIN_PATCH_SIZE)
    return TS_MIN_PATCH_SIZE;
  return size | 1;
}

void
ts_op_patch_sizes (int patch_size, int fine_patch_size, int *patch_out, int *fine_out)
{
  *patch_out = odd_size (patch_size);
  *fine_out = odd_size (fine_patch_size);
  /* Only a combination the user chose explicitly can conflict. */
  if (*patch_out && *fine_out > *patch_out)
    *fine_out = *patch_out;
}

size_t
ts_op_memory_limit (int mebibytes)
{
  return mebibytes > 0 ? (size_t) mebibytes << 20 : 0;
}

void
ts_op_fail (GeglOperation       *operation,
            GeglBuffer          *output,
            const GeglRectangle *roi,
            const gchar         *message)
{
  const gchar *name = gegl_operation_get_name (operation);

  g_warning ("%s: %s", name ? name : "texsynth", message);
  /* The output may be a cache that still holds an earlier result. */
  gegl_buffer_clear (output, roi);
}

gboolean
ts_op_set_error (TsError *error, TsStatus status, const gchar *format, ...)
{
  va_list args;

  error->status = status;
  va_start (args, format);
  vsnprintf (error->message, sizeof error->message, format, args);
  va_end (args);
  return FALSE;
}
