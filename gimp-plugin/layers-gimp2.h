/* GIMP 2.10's material-set procedure (layers-gimp2.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_LAYERS_GIMP2_H
#define TEXSYNTH_LAYERS_GIMP2_H

#include "compat-gimp2.h"

/* plug-in-texsynth-render-layers. */
gboolean ts_run_layers2 (GimpRunMode mode, const GimpParam *params, gint n_params,
                         Outcome *outcome);

#endif /* TEXSYNTH_LAYERS_GIMP2_H */
