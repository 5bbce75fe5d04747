/* texsynth:guided: texture by numbers and style transfer.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * The input is the target guide (a label map, a sketch, a height map, or
 * the photo to restyle), aux the exemplar and aux2 the exemplar's own
 * guide, aligned with it. The output has the input's size and place, is
 * made of the exemplar's pixels and follows the input's layout. Without
 * aux2 both guides are lightness (style transfer). A whole-image
 * operation, like texsynth:synthesize.
 */
#include <glib/gi18n-lib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "op-common.h"
#include "op-guides.h"
#include "op-source-map.h"

#ifdef GEGL_PROPERTIES

enum_start (texsynth_guide_compare)
  enum_value (TEXSYNTH_GUIDE_COMPARE_AUTO, "auto", N_("Automatic"))
  enum_value (TEXSYNTH_GUIDE_COMPARE_LABELS, "labels", N_("Labels"))
  enum_value (TEXSYNTH_GUIDE_COMPARE_VALUES, "values", N_("Values"))
enum_end (TexsynthGuideCompare)

property_double (guide_weight, _("Guide weight"), TS_DEFAULT_GUIDE_WEIGHT)
  description (_("How much following the guides counts against a coherent "
                 "texture: at 1 a pixel whose guide disagrees costs as much "
                 "as two unrelated pixels of the texture. Labels without "
                 "blended edges are followed exactly at any weight above 0"))
  value_range (0.0, TS_MAX_GUIDE_WEIGHT)
  ui_range    (0.0, 10.0)

property_enum (compare, _("Compare guides as"), TexsynthGuideCompare, texsynth_guide_compare,
               TEXSYNTH_GUIDE_COMPARE_AUTO)
  description (_("Labels: guide colours are equal or not (flat-colour or "
                 "indexed maps). Values: they are compared by difference "
                 "(heights, sketches). Automatic takes labels when the "
                 "exemplar's guide has few colours and most of the input "
                 "uses them"))

property_boolean (blend_edges, _("Blend label edges"), FALSE)
  description (_("Labels only. Off: each label's area is grown from its own "
                 "texture alone and cut at the label's edges, so areas of "
                 "any width keep their texture. On: one synthesis over the "
                 "whole image, whose textures blend across label edges as "
                 "they do in the exemplar, but areas narrower than about 30 "
                 "pixels lose some of their texture"))

property_boolean (tileable, _("Tileable"), FALSE)
  description (_("Make the result tile seamlessly: its left edge continues "
                 "its right edge and its top edge its bottom edge"))

#include "synthesis-properties.h"

#else

#define GEGL_OP_COMPOSER3
#define GEGL_OP_NAME     texsynth_guided
#define GEGL_OP_C_SOURCE texsynth-guided.c

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define GEGL_OP_BUNDLE /* TS_OP_MODULE: the module entry points bind the text domain */
#include "gegl-op.h"
#pragma GCC diagnostic pop

TS_OP_MODULE (texsynth_guided)

/* The output takes the input's (the target guide's) place and size. */
static GeglRectangle
get_bounding_box (GeglOperation *operation)
{
  return ts_op_required_input (operation);
}

static void
prepare (GeglOperation *operation)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  const Babl *aux = gegl_operation_get_source_format (operation, "aux");

  /* Every pad is read in its own format, converted here as need be. */
  for (int i = 0; i < 3; i++)
    {
      const gchar *pad = (const gchar *[]) { "input", "aux", "aux2" }[i];
      const Babl *format = gegl_operation_get_source_format (operation, pad);
      gegl_operation_set_format (operation, pad, format ? format : babl_format (TS_OP_FORMAT));
    }
  /* Colours come from the exemplar: its space. */
  gegl_operation_set_format (operation, "output",
                             o->source_map ? ts_op_source_map_format ()
                             : babl_format_with_space ("R'G'B'A float",
                                                       aux ? ts_op_source_space (operation, "aux")
                                                           : NULL));
}

static GeglRectangle
get_required_for_output (GeglOperation *operation, const gchar *input_pad,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, input_pad);
  GeglRectangle empty = { 0, 0, 0, 0 };

  if (!strcmp (input_pad, "input"))
    return ts_op_required_input (operation);
  if (!box || gegl_rectangle_is_infinite_plane (box) || box->width > TS_MAX_OUTPUT_SIDE ||
      box->height > TS_MAX_OUTPUT_SIDE)
    return empty;
  return *box;
}

typedef struct
{
  TsImage        exemplar;
  GeglRectangle  target_box, exemplar_box;
  float         *target_guide, *exemplar_guide;
  TsGuides       guides;
} Inputs;

static void
inputs_free (Inputs *in)
{
  g_free (in->exemplar.pixels);
  g_free (in->target_guide);
  g_free (in->exemplar_guide);
}

/* The guides: the two maps, as one channel if both are grey, else three;
 * without aux2 the lightness of the input (L / 100). */
static gboolean
read_guides (GeglOperation *operation, GeglBuffer *input, GeglBuffer *aux2, Inputs *in,
             gchar *message, gsize size)
{
  gsize target_n = (gsize) in->target_box.width * (gsize) in->target_box.height;
  GeglRectangle guide_box;
  gboolean grey_target, grey_exemplar;

  if (!aux2 || !gegl_operation_source_get_bounding_box (operation, "aux2"))
    {
      float *lab = g_try_malloc (target_n * TS_CHANNELS * sizeof (float));
      in->target_guide = g_try_malloc (target_n * sizeof (float));
      if (!lab || !in->target_guide)
        {
          g_free (lab);
          snprintf (message, size, _("out of memory reading a %dx%d guide"),
                    in->target_box.width, in->target_box.height);
          return FALSE;
        }
      ts_op_read_lab (input, &in->target_box, lab);
      for (gsize i = 0; i < target_n; i++)
        in->target_guide[i] = lab[i * TS_CHANNELS] / 100.0f;
      g_free (lab);
      in->guides.channels = 1;
      return TRUE;
    }
  if (!ts_op_pad_box (operation, "aux2", _("the exemplar's guide (aux2)"), &guide_box, message,
                      size))
    return FALSE;
  if (guide_box.width != in->exemplar_box.width || guide_box.height != in->exemplar_box.height)
    {
      snprintf (message, size,
                _("the exemplar's guide (aux2) is %dx%d but the exemplar (aux) is %dx%d; "
                  "the guide must be aligned with the exemplar, of the same size"),
                guide_box.width, guide_box.height, in->exemplar_box.width,
                in->exemplar_box.height);
      return FALSE;
    }
  if (!ts_op_read_guide (input, &in->target_box, &in->target_guide, &grey_target, message, size) ||
      !ts_op_read_guide (aux2, &guide_box, &in->exemplar_guide, &grey_exemplar, message, size))
    return FALSE;
  if (grey_target && grey_exemplar)
    {
      ts_op_guide_to_grey (in->target_guide, target_n);
      ts_op_guide_to_grey (in->exemplar_guide,
                           (gsize) guide_box.width * (gsize) guide_box.height);
    }
  in->guides.channels = grey_target && grey_exemplar ? 1 : 3;
  return TRUE;
}

static gboolean
read_inputs (GeglOperation *operation, GeglBuffer *input, GeglBuffer *aux, GeglBuffer *aux2,
             Inputs *in, gchar *message, gsize size)
{
  gsize ex_n;

  if (!ts_op_pad_box (operation, "input", _("the target guide (input)"), &in->target_box,
                      message, size) || !input)
    {
      if (!input)
        snprintf (message, size, _("%s is missing or empty"), _("the target guide (input)"));
      return FALSE;
    }
  if (in->target_box.width < TS_MIN_PATCH_SIZE || in->target_box.height < TS_MIN_PATCH_SIZE)
    {
      snprintf (message, size,
                _("the target guide (input) is %dx%d pixels; it needs at least %dx%d"),
                in->target_box.width, in->target_box.height, TS_MIN_PATCH_SIZE, TS_MIN_PATCH_SIZE);
      return FALSE;
    }
  if (!ts_op_pad_box (operation, "aux", _("the exemplar (aux)"), &in->exemplar_box, message,
                      size) || !aux)
    {
      if (!aux)
        snprintf (message, size, _("%s is missing or empty"), _("the exemplar (aux)"));
      return FALSE;
    }
  ex_n = (gsize) in->exemplar_box.width * (gsize) in->exemplar_box.height;
  in->exemplar.pixels = g_try_malloc (ex_n * TS_CHANNELS * sizeof (float));
  if (!in->exemplar.pixels)
    {
      snprintf (message, size, _("out of memory reading the %dx%d exemplar (%.1f MiB)"),
                in->exemplar_box.width, in->exemplar_box.height,
                (double) (ex_n * TS_CHANNELS * sizeof (float)) / 1048576.0);
      return FALSE;
    }
  ts_op_read_lab (aux, &in->exemplar_box, in->exemplar.pixels);
  in->exemplar.width = (size_t) in->exemplar_box.width;
  in->exemplar.height = (size_t) in->exemplar_box.height;
  if (!read_guides (operation, input, aux2, in, message, size))
    return FALSE;
  in->guides.target_guide = in->target_guide;
  in->guides.exemplar_guide = in->exemplar_guide;
  return TRUE;
}

static void
fill_params (GeglProperties *o, const Inputs *in, TsParams *params)
{
  ts_params_init (params);
  params->output_width = (size_t) in->target_box.width;
  params->output_height = (size_t) in->target_box.height;
  params->wrap_x = params->wrap_y = o->tileable;
  params->quality = o->quality;
  params->seed = o->seed;
  ts_op_patch_sizes (o->patch_size, o->fine_patch_size, &params->patch_size,
                     &params->fine_patch_size);
  params->max_iterations = o->iterations;
  params->histogram_matching = o->histogram_matching;
  params->memory_limit = ts_op_memory_limit (o->memory_limit);
  params->guides = &in->guides;
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *input,
         GeglBuffer          *aux,
         GeglBuffer          *aux2,
         GeglBuffer          *output,
         const GeglRectangle *roi,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  Inputs in;
  TsParams params;
  TsImage result = { 0, 0, NULL };
  int32_t *sources = NULL;
  TsError error = { TS_OK, "" };
  TsOpProgress progress;
  TsStatus status = TS_OK;

  memset (&in, 0, sizeof in);
  ts_guides_init (&in.guides);
  in.guides.weight = o->guide_weight;
  in.guides.blend_edges = o->blend_edges;
  in.guides.compare = o->compare == TEXSYNTH_GUIDE_COMPARE_LABELS ? TS_GUIDE_LABELS
                      : o->compare == TEXSYNTH_GUIDE_COMPARE_VALUES ? TS_GUIDE_VALUES
                                                                    : TS_GUIDE_AUTO;
  if (!read_inputs (operation, input, aux, aux2, &in, error.message, sizeof error.message))
    status = TS_ERROR_INVALID_ARGUMENT;
  if (status == TS_OK)
    {
      fill_params (o, &in, &params);
      status = ts_op_alloc_output (&params, &in.exemplar, &result, &error);
    }
  if (status == TS_OK && o->source_map)
    {
      params.source_map = sources = g_try_malloc (result.width * result.height * 2 * sizeof (int32_t));
      if (!sources)
        {
          status = TS_ERROR_OUT_OF_MEMORY;
          g_snprintf (error.message, sizeof error.message,
                      _("out of memory allocating the %zux%zu source map"),
                      result.width, result.height);
        }
    }
  if (status == TS_OK)
    {
      ts_op_progress_init (&progress, operation);
      ts_op_progress_func (0.0, "starting", &progress);
      status = ts_synthesize (&params, &in.exemplar, &result, ts_op_progress_func, &progress,
                              &error);
      ts_op_progress_func (1.0, "done", &progress);
      ts_op_progress_clear (&progress);
    }

  /* A failure still yields a defined (transparent) image, and TRUE, so
   * that a graph goes on rendering and the warning says what went wrong. */
  if (status == TS_OK && o->source_map)
    {
      if (!ts_op_write_source_map (output, roi, sources, result.width, result.height,
                                   in.target_box.x, in.target_box.y, in.exemplar_box.x,
                                   in.exemplar_box.y))
        g_warning ("%s: %s", gegl_operation_get_name (operation), _("out of memory"));
    }
  else if (status == TS_OK)
    ts_op_write_output (output, roi, &result, in.target_box.x, in.target_box.y);
  else
    ts_op_fail (operation, output, roi,
                error.message[0] ? error.message : ts_status_string (status));

  g_free (sources);
  g_free (result.pixels);
  inputs_free (&in);
  return TRUE;
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass *operation_class = GEGL_OPERATION_CLASS (klass);

  ts_op_class_init_whole_image_methods (operation_class, get_bounding_box);
  operation_class->prepare                 = prepare;
  operation_class->get_required_for_output = get_required_for_output;
  GEGL_OPERATION_COMPOSER3_CLASS (klass)->process = process;

  gegl_operation_class_set_keys (operation_class,
    "name",               "texsynth:guided",
    "title",              _("Guided Texture Synthesis"),
    "categories",         "render:tile",
    "position-dependent", "true",
    "description",        _("Texture by numbers and style transfer: paints the "
                            "layout of the input (a label map, a sketch, or a "
                            "photo) with the texture of the exemplar (aux), "
                            "following the exemplar's own guide (aux2); "
                            "without aux2, the lightness of both"),
    NULL);
}

#endif
