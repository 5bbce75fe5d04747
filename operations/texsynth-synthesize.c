/* texsynth:synthesize: grow a texture of any size from an example image.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A whole-image operation: it reads the entire input (the exemplar), runs
 * the engine once and produces the entire output, whatever region GEGL
 * asks for; the output is cached so later requests are cheap.
 */
#include <glib/gi18n-lib.h>
#include <stdlib.h>
#include <string.h>

#include "op-common.h"
#include "op-features.h"
#include "op-source-map.h"

#ifdef GEGL_PROPERTIES

property_int (width, _("Width"), 512)
  description (_("Width of the synthesised texture"))
  value_range (1, TS_MAX_OUTPUT_SIDE)
  ui_range    (16, 4096)
  ui_meta     ("unit", "pixel-distance")
  ui_meta     ("axis", "x")

property_int (height, _("Height"), 512)
  description (_("Height of the synthesised texture"))
  value_range (1, TS_MAX_OUTPUT_SIDE)
  ui_range    (16, 4096)
  ui_meta     ("unit", "pixel-distance")
  ui_meta     ("axis", "y")

property_boolean (tileable, _("Tileable"), FALSE)
  description (_("Make the result tile seamlessly: its left edge continues "
                 "its right edge and its top edge its bottom edge"))

property_double (feature_weight, _("Feature weight"), 1.0)
  description (_("How much the feature map (aux: a height, normal or mask "
                 "aligned with the input) counts in the match beside the "
                 "colours; at 1 its full range weighs as the range of "
                 "lightness"))
  value_range (0.0, TS_MAX_FEATURE_WEIGHT)
  ui_range    (0.0, 4.0)

#include "synthesis-properties.h"

#else

#define GEGL_OP_COMPOSER
#define GEGL_OP_NAME     texsynth_synthesize
#define GEGL_OP_C_SOURCE texsynth-synthesize.c

/* gegl-op.h's generated boilerplate trips -Wextra; our own code must not. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define GEGL_OP_BUNDLE /* TS_OP_MODULE: the module entry points bind the text domain */
#include "gegl-op.h"
#pragma GCC diagnostic pop

TS_OP_MODULE (texsynth_synthesize)

/* The output has the requested size at the origin, whatever the input's
 * size and position. */
static GeglRectangle
get_bounding_box (GeglOperation *operation)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  GeglRectangle box = { 0, 0, o->width, o->height };

  return box;
}

static void
prepare (GeglOperation *operation)
{
  ts_op_prepare_source_map (operation, GEGL_PROPERTIES (operation)->source_map);
  gegl_operation_set_format (operation, "aux", babl_format ("R'G'B' float"));
}

static void
fill_params (GeglProperties *o, TsParams *params)
{
  ts_params_init (params);
  params->output_width = (size_t) o->width;
  params->output_height = (size_t) o->height;
  params->wrap_x = params->wrap_y = o->tileable;
  params->quality = o->quality;
  params->seed = o->seed;
  ts_op_patch_sizes (o->patch_size, o->fine_patch_size,
                     &params->patch_size, &params->fine_patch_size);
  params->max_iterations = o->iterations;
  params->histogram_matching = o->histogram_matching;
  params->memory_limit = ts_op_memory_limit (o->memory_limit);
}

/* All of the input, and all of the feature map. */
static GeglRectangle
get_required_for_output (GeglOperation       *operation,
                         const gchar         *input_pad,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, input_pad);
  GeglRectangle empty = { 0, 0, 0, 0 };

  if (!strcmp (input_pad, "input"))
    return ts_op_required_input (operation);
  return box && !gegl_rectangle_is_infinite_plane (box) ? *box : empty;
}

/* The exemplar the synthesis matches on: with a feature map, its pixels
 * in appearance space (ts_feature_matching_image), else the exemplar. */
static TsStatus
matching_image (GeglOperation *operation, GeglBuffer *aux, const TsImage *exemplar,
                TsImage *matching, TsError *error)
{
  TsFeatureMap features;
  TsStatus status;

  matching->width = matching->height = 0;
  matching->pixels = NULL;
  if (!aux)
    return TS_OK;
  if (!ts_op_read_features (operation, aux, &features, error->message, sizeof error->message))
    return error->status = TS_ERROR_BAD_PARAMETER;
  status = ts_feature_matching_image (exemplar, &features, GEGL_PROPERTIES (operation)->feature_weight,
                                      matching, error);
  g_free ((float *) features.values);
  return status;
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *input,
         GeglBuffer          *aux,
         GeglBuffer          *output,
         const GeglRectangle *roi,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  TsParams params;
  TsImage exemplar, matching = { 0, 0, NULL }, result = { 0, 0, NULL };
  int32_t *sources = NULL;
  GeglRectangle box = ts_op_required_input (operation);
  TsError error = { TS_OK, "" };
  TsOpProgress progress;
  TsStatus status;

  fill_params (o, &params);
  if (!ts_op_read_input (operation, input, &exemplar, error.message, sizeof error.message))
    {
      ts_op_fail (operation, output, roi, error.message);
      return TRUE;
    }

  status = ts_op_alloc_output (&params, &exemplar, &result, &error);
  if (status == TS_OK)
    status = matching_image (operation, aux, &exemplar, &matching, &error);
  if (status == TS_OK && (o->source_map || matching.pixels))
    {
      params.source_map = sources = g_try_malloc (result.width * result.height * 2 * sizeof (int32_t));
      if (!sources)
        {
          status = error.status = TS_ERROR_OUT_OF_MEMORY;
          g_snprintf (error.message, sizeof error.message,
                      _("out of memory allocating the %zux%zu source map"),
                      result.width, result.height);
        }
    }
  if (status == TS_OK)
    {
      ts_op_progress_init (&progress, operation);
      ts_op_progress_func (0.0, "starting", &progress);
      status = ts_synthesize (&params, matching.pixels ? &matching : &exemplar, &result,
                              ts_op_progress_func, &progress, &error);
      ts_op_progress_func (1.0, "done", &progress);
      ts_op_progress_clear (&progress);
    }
  /* Matched in appearance space: the colours are the exemplar's own. */
  if (status == TS_OK && matching.pixels)
    ts_copy_by_source_map (&exemplar, sources, &result);

  /* A failure still yields a defined (transparent) image, and TRUE, so
   * that a graph goes on rendering and the warning says what went wrong. */
  if (status == TS_OK && o->source_map)
    {
      if (!ts_op_write_source_map (output, roi, sources, result.width, result.height, 0, 0,
                                   box.x, box.y))
        g_warning ("%s: %s", gegl_operation_get_name (operation), _("out of memory"));
    }
  else if (status == TS_OK)
    ts_op_write_output (output, roi, &result, 0, 0);
  else
    ts_op_fail (operation, output, roi,
                error.message[0] ? error.message : ts_status_string (status));

  free (matching.pixels);
  g_free (sources);
  g_free (result.pixels);
  g_free (exemplar.pixels);
  return TRUE;
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass       *operation_class = GEGL_OPERATION_CLASS (klass);

  ts_op_class_init_whole_image_methods (operation_class, get_bounding_box);
  operation_class->prepare                 = prepare;
  operation_class->get_required_for_output = get_required_for_output;
  GEGL_OPERATION_COMPOSER_CLASS (klass)->process = process;

  gegl_operation_class_set_keys (operation_class,
    "name",               "texsynth:synthesize",
    "title",              _("Texture Synthesis"),
    "categories",         "render:tile",
    "position-dependent", "true",
    "description",        _("Synthesises a new texture of any size that looks "
                            "like the input image (the exemplar) but does not "
                            "repeat it, optionally tileable"),
    "gimp:menu-path",     "<Image>/Filters/Render/Pattern",
    "gimp:menu-label",    _("Texture Synthesis..."),
    NULL);
}

#endif
