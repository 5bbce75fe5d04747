/* GIMP 3's material-set procedure (layers-gimp3.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_LAYERS_GIMP3_H
#define TEXSYNTH_LAYERS_GIMP3_H

#include <libgimp/gimp.h>

/* plug-in-texsynth-render-layers. */
GimpValueArray *ts_run_layers3 (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image,
                                GimpDrawable **drawables, GimpProcedureConfig *config,
                                gpointer data);

#endif /* TEXSYNTH_LAYERS_GIMP3_H */
