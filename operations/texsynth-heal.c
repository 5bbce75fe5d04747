/* texsynth:heal: fill a hole (a selection, the transparent pixels, a new
 * border) with texture continued from the rest of the image.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * A whole-image composer: input is the image, aux an optional mask (fill
 * where its grey value times its alpha is at least 50 %; without it the
 * pixels that are not fully opaque), aux2 an optional image to copy from.
 * Pixels outside the hole are copied in the input's own format, bit for
 * bit; only the hole's pixels go through CIE Lab.
 */
#include <glib/gi18n-lib.h>

#include "op-common.h"

#ifdef GEGL_PROPERTIES

enum_start (texsynth_heal_sample_from)
  enum_value (TEXSYNTH_HEAL_ALL_AROUND,  "all-around",  N_("All around"))
  enum_value (TEXSYNTH_HEAL_SIDES,       "sides",       N_("Sides"))
  enum_value (TEXSYNTH_HEAL_ABOVE_BELOW, "above-below", N_("Above and below"))
enum_end (TexsynthHealSampleFrom)

property_int (context, _("Context width"), 0)
  description (_("How far around the hole, in pixels, the texture may be "
                 "copied from; 0 uses the whole image. A small context is "
                 "faster and keeps the fill like its surroundings"))
  value_range (0, TS_HEAL_MAX_CONTEXT)
  ui_range    (0, 500)

property_enum (sample_from, _("Sample from"),
               TexsynthHealSampleFrom, texsynth_heal_sample_from,
               TEXSYNTH_HEAL_ALL_AROUND)
  description (_("Where the texture may come from: all around the hole, "
                 "only beside it (left and right of its bounds) or only "
                 "above and below it"))

property_int (quality, _("Quality"), ts_op_default_params ().quality)
  description (_("Search effort per patch and iterations per level: "
                 "higher searches more and is slower"))
  value_range (TS_MIN_QUALITY, TS_MAX_QUALITY)

property_seed (seed, _("Random seed"), rand)
  description (_("The same seed with the same settings gives the same "
                 "result, whatever the number of threads; change it for "
                 "another variation"))

property_int (patch_size, _("Patch size"), 0)
  description (_("Size in pixels of the neighbourhoods compared on the "
                 "coarser levels; 0 chooses automatically; even values "
                 "are rounded up to odd"))
  value_range (0, TS_MAX_PATCH_SIZE)
  ui_meta     ("role", "advanced")

property_int (fine_patch_size, _("Fine patch size"), 0)
  description (_("Size in pixels of the neighbourhoods compared on the "
                 "finest level; 0 chooses automatically"))
  value_range (0, TS_MAX_PATCH_SIZE)
  ui_meta     ("role", "advanced")

property_int (memory_limit, _("Memory limit (MiB)"), 0)
  description (_("Refuse, with a message saying how much it would need, a "
                 "synthesis that needs more memory than this; 0 means a "
                 "quarter of the RAM (at least 1 GiB)"))
  value_range (0, G_MAXINT)
  ui_range    (0, 65536)
  ui_meta     ("role", "advanced")

#else

#define GEGL_OP_COMPOSER3
#define GEGL_OP_NAME     texsynth_heal
#define GEGL_OP_C_SOURCE texsynth-heal.c

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define GEGL_OP_BUNDLE /* TS_OP_MODULE: the module entry points bind the text domain */
#include "gegl-op.h"
#pragma GCC diagnostic pop

#include "heal-io.h"

TS_OP_MODULE (texsynth_heal)

static void
prepare (GeglOperation *operation)
{
  const Babl *format = gegl_operation_get_source_format (operation, "input");

  /* The output keeps the input's format, so kept pixels stay bit-exact. */
  if (!format)
    format = babl_format ("RGBA float");
  gegl_operation_set_format (operation, "input", format);
  gegl_operation_set_format (operation, "output", format);
  gegl_operation_set_format (operation, "aux", babl_format ("Y'A float"));
  gegl_operation_set_format (operation, "aux2", babl_format (TS_OP_FORMAT));
}

static GeglRectangle
get_required_for_output (GeglOperation *operation, const gchar *input_pad,
                         const GeglRectangle *roi G_GNUC_UNUSED)
{
  const GeglRectangle *box = gegl_operation_source_get_bounding_box (operation, input_pad);
  GeglRectangle empty = { 0, 0, 0, 0 };

  if (!box || gegl_rectangle_is_infinite_plane (box))
    {
      /* An unbounded mask (a colour fill) is read over the image only. */
      if (box && g_strcmp0 (input_pad, "aux") == 0)
        return ts_op_input_bounding_box (operation);
      return empty;
    }
  if (g_strcmp0 (input_pad, "aux") == 0)
    return ts_op_input_bounding_box (operation);
  return *box;
}

static void
fill_params (GeglProperties *o, TsHealParams *params)
{
  ts_heal_params_init (params);
  params->context = (size_t) o->context;
  switch (o->sample_from)
    {
    case TEXSYNTH_HEAL_SIDES:       params->sample_from = TS_HEAL_SIDES; break;
    case TEXSYNTH_HEAL_ABOVE_BELOW: params->sample_from = TS_HEAL_ABOVE_BELOW; break;
    default:                        params->sample_from = TS_HEAL_ALL_AROUND; break;
    }
  params->quality = o->quality;
  params->seed = o->seed;
  ts_op_patch_sizes (o->patch_size, o->fine_patch_size,
                     &params->patch_size, &params->fine_patch_size);
  params->memory_limit = ts_op_memory_limit (o->memory_limit);
}

static gboolean
process (GeglOperation       *operation,
         GeglBuffer          *input,
         GeglBuffer          *aux,
         GeglBuffer          *aux2,
         GeglBuffer          *output,
         const GeglRectangle *result G_GNUC_UNUSED,
         gint                 level G_GNUC_UNUSED)
{
  GeglProperties *o = GEGL_PROPERTIES (operation);
  GeglRectangle box = ts_op_input_bounding_box (operation);
  TsHealParams params;
  gchar message[TS_MESSAGE_SIZE] = "";

  if (box.width <= 0 || box.height <= 0 || !input)
    return TRUE;
  /* Start from the input itself: whatever happens, kept pixels (and on
   * failure all of them) are the input's, bit for bit. */
  gegl_buffer_copy (input, &box, GEGL_ABYSS_NONE, output, &box);
  fill_params (o, &params);
  if (!ts_heal_op_run (operation, &params, input, aux, aux2, output, &box,
                       message, sizeof message))
    /* TRANSLATORS: the operation's name, then what went wrong. */
    g_warning (_("%s: %s; the image is left unchanged"), gegl_operation_get_name (operation),
               message);
  return TRUE;
}

static void
gegl_op_class_init (GeglOpClass *klass)
{
  GeglOperationClass *operation_class = GEGL_OPERATION_CLASS (klass);

  ts_op_class_init_whole_image_methods (operation_class, ts_op_input_bounding_box);
  operation_class->prepare                 = prepare;
  operation_class->get_required_for_output = get_required_for_output;
  GEGL_OPERATION_COMPOSER3_CLASS (klass)->process = process;

  gegl_operation_class_set_keys (operation_class,
    "name",               "texsynth:heal",
    "title",              _("Heal by Synthesis"),
    "categories",         "enhance",
    "position-dependent", "true",
    "description",        _("Fills a hole with texture continued from the rest "
                            "of the image: where the mask (aux) is at least "
                            "half white, or without a mask the pixels that are "
                            "not fully opaque. The mask is read at the image's "
                            "coordinates: image pixels it does not cover are "
                            "kept. Everything outside the hole stays exactly as "
                            "it was. aux2 may give another image to copy from"),
    "gimp:menu-path",     "<Image>/Filters/Enhance",
    "gimp:menu-label",    _("Heal by Synthesis\xe2\x80\xa6"),
    NULL);
}

#endif
