/* The guided procedures, texture by numbers and style transfer, as both
 * GIMPs share them: names, arguments, their checks and the run of
 * texsynth:guided (guided-run.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_GUIDED_PLUGIN_H
#define TEXSYNTH_GUIDED_PLUGIN_H

#include "texsynth-plugin.h"

#define TS_PROC_BY_NUMBERS "plug-in-texsynth-texture-by-numbers"
#define TS_PROC_STYLE      "plug-in-texsynth-style-transfer"
#define TS_OP_GUIDED       "texsynth:guided"

/* texsynth:guided's guide-weight range and default. */
#define TS_PLUGIN_MAX_GUIDE_WEIGHT     100.0
#define TS_PLUGIN_DEFAULT_GUIDE_WEIGHT 1.0

/* Flat: GIMP 2.10 stores last values as raw bytes. */
typedef struct
{
  gdouble  guide_weight;
  gboolean blend_edges; /* texture by numbers only */
  gboolean tileable;    /* texture by numbers only */
  gint     quality;
  gint     seed;
} TsGuidedArgs;

void   ts_guided_args_init  (TsGuidedArgs *args);
/* NULL when valid, else a message for the user (g_free it). */
gchar *ts_guided_args_check (const TsGuidedArgs *args);

/* NULL if a texture-by-numbers run can use these layers (the exemplar's
 * guide has the exemplar's size), else a message naming the layers. */
gchar *ts_guides_size_check (const gchar *exemplar, gint exemplar_width, gint exemplar_height,
                             const gchar *guide, gint guide_width, gint guide_height);

/* Runs texsynth:guided on private copies: `target` is the target guide
 * (or the layer to restyle), `exemplar_guide` the exemplar's own guide, or
 * NULL for style transfer. The result has the target's size, in the
 * engine's format (CIE Lab alpha float). Shows progress; FALSE and
 * `error` if the op could not make a result. */
gboolean ts_plugin_guided (const TsExemplar   *exemplar,
                           GeglBuffer         *exemplar_guide,
                           GeglBuffer         *target,
                           const TsGuidedArgs *args,
                           GeglBuffer        **result,
                           GError            **error);

#endif /* TEXSYNTH_GUIDED_PLUGIN_H */
