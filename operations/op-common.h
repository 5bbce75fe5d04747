/* Helpers shared by the texsynth GEGL operations: buffer conversion,
 * progress forwarding and the failure path. Compiled into each module.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#ifndef TEXSYNTH_OP_COMMON_H
#define TEXSYNTH_OP_COMMON_H

#include <gegl-plugin.h>

#include "texsynth.h"
#include "op-lab.h" /* TS_OP_FORMAT */

/* Binds the "texsynth" text domain to LOCALEDIR, or to $TEXSYNTH_LOCALEDIR
 * if set (tests use the catalogues of the build tree), in UTF-8. Must run
 * before the op class is initialised: its title and property labels are
 * translated then. */
void ts_op_bind_textdomain (void);

/* The module entry points gegl-op.h writes when GEGL_OP_BUNDLE is not
 * defined, with the text domain bound first. Each op defines GEGL_OP_BUNDLE
 * before including gegl-op.h, then writes TS_OP_MODULE (<its GEGL_OP_NAME>). */
#define TS_OP_MODULE(op_name)                                           \
  G_MODULE_EXPORT const GeglModuleInfo *                                \
  gegl_module_query (GTypeModule *module G_GNUC_UNUSED)                 \
  {                                                                     \
    return &modinfo;                                                    \
  }                                                                     \
  G_MODULE_EXPORT gboolean                                              \
  gegl_module_register (GTypeModule *module)                            \
  {                                                                     \
    ts_op_bind_textdomain ();                                           \
    gegl_op_##op_name##_register_type (module);                         \
    return TRUE;                                                        \
  }

/* The engine's defaults, so the properties default to the same values
 * (evaluated when the op class registers its properties). */
TsParams ts_op_default_params (void);

/* The region of "input" to render for any output: all of it, or nothing
 * if it is larger than the engine accepts (e.g. an infinite plane such as
 * gegl:color), which GEGL would otherwise try to render in full. */
GeglRectangle ts_op_required_input (GeglOperation *operation);

/* The bounding box of "input", or an empty one if it has none: the output
 * of an op that changes its input in place. */
GeglRectangle ts_op_input_bounding_box (GeglOperation *operation);

/* Read the whole "input" of `operation` from `input` into a newly
 * allocated image (g_free its pixels). An empty or missing input gives a
 * 0x0 image with NULL pixels, which the engine reports as empty; returns
 * FALSE only if the copy cannot be allocated (then `message` says why). */
gboolean ts_op_read_input (GeglOperation *operation,
                           GeglBuffer    *input,
                           TsImage       *image,
                           gchar         *message,
                           gsize          message_size);

/* Allocate an output image of the size in `params`, after checking with
 * the engine that the synthesis fits its memory limit. On failure fills
 * `error` and returns its status. */
TsStatus ts_op_alloc_output (const TsParams *params,
                             const TsImage  *exemplar,
                             TsImage        *output,
                             TsError        *error);

/* Forwards engine progress to gegl_operation_progress(). The engine may
 * call it from worker threads, so calls are serialised and thinned out. */
typedef struct
{
  GeglOperation *operation;
  GMutex         lock;
  gdouble        last_fraction;
  const gchar   *last_stage;
} TsOpProgress;

void ts_op_progress_init  (TsOpProgress *progress, GeglOperation *operation);
void ts_op_progress_clear (TsOpProgress *progress);
bool ts_op_progress_func  (double fraction, const char *stage, void *user_data);

/* The colour space of what is connected to `pad`: NULL (sRGB) if nothing
 * is, or if its space is grey or CMYK (results are in colour). */
const Babl *ts_op_source_space (GeglOperation *operation, const gchar *pad);

/* The format of a colour result: float RGBA in the "input" pad's
 * ts_op_source_space, with the source's curve: none for a linear source,
 * else the space's (or the sRGB curve for a "~" source). GEGL's own ops
 * keep the source's space too. */
const Babl *ts_op_result_format (GeglOperation *operation);

/* Copy the part of `image` (Lab), placed with its top-left pixel at
 * (x, y), that lies in `roi` into `output`, in the output's format. */
void ts_op_write_output (GeglBuffer          *output,
                         const GeglRectangle *roi,
                         const TsImage       *image,
                         gint                 x,
                         gint                 y);

/* Class methods the whole-image ops share: input in the engine's format,
 * output in ts_op_result_format; all of the input for any output; the whole output
 * cached and invalidated at once, since synthesis is global. */
void          ts_op_prepare (GeglOperation *operation);
GeglRectangle ts_op_get_required_for_output (GeglOperation *operation, const gchar *input_pad,
                                             const GeglRectangle *roi);
GeglRectangle ts_op_get_cached_region (GeglOperation *operation, const GeglRectangle *roi);
GeglRectangle ts_op_get_invalidated_by_change (GeglOperation *operation, const gchar *input_pad,
                                               const GeglRectangle *input_region);

/* Installs the methods above plus `get_bounding_box` and `process` on a
 * filter class: one whole-image, uncached-per-tile, single-call op. */
void ts_op_class_init_whole_image (GeglOperationClass *operation_class,
                                   GeglRectangle (*get_bounding_box) (GeglOperation *),
                                   gboolean (*process) (GeglOperation *, GeglBuffer *, GeglBuffer *,
                                                        const GeglRectangle *, gint));
/* The same methods but `process`, for an op of another base class (a
 * composer sets its own); an op with its own pads replaces prepare and
 * get_required_for_output afterwards. */
void ts_op_class_init_whole_image_methods (GeglOperationClass *operation_class,
                                           GeglRectangle (*get_bounding_box) (GeglOperation *));

/* The two patch-size properties as the engine takes them: 0 stays
 * automatic, other values become odd and at least TS_MIN_PATCH_SIZE
 * (sliders give any integer), and a fine size chosen above the chosen
 * large size is lowered to it. */
void ts_op_patch_sizes (int patch_size, int fine_patch_size, int *patch_out, int *fine_out);

/* The memory-limit property (MiB, 0 = the engine's default) in bytes. */
size_t ts_op_memory_limit (int mebibytes);

/* Fill `error` with `status` and a printf-style message; returns FALSE,
 * so a check can `return ts_op_set_error (...)`. */
gboolean ts_op_set_error (TsError *error, TsStatus status, const gchar *format, ...)
  G_GNUC_PRINTF (3, 4);

/* The defined result of a failed synthesis: warn "<op name>: <message>"
 * and make `roi` of `output` fully transparent. */
void ts_op_fail (GeglOperation       *operation,
                 GeglBuffer          *output,
                 const GeglRectangle *roi,
                 const gchar         *message);

#endif /* TEXSYNTH_OP_COMMON_H */
