/* texsynth:tileable: make an image tile seamlessly by re-synthesising the
 * parts near its edges, keeping the rest of the picture as it is.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A whole-image filter: the output has the input's extent; it reads all of
 * the input, runs the engine once (ts_make_tileable) and caches the result.
 */
#include <glib/gi18n-lib.h>

#include "op-common.h"
#include "op-source-map.h"

#ifdef GEGL_PROPERTIES

enum_start (texsynth_tileable_direction)
  enum_value (TEXSYNTH_TILEABLE_BOTH,       "both",       N_("Both"))
  enum_value (TEXSYNTH_TILEABLE_HORIZONTAL, "horizontal", N_("Horizontally"))
  enum_value (TEXSYNTH_TILEABLE_VERTICAL,   "vertical",   N_("Vertically"))
enum_end (TexsynthTileableDirection)

property_enum (direction, _("Direction"),
               TexsynthTileableDirection, texsynth_tileable_direction,
               TEXSYNTH_TILEABLE_BOTH)
  description (_("Which edges must continue each other: both pairs, left "
                 "and right only (tiles horizontally) or top and bottom "
                 "only (tiles vertically)"))

property_double (seam_width, _("Seam width"), 0.125)
  description (_("How much of the image may change: the width of the band "
                 "along each edge that is re-synthesised, as a fraction of "
                 "the image's width or height. Wider bands hide a seam "
                 "better in large-scale textures; everything beyond the "
                 "band and its blend stays as it is"))
  value_range (TS_TILEABLE_MIN_SEAM_WIDTH, TS_TILEABLE_MAX_SEAM_WIDTH)

#include "synthesis-properties.h"

#else

#define GEGL_OP_FILTER
#define GEGL_OP_NAME     texsynth_tileable
#define GEGL_OP_C_SOURCE texsynth-tileable.c

/* gegl-op.h's generated boilerplate trips -Wextra; our own code must not. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define GEGL_OP_BUNDLE /* TS_OP_MODULE: the module entry points bind the text domain */
#include "gegl-op.h"
#pragma GCC diagnostic pop

TS_OP_MODULE (texsynth_tileable)

static void
prepare (GeglOperation *operation)
{
  ts_op_prepare_source_map (operation, GEGL_PROPERTIES (operation)->source_map);
}

static void
fill_params (GeglProperties *o, TsTileableParams *params)
{
  ts_tileable_params_init (params);
  switch (o->direction)
    {
    case TEXSYNTH_TILEABLE_HORIZONTAL: params->direction = TS_TILEABLE_HORIZONTAL; break;
    case TEXSYNTH_TILEABLE_VERTICAL:   params->direction = TS_TILEABLE_VERTICAL; break;
    default:                           params->direction = TS_TILEABLE_BOTH; break;
    }
  params->seam_width = o->seam_width;
  params->quality = o->quality;
  params->seed = o->seed;
  ts_op_patch_sizes (o->patch_size, o->fine_patch_size,
                     &params->patch_size, &params->fine_patch_size);
  params->max_iterations = o->iterations;
  params->histogram_matching = o->histogram_matching;
  params->memory_limit = ts_op_memory_limit (o->memory_limit);
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *input,
         GeglBuffer          *output,
         const GeglRectangle *roi,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  GeglRectangle box = ts_op_input_bounding_box (operation);
  TsTileableParams params;
  TsImage image, result = { 0, 0, NULL };
  int32_t *sources = NULL;
  TsError error = { TS_OK, "" };
  TsOpProgress progress;
  TsStatus status;

  fill_params (o, &params);
  if (!ts_op_read_input (operation, input, &image, error.message, sizeof error.message))
    {
      ts_op_fail (operation, output, roi, error.message);
      return TRUE;
    }

  status = ts_tileable_params_validate (&params, &image, &error);
  if (status == TS_OK)
    {
      result.pixels = g_try_malloc (image.width * image.height * TS_CHANNELS * sizeof (float));
      result.width = image.width;
      result.height = image.height;
      if (o->source_map)
        params.source_map = sources = g_try_malloc (image.width * image.height * 2 * sizeof (int32_t));
      if (!result.pixels || (o->source_map && !sources))
        {
          status = TS_ERROR_OUT_OF_MEMORY;
          g_snprintf (error.message, sizeof error.message,
                      _("out of memory allocating the %zux%zu output"), image.width, image.height);
        }
    }
  if (status == TS_OK)
    {
      ts_op_progress_init (&progress, operation);
      ts_op_progress_func (0.0, "starting", &progress);
      status = ts_make_tileable (&params, &image, &result,
                                 ts_op_progress_func, &progress, &error);
      ts_op_progress_func (1.0, "done", &progress);
      ts_op_progress_clear (&progress);
    }

  if (o->source_map && (status == TS_OK || image.pixels))
    {
      /* On failure the identity: the picture left as it was. */
      if (status != TS_OK)
        g_warning (_("%s: %s; the image is left unchanged"), gegl_operation_get_name (operation),
                   error.message[0] ? error.message : ts_status_string (status));
      if (!ts_op_write_source_map (output, roi, status == TS_OK ? sources : NULL,
                                   image.width, image.height, box.x, box.y, box.x, box.y))
        g_warning ("%s: %s", gegl_operation_get_name (operation), _("out of memory"));
    }
  else if (status == TS_OK)
    ts_op_write_output (output, roi, &result, box.x, box.y);
  else if (image.pixels)
    {
      /* A filter that fails leaves the picture as it was (and says so),
       * rather than erasing it. */
      /* TRANSLATORS: the operation's name, then what went wrong. */
      g_warning (_("%s: %s; the image is left unchanged"), gegl_operation_get_name (operation),
                 error.message[0] ? error.message : ts_status_string (status));
      gegl_buffer_clear (output, roi);
      ts_op_write_output (output, roi, &image, box.x, box.y);
    }
  else
    ts_op_fail (operation, output, roi, error.message[0] ? error.message
                                        : _("the input is empty: there is nothing to make tileable"));

  g_free (sources);
  g_free (result.pixels);
  g_free (image.pixels);
  return TRUE;
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass       *operation_class = GEGL_OPERATION_CLASS (klass);

  /* The output covers exactly the input. */
  ts_op_class_init_whole_image (operation_class, ts_op_input_bounding_box, process);
  operation_class->prepare = prepare;

  gegl_operation_class_set_keys (operation_class,
    "name",               "texsynth:tileable",
    "title",              _("Make Seamless by Synthesis"),
    "categories",         "map:tile",
    "position-dependent", "true",
    "description",        _("Makes an image tile seamlessly, horizontally, "
                            "vertically or both, by re-synthesising only the "
                            "parts near its edges from the image itself: "
                            "structure continues across the edges, without "
                            "cross-fading, and the rest of the picture stays "
                            "as it is"),
    "gimp:menu-path",     "<Image>/Filters/Map",
    "gimp:menu-label",    _("Make Seamless by Synthesis\xe2\x80\xa6"),
    NULL);
}

#endif
